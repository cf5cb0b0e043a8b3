//! Reference traversal: one ray at a time, one child at a time. Always compiled, the fallback on
//! CPUs without AVX2, and the algorithm the WGSL traversal follows step for step.
//!
//! Input: nodes and blocks in the shared layout (see [`crate::layout::GpuBvh8Node`]), a ray.
//! Output: closest hit or any hit. Any thread; reads only. Must not: allocate.
//!
//! Algorithm per 8-wide node, for a ray of octant `o` (sign bits of the direction):
//! 1. for each slot, slab distances by one fused multiply-add per plane ([`SlabRay`]: safe
//!    reciprocal, no NaN, far side widened) with the near plane read from `min` where the
//!    direction component is positive and from `max` where it is negative (empty slots,
//!    `min = +inf, max = -inf`, then never pass);
//! 2. `t_near = max(near_x, near_y, near_z, t_min)`, `t_far = min(far_x, far_y, far_z,
//!    far_limit(t_max))`, hit when `t_near <= t_far` (conservative, see [`SlabRay`]);
//! 3. visit slots in the order `perm[rank] >> 3o & 7` for rank 7 down to 0 and push the hit
//!    children with their `t_near`, so the front-most child is on top of the stack;
//! 4. pop; skip entries whose `t_near` lies beyond the current closest hit; a leaf entry
//!    (`LEAF_BIT`) is a run of 1 to 4 consecutive triangle blocks (BLAS, tested in order, see
//!    [`crate::layout::LEAF_COUNT_SHIFT`]) or an instance (TLAS).

use super::STACK_SIZE;
use super::ray::{Ray, SlabRay};
use super::triangle::{TriRay, intersect_lane};
use crate::layout::{GpuBvh8Node, GpuTri4, INVALID, LEAF_BIT, LEAF_COUNT_SHIFT, LEAF_INDEX_MASK};

/// Runs `f` inside a function compiled with FMA when this x86-64 CPU has it, so that the
/// `f32::mul_add` calls of the reference code become single instructions instead of libm calls.
/// Fused multiply-adds are exactly rounded either way: the results are identical.
#[inline(always)]
pub(crate) fn with_fma<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU supports FMA.
        return unsafe { call_with_fma(f) };
    }
    f()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn call_with_fma<R>(f: impl FnOnce() -> R) -> R {
    f()
}

/// Closest hit inside one BLAS, in that BLAS's space: `(t, u, v, triangle)`.
pub(crate) type BlasHit = (f32, f32, f32, u32);

/// What a walk does at a leaf entry (a trait rather than a closure so that every kernel can
/// force it inline into its `#[target_feature]` function).
pub(crate) trait Leaf {
    /// Handles leaf `payload`; may lower `t_max` (closest hit); returns true to stop the walk.
    fn visit(&mut self, payload: u32, t_max: &mut f32) -> bool;
}

/// Walks one tree; returns true when a leaf asked to stop.
#[inline(always)]
pub(crate) fn walk(
    nodes: &[GpuBvh8Node],
    ray: &Ray,
    t_max: &mut f32,
    leaf: &mut impl Leaf,
) -> bool {
    let slab = SlabRay::new(ray.origin, ray.direction);
    let SlabRay {
        rcp,
        near_orcp: on,
        far_rcp: rf,
        far_sub: of,
        octant,
        ..
    } = slab;
    let shift = 3 * octant;
    let negative = [octant & 1 != 0, octant & 2 != 0, octant & 4 != 0];
    let mut stack_entry = [0u32; STACK_SIZE];
    let mut stack_t = [0f32; STACK_SIZE];
    let mut sp = 0usize;
    let mut entry = 0u32; // the root: always an inner node
    loop {
        if entry & LEAF_BIT != 0 {
            if leaf.visit(entry & !LEAF_BIT, t_max) {
                return true;
            }
        } else if let Some(node) = nodes.get(entry as usize) {
            for rank in (0..8).rev() {
                let slot = ((node.perm[rank] >> shift) & 7) as usize;
                let (near_x, far_x) = pick(node.min_x[slot], node.max_x[slot], negative[0]);
                let (near_y, far_y) = pick(node.min_y[slot], node.max_y[slot], negative[1]);
                let (near_z, far_z) = pick(node.min_z[slot], node.max_z[slot], negative[2]);
                let t_near = near_x
                    .mul_add(rcp.x, -on.x)
                    .max(near_y.mul_add(rcp.y, -on.y))
                    .max(near_z.mul_add(rcp.z, -on.z))
                    .max(ray.t_min);
                let t_far = far_x
                    .mul_add(rf.x, -of.x)
                    .min(far_y.mul_add(rf.y, -of.y))
                    .min(far_z.mul_add(rf.z, -of.z))
                    .min(slab.far_limit(*t_max));
                let child = node.child[slot];
                if t_near <= t_far && child != INVALID && sp < STACK_SIZE {
                    stack_entry[sp] = child;
                    stack_t[sp] = t_near;
                    sp += 1;
                }
            }
        }
        loop {
            if sp == 0 {
                return false;
            }
            sp -= 1;
            if stack_t[sp] <= slab.far_limit(*t_max) {
                entry = stack_entry[sp];
                break;
            }
        }
    }
}

