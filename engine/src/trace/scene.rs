//! The public entry points: two-level (TLAS → instance → BLAS) queries over the flattened scene,
//! single-BLAS queries, and the choice of kernel.
//!
//! Input: [`TraceScene`] (borrowed node, block and instance buffers) and a world-space [`Ray`].
//! Output: [`Hit`] or a boolean. Any thread, many at once (read only). Must not: allocate or
//! write anything; the scene is the previous frame's commit, shared with the render thread.

use super::Kernel;
use super::ray::{Hit, Ray, to_object_space};
use super::scalar::{self, Leaf};
use crate::layout::{GpuBvh8Node, GpuInstance, GpuTri4, INVALID};

/// The flattened scene as both tracers read it. The TLAS lives in `nodes` from `tlas_root` on
/// (its inner child indices are relative to `tlas_root`, its leaf payloads index `instances`);
/// each instance's BLAS starts at its `node_base` / `block_base`.
#[derive(Clone, Copy, Debug)]
pub struct TraceScene<'a> {
    pub nodes: &'a [GpuBvh8Node],
    pub blocks: &'a [GpuTri4],
    pub instances: &'a [GpuInstance],
    pub tlas_root: u32,
}

/// One tree walk and block tests, implemented by each kernel (scalar, AVX2, AVX-512).
pub(crate) trait Walker: Copy {
    /// Closest hit in one BLAS: `(t, u, v, triangle)`; lowers `t_max` on a hit.
    fn closest_blas(
        self,
        nodes: &[GpuBvh8Node],
        blocks: &[GpuTri4],
        ray: &Ray,
        t_max: &mut f32,
    ) -> Option<scalar::BlasHit>;
    /// Any hit in one BLAS.
    fn occluded_blas(self, nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> bool;
    /// Walks a TLAS; `leaf(instance, t_max)` returns true to stop.
    fn walk_tlas(
        self,
        nodes: &[GpuBvh8Node],
        ray: &Ray,
        t_max: &mut f32,
        leaf: &mut impl Leaf,
    ) -> bool;
}

/// The reference kernel.
#[derive(Clone, Copy)]
pub(crate) struct ScalarWalker;

impl Walker for ScalarWalker {
    #[inline(always)]
    fn closest_blas(
        self,
        nodes: &[GpuBvh8Node],
        blocks: &[GpuTri4],
        ray: &Ray,
        t_max: &mut f32,
    ) -> Option<scalar::BlasHit> {
        scalar::closest_blas(nodes, blocks, ray, t_max)
    }
    #[inline(always)]
    fn occluded_blas(self, nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> bool {
        scalar::occluded_blas(nodes, blocks, ray)
    }
    #[inline(always)]
    fn walk_tlas(
        self,
        nodes: &[GpuBvh8Node],
        ray: &Ray,
        t_max: &mut f32,
        leaf: &mut impl Leaf,
    ) -> bool {
        scalar::walk(nodes, ray, t_max, leaf)
    }
}

/// The instance's BLAS buffers and object-space ray, or `None` when its bases are out of range.
#[inline(always)]
fn instance_view<'a>(
    scene: &TraceScene<'a>,
    index: u32,
    ray: &Ray,
) -> Option<(&'a [GpuBvh8Node], &'a [GpuTri4], Ray)> {
    let instance = scene.instances.get(index as usize)?;
    let nodes = scene.nodes.get(instance.node_base as usize..)?;
    let blocks = scene.blocks.get(instance.block_base as usize..)?;
    Some((nodes, blocks, to_object_space(instance, ray)))
}

/// TLAS leaf visitor of a closest-hit query: the instance's BLAS with the object-space ray.
struct ClosestInstance<'s, 'a, W> {
    walker: W,
    scene: &'s TraceScene<'a>,
    ray: &'s Ray,
    best: Option<Hit>,
}

impl<W: Walker> Leaf for ClosestInstance<'_, '_, W> {
    #[inline(always)]
    fn visit(&mut self, index: u32, t_max: &mut f32) -> bool {
        if let Some((nodes, blocks, local)) = instance_view(self.scene, index, self.ray)
            && let Some((t, u, v, triangle)) =
                self.walker.closest_blas(nodes, blocks, &local, t_max)
        {
            self.best = Some(Hit {
                t,
                u,
                v,
                instance: index,
                triangle,
            });
        }
        false
    }
}

/// TLAS leaf visitor of an any-hit query.
struct AnyInstance<'s, 'a, W> {
    walker: W,
    scene: &'s TraceScene<'a>,
    ray: &'s Ray,
}

impl<W: Walker> Leaf for AnyInstance<'_, '_, W> {
    #[inline(always)]
    fn visit(&mut self, index: u32, _t_max: &mut f32) -> bool {
        instance_view(self.scene, index, self.ray)
            .is_some_and(|(nodes, blocks, local)| self.walker.occluded_blas(nodes, blocks, &local))
    }
}

/// Two-level closest hit with any kernel.
#[inline(always)]
pub(crate) fn closest_scene<W: Walker>(walker: W, scene: &TraceScene, ray: &Ray) -> Option<Hit> {
    let tlas = scene.nodes.get(scene.tlas_root as usize..)?;
    let mut leaf = ClosestInstance {
        walker,
        scene,
        ray,
        best: None,
    };
    walker.walk_tlas(tlas, ray, &mut { ray.t_max }, &mut leaf);
    leaf.best
}

/// Two-level any hit with any kernel.
#[inline(always)]
pub(crate) fn occluded_scene<W: Walker>(walker: W, scene: &TraceScene, ray: &Ray) -> bool {
    let Some(tlas) = scene.nodes.get(scene.tlas_root as usize..) else {
        return false;
    };
    let mut leaf = AnyInstance { walker, scene, ray };
    walker.walk_tlas(tlas, ray, &mut { ray.t_max }, &mut leaf)
}

impl TraceScene<'_> {
    /// Closest hit along the ray (`t_min < t < t_max`), with the fastest kernel of this CPU.
    pub fn closest(&self, ray: &Ray) -> Option<Hit> {
        self.closest_with(Kernel::best(), ray)
    }

