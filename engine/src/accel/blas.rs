//! Bottom-level acceleration structure: one per mesh, shared by every instance of it.
//!
//! Input: object-space vertex positions (metres) and triangles as vertex-index triples.
//! Output: a [`Blas`]: 8-wide nodes (root = node 0, child indices relative to node 0, leaf payload
//! = `(blocks - 1) << LEAF_COUNT_SHIFT | first block`, relative to block 0) and 1 to
//! [`MAX_LEAF_BLOCKS`] consecutive [`GpuTri4`] blocks per leaf, `prim` = the mesh-local triangle
//! index. Main thread (the `accel` phase of a frame) or a loader thread; pure function.
//! Must not: touch other meshes' data or the scene; the caller places nodes and blocks in the
//! shared buffers and records `node_base` / `block_base` in each `GpuInstance`.
//!
//! Phases: binary build (our binned SAH by default, or an obvhs PLOC preset: `bvh2.rs`,
//! `binned.rs`), SAH-optimal collapse to 8 wide with leaves of at most `4 · max_leaf_blocks`
//! triangles (`collapse.rs`), packing of each leaf into consecutive blocks, four triangles to a
//! block in the binary tree's order, all full but the last (here).

use glam::{Vec3, Vec3A};
use obvhs::{aabb::Aabb as ObAabb, triangle::Triangle};

use super::bvh2::{BuildQuality, build_balanced, build_bvh2};
use super::collapse::{Costs, Wide, collapse};
use crate::layout::{
    GpuBvh8Node, GpuTri4, INVALID, LEAF_BIT, LEAF_COUNT_SHIFT, LEAF_INDEX_MASK, MAX_LEAF_BLOCKS,
};
use crate::scene::Aabb;
use crate::trace::MAX_DEPTH;
use crate::trace::triangle::tri_lane;

/// How a BLAS is built. [`BlasParams::default`] is what the engine uses; the other values exist
/// for measurements (`tools/peer_bench`) and offline builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlasParams {
    /// Binary-build preset.
    pub quality: BuildQuality,
    /// SAH cost of visiting an 8-wide node (the unit of the costs below).
    pub node_cost: f32,
    /// SAH cost of testing one [`GpuTri4`] block, relative to `node_cost`. A leaf of `k` blocks
    /// costs `k` times this.
    pub block_cost: f32,
    /// Most blocks one leaf may reference, 1 to [`MAX_LEAF_BLOCKS`] (clamped).
    pub max_leaf_blocks: u32,
}

impl Default for BlasParams {
    /// Binned SAH, node cost 1, block cost 0.25, leaves of up to four blocks. Measured on the
    /// peer benchmark's dragon (see `accel/mod.rs`): block costs from 0.15 to 0.35 trace alike,
    /// 1.0 (one block per leaf, the earlier layout) 7–10 % slower.
    fn default() -> Self {
        Self {
            quality: BuildQuality::BinnedSah,
            node_cost: 1.0,
            block_cost: 0.25,
            max_leaf_blocks: MAX_LEAF_BLOCKS,
        }
    }
}

impl BlasParams {
    fn costs(&self) -> Costs {
        Costs {
            node: self.node_cost,
            leaf: self.block_cost,
            max_leaf_prims: 4 * self.max_leaf_blocks.clamp(1, MAX_LEAF_BLOCKS),
            prims_per_block: 4,
        }
    }
}

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
    /// SAH cost of the tree: `Σ_nodes A(node)/A(root) · node_cost + Σ_leaves A(leaf)/A(root) ·
    /// blocks(leaf) · block_cost` ([`BlasParams`]; A = surface area, the root counted once). Compare it with the cost after
    /// a refit to decide refit versus rebuild. 0 for an empty mesh. When all triangles lie on a
    /// line or a point (root area 0) it is the plain count `nodes · node + blocks · leaf`.
    pub sah_cost: f32,
}

/// Builds a BLAS with the default parameters ([`BlasParams::default`]).
///
/// Never panics. Triangles with a vertex index outside `positions` or a non-finite vertex are
/// left out (they can never be hit; callers are expected to reject such meshes earlier).
/// Zero-area and duplicate triangles are built in like any other. An empty mesh (or one whose
/// triangles are all left out) gives one [`GpuBvh8Node::EMPTY`] root and no blocks.
pub fn build_blas(positions: &[Vec3], triangles: &[[u32; 3]]) -> Blas {
    build_blas_with_params(positions, triangles, BlasParams::default())
}

/// [`build_blas`] with an explicit binary-build preset (for measurements and offline builds).
pub fn build_blas_with(positions: &[Vec3], triangles: &[[u32; 3]], quality: BuildQuality) -> Blas {
    let params = BlasParams {
        quality,
        ..BlasParams::default()
    };
    build_blas_with_params(positions, triangles, params)
}

/// [`build_blas`] with explicit parameters.
pub fn build_blas_with_params(
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    params: BlasParams,
) -> Blas {
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
    let wide = collapse_bounded(&boxes, Some(&tris), params.quality, params.costs());
    // Each leaf's triangles, four to a block, in consecutive blocks; its payload names them.
    let mut blocks = Vec::with_capacity(wide.leaf_prims.len().div_ceil(4));
    let payloads: Vec<u32> = wide
        .leaf_ranges
        .iter()
        .map(|&(start, count)| {
            let refs = &wide.leaf_prims[start as usize..(start + count) as usize];
            let first = blocks.len() as u32;
            for chunk in refs.chunks(4) {
                blocks.push(pack_block(
                    chunk
                        .iter()
                        .map(|&p| (&tris[p as usize], original[p as usize])),
                ));
            }
            let count = blocks.len() as u32 - first;
            // At most 2^31 triangles (u32 indices) make at most 2^29 blocks of four.
            assert!(
                first <= LEAF_INDEX_MASK && (1..=MAX_LEAF_BLOCKS).contains(&count),
                "BLAS leaf at block {first} with {count} blocks: the payload holds at most \
                 block {LEAF_INDEX_MASK} and {MAX_LEAF_BLOCKS} blocks"
            );
            LEAF_BIT | (count - 1) << LEAF_COUNT_SHIFT | first
        })
        .collect();
    let mut nodes = wide.nodes;
    for node in &mut nodes {
        for child in &mut node.child {
            if *child != INVALID && *child & LEAF_BIT != 0 {
                *child = payloads[(*child & !LEAF_BIT) as usize];
            }
        }
    }
    Blas {
        nodes,
        blocks,
        bounds,
        sah_cost: wide.sah_cost,
    }
}

/// Binary build and collapse; if the result is deeper than the tracers' stacks allow
/// ([`MAX_DEPTH`]), the balanced binary build instead (its depth is at most log2 n + 1).
pub(crate) fn collapse_bounded(
    boxes: &[ObAabb],
    triangles: Option<&[Triangle]>,
    quality: BuildQuality,
    costs: Costs,
) -> Wide {
    let wide = collapse(
        &build_bvh2(boxes, triangles, quality, costs.prims_per_block),
        costs,
    );
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
