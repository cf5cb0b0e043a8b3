//! Binary BVH construction: the first phase of every BLAS and TLAS build.
//!
//! Input: one box per primitive (and the triangles themselves when pre-splitting). Output: an
//! obvhs [`Bvh2`] with exactly one primitive reference per leaf (`prim_count == 1`), leaf
//! `first_index` indexing `primitive_indices`, which hold indices into the input slice. The
//! 8-wide collapse (`collapse.rs`) then decides which subtrees become 4-triangle leaves.
//!
//! Two builders: obvhs's PLOC with parallel reinsertion (the normal path, preset chosen by
//! [`BuildQuality`]), and a balanced median split whose depth is at most `ceil(log2 n) + 1`,
//! used only when PLOC's tree would be deeper than the tracers' fixed stacks allow.
//! Runs on the calling thread (obvhs without its `parallel` feature). Must not: know the GPU
//! layout.

use glam::Vec3A;
use obvhs::{
    BvhBuildParams,
    aabb::Aabb as ObAabb,
    bvh2::{Bvh2, node::Bvh2Node, reinsertion::ReinsertionOptimizer},
    ploc::PlocBuilder,
    splits::split_aabbs_preset,
    triangle::Triangle,
};

/// Speed-versus-quality presets of the binary build, mapped onto obvhs's `BvhBuildParams`
/// presets of the same name (PLOC search radius, reinsertion ratio, pre-splits). Leaf collapsing
/// is ours (`collapse.rs`), so obvhs's `max_prims_per_leaf` and collapse costs are not used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BuildQuality {
    /// PLOC radius 1, no reinsertion.
    Fastest,
    /// PLOC radius 1, 1 % reinsertion.
    VeryFast,
    /// PLOC radius 6, 2 % reinsertion.
    Fast,
    /// PLOC radius 14, 5 % reinsertion (+ a second 10 % pass).
    Medium,
    /// PLOC radius 24, pre-split large triangles, 20 % reinsertion (+ a second 40 % pass).
    Slow,
    /// PLOC radius 14, pre-split, reinsertion over every node (+ a second full pass).
    VerySlow,
    /// Not obvhs: our top-down binned SAH build (`binned.rs`), 16 bins per axis. The default:
    /// see `accel/mod.rs` for the measurements that chose it.
    #[default]
    BinnedSah,
}

impl BuildQuality {
    /// Every preset, fastest build first.
    pub const ALL: [Self; 7] = [
        Self::Fastest,
        Self::VeryFast,
        Self::Fast,
        Self::Medium,
        Self::Slow,
        Self::VerySlow,
        Self::BinnedSah,
    ];

    fn params(self) -> BvhBuildParams {
        match self {
            Self::Fastest => BvhBuildParams::fastest_build(),
            Self::VeryFast => BvhBuildParams::very_fast_build(),
            Self::Fast => BvhBuildParams::fast_build(),
            Self::Medium => BvhBuildParams::medium_build(),
            Self::Slow => BvhBuildParams::slow_build(),
            Self::VerySlow => BvhBuildParams::very_slow_build(),
            Self::BinnedSah => BvhBuildParams::medium_build(),
        }
    }
}

/// The binary tree of the chosen preset over `boxes` (one per primitive, all finite);
/// `prims_per_block` is the leaf block size the binned SAH rounds counts up to.
pub(crate) fn build_bvh2(
    boxes: &[ObAabb],
    triangles: Option<&[Triangle]>,
    quality: BuildQuality,
    prims_per_block: u32,
) -> Bvh2 {
    match quality {
        BuildQuality::BinnedSah => super::binned::build_binned(boxes, prims_per_block),
        _ => build_ploc(boxes, triangles, quality),
    }
}

