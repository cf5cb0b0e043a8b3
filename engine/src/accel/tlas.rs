//! Top-level acceleration structure over all instances, rebuilt every frame any instance moves.
//!
//! Input: world-space bounds per instance (index = instance index). Output: 8-wide nodes in the
//! shared layout, root first, inner child indices relative to the first node, leaf payload = the
//! instance index, one instance per leaf slot. Main thread (end of the `accel` phase).
//! Must not: read BLAS data or instance transforms (the caller transforms each mesh's bounds).

use obvhs::aabb::Aabb as ObAabb;

use super::blas::collapse_bounded;
use super::bvh2::BuildQuality;
use super::collapse::Costs;
use crate::layout::{GpuBvh8Node, LEAF_BIT};
use crate::scene::Aabb;

/// SAH constants of the TLAS: an instance leaf costs a ray transform plus a BLAS root visit,
/// about two node visits.
const TLAS_COSTS: Costs = Costs {
    node: 1.0,
    leaf: 2.0,
    max_leaf_prims: 1,
    prims_per_block: 1,
};

/// Up to this many instances the per-frame TLAS uses the binned SAH build
/// ([`BuildQuality::BinnedSah`]); above it PLOC very fast. Measured 2026-12-06 (Intel Xeon, one
/// thread, `bench instance-merge` / `bench chamber-rays` A/B and `bench build`): on Reflect's
/// chamber 1 (279 instances) the binned tree traces the game's frame 3 % faster (median) (2.03–2.11
/// against 1.97–1.98 Mrays per CPU second, three interleaved rounds) for a build of well under a
/// millisecond; at 10,000 instances it builds in 14.5 ms against PLOC's 9.9 ms, a per-frame cost
/// that the small gain does not repay.
const BINNED_TLAS_MAX_INSTANCES: usize = 2048;

/// The binary preset of the per-frame TLAS build for `instances` instances.
fn tlas_quality(instances: usize) -> BuildQuality {
    if instances <= BINNED_TLAS_MAX_INSTANCES {
        BuildQuality::BinnedSah
    } else {
        BuildQuality::VeryFast
    }
}

/// Builds the TLAS. Instances whose bounds are empty or not finite (for example an instance of
/// an empty mesh) are left out and can never be hit. No instances (or none left) gives one
/// [`GpuBvh8Node::EMPTY`] root.
pub fn build_tlas(instance_bounds: &[Aabb]) -> Vec<GpuBvh8Node> {
    let mut boxes = Vec::with_capacity(instance_bounds.len());
    let mut original = Vec::with_capacity(instance_bounds.len());
    for (index, b) in instance_bounds.iter().enumerate() {
        if b.is_finite() {
            boxes.push(ObAabb::new(b.min.into(), b.max.into()));
            original.push(index as u32);
        }
    }
    if boxes.is_empty() {
        return vec![GpuBvh8Node::EMPTY];
    }
    let wide = collapse_bounded(&boxes, None, tlas_quality(boxes.len()), TLAS_COSTS);
    let mut nodes = wide.nodes;
    for node in &mut nodes {
        for child in &mut node.child {
            if *child != crate::layout::INVALID && *child & LEAF_BIT != 0 {
                let (start, _) = wide.leaf_ranges[(*child & !LEAF_BIT) as usize];
                let prim = wide.leaf_prims[start as usize];
                *child = LEAF_BIT | original[prim as usize];
            }
        }
    }
    nodes
}
