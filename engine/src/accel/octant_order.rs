//! The traversal order of an 8-wide node's children per ray octant (`GpuBvh8Node::perm`):
//! both the build (`collapse.rs`) and every refit (`refit.rs`) compute it for every node, so a
//! frame of several settled steps computes it once per node of the explorer per step.
//!
//! Owns: [`octant_orders`]. Calling thread, pure. Must not: change the order itself (both
//! tracers and the game's ray queries visit children in it; a tie between two equally near
//! hits goes to the first visited).
//!
//! Speed: the order was ranked by comparing every pair of slots (64 pairs × 2 orders × 4
//! octants); sorting the occupied slots by insertion gives the same permutation with about a
//! quarter of the comparisons (the test below checks it against the pairwise ranking). In
//! It's About Time's bench, before this change, the ranking was 46 % of `refit_blas` (perf,
//! 2026-12-06; `docs/PERFORMANCE.md`). A refit starts each sort from the node's previous order
//! ([`octant_orders_from`]): the order is unique (a strict total order), so the result is the
//! same bits from any start, and a node whose children barely moved is already sorted (one
//! comparison per slot instead of a quarter of all pairs).

use glam::Vec3;

use crate::layout::{GpuBvh8Node, INVALID};

/// `perm` of a node: for each ray octant `o` (bit set = negative direction component), the
/// occupied slots sorted by their box centre projected on the octant's diagonal (±1, ±1, ±1),
/// nearest first (ties by slot index), then the empty slots in slot order; rank `i`'s slot
/// goes to bits `3o..3o+3` of `perm[i]`. Octant `7 − o` sees the keys negated, so it sorts
/// them the other way (ties still by slot index).
pub(crate) fn octant_orders(node: &GpuBvh8Node) -> [u32; 8] {
    orders(node, None)
}

/// [`octant_orders`] of `node`, each sort started from the order in `previous` (the node's
/// `perm` before its boxes moved: a refit). Bit for bit the same as [`octant_orders`] whatever
/// `previous` holds; a `previous` whose occupied ranks are not exactly the node's occupied
/// slots (another node's, garbage) starts from slot order instead.
pub(crate) fn octant_orders_from(node: &GpuBvh8Node, previous: &[u32; 8]) -> [u32; 8] {
    orders(node, Some(previous))
}

/// The first `n` ranks of `previous`'s order for `octant`, when they are exactly the slots of
/// `mask` (bit `s`: slot `s` occupied, `n` bits set).
fn start(previous: Option<&[u32; 8]>, octant: u32, n: usize, mask: u32) -> Option<[usize; 8]> {
    let previous = previous?;
    let mut order = [0usize; 8];
    let mut seen = 0u32;
    for rank in 0..n {
        let s = previous[rank] >> (3 * octant) & 7;
        seen |= 1 << s;
        order[rank] = s as usize;
    }
    (seen == mask).then_some(order)
}

fn orders(node: &GpuBvh8Node, previous: Option<&[u32; 8]>) -> [u32; 8] {
    let centers: [Vec3; 8] = std::array::from_fn(|s| {
        Vec3::new(
            node.min_x[s] + node.max_x[s],
            node.min_y[s] + node.max_y[s],
            node.min_z[s] + node.max_z[s],
        )
    });
    let (mut occupied, mut empty) = ([0usize; 8], [0usize; 8]);
    let (mut n, mut m, mut mask) = (0, 0, 0u32);
    for s in 0..8 {
        if node.child[s] != INVALID {
            occupied[n] = s;
            mask |= 1 << s;
            n += 1;
        } else {
            empty[m] = s;
            m += 1;
        }
    }
    let mut perm = [0u32; 8];
    for octant in 0..4u32 {
        let sign = Vec3::new(
            if octant & 1 != 0 { -1.0 } else { 1.0 },
            if octant & 2 != 0 { -1.0 } else { 1.0 },
            if octant & 4 != 0 { -1.0 } else { 1.0 },
        );
        let key: [f32; 8] = std::array::from_fn(|s| centers[s].dot(sign));
        // total_cmp: a strict total order even for NaN keys (centres that overflowed).
        let mut order = start(previous, octant, n, mask).unwrap_or(occupied);
        sort_by(&mut order[..n], |a, b| {
            key[a].total_cmp(&key[b]).then(a.cmp(&b)).is_lt()
        });
        let mut order_rev = start(previous, 7 - octant, n, mask).unwrap_or(occupied);
        sort_by(&mut order_rev[..n], |a, b| {
            key[b].total_cmp(&key[a]).then(a.cmp(&b)).is_lt()
        });
        order[n..n + m].copy_from_slice(&empty[..m]);
        order_rev[n..n + m].copy_from_slice(&empty[..m]);
        for rank in 0..8 {
            perm[rank] |= (order[rank] as u32) << (3 * octant);
            perm[rank] |= (order_rev[rank] as u32) << (3 * (7 - octant));
        }
    }
    perm
}

