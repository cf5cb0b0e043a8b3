//! Top-down binned SAH build of a binary BVH (Wald 2007, "On fast construction of SAH-based
//! bounding volume hierarchies"), split down to one primitive per leaf; the 8-wide collapse
//! (`collapse.rs`) then chooses the leaves.
//!
//! Input: one finite box per primitive. Output: an obvhs [`Bvh2`] in the same form as
//! `bvh2::build_ploc` returns (`prim_count == 1` leaves, `first_index` into
//! `primitive_indices`). Calling thread; O(n log n). Must not: know the GPU layout.
//!
//! Per node: centroid bounds; on each axis `BINS` bins of boxes and counts; a sweep gives the
//! SAH cost `A(left)·⌈n(left)/b⌉ + A(right)·⌈n(right)/b⌉` of every bin boundary, with `b` the
//! primitives per leaf block (4 for triangles, as Embree's `sahBlockSize`: counts that fill whole
//! blocks are cheaper); the cheapest split over all axes wins. Where all centroids coincide (or a split would leave one side empty), and for
//! ranges of four or fewer primitives, the node is split at the median of its primitives
//! instead, so depth stays bounded.

use glam::Vec3A;
use obvhs::aabb::Aabb as ObAabb;
use obvhs::bvh2::{Bvh2, node::Bvh2Node};

/// Bins per axis.
const BINS: usize = 16;

/// Ranges of at most this many primitives are split at the median instead of by SAH.
const SMALL: usize = 4;

/// A range of primitives waiting to become binary node `index`, with its box and the box of its
/// primitives' centroids (both known from the parent's partition pass).
struct Range {
    index: usize,
    start: usize,
    end: usize,
    bounds: ObAabb,
    centroids: ObAabb,
}

/// Builds the tree (see the module docs). `boxes` must be non-empty and finite.
pub(crate) fn build_binned(boxes: &[ObAabb], prims_per_block: u32) -> Bvh2 {
    let prims_per_block = prims_per_block.max(1);
    let n = boxes.len();
    if n == 0 {
        return Bvh2::default();
    }
    // Primitive boxes and their original indices, permuted together so every pass over a
    // range reads memory in order.
    let mut prims = boxes.to_vec();
    let mut order: Vec<u32> = (0..n as u32).collect();
    let (mut bounds, mut centroids) = (ObAabb::empty(), ObAabb::empty());
    for b in boxes {
        bounds = bounds.union(b);
        centroids.extend(b.center());
    }
    let mut nodes = Vec::with_capacity(2 * n - 1);
    nodes.push(Bvh2Node::default());
    let mut work = vec![Range {
        index: 0,
        start: 0,
        end: n,
        bounds,
        centroids,
    }];
    while let Some(r) = work.pop() {
        if r.end - r.start == 1 {
            nodes[r.index] = Bvh2Node::new(r.bounds, 1, r.start as u32);
            continue;
        }
        let range = r.start..r.end;
        // Four or fewer primitives usually end up in one leaf anyway: skip the binning.
        let binned = if r.end - r.start > SMALL {
            best_split(&prims[range.clone()], &r.centroids, prims_per_block)
        } else {
            None
        };
        let (mid, halves) = match binned {
            Some((axis, boundary)) => partition(
                &mut prims[range.clone()],
                &mut order[range.clone()],
                &r.centroids,
                axis,
                boundary,
            ),
            None => None,
        }
        .unwrap_or_else(|| {
            median_split(&mut prims[range.clone()], &mut order[range], &r.centroids)
        });
        let left = nodes.len();
        nodes.push(Bvh2Node::default());
        nodes.push(Bvh2Node::default());
        nodes[r.index] = Bvh2Node::new(r.bounds, 0, left as u32);
        let [(lb, lc), (rb, rc)] = halves;
        work.push(Range {
            index: left,
            start: r.start,
            end: r.start + mid,
            bounds: lb,
            centroids: lc,
        });
        work.push(Range {
            index: left + 1,
            start: r.start + mid,
            end: r.end,
            bounds: rb,
            centroids: rc,
        });
    }
    Bvh2 {
        nodes,
        primitive_indices: order,
        ..Bvh2::default()
    }
}

/// Bin of a centroid per axis.
#[inline(always)]
fn bins_of(center: Vec3A, centroids: &ObAabb, scale: Vec3A) -> [usize; 3] {
    let f = ((center - centroids.min) * scale).to_array();
    f.map(|x| (x as usize).min(BINS - 1))
}

