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

/// The binary preset of the per-frame TLAS build (fast build; the tree is small).
const TLAS_QUALITY: BuildQuality = BuildQuality::VeryFast;

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
    let wide = collapse_bounded(&boxes, None, TLAS_QUALITY, TLAS_COSTS);
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
