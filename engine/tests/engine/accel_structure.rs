//! Structural invariants of built trees: every triangle (or instance) exactly once, child boxes
//! inside their parents' slots, `perm` a front-to-back permutation per octant, depth bounded,
//! padding lanes empty.

use crate::common;

use std::ops::Range;

use candela::accel::{
    Aabb, BlasParams, BuildQuality, MAX_DEPTH, build_blas, build_blas_with, build_blas_with_params,
    build_tlas,
};
use candela::layout::{
    GpuBvh8Node, GpuTri4, INVALID, LEAF_BIT, LEAF_COUNT_SHIFT, LEAF_INDEX_MASK, MAX_LEAF_BLOCKS,
};
use common::*;
use glam::Vec3;

fn slot_box(node: &GpuBvh8Node, s: usize) -> Aabb {
    Aabb::new(
        Vec3::new(node.min_x[s], node.min_y[s], node.min_z[s]),
        Vec3::new(node.max_x[s], node.max_y[s], node.max_z[s]),
    )
}

/// The blocks a BLAS leaf payload names.
fn leaf_range(payload: u32) -> Range<usize> {
    let first = (payload & LEAF_INDEX_MASK) as usize;
    first..first + (payload >> LEAF_COUNT_SHIFT) as usize + 1
}

/// Triangles held by the leaves of a BLAS.
fn triangle_count(nodes: &[GpuBvh8Node], blocks: &[GpuTri4]) -> usize {
    let mut count = 0;
    walk(nodes, |p, _| {
        count += blocks[leaf_range(p)]
            .iter()
            .flat_map(|b| b.prim)
            .filter(|&q| q != INVALID)
            .count();
    });
    count
}

fn contains(outer: Aabb, inner: Aabb) -> bool {
    outer.min.cmple(inner.min).all() && outer.max.cmpge(inner.max).all()
}

/// Walks a tree; calls `leaf(payload, slot box)` for each leaf slot; returns the depth.
fn walk(nodes: &[GpuBvh8Node], mut leaf: impl FnMut(u32, Aabb)) -> u32 {
    let mut depth = 0;
    let mut visited = vec![false; nodes.len()];
    let mut stack = vec![(0usize, 1u32, None::<Aabb>)];
    while let Some((i, d, parent)) = stack.pop() {
        assert!(!visited[i], "node {i} reached twice");
        visited[i] = true;
        depth = depth.max(d);
        let node = &nodes[i];
        let mut node_box = Aabb::EMPTY;
        for s in 0..8 {
            let c = node.child[s];
            if c == INVALID {
                assert_eq!(slot_box(node, s), Aabb::EMPTY, "empty slot with a box");
                continue;
            }
            let b = slot_box(node, s);
            node_box = node_box.union(b);
            if c & LEAF_BIT != 0 {
                leaf(c & !LEAF_BIT, b);
            } else {
                stack.push((c as usize, d + 1, Some(b)));
            }
        }
        if let Some(p) = parent {
            assert_eq!(
                p, node_box,
                "slot box of node {i} is not the union of its children"
            );
        }
        // perm: a permutation per octant, occupied slots first, sorted front to back.
        for octant in 0..8 {
            let order: Vec<usize> = (0..8)
                .map(|r| ((node.perm[r] >> (3 * octant)) & 7) as usize)
                .collect();
            let mut sorted = order.clone();
            sorted.sort();
            assert_eq!(sorted, (0..8).collect::<Vec<_>>());
            let sign = Vec3::new(
                if octant & 1 != 0 { -1.0 } else { 1.0 },
                if octant & 2 != 0 { -1.0 } else { 1.0 },
                if octant & 4 != 0 { -1.0 } else { 1.0 },
            );
            let keys: Vec<Option<f32>> = order
                .iter()
                .map(|&s| (node.child[s] != INVALID).then(|| slot_box(node, s).center().dot(sign)))
                .collect();
            if keys.iter().flatten().any(|k| !k.is_finite()) {
                continue; // overflowed centres: only the permutation property is checked
            }
            for w in keys.windows(2) {
                match (w[0], w[1]) {
                    (Some(a), Some(b)) => assert!(
                        a <= b + 1e-6 * (a.abs() + b.abs() + 1e-3),
                        "octant {octant} order {keys:?}"
                    ),
                    (None, Some(_)) => panic!("empty slot before an occupied one"),
                    _ => {}
                }
            }
        }
    }
    depth
}