    /// Whether anything is hit along the ray (`t_min < t < t_max`); stops at the first hit.
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.occluded_with(Kernel::best(), ray)
    }

    /// [`Self::closest`] with a chosen kernel (one this CPU lacks runs the scalar kernel).
    pub fn closest_with(&self, kernel: Kernel, ray: &Ray) -> Option<Hit> {
        match kernel.checked() {
            // SAFETY (all SIMD arms): `checked` returned the kernel, so the CPU supports it.
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx512 => unsafe { super::x86::avx512::closest_scene(self, ray) },
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx2 => unsafe { super::x86::avx2::closest_scene(self, ray) },
            _ => scalar::with_fma(|| closest_scene(ScalarWalker, self, ray)),
        }
    }

    /// [`Self::occluded`] with a chosen kernel (one this CPU lacks runs the scalar kernel).
    pub fn occluded_with(&self, kernel: Kernel, ray: &Ray) -> bool {
        match kernel.checked() {
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx512 => unsafe { super::x86::avx512::occluded_scene(self, ray) },
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx2 => unsafe { super::x86::avx2::occluded_scene(self, ray) },
            _ => scalar::with_fma(|| occluded_scene(ScalarWalker, self, ray)),
        }
    }
}

/// Closest hit in a single BLAS (`nodes`, `blocks` as `accel::Blas` holds them), in its
/// own space; `Hit::instance` is `INVALID`. Fastest kernel of this CPU.
pub fn closest_blas(nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> Option<Hit> {
    closest_blas_with(Kernel::best(), nodes, blocks, ray)
}

/// Whether a single BLAS is hit along the ray. Fastest kernel of this CPU.
pub fn occluded_blas(nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> bool {
    occluded_blas_with(Kernel::best(), nodes, blocks, ray)
}

/// [`closest_blas`] with a chosen kernel (one this CPU lacks runs the scalar kernel).
pub fn closest_blas_with(
    kernel: Kernel,
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    ray: &Ray,
) -> Option<Hit> {
    let mut t_max = ray.t_max;
    let hit = match kernel.checked() {
        // SAFETY (all SIMD arms): `checked` returned the kernel, so the CPU supports it.
        #[cfg(target_arch = "x86_64")]
        Kernel::Avx512 => unsafe {
            super::x86::avx512::closest_blas(nodes, blocks, ray, &mut t_max)
        },
        #[cfg(target_arch = "x86_64")]
        Kernel::Avx2 => unsafe { super::x86::avx2::closest_blas(nodes, blocks, ray, &mut t_max) },
        _ => scalar::with_fma(|| scalar::closest_blas(nodes, blocks, ray, &mut t_max)),
    };
    hit.map(|(t, u, v, triangle)| Hit {
        t,
        u,
        v,
        instance: INVALID,
        triangle,
    })
}

/// [`occluded_blas`] with a chosen kernel (one this CPU lacks runs the scalar kernel).
pub fn occluded_blas_with(
    kernel: Kernel,
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    ray: &Ray,
) -> bool {
    match kernel.checked() {
        #[cfg(target_arch = "x86_64")]
        Kernel::Avx512 => unsafe { super::x86::avx512::occluded_blas(nodes, blocks, ray) },
        #[cfg(target_arch = "x86_64")]
        Kernel::Avx2 => unsafe { super::x86::avx2::occluded_blas(nodes, blocks, ray) },
        _ => scalar::with_fma(|| scalar::occluded_blas(nodes, blocks, ray)),
    }
}
