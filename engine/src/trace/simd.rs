//! The x86-64 SIMD tree walk shared by the AVX2 and AVX-512 kernels (`x86.rs` holds their entry
//! points, `simd_block.rs` the triangle-block test): 8-lane slab test per node, children
//! permuted into the ray octant's order by `perm`, hit children compressed and pushed so the
//! nearest is popped first (Fuetterling et al. 2017; tinybvh's `BVH8_CPU`).
//!
//! Same algorithm and the same f32 operations as `scalar.rs` (fused exactly where it fuses), so
//! the hits are bit-identical; only the order of visiting ties may differ. `W512` selects AVX-512
//! mask compares and `vpcompressd` (register form; the memory form is slow on AMD Zen 4/5)
//! over an AVX2 compare + `movemask` + 256-entry compress table.
//!
//! Safety: every function here uses x86 intrinsics and must only run inside a
//! `#[target_feature]` function of `x86.rs` whose features the CPU was checked for (AVX2 for
//! `W512 = false`, AVX-512 F/VL/BW/DQ for `W512 = true`). They are `#[inline(always)]` so they
//! compile with those features. Memory accesses are bounds-checked (`get`) or within a node or
//! block reference; the stack never exceeds `STACK_SIZE` (a push needs 8 free entries, else
//! the walk stops early: only a tree deeper than `MAX_DEPTH`, which no builder emits).

use core::arch::x86_64::*;
use core::mem::{MaybeUninit, offset_of};

use super::STACK_SIZE;
use super::ray::{Ray, SlabRay};
use super::scalar::Leaf;
use crate::layout::{GpuBvh8Node, LEAF_BIT};

/// Per-ray constants of the 8-lane slab test.
pub(crate) struct NodeRay {
    /// Byte offsets of the near-plane / far-plane arrays per axis within a node.
    near: [usize; 3],
    far: [usize; 3],
    near_orcp: [__m256; 3],
    far_sub: [__m256; 3],
    rcp: [__m256; 3],
    far_rcp: [__m256; 3],
    t_min: __m256,
    /// The scalar form, for stack culling.
    slab: SlabRay,
    /// `3 · octant`, the right shift that brings the octant's 3-bit field of `perm` down.
    shift: __m128i,
}

impl NodeRay {
    #[inline(always)]
    pub(crate) fn new(ray: &Ray) -> Self {
        let s = SlabRay::new(ray.origin, ray.direction);
        let axis_offsets = [
            (
                offset_of!(GpuBvh8Node, min_x),
                offset_of!(GpuBvh8Node, max_x),
            ),
            (
                offset_of!(GpuBvh8Node, min_y),
                offset_of!(GpuBvh8Node, max_y),
            ),
            (
                offset_of!(GpuBvh8Node, min_z),
                offset_of!(GpuBvh8Node, max_z),
            ),
        ];
        let mut near = [0; 3];
        let mut far = [0; 3];
        for a in 0..3 {
            let (min, max) = axis_offsets[a];
            (near[a], far[a]) = if s.octant & (1 << a) != 0 {
                (max, min)
            } else {
                (min, max)
            };
        }
        // SAFETY: callers run with AVX enabled (module contract).
        unsafe {
            Self {
                near,
                far,
                near_orcp: s.near_orcp.to_array().map(|v| _mm256_set1_ps(v)),
                far_sub: s.far_sub.to_array().map(|v| _mm256_set1_ps(v)),
                rcp: s.rcp.to_array().map(|v| _mm256_set1_ps(v)),
                far_rcp: s.far_rcp.to_array().map(|v| _mm256_set1_ps(v)),
                t_min: _mm256_set1_ps(ray.t_min),
                slab: s,
                shift: _mm_cvtsi32_si128(3 * s.octant as i32),
            }
        }
    }
}

/// For each 8-bit hit mask, the lanes of its set bits packed to the front (AVX2 compress).
static COMPRESS: [[u32; 8]; 256] = {
    let mut table = [[0u32; 8]; 256];
    let mut mask = 0;
    while mask < 256 {
        let (mut lane, mut n) = (0, 0);
        while lane < 8 {
            if mask & (1 << lane) != 0 {
                table[mask][n] = lane as u32;
                n += 1;
            }
            lane += 1;
        }
        mask += 1;
    }
    table
};