/// The cheapest binned SAH split `(axis, first bin of the right side)` over all three axes,
/// binned in one pass; `None` when no bin boundary separates the centroids.
fn best_split(
    prims: &[ObAabb],
    centroids: &ObAabb,
    prims_per_block: u32,
) -> Option<(usize, usize)> {
    let extent = centroids.diagonal();
    let scale = Vec3A::from_array(
        extent
            .to_array()
            .map(|e| if e > 0.0 { BINS as f32 / e } else { 0.0 }),
    );
    let mut bin_box = [[ObAabb::empty(); BINS]; 3];
    let mut bin_count = [[0u32; BINS]; 3];
    for p in prims {
        let bins = bins_of(p.center(), centroids, scale);
        for axis in 0..3 {
            let b = bins[axis];
            bin_box[axis][b] = bin_box[axis][b].union(p);
            bin_count[axis][b] += 1;
        }
    }
    let total = prims.len() as u32;
    let weight = |count: u32| count.div_ceil(prims_per_block) as f32;
    let mut best = (f32::INFINITY, 0usize, 0usize); // cost, axis, boundary
    for axis in 0..3 {
        if extent[axis].partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            continue;
        }
        // Sweep from the right: area times count of bins b..BINS.
        let mut right_cost = [0.0f32; BINS];
        let (mut acc, mut count) = (ObAabb::empty(), 0u32);
        for b in (1..BINS).rev() {
            acc = acc.union(&bin_box[axis][b]);
            count += bin_count[axis][b];
            right_cost[b] = if count > 0 {
                acc.half_area() * weight(count)
            } else {
                0.0
            };
        }
        let (mut acc, mut count) = (ObAabb::empty(), 0u32);
        for b in 1..BINS {
            acc = acc.union(&bin_box[axis][b - 1]);
            count += bin_count[axis][b - 1];
            if count == 0 || count == total {
                continue;
            }
            let cost = acc.half_area() * weight(count) + right_cost[b];
            if cost < best.0 {
                best = (cost, axis, b);
            }
        }
    }
    best.0.is_finite().then_some((best.1, best.2))
}

/// Box and centroid box of each side.
type Halves = [(ObAabb, ObAabb); 2];

/// Moves the primitives whose centroid bin on `axis` is below `boundary` to the front; returns
/// their count and both sides' boxes, or `None` if a side came out empty.
fn partition(
    prims: &mut [ObAabb],
    order: &mut [u32],
    centroids: &ObAabb,
    axis: usize,
    boundary: usize,
) -> Option<(usize, Halves)> {
    let extent = centroids.diagonal()[axis];
    let scale = BINS as f32 / extent;
    let min = centroids.min[axis];
    let mut halves = [(ObAabb::empty(), ObAabb::empty()); 2];
    let mut left = 0;
    for i in 0..prims.len() {
        let c = prims[i].center();
        let side = usize::from((((c[axis] - min) * scale) as usize).min(BINS - 1) >= boundary);
        halves[side].0 = halves[side].0.union(&prims[i]);
        halves[side].1.extend(c);
        if side == 0 {
            prims.swap(left, i);
            order.swap(left, i);
            left += 1;
        }
    }
    (left > 0 && left < prims.len()).then_some((left, halves))
}

/// Splits at the median centroid along the longest centroid axis (all centroids may coincide);
/// always leaves both sides non-empty for two or more primitives.
fn median_split(prims: &mut [ObAabb], order: &mut [u32], centroids: &ObAabb) -> (usize, Halves) {
    let axis = centroids.largest_axis();
    let mid = prims.len() / 2;
    let mut pairs: Vec<(ObAabb, u32)> = prims.iter().copied().zip(order.iter().copied()).collect();
    pairs.select_nth_unstable_by(mid, |a, b| {
        a.0.center()[axis].total_cmp(&b.0.center()[axis])
    });
    let mut halves = [(ObAabb::empty(), ObAabb::empty()); 2];
    for (i, (b, o)) in pairs.into_iter().enumerate() {
        let side = usize::from(i >= mid);
        halves[side].0 = halves[side].0.union(&b);
        halves[side].1.extend(b.center());
        prims[i] = b;
        order[i] = o;
    }
    (mid, halves)
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
        let bvh = build_binned(&boxes, 4);
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