/// `(near, far)` plane of one axis for the ray's direction sign on that axis.
#[inline(always)]
fn pick(min: f32, max: f32, negative: bool) -> (f32, f32) {
    if negative { (max, min) } else { (min, max) }
}

/// The blocks of a BLAS leaf payload (see [`LEAF_COUNT_SHIFT`]); empty when out of range.
#[inline(always)]
pub(crate) fn leaf_blocks(blocks: &[GpuTri4], payload: u32) -> &[GpuTri4] {
    let first = (payload & LEAF_INDEX_MASK) as usize;
    let count = (payload >> LEAF_COUNT_SHIFT & 3) as usize + 1;
    blocks.get(first..first + count).unwrap_or(&[])
}

/// Leaf visitor: closest hit in a leaf's triangle blocks.
struct ClosestBlock<'a> {
    blocks: &'a [GpuTri4],
    ray: TriRay,
    t_min: f32,
    best: Option<BlasHit>,
}

impl Leaf for ClosestBlock<'_> {
    #[inline(always)]
    fn visit(&mut self, payload: u32, t_max: &mut f32) -> bool {
        for block in leaf_blocks(self.blocks, payload) {
            for lane in 0..4 {
                if let Some((t, u, v)) = intersect_lane(block, lane, &self.ray, self.t_min, *t_max)
                {
                    *t_max = t;
                    self.best = Some((t, u, v, block.prim[lane]));
                }
            }
        }
        false
    }
}

/// Leaf visitor: any hit in a triangle block.
struct AnyBlock<'a> {
    blocks: &'a [GpuTri4],
    ray: TriRay,
    t_min: f32,
}

impl Leaf for AnyBlock<'_> {
    #[inline(always)]
    fn visit(&mut self, payload: u32, t_max: &mut f32) -> bool {
        leaf_blocks(self.blocks, payload).iter().any(|block| {
            (0..4).any(|lane| intersect_lane(block, lane, &self.ray, self.t_min, *t_max).is_some())
        })
    }
}

/// Closest hit in one BLAS (`nodes`/`blocks` start at the BLAS's first node and block).
#[inline(always)]
pub(crate) fn closest_blas(
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    ray: &Ray,
    t_max: &mut f32,
) -> Option<BlasHit> {
    let mut leaf = ClosestBlock {
        blocks,
        ray: TriRay::new(ray.origin, ray.direction),
        t_min: ray.t_min,
        best: None,
    };
    walk(nodes, ray, t_max, &mut leaf);
    leaf.best
}

/// Any hit in one BLAS.
#[inline(always)]
pub(crate) fn occluded_blas(nodes: &[GpuBvh8Node], blocks: &[GpuTri4], ray: &Ray) -> bool {
    let mut leaf = AnyBlock {
        blocks,
        ray: TriRay::new(ray.origin, ray.direction),
        t_min: ray.t_min,
    };
    walk(nodes, ray, &mut { ray.t_max }, &mut leaf)
}
