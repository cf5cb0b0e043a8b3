//! The triangle-block test of the x86-64 SIMD kernels and the single-BLAS queries built on it
//! (`simd.rs` walks the tree, `x86.rs` holds the `#[target_feature]` entry points). A leaf's
//! blocks are tested two at a time (8 lanes, `__m256`), an odd last one alone (4 lanes):
//! measured on the peer benchmark's dragon, 1–3 % faster than one block at a time.
//!
//! Repeats `triangle::intersect_permuted` lane for lane (fused exactly where it fuses, the same
//! instructions at either width: `simd_lanes.rs`), so `t`, `u`, `v` are bit-identical to the
//! scalar kernel's; the closest lane is the lowest among the smallest `t` (block order, then
//! lane order), as the scalar loop picks it. Any thread. Safety: as `simd.rs` (AVX2 + FMA at
//! least, enabled by the caller's `#[target_feature]`); block reads are bounds-checked.
//! Closures and iterator adaptors that take closures are avoided in the visitors: a closure
//! passed to a generic library function is not compiled with the caller's target features, and
//! the shadow kernel ran 40 % slower that way.

use core::arch::x86_64::*;

use super::ray::Ray;
use super::scalar::{BlasHit, Leaf, leaf_blocks};
use super::simd::{NodeRay, walk};
use super::simd_lanes::Lanes;
use super::triangle::{DEGENERATE_RATIO, EDGE_SLACK, SLACK_SCALE, TriRay};
use crate::layout::{GpuBvh8Node, GpuTri4};

/// Per-ray constants of the triangle test (see `triangle.rs`), kept scalar: each block test
/// broadcasts them (one load each), which is cheaper than carrying eight vectors around.
#[derive(Clone, Copy)]
pub(super) struct BlockRay {
    /// Byte offsets of the rows `v0[k]`, per permuted axis (add 48 for `e1`, 96 for `e2`).
    row: [usize; 3],
    origin: [f32; 3],
    shear: [f32; 3],
    t_min: f32,
}

impl BlockRay {
    #[inline(always)]
    pub(super) fn new(ray: &Ray) -> Self {
        let t = TriRay::new(ray.origin, ray.direction);
        Self {
            row: t.k.map(|k| 16 * k),
            origin: t.origin,
            shear: t.shear,
            t_min: ray.t_min,
        }
    }
}

/// `triangle::intersect_permuted` on every lane of `L::BLOCKS` consecutive blocks from
/// `block`: hit mask (bit per lane), `t`, `u`, `v`.
///
/// # Safety
/// Module contract (AVX2 and FMA enabled); `block..block + L::BLOCKS` are valid blocks.
#[inline(always)]
unsafe fn block_test<L: Lanes>(block: *const GpuTri4, r: &BlockRay, t_max: f32) -> (u32, L, L, L) {
    unsafe {
        let row = |offset: usize| L::row(block, offset);
        let (sx, sy, sz) = (
            L::splat(r.shear[0]),
            L::splat(r.shear[1]),
            L::splat(r.shear[2]),
        );
        let a0 = row(r.row[0]).sub(L::splat(r.origin[0]));
        let a1 = row(r.row[1]).sub(L::splat(r.origin[1]));
        let a2 = row(r.row[2]).sub(L::splat(r.origin[2]));
        let e1z = row(48 + r.row[2]);
        let e2z = row(96 + r.row[2]);
        let ax = sx.fnmadd(a2, a0);
        let ay = sy.fnmadd(a2, a1);
        let e1x = sx.fnmadd(e1z, row(48 + r.row[0]));
        let e1y = sy.fnmadd(e1z, row(48 + r.row[1]));
        let e2x = sx.fnmadd(e2z, row(96 + r.row[0]));
        let e2y = sy.fnmadd(e2z, row(96 + r.row[1]));
        let w1 = ax.fmsub(e2y, ay.mul(e2x));
        let w2 = e1x.fmsub(ay, e1y.mul(ax));
        let p2 = e2y.mul(e1x);
        let det = e2x.fmsub(e1y, p2);
        let sign = L::splat(-0.0);
        let bound = p2.andnot(sign).mul(L::splat(DEGENERATE_RATIO));
        let inv_det = L::splat(1.0).div(det);
        let u = w1.mul(inv_det);
        let v = w2.mul(inv_det);
        let t = v.fmadd(e2z, u.fmadd(e1z, a2)).mul(sz);
        // The rounding-error slack per edge, in `triangle::intersect_permuted`'s order.
        let m = ax.andnot(sign).add(ay.andnot(sign)).add(a2.andnot(sign));
        let c = m.mul(inv_det.andnot(sign).mul(L::splat(SLACK_SCALE)));
        let len1 = e1x.andnot(sign).add(e1y.andnot(sign)).add(e1z.andnot(sign));
        let len2 = e2x.andnot(sign).add(e2y.andnot(sign)).add(e2z.andnot(sign));
        // `u >= -(c·len2 + EDGE_SLACK)` tested as `c·len2 + u >= -EDGE_SLACK` (one rounding),
        // and so on, in `triangle::intersect_permuted`'s order.
        let ok = det
            .andnot(sign)
            .gt(bound)
            .and(c.fmadd(len2, u).ge(L::splat(-EDGE_SLACK)))
            .and(c.fmadd(len1, v).ge(L::splat(-EDGE_SLACK)))
            .and(
                c.fnmadd(len1.add(len2), u.add(v))
                    .le(L::splat(1.0 + EDGE_SLACK)),
            )
            .and(t.gt(L::splat(r.t_min)))
            .and(t.lt(L::splat(t_max)));
        (ok.mask(), t, u, v)
    }
}