/// Insertion sort of at most 8 slots by the strict order `before`.
fn sort_by(slots: &mut [usize], before: impl Fn(usize, usize) -> bool) {
    for i in 1..slots.len() {
        let s = slots[i];
        let mut j = i;
        while j > 0 && before(s, slots[j - 1]) {
            slots[j] = slots[j - 1];
            j -= 1;
        }
        slots[j] = s;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ranking this file replaced: every occupied slot's rank counted over all pairs.
    #[allow(clippy::needless_range_loop)]
    fn pairwise(node: &GpuBvh8Node) -> [u32; 8] {
        let used = node.child.map(|c| c != INVALID);
        let centers: [Vec3; 8] = std::array::from_fn(|s| {
            Vec3::new(
                node.min_x[s] + node.max_x[s],
                node.min_y[s] + node.max_y[s],
                node.min_z[s] + node.max_z[s],
            )
        });
        let occupied = used.iter().filter(|&&u| u).count();
        let mut perm = [0u32; 8];
        // Octant 7 - o sees the keys negated: its order of the occupied slots is the reverse of
        // octant o's (ties aside, which both break by slot index), so only octants 0..4 are ranked.
        for octant in 0..4u32 {
            let sign = Vec3::new(
                if octant & 1 != 0 { -1.0 } else { 1.0 },
                if octant & 2 != 0 { -1.0 } else { 1.0 },
                if octant & 4 != 0 { -1.0 } else { 1.0 },
            );
            let key: [f32; 8] = std::array::from_fn(|s| centers[s].dot(sign));
            // Rank of each occupied slot among the occupied ones: smaller key first, ties by slot.
            let mut order = [0usize; 8];
            let mut order_rev = [0usize; 8];
            let mut next_empty = occupied;
            for s in 0..8 {
                if !used[s] {
                    order[next_empty] = s;
                    order_rev[next_empty] = s;
                    next_empty += 1;
                    continue;
                }
                let (mut rank, mut rank_rev) = (0, 0);
                for t in 0..8 {
                    if used[t] && t != s {
                        // total_cmp: a strict total order even for NaN keys (centres that
                        // overflowed), so the ranks always form a permutation.
                        let order = key[t].total_cmp(&key[s]).then(t.cmp(&s));
                        rank += usize::from(order.is_lt());
                        rank_rev += usize::from(
                            key[t].total_cmp(&key[s]).reverse().then(t.cmp(&s)).is_lt(),
                        );
                    }
                }
                order[rank] = s;
                order_rev[rank_rev] = s;
            }
            for rank in 0..8 {
                perm[rank] |= (order[rank] as u32) << (3 * octant);
                perm[rank] |= (order_rev[rank] as u32) << (3 * (7 - octant));
            }
        }
        perm
    }

    /// Random nodes (boxes from a small integer grid so that ties happen, some slots empty,
    /// some keys NaN) get the same permutation as the pairwise ranking.
    #[test]
    fn insertion_sorted_orders_equal_the_pairwise_ranking() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for case in 0..20_000 {
            let mut node = GpuBvh8Node::EMPTY;
            for s in 0..8 {
                let r = next();
                if r % 4 == 0 {
                    continue;
                }
                let v = |shift: u32| ((r >> shift) % 5) as f32 - 2.0;
                node.child[s] = s as u32;
                node.min_x[s] = v(8);
                node.max_x[s] = v(8) + v(11).abs();
                node.min_y[s] = v(14);
                node.max_y[s] = v(14) + v(17).abs();
                node.min_z[s] = v(20);
                node.max_z[s] = v(20) + v(23).abs();
                if r % 97 == 1 {
                    node.min_x[s] = f32::NAN;
                }
            }
            assert_eq!(
                octant_orders(&node),
                pairwise(&node),
                "case {case}: {node:?}"
            );
        }
    }

    /// Every sort started from another order (the node's own before its boxes moved, another
    /// node's, garbage) gives the bits of a sort from slot order.
    #[test]
    fn an_order_started_from_any_previous_order_is_the_same_bits() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut warm = 0;
        for case in 0..20_000 {
            let mut node = GpuBvh8Node::EMPTY;
            for s in 0..8 {
                let r = next();
                if r % 5 == 0 {
                    continue;
                }
                let v = |shift: u32| ((r >> shift) % 7) as f32 - 3.0;
                node.child[s] = s as u32;
                node.min_x[s] = v(8);
                node.max_x[s] = v(8) + v(11).abs();
                node.min_y[s] = v(14);
                node.max_y[s] = v(14) + v(17).abs();
                node.min_z[s] = v(20);
                node.max_z[s] = v(20) + v(23).abs();
                if r % 89 == 1 {
                    node.min_z[s] = f32::NAN;
                }
            }
            let before = octant_orders(&node);
            // The same node moved a little (a refit), or the previous order is garbage.
            let mut moved = node;
            for s in 0..8 {
                let d = (next() % 9) as f32 * 0.25 - 1.0;
                moved.min_y[s] += d;
                moved.max_y[s] += d;
            }
            let previous = match case % 3 {
                0 => before,
                1 => std::array::from_fn(|_| next() as u32),
                _ => octant_orders(&moved),
            };
            warm += usize::from(case % 3 != 1);
            assert_eq!(
                octant_orders_from(&moved, &previous),
                octant_orders(&moved),
                "case {case}: {moved:?} from {previous:?}"
            );
        }
        assert!(warm > 10_000);
    }
}
