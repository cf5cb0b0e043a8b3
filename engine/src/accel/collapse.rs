//! Collapse of a binary BVH into the 8-wide [`GpuBvh8Node`] layout, SAH-optimal for the tree given.
//!
//! Input: an obvhs [`Bvh2`] with one primitive per leaf and the [`Costs`] of the target
//! traversal. Output: [`Wide`]: nodes (root first, child indices relative to node 0, leaf
//! payload = leaf index), each leaf's primitive references (at most `Costs::max_leaf_prims`,
//! deduplicated), the SAH cost of the result and its depth. Calling thread, no shared state.
//! Must not: know what a primitive is (triangles and instances look the same here).
//!
//! Algorithm: the dynamic programme of Ylitie, Karras and Laine 2017 ("Efficient Incoherent Ray
//! Traversal on GPUs Through Compressed Wide BVHs", §4.1), with a leaf cost that does not depend
//! on the primitive count, because a [`crate::layout::GpuTri4`] block tests its four lanes at
//! once. For every binary node `n` and slot budget `i` in 1..=8, `cost(n, i)` is the cheapest way
//! to represent `n`'s subtree with at most `i` slots of the parent 8-wide node:
//!
//! ```text
//! cost(n, 1) = min( A(n)·leaf        if prims(n) <= max_leaf_prims,
//!                   A(n)·node + split(n, 8) )            n becomes one 8-wide node
//! cost(n, i) = min( cost(n, 1), split(n, i) )             i >= 2
//! split(n, j) = min over k in 1..j of cost(left, k) + cost(right, j - k)
//! ```
//!
//! `A` is surface area. The root is always an 8-wide node. Then the nodes are emitted depth first,
//! each node's inner children stored next to each other, leaves numbered in emission order.

use glam::Vec3;
use obvhs::bvh2::Bvh2;

use super::octant_order::octant_orders;
use crate::layout::{GpuBvh8Node, LEAF_BIT};
use crate::scene::Aabb;

/// Relative costs the collapse minimises (units: one 8-wide node test). Also the constants of the
/// reported SAH cost: `sah = Σ_nodes A(node)/A(root)·node + Σ_leaves A(leaf)/A(root)·leaf·blocks`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Costs {
    /// Cost of visiting an 8-wide node: load it, eight slab tests, order and push the hits.
    pub node: f32,
    /// Cost of one block of a leaf: a 4-lane triangle block (BLAS) or an instance (TLAS).
    pub leaf: f32,
    /// Most primitive references in one leaf (a few `GpuTri4` blocks, 1 for a TLAS instance).
    pub max_leaf_prims: u32,
    /// Primitives per block: a leaf of `n` primitives costs `leaf · ceil(n / prims_per_block)`
    /// (4 for `GpuTri4` blocks, 1 for instances).
    pub prims_per_block: u32,
}

impl Costs {
    /// Cost of a leaf of `count` primitives per unit of surface area.
    fn leaf_cost(&self, count: u32) -> f32 {
        self.leaf * count.div_ceil(self.prims_per_block.max(1)) as f32
    }
}

/// The 8-wide tree before its leaves are turned into triangle blocks or instance indices.
pub(crate) struct Wide {
    /// Root first; `child` holds inner-node indices (relative to node 0) or `LEAF_BIT | leaf`.
    pub nodes: Vec<GpuBvh8Node>,
    /// Per leaf: range `start..start + count` of `leaf_prims`.
    pub leaf_ranges: Vec<(u32, u32)>,
    /// Values of `Bvh2::primitive_indices` (deduplicated per leaf).
    pub leaf_prims: Vec<u32>,
    /// SAH cost with the [`Costs`] used (see there).
    pub sah_cost: f32,
    /// Levels of 8-wide nodes on the longest root-to-leaf path (1 for a lone root).
    pub depth: u32,
}

/// A slot of an 8-wide node before emission: the binary subtree becomes a leaf or a node.
#[derive(Clone, Copy)]
enum Slot {
    Leaf(u32),
    Node(u32),
}

/// Per binary node, the decisions of the dynamic programme, packed in a u32: bits `3(j-2)..+3`
/// hold the best `k` of `split(n, j)` for j in 2..=8; bit 21: `cost(n, 1)` is the leaf;
/// bit 22 + (i-2): `cost(n, i)` is `cost(n, 1)` (for i in 2..=8).
#[derive(Clone, Copy, Default)]
struct Decision(u32);

