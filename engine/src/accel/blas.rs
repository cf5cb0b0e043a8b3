//! Bottom-level acceleration structure: one per mesh, shared by every instance of it.
//!
//! Input: object-space vertex positions (metres) and triangles as vertex-index triples.
//! Output: a [`Blas`]: 8-wide nodes (root = node 0, child indices relative to node 0, leaf payload
//! = block index relative to block 0) and one [`GpuTri4`] block per leaf, `prim` = the mesh-local
//! triangle index. Main thread (the `accel` phase of a frame) or a loader thread; pure function.
//! Must not: touch other meshes' data or the scene; the caller places nodes and blocks in the
//! shared buffers and records `node_base` / `block_base` in each `GpuInstance`.
//!
//! Phases: binary build (our binned SAH by default, or an obvhs PLOC preset: `bvh2.rs`,
//! `binned.rs`), SAH-optimal collapse to 8 wide with leaves of
//! at most four triangles (`collapse.rs`), packing of each leaf into one block (here).

use glam::{Vec3, Vec3A};
use obvhs::{aabb::Aabb as ObAabb, triangle::Triangle};

use super::MAX_DEPTH;
use super::bounds::Aabb;
use super::bvh2::{BuildQuality, build_balanced, build_bvh2};
use super::collapse::{Costs, Wide, collapse};
use crate::layout::{GpuBvh8Node, GpuTri4};

/// SAH constants of a BLAS, in units of one 8-wide node visit. A 4-triangle block test costs
/// about as much as a node test on this layout (both are one SIMD pass over a 160-256 byte
/// record). Measured: leaf costs from 0.5 to 3 and node costs up to 4 changed the dragon's
/// tree by under 1 % and its traversal speed by less than the noise (±3 %).
pub const BLAS_NODE_COST: f32 = 1.0;
/// Cost of testing one [`GpuTri4`] block (1 to 4 triangles alike), relative to a node visit.
pub const BLAS_LEAF_COST: f32 = 1.0;

const BLAS_COSTS: Costs = Costs {
    node: BLAS_NODE_COST,
    leaf: BLAS_LEAF_COST,
    max_leaf_prims: 4,
};

/// The acceleration structure of one mesh, in the shared layout.
#[derive(Clone, Debug)]
pub struct Blas {
    /// Root first. Inner child indices are relative to the first node; leaf payloads are block
    /// indices relative to the first block.
    pub nodes: Vec<GpuBvh8Node>,
    /// One block per leaf, each holding 1 to 4 triangles; unused lanes have zero edges and
    /// `prim = INVALID`.
    pub blocks: Vec<GpuTri4>,
    /// Object-space bounds of every triangle that was built in (empty for an empty mesh).
    pub bounds: Aabb,
    /// SAH cost of the tree: `Σ_nodes A(node)/A(root) · BLAS_NODE_COST + Σ_blocks A(block)/A(root)
    /// · BLAS_LEAF_COST` (A = surface area, the root counted once). Compare it with the cost after
    /// a refit to decide refit versus rebuild. 0 for an empty mesh. When all triangles lie on a
    /// line or a point (root area 0) it is the plain count `nodes · node + blocks · leaf`.
    pub sah_cost: f32,
}

/// Builds a BLAS with the default quality ([`BuildQuality::BinnedSah`]).
///
/// Never panics. Triangles with a vertex index outside `positions` or a non-finite vertex are
/// left out (they can never be hit; callers are expected to reject such meshes earlier).
/// Zero-area and duplicate triangles are built in like any other. An empty mesh (or one whose
/// triangles are all left out) gives one [`GpuBvh8Node::EMPTY`] root and no blocks.
pub fn build_blas(positions: &[Vec3], triangles: &[[u32; 3]]) -> Blas {
    build_blas_with(positions, triangles, BuildQuality::default())
}

/// [`build_blas`] with an explicit binary-build preset (for measurements and offline builds).
pub fn build_blas_with(positions: &[Vec3], triangles: &[[u32; 3]], quality: BuildQuality) -> Blas {
    let mut tris = Vec::with_capacity(triangles.len());
    let mut boxes = Vec::with_capacity(triangles.len());
    let mut original = Vec::with_capacity(triangles.len());
    let mut bounds = Aabb::EMPTY;
    for (index, t) in triangles.iter().enumerate() {
        let vertex = |i: u32| positions.get(i as usize).copied().filter(|p| p.is_finite());
        let (Some(a), Some(b), Some(c)) = (vertex(t[0]), vertex(t[1]), vertex(t[2])) else {
            continue;
        };
        let tri = Triangle {
            v0: Vec3A::from(a),
            v1: Vec3A::from(b),
            v2: Vec3A::from(c),
        };
        let b = tri.aabb();
        bounds = bounds.union(Aabb::new(Vec3::from(b.min), Vec3::from(b.max)));
        tris.push(tri);
        boxes.push(b);
        original.push(index as u32);
    }
    if tris.is_empty() {
        return Blas {
            nodes: vec![GpuBvh8Node::EMPTY],
            blocks: Vec::new(),
            bounds: Aabb::EMPTY,
            sah_cost: 0.0,
        };
    }
    let wide = collapse_bounded(&boxes, Some(&tris), quality, BLAS_COSTS);
    let blocks = wide
        .leaf_ranges
        .iter()
        .map(|&(start, count)| {
            let refs = &wide.leaf_prims[start as usize..(start + count) as usize];
            pack_block(
                refs.iter()
                    .map(|&p| (&tris[p as usize], original[p as usize])),
            )
        })
        .collect();
    Blas {
        nodes: wide.nodes,
        blocks,
        bounds,
        sah_cost: wide.sah_cost,
    }
}

/// PLOC build and collapse; if the result is deeper than the tracers' stacks allow
/// ([`MAX_DEPTH`]), the balanced binary build instead (its depth is at most log2 n + 1).
pub(crate) fn collapse_bounded(
    boxes: &[ObAabb],
    triangles: Option<&[Triangle]>,
    quality: BuildQuality,
    costs: Costs,
) -> Wide {
    let wide = collapse(&build_bvh2(boxes, triangles, quality), costs);
    if wide.depth <= MAX_DEPTH {
        return wide;
    }
    log::debug!(
        "accel: PLOC tree of {} primitives is {} levels deep (limit {MAX_DEPTH}); using the balanced build",
        boxes.len(),
        wide.depth
    );
    collapse(&build_balanced(boxes), costs)
}

/// One block from up to four (triangle, mesh-local index) pairs; the rest stay unused lanes.
fn pack_block<'a>(tris: impl Iterator<Item = (&'a Triangle, u32)>) -> GpuTri4 {
    let mut block = GpuTri4::EMPTY;
    for (lane, (tri, prim)) in tris.take(4).enumerate() {
        let [v0, e1, e2] = tri_lane(tri.v0.into(), tri.v1.into(), tri.v2.into());
        [block.v0_x[lane], block.v0_y[lane], block.v0_z[lane]] = v0.to_array();
        [block.e1_x[lane], block.e1_y[lane], block.e1_z[lane]] = e1.to_array();
        [block.e2_x[lane], block.e2_y[lane], block.e2_z[lane]] = e2.to_array();
        block.prim[lane] = prim;
    }
    block
}

/// The stored form of a triangle: `[v0, e1 = v1 - v0, e2 = v2 - v0]`. Every consumer (blocks,
/// the brute-force reference) uses this function so that all of them intersect the same numbers.
pub fn tri_lane(v0: Vec3, v1: Vec3, v2: Vec3) -> [Vec3; 3] {
    [v0, v1 - v0, v2 - v0]
}
