//! Refitting a BLAS to moved vertices: same tree, new boxes.
//!
//! Input: a [`Blas`] built for a mesh and the mesh's new object-space positions (same vertex and
//! triangle count, same topology). Output: the blocks' triangles re-read, every node's child
//! boxes recomputed bottom-up, the per-octant child orders recomputed, and the tree's SAH cost
//! ([`sah_cost`]) and triangle area ratio ([`triangle_area_ratio`], from the same pass that
//! re-reads the triangles: [`refit_blas_measured`]) so that the upkeep policy can tell when a
//! rebuild is due.
//! Main thread (the `accel` phase); O(nodes + triangles). Must not: change the tree's shape
//! (that is a rebuild).

use glam::Vec3;

use super::blas::{Blas, BlasParams};
use super::octant_order::octant_orders_from;
use crate::layout::{GpuBvh8Node, GpuTri4, INVALID, LEAF_BIT, LEAF_COUNT_SHIFT, LEAF_INDEX_MASK};
use crate::scene::Aabb;
use crate::trace::leaf_blocks;
use crate::trace::triangle::tri_lane;

/// Bounds of the triangle in lane `lane` of a block (`None` for an unused lane).
fn lane_bounds(block: &GpuTri4, lane: usize) -> Option<Aabb> {
    if block.prim[lane] == INVALID {
        return None;
    }
    let v0 = Vec3::new(block.v0_x[lane], block.v0_y[lane], block.v0_z[lane]);
    let e1 = Vec3::new(block.e1_x[lane], block.e1_y[lane], block.e1_z[lane]);
    let e2 = Vec3::new(block.e2_x[lane], block.e2_y[lane], block.e2_z[lane]);
    Some(Aabb::EMPTY.grow(v0).grow(v0 + e1).grow(v0 + e2))
}

fn slot_bounds(node: &GpuBvh8Node, slot: usize) -> Aabb {
    Aabb {
        min: Vec3::new(node.min_x[slot], node.min_y[slot], node.min_z[slot]),
        max: Vec3::new(node.max_x[slot], node.max_y[slot], node.max_z[slot]),
    }
}

fn set_slot(node: &mut GpuBvh8Node, slot: usize, b: Aabb) {
    node.min_x[slot] = b.min.x;
    node.min_y[slot] = b.min.y;
    node.min_z[slot] = b.min.z;
    node.max_x[slot] = b.max.x;
    node.max_y[slot] = b.max.y;
    node.max_z[slot] = b.max.z;
}

/// The union of a node's child boxes.
pub fn node_bounds(node: &GpuBvh8Node) -> Aabb {
    (0..8)
        .filter(|&s| node.child[s] != INVALID)
        .fold(Aabb::EMPTY, |acc, s| acc.union(slot_bounds(node, s)))
}

/// Nodes in an order where every inner child comes before its parent (post-order).
fn post_order(nodes: &[GpuBvh8Node]) -> Vec<usize> {
    let mut order = Vec::with_capacity(nodes.len());
    let mut stack = vec![(0usize, false)];
    while let Some((n, expanded)) = stack.pop() {
        if n >= nodes.len() {
            continue;
        }
        if expanded {
            order.push(n);
            continue;
        }
        stack.push((n, true));
        for &c in &nodes[n].child {
            if c != INVALID && c & LEAF_BIT == 0 {
                stack.push((c as usize, false));
            }
        }
    }
    order
}

/// What a refit measured of the refitted tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refit {
    /// [`sah_cost`] of the refitted tree.
    pub cost: f32,
    /// [`triangle_area_ratio`] of the refitted tree, bit for bit.
    pub area_ratio: f32,
}

/// The indices of a BLAS leaf payload's blocks within `count` blocks (the encoding of
/// [`LEAF_COUNT_SHIFT`], as the tracers read it); empty when out of range.
fn leaf_range(payload: u32, count: usize) -> std::ops::Range<usize> {
    let first = (payload & LEAF_INDEX_MASK) as usize;
    let end = first + (payload >> LEAF_COUNT_SHIFT & 3) as usize + 1;
    if end <= count { first..end } else { 0..0 }
}

/// Refits `blas` to `positions` (the mesh's new vertex positions; `triangles` unchanged) and
/// returns its new [`sah_cost`]. Lanes whose triangle now has a non-finite or out-of-range
/// vertex become degenerate (zero edges at the origin), so they are never hit.
pub fn refit_blas(blas: &mut Blas, positions: &[Vec3], triangles: &[[u32; 3]]) -> f32 {
    refit_blas_measured(blas, positions, triangles).cost
}