impl Decision {
    const SINGLE_IS_LEAF: u32 = 1 << 21;
    fn k(self, j: usize) -> usize {
        ((self.0 >> (3 * (j - 2))) & 7) as usize
    }
    fn single_is_leaf(self) -> bool {
        self.0 & Self::SINGLE_IS_LEAF != 0
    }
    fn uses_single(self, i: usize) -> bool {
        i == 1 || self.0 & (1 << (22 + i - 2)) != 0
    }
}

/// Collapses `bvh` (non-empty, one primitive per leaf) into 8-wide nodes.
pub(crate) fn collapse(bvh: &Bvh2, costs: Costs) -> Wide {
    let decisions = plan(bvh, costs);
    emit(bvh, &decisions, costs)
}

fn half_area_of(bvh: &Bvh2, n: usize) -> f32 {
    bvh.nodes[n].aabb().half_area()
}

/// Bottom-up dynamic programme (iterative post-order; the cost vectors of children live on a
/// value stack, so memory is O(depth) for costs plus one u32 decision per binary node).
fn plan(bvh: &Bvh2, costs: Costs) -> Vec<Decision> {
    let mut decisions = vec![Decision::default(); bvh.nodes.len()];
    let mut values: Vec<([f32; 8], u32)> = Vec::new();
    let mut work: Vec<(usize, bool)> = vec![(0, false)];
    while let Some((n, children_done)) = work.pop() {
        let node = &bvh.nodes[n];
        let area = half_area_of(bvh, n);
        if node.is_leaf() {
            let leaf = if node.prim_count <= costs.max_leaf_prims {
                area * costs.leaf_cost(node.prim_count)
            } else {
                f32::INFINITY
            };
            decisions[n] = Decision(Decision::SINGLE_IS_LEAF | (0x7f << 22));
            values.push(([leaf; 8], node.prim_count));
            continue;
        }
        if !children_done {
            work.push((n, true));
            work.push((node.first_index as usize + 1, false));
            work.push((node.first_index as usize, false));
            continue;
        }
        let (right, right_count) = values.pop().unwrap_or(([f32::INFINITY; 8], 0));
        let (left, left_count) = values.pop().unwrap_or(([f32::INFINITY; 8], 0));
        let count = left_count.saturating_add(right_count);
        let mut bits = 0u32;
        let mut split = [f32::INFINITY; 9];
        for j in 2..=8 {
            let (mut best, mut best_k) = (left[0] + right[j - 2], 1);
            for k in 2..j {
                let c = left[k - 1] + right[j - k - 1];
                if c < best {
                    best = c;
                    best_k = k;
                }
            }
            split[j] = best;
            bits |= (best_k as u32) << (3 * (j - 2));
        }
        let as_node = area * costs.node + split[8];
        let as_leaf = area * costs.leaf_cost(count);
        let leaf_ok = count <= costs.max_leaf_prims && (as_leaf <= as_node || as_node.is_nan());
        let single = if leaf_ok {
            bits |= Decision::SINGLE_IS_LEAF;
            as_leaf
        } else {
            as_node
        };
        let mut out = [single; 8];
        for i in 2..=8 {
            if single <= split[i] {
                bits |= 1 << (22 + i - 2);
            } else {
                out[i - 1] = split[i];
            }
        }
        decisions[n] = Decision(bits);
        values.push((out, count));
    }
    decisions
}

/// The slots that represent subtree `n` with a budget of `i` slots.
fn gather(bvh: &Bvh2, decisions: &[Decision], n: usize, i: usize, out: &mut Vec<Slot>) {
    let node = &bvh.nodes[n];
    let d = decisions[n];
    if node.is_leaf() || d.uses_single(i) {
        out.push(if node.is_leaf() || d.single_is_leaf() {
            Slot::Leaf(n as u32)
        } else {
            Slot::Node(n as u32)
        });
        return;
    }
    let k = d.k(i).clamp(1, i - 1);
    gather(bvh, decisions, node.first_index as usize, k, out);
    gather(bvh, decisions, node.first_index as usize + 1, i - k, out);
}