/// PLOC build over `boxes` (one per primitive, all finite). With `triangles` (same length and
/// order as `boxes`) and a preset that pre-splits, large triangles get several clipped boxes,
/// so one triangle index can appear in several leaves.
pub(crate) fn build_ploc(
    boxes: &[ObAabb],
    triangles: Option<&[Triangle]>,
    quality: BuildQuality,
) -> Bvh2 {
    let params = quality.params();
    let mut boxes_split;
    let mut indices: Vec<u32> = (0..boxes.len() as u32).collect();
    let mut input = boxes;
    if let (true, Some(tris)) = (params.pre_split, triangles) {
        boxes_split = boxes.to_vec();
        let (mut largest, mut sum) = (0.0f32, 0.0f32);
        for b in boxes {
            largest = largest.max(b.half_area());
            sum += b.half_area();
        }
        let average = sum / boxes.len().max(1) as f32;
        split_aabbs_preset(&mut boxes_split, &mut indices, tris, average, largest);
        input = &boxes_split;
    }
    let mut bvh = PlocBuilder::with_capacity(input.len()).build(
        params.ploc_search_distance,
        input,
        indices,
        params.sort_precision,
        params.search_depth_threshold,
    );
    let mut optimizer = ReinsertionOptimizer::default();
    optimizer.run(&mut bvh, params.reinsertion_batch_ratio, None);
    optimizer.run(
        &mut bvh,
        params.reinsertion_batch_ratio * params.post_collapse_reinsertion_batch_ratio_multiplier,
        None,
    );
    bvh
}

/// Balanced top-down build: split every node at the median centroid along the longest axis of
/// its centroid box. Depth is at most `ceil(log2 n) + 1`; quality is worse than PLOC's, so it
/// is only the fallback for pathological inputs.
pub(crate) fn build_balanced(boxes: &[ObAabb]) -> Bvh2 {
    let n = boxes.len();
    let mut order: Vec<u32> = (0..n as u32).collect();
    let mut nodes = Vec::with_capacity((2 * n).saturating_sub(1));
    if n == 0 {
        return Bvh2::default();
    }
    let centers: Vec<Vec3A> = boxes.iter().map(|b| b.center()).collect();
    nodes.push(Bvh2Node::default());
    let mut work = vec![(0usize, 0usize, n)];
    while let Some((index, start, end)) = work.pop() {
        let mut bounds = ObAabb::empty();
        let mut centroid_bounds = ObAabb::empty();
        for &p in &order[start..end] {
            bounds = bounds.union(&boxes[p as usize]);
            centroid_bounds.extend(centers[p as usize]);
        }
        if end - start == 1 {
            nodes[index] = Bvh2Node::new(bounds, 1, start as u32);
            continue;
        }
        let axis = centroid_bounds.largest_axis();
        let mid = start + (end - start) / 2;
        order[start..end].select_nth_unstable_by(mid - start, |&a, &b| {
            centers[a as usize][axis].total_cmp(&centers[b as usize][axis])
        });
        let left = nodes.len();
        nodes.push(Bvh2Node::default());
        nodes.push(Bvh2Node::default());
        nodes[index] = Bvh2Node::new(bounds, 0, left as u32);
        work.push((left, start, mid));
        work.push((left + 1, mid, end));
    }
    Bvh2 {
        nodes,
        primitive_indices: order,
        ..Bvh2::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boxes(n: usize) -> Vec<ObAabb> {
        (0..n)
            .map(|i| {
                let p = Vec3A::new((i as f32 * 0.37).sin(), i as f32 * 0.01, (i % 7) as f32);
                ObAabb::new(p, p + Vec3A::splat(0.05))
            })
            .collect()
    }

    fn check_one_prim_leaves(bvh: &Bvh2, n: usize) {
        let mut seen = vec![0u32; n];
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            let node = &bvh.nodes[i];
            if node.is_leaf() {
                assert_eq!(node.prim_count, 1);
                seen[bvh.primitive_indices[node.first_index as usize] as usize] += 1;
            } else {
                stack.push(node.first_index as usize);
                stack.push(node.first_index as usize + 1);
            }
        }
        assert!(seen.iter().all(|&c| c == 1), "every primitive exactly once");
    }

    #[test]
    fn ploc_and_balanced_cover_every_primitive_once() {
        for n in [1, 2, 3, 100, 1000] {
            let b = boxes(n);
            check_one_prim_leaves(&build_ploc(&b, None, BuildQuality::Medium), n);
            let balanced = build_balanced(&b);
            check_one_prim_leaves(&balanced, n);
            let depth_limit = (n as f32).log2().ceil() as usize + 1;
            assert!(balanced.depth(0) <= depth_limit, "n {n}");
        }
    }
}