/// Walks one tree (see `scalar::walk` for the contract). Same visiting rule as the scalar walk
/// except for when far entries are dropped: popping does not compare distances; instead, each
/// time a leaf lowers `t_max` the stack is compacted once, dropping every entry whose entry
/// distance lies beyond it (tinybvh does the same). That takes a compare and a branch out of
/// every pop.
///
/// # Safety
/// Module contract: AVX2 (and AVX-512 F/VL/BW/DQ when `W512`) must be enabled and supported.
#[inline(always)]
pub(crate) unsafe fn walk<const W512: bool, const ANY: bool>(
    nodes: &[GpuBvh8Node],
    r: &NodeRay,
    t_max: &mut f32,
    leaf: &mut impl Leaf,
) -> bool {
    // STACK_SIZE entries plus room for one 8-lane store past the last one (see `compact`).
    let mut stack_entry = MaybeUninit::<[u32; STACK_SIZE + 8]>::uninit();
    let mut stack_t = MaybeUninit::<[f32; STACK_SIZE + 8]>::uninit();
    let stack_entry = stack_entry.as_mut_ptr() as *mut u32;
    let stack_t = stack_t.as_mut_ptr() as *mut f32;
    let mut sp = 0usize; // entries below sp are initialised; only those are ever read
    let mut entry = 0u32; // the root: always an inner node
    unsafe {
        let reverse = _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0);
        let mut t_far_limit = _mm256_set1_ps(r.slab.far_limit(*t_max));
        loop {
            // Inner nodes until a leaf comes up (or nothing is left).
            while entry & LEAF_BIT == 0 {
                let Some(node) = nodes.get(entry as usize) else {
                    break; // corrupt index: treated as a miss
                };
                let base = (node as *const GpuBvh8Node).cast::<u8>();
                // The child indices sit in the node's last cache line, which the slab test does
                // not read: request it now so it has arrived when the next index is known.
                _mm_prefetch::<_MM_HINT_T0>(base.add(offset_of!(GpuBvh8Node, child)).cast());
                let plane = |offset: usize| _mm256_load_ps(base.add(offset).cast::<f32>());
                let dist = |offset: usize, orcp: __m256, rcp: __m256| {
                    _mm256_fmsub_ps(plane(offset), rcp, orcp)
                };
                let nx = dist(r.near[0], r.near_orcp[0], r.rcp[0]);
                let ny = dist(r.near[1], r.near_orcp[1], r.rcp[1]);
                let nz = dist(r.near[2], r.near_orcp[2], r.rcp[2]);
                let fx = dist(r.far[0], r.far_sub[0], r.far_rcp[0]);
                let fy = dist(r.far[1], r.far_sub[1], r.far_rcp[1]);
                let fz = dist(r.far[2], r.far_sub[2], r.far_rcp[2]);
                let t_near = _mm256_max_ps(_mm256_max_ps(nx, ny), _mm256_max_ps(nz, r.t_min));
                let t_far = _mm256_min_ps(_mm256_min_ps(fx, fy), _mm256_min_ps(fz, t_far_limit));
                let hits = if W512 {
                    u32::from(_mm256_cmp_ps_mask::<_CMP_LE_OQ>(t_near, t_far))
                } else {
                    _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(t_near, t_far)) as u32
                };
                if hits & hits.wrapping_sub(1) == 0 {
                    if hits == 0 {
                        break; // nothing hit: pop
                    }
                    // One child hit (the common case low in the tree): descend at once.
                    entry = node.child[(hits.trailing_zeros() & 7) as usize];
                    continue;
                }
                // Several: rank order, farthest first (lane i holds the slot of rank 7 - i),
                // compress the hit ones, push all but the nearest, descend into the nearest.
                let perm = _mm256_load_si256(base.add(offset_of!(GpuBvh8Node, perm)).cast());
                let order = _mm256_srl_epi32(_mm256_permutevar8x32_epi32(perm, reverse), r.shift);
                let near_ordered = _mm256_permutevar8x32_ps(t_near, order);
                let far_ordered = _mm256_permutevar8x32_ps(t_far, order);
                let child = _mm256_load_si256(base.add(offset_of!(GpuBvh8Node, child)).cast());
                let child_ordered = _mm256_permutevar8x32_epi32(child, order);
                let (children, dists) = if W512 {
                    let mask = _mm256_cmp_ps_mask::<_CMP_LE_OQ>(near_ordered, far_ordered);
                    (
                        _mm256_maskz_compress_epi32(mask, child_ordered),
                        _mm256_maskz_compress_ps(mask, near_ordered),
                    )
                } else {
                    let hit = _mm256_cmp_ps::<_CMP_LE_OQ>(near_ordered, far_ordered);
                    let mask = _mm256_movemask_ps(hit) as usize & 0xff;
                    let lanes = _mm256_loadu_si256(COMPRESS[mask].as_ptr().cast());
                    (
                        _mm256_permutevar8x32_epi32(child_ordered, lanes),
                        _mm256_permutevar8x32_ps(near_ordered, lanes),
                    )
                };
                if sp + 8 > STACK_SIZE {
                    return false; // deeper than MAX_DEPTH: never built by `accel`
                }
                _mm256_storeu_si256(stack_entry.add(sp).cast(), children);
                _mm256_storeu_ps(stack_t.add(sp), dists);
                sp += hits.count_ones() as usize - 1;
                entry = *stack_entry.add(sp);
            }
            if entry & LEAF_BIT != 0 {
                let before = *t_max;
                if leaf.visit(entry & !LEAF_BIT, t_max) {
                    return true;
                }
                if !ANY && *t_max < before {
                    let limit = r.slab.far_limit(*t_max);
                    t_far_limit = _mm256_set1_ps(limit);
                    sp = compact::<W512>(stack_entry, stack_t, sp, limit);
                }
            }
            if sp == 0 {
                return false;
            }
            sp -= 1;
            entry = *stack_entry.add(sp);
        }
    }
}