/// The slots of the 8-wide node made from binary node `n`.
fn node_slots(bvh: &Bvh2, decisions: &[Decision], n: usize, out: &mut Vec<Slot>) {
    out.clear();
    let node = &bvh.nodes[n];
    if node.is_leaf() {
        out.push(Slot::Leaf(n as u32));
        return;
    }
    let k = decisions[n].k(8).clamp(1, 7);
    gather(bvh, decisions, node.first_index as usize, k, out);
    gather(bvh, decisions, node.first_index as usize + 1, 8 - k, out);
}

/// Appends the deduplicated primitive references of subtree `n` to `prims`.
fn collect_prims(bvh: &Bvh2, n: usize, prims: &mut Vec<u32>) {
    let start = prims.len();
    let mut stack = vec![n];
    while let Some(i) = stack.pop() {
        let node = &bvh.nodes[i];
        if node.is_leaf() {
            let first = node.first_index as usize;
            for &p in &bvh.primitive_indices[first..first + node.prim_count as usize] {
                if !prims[start..].contains(&p) {
                    prims.push(p);
                }
            }
        } else {
            stack.push(node.first_index as usize + 1);
            stack.push(node.first_index as usize);
        }
    }
}

fn to_aabb(b: &obvhs::aabb::Aabb) -> Aabb {
    Aabb::new(Vec3::from(b.min), Vec3::from(b.max))
}

/// Writes the nodes depth first and accumulates the SAH cost.
fn emit(bvh: &Bvh2, decisions: &[Decision], costs: Costs) -> Wide {
    let mut wide = Wide {
        nodes: vec![GpuBvh8Node::EMPTY],
        leaf_ranges: Vec::new(),
        leaf_prims: Vec::new(),
        sah_cost: 0.0,
        depth: 1,
    };
    let (mut node_area, mut leaf_area, mut leaf_blocks) = (0.0f64, 0.0f64, 0.0f64);
    let mut slots = Vec::with_capacity(8);
    let mut work = vec![(0usize, 0usize, 1u32)];
    let mut root_box = Aabb::EMPTY;
    while let Some((wide_index, n, depth)) = work.pop() {
        wide.depth = wide.depth.max(depth);
        node_slots(bvh, decisions, n, &mut slots);
        let mut node = GpuBvh8Node::EMPTY;
        let first_child = wide.nodes.len();
        let mut inner = Vec::with_capacity(8);
        for (s, slot) in slots.iter().enumerate() {
            let (Slot::Leaf(b) | Slot::Node(b)) = *slot;
            let b = to_aabb(bvh.nodes[b as usize].aabb());
            [node.min_x[s], node.min_y[s], node.min_z[s]] = b.min.to_array();
            [node.max_x[s], node.max_y[s], node.max_z[s]] = b.max.to_array();
            if wide_index == 0 {
                root_box = root_box.union(b);
            }
            node.child[s] = match *slot {
                Slot::Leaf(b) => {
                    let start = wide.leaf_prims.len();
                    collect_prims(bvh, b as usize, &mut wide.leaf_prims);
                    let count = wide.leaf_prims.len() - start;
                    wide.leaf_ranges.push((start as u32, count as u32));
                    let blocks = (count as u32).div_ceil(costs.prims_per_block.max(1));
                    leaf_area += half_area_of(bvh, b as usize) as f64 * blocks as f64;
                    leaf_blocks += blocks as f64;
                    LEAF_BIT | (wide.leaf_ranges.len() as u32 - 1)
                }
                Slot::Node(b) => {
                    inner.push(b as usize);
                    (first_child + inner.len() - 1) as u32
                }
            };
        }
        if wide_index != 0 {
            node_area += half_area_of(bvh, n) as f64;
        }
        node.perm = octant_orders(&node);
        wide.nodes[wide_index] = node;
        wide.nodes
            .resize(first_child + inner.len(), GpuBvh8Node::EMPTY);
        for (c, &b) in inner.iter().enumerate().rev() {
            work.push((first_child + c, b, depth + 1));
        }
    }
    let root_area = f64::from(root_box.surface_area() * 0.5);
    wide.sah_cost = if root_area > 0.0 && root_area.is_finite() {
        (costs.node as f64 * (1.0 + node_area / root_area)
            + costs.leaf as f64 * leaf_area / root_area) as f32
    } else {
        // All geometry on a line or a point: every box is hit with the same probability.
        (costs.node as f64 * wide.nodes.len() as f64 + costs.leaf as f64 * leaf_blocks) as f32
    };
    wide
}