/// [`refit_blas`], also measuring the refitted tree's [`triangle_area_ratio`] on the way: each
/// lane's box is computed once, for its block's box and for the ratio (instead of a second pass
/// over the blocks afterwards).
pub fn refit_blas_measured(blas: &mut Blas, positions: &[Vec3], triangles: &[[u32; 3]]) -> Refit {
    let mut block_boxes = Vec::with_capacity(blas.blocks.len());
    // Each lane's box area, summed after the loop in the same order (the same bits as one
    // running sum; the running sum in the loop was a chain through memory, perf 2026-12-07).
    let mut lane_areas = Vec::with_capacity(4 * blas.blocks.len());
    for block in &mut blas.blocks {
        let mut block_box = Aabb::EMPTY;
        for lane in 0..4 {
            let prim = block.prim[lane];
            if prim == INVALID {
                continue;
            }
            let vertex = |i: u32| positions.get(i as usize).copied().filter(|p| p.is_finite());
            let corners = triangles
                .get(prim as usize)
                .and_then(|t| Some((vertex(t[0])?, vertex(t[1])?, vertex(t[2])?)));
            let [v0, e1, e2] = match corners {
                Some((a, b, c)) => tri_lane(a, b, c),
                None => [Vec3::ZERO; 3],
            };
            (block.v0_x[lane], block.v0_y[lane], block.v0_z[lane]) = (v0.x, v0.y, v0.z);
            (block.e1_x[lane], block.e1_y[lane], block.e1_z[lane]) = (e1.x, e1.y, e1.z);
            (block.e2_x[lane], block.e2_y[lane], block.e2_z[lane]) = (e2.x, e2.y, e2.z);
            // As `triangle_area_ratio` and `block_bounds` read the lane back.
            if let Some(b) = lane_bounds(block, lane) {
                lane_areas.push(b.surface_area());
                block_box = block_box.union(b);
            }
        }
        block_boxes.push(block_box);
    }
    let lane_area = lane_areas.iter().fold(0.0f64, |sum, &a| sum + a as f64);
    let mut subtree = vec![Aabb::EMPTY; blas.nodes.len()];
    for n in post_order(&blas.nodes) {
        let mut node = blas.nodes[n];
        for slot in 0..8 {
            let child = node.child[slot];
            if child == INVALID {
                continue;
            }
            let b = if child & LEAF_BIT != 0 {
                block_boxes[leaf_range(child & !LEAF_BIT, block_boxes.len())]
                    .iter()
                    .fold(Aabb::EMPTY, |acc, b| acc.union(*b))
            } else {
                subtree.get(child as usize).copied().unwrap_or(Aabb::EMPTY)
            };
            set_slot(&mut node, slot, b);
        }
        // Started from the order before the boxes moved: the same bits, fewer comparisons.
        let previous = node.perm;
        node.perm = octant_orders_from(&node, &previous);
        subtree[n] = node_bounds(&node);
        blas.nodes[n] = node;
    }
    blas.bounds = subtree.first().copied().unwrap_or(Aabb::EMPTY);
    blas.sah_cost = sah_cost(&blas.nodes, &blas.blocks);
    let root = blas.bounds.surface_area();
    Refit {
        cost: blas.sah_cost,
        area_ratio: if root > 0.0 && root.is_finite() {
            (lane_area / root as f64) as f32
        } else {
            0.0
        },
    }
}

/// SAH cost of a tree with the default [`BlasParams`] costs, the same sum the build reports in
/// [`Blas::sah_cost`]: Σ over nodes of A(node)/A(root)·`node_cost` + Σ over leaves of
/// A(leaf)/A(root)·blocks(leaf)·`block_cost`, A = surface area of the node's or leaf's box.
/// Falls back to the plain count `nodes·node_cost + blocks·block_cost` when the root has no area.
pub fn sah_cost(nodes: &[GpuBvh8Node], blocks: &[GpuTri4]) -> f32 {
    let BlasParams {
        node_cost,
        block_cost,
        ..
    } = BlasParams::default();
    let Some(root) = nodes.first() else {
        return 0.0;
    };
    let root_area = node_bounds(root).surface_area();
    if !(root_area > 0.0 && root_area.is_finite()) {
        return nodes.len() as f32 * node_cost + blocks.len() as f32 * block_cost;
    }
    let mut cost = 0.0f64;
    for node in nodes {
        cost += (node_bounds(node).surface_area() / root_area) as f64 * node_cost as f64;
        for slot in 0..8 {
            let child = node.child[slot];
            if child != INVALID && child & LEAF_BIT != 0 {
                let count = leaf_blocks(blocks, child & !LEAF_BIT).len();
                cost += (slot_bounds(node, slot).surface_area() / root_area) as f64
                    * (block_cost as f64 * count as f64);
            }
        }
    }
    cost as f32
}