/// Drops the stack entries whose entry distance exceeds `limit`, keeping the order; returns
/// the new stack height. Reads only the `sp` initialised entries (masked loads for the last,
/// partial chunk); writes 8-lane vectors at `out <= i`, so never past `sp + 7`.
///
/// # Safety
/// Module contract; `entries` and `dists` hold `sp` initialised values and have room for
/// `sp + 7` values.
#[inline(always)]
unsafe fn compact<const W512: bool>(
    entries: *mut u32,
    dists: *mut f32,
    sp: usize,
    limit: f32,
) -> usize {
    unsafe {
        let limit8 = _mm256_set1_ps(limit);
        let mut out = 0usize;
        let mut i = 0usize;
        while i < sp {
            let valid = (1u32 << (sp - i).min(8)) - 1;
            let (d, e) = if valid == 0xff {
                (
                    _mm256_loadu_ps(dists.add(i)),
                    _mm256_loadu_si256(entries.add(i).cast()),
                )
            } else if W512 {
                (
                    _mm256_maskz_loadu_ps(valid as u8, dists.add(i)),
                    _mm256_maskz_loadu_epi32(valid as u8, entries.add(i).cast()),
                )
            } else {
                let lanes = _mm256_cmpgt_epi32(
                    _mm256_set1_epi32((sp - i) as i32),
                    _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7),
                );
                (
                    _mm256_maskload_ps(dists.add(i), lanes),
                    _mm256_maskload_epi32(entries.add(i).cast(), lanes),
                )
            };
            let keep = if W512 {
                u32::from(_mm256_cmp_ps_mask::<_CMP_LE_OQ>(d, limit8)) & valid
            } else {
                _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(d, limit8)) as u32 & valid
            };
            let (e, d) = if W512 {
                (
                    _mm256_maskz_compress_epi32(keep as u8, e),
                    _mm256_maskz_compress_ps(keep as u8, d),
                )
            } else {
                let lanes = _mm256_loadu_si256(COMPRESS[keep as usize].as_ptr().cast());
                (
                    _mm256_permutevar8x32_epi32(e, lanes),
                    _mm256_permutevar8x32_ps(d, lanes),
                )
            };
            // out <= i, so these stores never overrun what was read (reads stay ahead).
            _mm256_storeu_si256(entries.add(out).cast(), e);
            _mm256_storeu_ps(dists.add(out), d);
            out += keep.count_ones() as usize;
            i += 8;
        }
        out
    }
}
