//! Top-down binned SAH build of a binary BVH (Wald 2007, "On fast construction of SAH-based
//! bounding volume hierarchies"), split down to one primitive per leaf; the 8-wide collapse
//! (`collapse.rs`) then chooses the leaves.
//!
//! Input: one finite box per primitive. Output: an obvhs [`Bvh2`] in the same form as
//! `bvh2::build_ploc` returns (`prim_count == 1` leaves, `first_index` into
//! `primitive_indices`). Calling thread; O(n log n). Must not: know the GPU layout.
//!
//! Per node: centroid bounds; on each axis `BINS` bins of boxes and counts; a sweep gives the
//! SAH cost `A(left)·n(left) + A(right)·n(right)` of every bin boundary; the cheapest split over
//! all axes wins. Where all centroids coincide (or a split would leave one side empty) the node
//! is split at the median of its primitives instead, so depth stays bounded.

use glam::Vec3A;
use obvhs::aabb::Aabb as ObAabb;
use obvhs::bvh2::{Bvh2, node::Bvh2Node};

/// Bins per axis.
const BINS: usize = 16;

/// Builds the tree (see the module docs). `boxes` must be non-empty and finite.
pub(crate) fn build_binned(boxes: &[ObAabb]) -> Bvh2 {
    let n = boxes.len();
    let mut order: Vec<u32> = (0..n as u32).collect();
    if n == 0 {
        return Bvh2::default();
    }
    let centers: Vec<Vec3A> = boxes.iter().map(|b| b.center()).collect();
    let mut nodes = Vec::with_capacity(2 * n - 1);
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
        let mid = best_split(boxes, &centers, &mut order[start..end], &centroid_bounds)
            .map_or(start + (end - start) / 2, |m| start + m);
        if mid == start + (end - start) / 2 && end - start > 1 {
            // A median split (either chosen by the sweep or forced): make it exact.
            let axis = centroid_bounds.largest_axis();
            order[start..end].select_nth_unstable_by(mid - start, |&a, &b| {
                centers[a as usize][axis].total_cmp(&centers[b as usize][axis])
            });
        }
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

/// Partitions `order` by the cheapest binned SAH split and returns the size of the left part,
/// or `None` when no bin boundary separates the centroids (the caller splits at the median).
fn best_split(
    boxes: &[ObAabb],
    centers: &[Vec3A],
    order: &mut [u32],
    centroid_bounds: &ObAabb,
) -> Option<usize> {
    let extent = centroid_bounds.diagonal();
    let mut best = (f32::INFINITY, 0usize, 0usize); // cost, axis, boundary
    for axis in 0..3 {
        if extent[axis].partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            continue;
        }
        let scale = BINS as f32 / extent[axis];
        let bin_of = |c: f32| (((c - centroid_bounds.min[axis]) * scale) as usize).min(BINS - 1);
        let mut bin_box = [ObAabb::empty(); BINS];
        let mut bin_count = [0u32; BINS];
        for &p in order.iter() {
            let b = bin_of(centers[p as usize][axis]);
            bin_box[b] = bin_box[b].union(&boxes[p as usize]);
            bin_count[b] += 1;
        }
        // Sweep from the right: area and count of bins b..BINS.
        let mut right_cost = [0.0f32; BINS];
        let (mut acc, mut count) = (ObAabb::empty(), 0u32);
        for b in (1..BINS).rev() {
            acc = acc.union(&bin_box[b]);
            count += bin_count[b];
            right_cost[b] = if count > 0 {
                acc.half_area() * count as f32
            } else {
                0.0
            };
        }
        let (mut acc, mut count) = (ObAabb::empty(), 0u32);
        for b in 1..BINS {
            acc = acc.union(&bin_box[b - 1]);
            count += bin_count[b - 1];
            let right = order.len() as u32 - count;
            if count == 0 || right == 0 {
                continue;
            }
            let cost = acc.half_area() * count as f32 + right_cost[b];
            if cost < best.0 {
                best = (cost, axis, b);
            }
        }
    }
    if !best.0.is_finite() {
        return None;
    }
    let (_, axis, boundary) = best;
    let scale = BINS as f32 / extent[axis];
    let goes_left = |p: &u32| {
        let c = centers[*p as usize][axis];
        ((((c - centroid_bounds.min[axis]) * scale) as usize).min(BINS - 1)) < boundary
    };
    // In-place partition.
    let mut left = 0;
    for i in 0..order.len() {
        if goes_left(&order[i]) {
            order.swap(left, i);
            left += 1;
        }
    }
    (left > 0 && left < order.len()).then_some(left)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_primitive_once_with_coincident_centroids() {
        let mut boxes: Vec<ObAabb> = (0..500)
            .map(|i| {
                let p = Vec3A::new((i as f32 * 0.37).sin(), (i % 13) as f32, 0.0);
                ObAabb::new(p, p + Vec3A::splat(0.1))
            })
            .collect();
        boxes.extend(std::iter::repeat_n(
            ObAabb::new(Vec3A::ZERO, Vec3A::ONE),
            300,
        ));
        let bvh = build_binned(&boxes);
        let mut seen = vec![0u32; boxes.len()];
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            let node = &bvh.nodes[i];
            if node.is_leaf() {
                seen[bvh.primitive_indices[node.first_index as usize] as usize] += 1;
            } else {
                stack.extend([node.first_index as usize, node.first_index as usize + 1]);
            }
        }
        assert!(seen.iter().all(|&c| c == 1));
    }
}