/// Σ over triangles of the surface area of each triangle's box, divided by the root box's
/// (dimensionless). Cheap (one pass over the blocks) and a predictor of what a *fresh* build
/// of the current shape would cost: over the swirling grid of `engine/tests/engine/refit_degradation.rs`
/// a fresh build's [`sah_cost`] varies by 1.6× between shapes while fresh cost / √(this)
/// stays within ±6 %.
pub fn triangle_area_ratio(blas: &Blas) -> f32 {
    let root = blas.bounds.surface_area();
    if !(root > 0.0 && root.is_finite()) {
        return 0.0;
    }
    let mut sum = 0.0f64;
    for block in &blas.blocks {
        for b in (0..4).filter_map(|lane| lane_bounds(block, lane)) {
            sum += b.surface_area() as f64;
        }
    }
    (sum / root as f64) as f32
}

/// The SAH cost above which a refitted tree is rebuilt: `ratio` × the estimated cost of a fresh
/// build of the current shape, never more than `ratio` × `built_cost` (the cost right after the
/// last build). The estimate scales `built_cost` by √(`area_now` / `area_built`)
/// ([`triangle_area_ratio`] now and at the last build): a shape that became simpler (a swirl
/// unwinding) would build a cheaper tree, and comparing against the old, dearer build alone
/// let a refitted tree reach 2.1× a fresh build's cost under a 1.5 ratio.
pub fn rebuild_bound(ratio: f32, built_cost: f32, area_built: f32, area_now: f32) -> f32 {
    let scale = if area_built > 0.0 && area_now.is_finite() {
        (area_now / area_built).sqrt().min(1.0)
    } else {
        1.0
    };
    ratio * built_cost * scale
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accel::build_blas;
    use crate::trace::brute::{BruteMesh, closest_brute_mesh};
    use crate::trace::{Ray, closest_blas};

    /// A wavy grid of `n × n` quads.
    fn grid(n: u32, phase: f32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let mut p = Vec::new();
        let mut t = Vec::new();
        for y in 0..=n {
            for x in 0..=n {
                let (fx, fy) = (x as f32 / n as f32, y as f32 / n as f32);
                p.push(Vec3::new(
                    fx,
                    0.2 * (6.0 * fx + phase).sin() * (4.0 * fy).cos(),
                    fy,
                ));
            }
        }
        for y in 0..n {
            for x in 0..n {
                let i = y * (n + 1) + x;
                t.push([i, i + n + 1, i + 1]);
                t.push([i + 1, i + n + 1, i + n + 2]);
            }
        }
        (p, t)
    }

    #[test]
    fn refitted_tree_matches_brute_force_and_a_fresh_build_of_the_same_shape() {
        let (start, triangles) = grid(40, 0.0);
        let mut blas = build_blas(&start, &triangles);
        // A fixed-seed xorshift: this test needs spread-out rays, not the tracers' RNG.
        let mut state = 0x9e37_79b9_u32;
        let mut u = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state >> 8) as f32 / (1u32 << 24) as f32
        };
        for step in 1..=20 {
            let (moved, _) = grid(40, step as f32 * 0.4);
            let cost = refit_blas(&mut blas, &moved, &triangles);
            assert_eq!(cost, sah_cost(&blas.nodes, &blas.blocks));
            let mesh = BruteMesh {
                positions: &moved,
                triangles: &triangles,
            };
            for i in 0..500 {
                let o = Vec3::new(u() * 1.2 - 0.1, 1.0, u() * 1.2 - 0.1);
                let d = Vec3::new(u() - 0.5, -1.0, u() - 0.5);
                let ray = Ray::new(o, d);
                let fast = closest_blas(&blas.nodes, &blas.blocks, &ray);
                let slow = closest_brute_mesh(&mesh, &ray);
                assert_eq!(
                    fast.map(|h| h.t.to_bits()),
                    slow.map(|h| h.t.to_bits()),
                    "step {step} ray {i}"
                );
            }
        }
        // A refit tree costs at least as much as a fresh one of the same shape, not vastly more
        // here (the grid only waves).
        let (last, _) = grid(40, 8.0);
        let fresh = build_blas(&last, &triangles);
        let fresh_cost = sah_cost(&fresh.nodes, &fresh.blocks);
        assert!(blas.sah_cost >= 0.95 * fresh_cost && blas.sah_cost < 3.0 * fresh_cost);
    }

    /// The area ratio measured during the refit is the separate pass's, bit for bit, and every
    /// leaf's box is the union of its blocks' triangle boxes as read back from the blocks.
    #[test]
    fn the_area_measured_in_the_refit_is_the_separate_pass_bit_for_bit() {
        let (start, triangles) = grid(24, 0.0);
        let mut blas = build_blas(&start, &triangles);
        for step in 1..=6 {
            let (mut moved, _) = grid(24, step as f32 * 0.7);
            // A stretched corner and a vertex gone bad, as a refit may meet.
            moved[0] *= 1.0 + step as f32;
            moved[7] = Vec3::NAN;
            let refit = refit_blas_measured(&mut blas, &moved, &triangles);
            assert_eq!(
                refit.cost,
                sah_cost(&blas.nodes, &blas.blocks),
                "step {step}"
            );
            assert_eq!(
                refit.area_ratio.to_bits(),
                triangle_area_ratio(&blas).to_bits(),
                "step {step}"
            );
            assert!(refit.area_ratio > 0.0);
            let mut leaves = 0;
            for node in &blas.nodes {
                for slot in
                    (0..8).filter(|&s| node.child[s] != INVALID && node.child[s] & LEAF_BIT != 0)
                {
                    let range = leaf_range(node.child[slot] & !LEAF_BIT, blas.blocks.len());
                    let expected = blas.blocks[range]
                        .iter()
                        .flat_map(|b| (0..4).filter_map(|lane| lane_bounds(b, lane)))
                        .fold(Aabb::EMPTY, Aabb::union);
                    assert_eq!(slot_bounds(node, slot), expected, "step {step}");
                    leaves += 1;
                }
            }
            assert!(leaves > 100, "{leaves} leaves");
        }
    }

    /// A tree refitted through many random ripples ends, node for node and block for block,
    /// bit-identical to the built tree refitted once to the last positions: the refit keeps no
    /// trace of where the boxes were (each octant order is started from the previous one,
    /// `octant_orders_from`, and is still the order a cold sort gives).
    #[test]
    fn a_tree_refitted_through_random_ripples_is_the_bits_of_one_refit() {
        let (start, triangles) = grid(32, 0.0);
        let built = build_blas(&start, &triangles);
        let mut rippled = built.clone();
        let mut state = 0x2545_f491_u32;
        let mut u = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state >> 8) as f32 / (1u32 << 24) as f32
        };
        let mut last = start.clone();
        for step in 0..30 {
            // Ripples: every vertex raised or lowered a little, a patch a lot (the boxes of
            // neighbouring children cross and their orders change).
            last = start
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    let patch = (i / 7 + step) % 11 == 0;
                    *p + Vec3::Y * (u() - 0.5) * if patch { 0.8 } else { 0.02 }
                })
                .collect();
            refit_blas_measured(&mut rippled, &last, &triangles);
        }
        let mut once = built.clone();
        refit_blas_measured(&mut once, &last, &triangles);
        let bytes = |b: &Blas| {
            (
                bytemuck::cast_slice::<_, u8>(&b.nodes).to_vec(),
                bytemuck::cast_slice::<_, u8>(&b.blocks).to_vec(),
            )
        };
        assert!(bytes(&rippled) == bytes(&once), "the ripples left a trace");
        assert_eq!(rippled.sah_cost.to_bits(), once.sah_cost.to_bits());
        for (n, node) in rippled.nodes.iter().enumerate() {
            assert_eq!(
                node.perm,
                crate::accel::octant_order::octant_orders(node),
                "node {n}"
            );
        }
        assert_ne!(bytes(&built), bytes(&once), "the boxes moved");
    }

    #[test]
    fn cost_of_a_fresh_build_is_the_builders_cost() {
        let (p, t) = grid(16, 1.0);
        let blas = build_blas(&p, &t);
        let ours = sah_cost(&blas.nodes, &blas.blocks);
        assert!(ours > 1.0 && ours.is_finite());
        assert!(
            (ours - blas.sah_cost).abs() <= 0.35 * blas.sah_cost,
            "{ours} vs {}",
            blas.sah_cost
        );
    }
}
