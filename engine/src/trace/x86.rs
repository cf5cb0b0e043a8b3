//! Entry points of the AVX2 and AVX-512 kernels: `#[target_feature]` functions that instantiate
//! the shared core (`simd.rs`, `simd_block.rs`) and the two-level scene walk (`scene.rs`) with
//! those features.
//!
//! Safety contract of every `unsafe fn` here: the CPU supports the features named on it; the
//! only caller, `scene.rs`, checks that with [`super::Kernel::checked`] first. Any thread.
//! Must not: be called without that check.

use super::ray::{Hit, Ray};
use super::scalar::{BlasHit, Leaf};
use super::scene::{TraceScene, Walker, closest_scene as closest_two_level, occluded_scene};
use super::simd::{self, NodeRay};
use super::simd_block;
use crate::layout::{GpuBvh8Node, GpuTri4};

/// The SIMD walker; only constructed inside the `#[target_feature]` functions below, so its
/// (inlined) methods always run with the features of `W512`.
#[derive(Clone, Copy)]
struct SimdWalker<const W512: bool>(());

impl<const W512: bool> Walker for SimdWalker<W512> {
    #[inline(always)]
    fn closest_blas(
        self,
        nodes: &[GpuBvh8Node],
        blocks: &[GpuTri4],
        ray: &Ray,
        t_max: &mut f32,
    ) -> Option<BlasHit> {
        // SAFETY: a SimdWalker exists only inside a function with the features enabled.
        unsafe { simd_block::closest_blas::<W512>(nodes, blocks, ray, t_max) }
    }
    #[inline(always)]
    fn occluded_blas(self, nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> bool {
        // SAFETY: as above.
        unsafe { simd_block::occluded_blas::<W512>(nodes, blocks, ray) }
    }
    #[inline(always)]
    fn walk_tlas(
        self,
        nodes: &[GpuBvh8Node],
        ray: &Ray,
        t_max: &mut f32,
        leaf: &mut impl Leaf,
    ) -> bool {
        let node_ray = NodeRay::new(ray);
        // SAFETY: as above. TLAS walks keep the distance check (closest) or stop at the first
        // leaf that reports a hit (occluded), exactly like the scalar walk.
        unsafe { simd::walk::<W512, false>(nodes, &node_ray, t_max, leaf) }
    }
}

macro_rules! kernel {
    ($module:ident, $features:literal, $wide:literal) => {
        pub(crate) mod $module {
            use super::*;

            /// # Safety
            #[doc = concat!("The CPU supports `", $features, "`.")]
            #[target_feature(enable = $features)]
            pub(crate) unsafe fn closest_blas(
                nodes: &[GpuBvh8Node],
                blocks: &[GpuTri4],
                ray: &Ray,
                t_max: &mut f32,
            ) -> Option<BlasHit> {
                unsafe { simd_block::closest_blas::<$wide>(nodes, blocks, ray, t_max) }
            }

            /// # Safety
            #[doc = concat!("The CPU supports `", $features, "`.")]
            #[target_feature(enable = $features)]
            pub(crate) unsafe fn occluded_blas(
                nodes: &[GpuBvh8Node],
                blocks: &[GpuTri4],
                ray: &Ray,
            ) -> bool {
                unsafe { simd_block::occluded_blas::<$wide>(nodes, blocks, ray) }
            }

            /// # Safety
            #[doc = concat!("The CPU supports `", $features, "`.")]
            #[target_feature(enable = $features)]
            pub(crate) unsafe fn closest_scene(scene: &TraceScene, ray: &Ray) -> Option<Hit> {
                closest_two_level(SimdWalker::<$wide>(()), scene, ray)
            }

            /// # Safety
            #[doc = concat!("The CPU supports `", $features, "`.")]
            #[target_feature(enable = $features)]
            pub(crate) unsafe fn occluded_scene(scene: &TraceScene, ray: &Ray) -> bool {
                super::occluded_scene(SimdWalker::<$wide>(()), scene, ray)
            }
        }
    };
}

kernel!(avx2, "avx2,fma,popcnt,bmi1", false);
kernel!(
    avx512,
    "avx512f,avx512vl,avx512bw,avx512dq,avx2,popcnt,bmi1",
    true
);