#[test]
fn blas_holds_every_triangle_once_in_bounded_blocks() {
    let mut rng = Rng::new(5);
    let meshes = [
        sphere(Vec3::ONE, 2.0, 20, 40),
        soup(&mut rng, 5000, 10.0),
        grid(40, 5.0, true),
    ];
    let mut variants: Vec<BlasParams> = [BuildQuality::Fastest, BuildQuality::Medium]
        .map(|quality| BlasParams {
            quality,
            ..BlasParams::default()
        })
        .to_vec();
    for (block_cost, max_leaf_blocks) in [(0.25, MAX_LEAF_BLOCKS), (1.0, 1), (0.05, 2), (0.02, 9)] {
        variants.push(BlasParams {
            block_cost,
            max_leaf_blocks,
            ..BlasParams::default()
        });
    }
    for mesh in &meshes {
        let mut largest_leaf = 0;
        for params in &variants {
            let blas = build_blas_with_params(&mesh.positions, &mesh.triangles, *params);
            let mut seen = vec![0u32; mesh.triangles.len()];
            let mut blocks_seen = vec![0u32; blas.blocks.len()];
            let depth = walk(&blas.nodes, |payload, b| {
                let range = leaf_range(payload);
                let count = range.len() as u32;
                assert!(count <= params.max_leaf_blocks.clamp(1, MAX_LEAF_BLOCKS));
                largest_leaf = largest_leaf.max(count);
                for (k, block) in blas.blocks[range.clone()].iter().enumerate() {
                    blocks_seen[range.start + k] += 1;
                    let used = block.prim.iter().filter(|&&p| p != INVALID).count();
                    // Every block of a leaf full but the last, which holds at least one.
                    assert!(used == 4 || (k + 1 == range.len() && used > 0));
                    for lane in 0..4 {
                        let p = block.prim[lane];
                        if p == INVALID {
                            assert_eq!(block.e1_x[lane], 0.0);
                            assert_eq!(block.e2_y[lane], 0.0);
                            continue;
                        }
                        seen[p as usize] += 1;
                        let t = mesh.triangles[p as usize].map(|i| mesh.positions[i as usize]);
                        assert!(
                            contains(b, Aabb::from_points(t)),
                            "triangle {p} outside its leaf box"
                        );
                    }
                }
            });
            assert!(
                seen.iter().all(|&c| c == 1),
                "{params:?}: a triangle missing or repeated"
            );
            assert!(
                blocks_seen.iter().all(|&c| c == 1),
                "a block unused or shared"
            );
            assert!(depth <= MAX_DEPTH);
            assert!(blas.sah_cost.is_finite() && blas.sah_cost > 0.0);
            assert_eq!(blas.bounds, mesh.bounds());
        }
        // The cheap-block variants do build multi-block leaves.
        assert!(largest_leaf >= 2, "no multi-block leaf");
    }
}

#[test]
fn deep_input_falls_back_to_a_bounded_tree() {
    // Triangles at exponentially growing distances: a clustering builder makes a long chain.
    let mut mesh = Mesh::default();
    for i in 0..400 {
        let x = 1.2f32.powi(i) * 1e-30;
        mesh.push_tri(
            Vec3::new(x, 0.0, 0.0),
            Vec3::new(x, x, 0.0),
            Vec3::new(x, 0.0, x),
        );
    }
    let blas = build_blas(&mesh.positions, &mesh.triangles);
    let depth = walk(&blas.nodes, |_, _| {});
    assert_eq!(triangle_count(&blas.nodes, &blas.blocks), 400);
    assert!(depth <= MAX_DEPTH, "depth {depth}");
}

#[test]
fn tlas_holds_every_valid_instance_once() {
    let mut rng = Rng::new(8);
    let mut bounds: Vec<Aabb> = (0..10_000)
        .map(|_| {
            let c = rng.vec3(Vec3::splat(-500.0), Vec3::splat(500.0));
            Aabb::new(c, c + rng.vec3(Vec3::splat(0.1), Vec3::splat(20.0)))
        })
        .collect();
    bounds[17] = Aabb::EMPTY;
    bounds[18] = Aabb::new(Vec3::ZERO, Vec3::new(f32::INFINITY, 1.0, 1.0));
    let nodes = build_tlas(&bounds);
    let mut seen = vec![0u32; bounds.len()];
    let depth = walk(&nodes, |i, b| {
        seen[i as usize] += 1;
        assert_eq!(b, bounds[i as usize]);
    });
    assert!(depth <= MAX_DEPTH);
    for (i, &c) in seen.iter().enumerate() {
        assert_eq!(c, u32::from(i != 17 && i != 18), "instance {i}");
    }
    assert_eq!(build_tlas(&[]).len(), 1);
    assert_eq!(build_tlas(&[Aabb::EMPTY]).len(), 1);
    let one = build_tlas(&[Aabb::new(Vec3::ZERO, Vec3::ONE)]);
    assert_eq!(one[0].child[0], LEAF_BIT);
}

#[test]
fn single_triangle_and_empty_blas() {
    let blas = build_blas(&[Vec3::ZERO, Vec3::X, Vec3::Y], &[[0, 1, 2]]);
    assert_eq!(blas.nodes.len(), 1);
    assert_eq!(blas.blocks.len(), 1);
    assert_eq!(blas.nodes[0].child[0], LEAF_BIT);
    assert_eq!(blas.blocks[0].prim, [0, INVALID, INVALID, INVALID]);
    let empty = build_blas(&[], &[]);
    assert_eq!(empty.nodes[0].child, [INVALID; 8]);
    assert_eq!(empty.sah_cost, 0.0);
}

/// Finite but enormous coordinates overflow areas and centroids to infinity: the builders must
/// still return a valid tree holding every triangle / instance (never panic).
#[test]
fn huge_coordinates_build_without_panicking() {
    let big = f32::MAX / 2.0;
    let mut mesh = Mesh::default();
    mesh.push_tri(
        Vec3::splat(-big),
        Vec3::new(big, -big, 0.0),
        Vec3::new(0.0, big, big),
    );
    mesh.push_tri(Vec3::splat(big), Vec3::new(-big, big, 0.0), Vec3::ZERO);
    for i in 0..50 {
        let p = Vec3::new(i as f32 * 5e36, -(i as f32) * 6e36, 1.0);
        mesh.push_tri(p, p + Vec3::X * 1e36, p + Vec3::Y * 1e36);
    }
    for quality in BuildQuality::ALL {
        let blas = build_blas_with(&mesh.positions, &mesh.triangles, quality);
        assert_eq!(
            triangle_count(&blas.nodes, &blas.blocks),
            mesh.triangles.len(),
            "{quality:?}"
        );
    }
    let boxes: Vec<Aabb> = (0..100)
        .map(|i| Aabb::new(Vec3::splat(-big + i as f32), Vec3::splat(big)))
        .collect();
    let nodes = build_tlas(&boxes);
    let mut seen = 0;
    walk(&nodes, |_, _| seen += 1);
    assert_eq!(seen, 100);
}