/// Leaf visitor: closest hit in a triangle block. The per-ray constants of the triangle test
/// are made at the first leaf: most primary rays never reach one.
struct ClosestBlock<'a> {
    blocks: &'a [GpuTri4],
    source: &'a Ray,
    ray: Option<BlockRay>,
    best: Option<BlasHit>,
}

impl Leaf for ClosestBlock<'_> {
    #[inline(always)]
    fn visit(&mut self, payload: u32, t_max: &mut f32) -> bool {
        let ray = &match self.ray {
            Some(ray) => ray,
            None => *self.ray.insert(BlockRay::new(self.source)),
        };
        let blocks = leaf_blocks(self.blocks, payload);
        let mut i = 0;
        while i < blocks.len() {
            let block = blocks[i..].as_ptr();
            // Two blocks at once (8 lanes) while two are left; the lanes go to memory only
            // when one hit. SAFETY: module contract; the blocks tested lie in `blocks`.
            let hit = if i + 1 < blocks.len() {
                let (mask, t, u, v) = unsafe { block_test::<__m256>(block, ray, *t_max) };
                if mask != 0 {
                    Some(unsafe { (mask, t.to_array(), u.to_array(), v.to_array()) })
                } else {
                    None
                }
            } else {
                let (mask, t, u, v) = unsafe { block_test::<__m128>(block, ray, *t_max) };
                if mask != 0 {
                    Some(unsafe { (mask, t.to_array(), u.to_array(), v.to_array()) })
                } else {
                    None
                }
            };
            if let Some((mask, t, u, v)) = hit {
                // The lowest lane among the smallest t, as the scalar loop picks it.
                let mut lane = mask.trailing_zeros() as usize;
                let mut rest = mask & (mask - 1);
                while rest != 0 {
                    let l = rest.trailing_zeros() as usize;
                    if t[l] < t[lane] {
                        lane = l;
                    }
                    rest &= rest - 1;
                }
                *t_max = t[lane];
                let prim = blocks[i + lane / 4].prim[lane % 4];
                self.best = Some((t[lane], u[lane], v[lane], prim));
            }
            i += 2;
        }
        false
    }
}

/// Leaf visitor: any hit in a triangle block (triangle constants made at the first leaf).
struct AnyBlock<'a> {
    blocks: &'a [GpuTri4],
    source: &'a Ray,
    ray: Option<BlockRay>,
}

impl Leaf for AnyBlock<'_> {
    #[inline(always)]
    fn visit(&mut self, payload: u32, t_max: &mut f32) -> bool {
        let ray = &match self.ray {
            Some(ray) => ray,
            None => *self.ray.insert(BlockRay::new(self.source)),
        };
        let blocks = leaf_blocks(self.blocks, payload);
        let mut i = 0;
        while i < blocks.len() {
            let block = blocks[i..].as_ptr();
            // SAFETY: module contract; the blocks tested lie in `blocks`.
            let mask = if i + 1 < blocks.len() {
                unsafe { block_test::<__m256>(block, ray, *t_max).0 }
            } else {
                unsafe { block_test::<__m128>(block, ray, *t_max).0 }
            };
            if mask != 0 {
                return true;
            }
            i += 2;
        }
        false
    }
}

/// Closest hit in one BLAS.
///
/// # Safety
/// Module contract.
#[inline(always)]
pub(super) unsafe fn closest_blas<const W512: bool>(
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    ray: &Ray,
    t_max: &mut f32,
) -> Option<BlasHit> {
    let node_ray = NodeRay::new(ray);
    let mut leaf = ClosestBlock {
        blocks,
        source: ray,
        ray: None,
        best: None,
    };
    unsafe { walk::<W512, false>(nodes, &node_ray, t_max, &mut leaf) };
    leaf.best
}

/// Any hit in one BLAS.
///
/// # Safety
/// Module contract.
#[inline(always)]
pub(super) unsafe fn occluded_blas<const W512: bool>(
    nodes: &[GpuBvh8Node],
    blocks: &[GpuTri4],
    ray: &Ray,
) -> bool {
    let node_ray = NodeRay::new(ray);
    let mut leaf = AnyBlock {
        blocks,
        source: ray,
        ray: None,
    };
    unsafe { walk::<W512, true>(nodes, &node_ray, &mut { ray.t_max }, &mut leaf) }
}
