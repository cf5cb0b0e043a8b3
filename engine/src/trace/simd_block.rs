//! The 4-lane triangle-block test of the x86-64 SIMD kernels and the single-BLAS queries built
//! on it (`simd.rs` walks the tree, `x86.rs` holds the `#[target_feature]` entry points).
//!
//! Repeats `triangle::intersect_permuted` lane for lane (fused exactly where it fuses), so `t`,
//! `u`, `v` are bit-identical to the scalar kernel's; the closest lane is the lowest among the
//! smallest `t`, as the scalar loop picks it. Any thread. Safety: as `simd.rs` (AVX2 + FMA at
//! least, enabled by the caller's `#[target_feature]`); block reads are bounds-checked.

use core::arch::x86_64::*;

use super::ray::Ray;
use super::scalar::{BlasHit, Leaf};
use super::simd::{NodeRay, walk};
use super::triangle::{DEGENERATE_RATIO, EDGE_SLACK, TriRay};
use crate::layout::{GpuBvh8Node, GpuTri4};

/// Per-ray constants of the 4-lane triangle test (see `triangle.rs`).
pub(super) struct BlockRay {
    /// Byte offsets of the rows `v0[k]`, per permuted axis (add 48 for `e1`, 96 for `e2`).
    row: [usize; 3],
    origin: [__m128; 3],
    shear: [__m128; 3],
    t_min: __m128,
}

impl BlockRay {
    #[inline(always)]
    pub(super) fn new(ray: &Ray) -> Self {
        let t = TriRay::new(ray.origin, ray.direction);
        // SAFETY: callers run with AVX enabled (module contract).
        unsafe {
            Self {
                row: t.k.map(|k| 16 * k),
                origin: t.origin.map(|v| _mm_set1_ps(v)),
                shear: t.shear.map(|v| _mm_set1_ps(v)),
                t_min: _mm_set1_ps(ray.t_min),
            }
        }
    }
}

/// The four lanes of `triangle::intersect_permuted`: hit mask (bit per lane), `t`, `u`, `v`.
///
/// # Safety
/// Module contract (AVX enabled).
#[inline(always)]
unsafe fn block_test(b: &GpuTri4, r: &BlockRay, t_max: f32) -> (u32, __m128, __m128, __m128) {
    unsafe {
        let base = (b as *const GpuTri4).cast::<u8>();
        let row = |offset: usize| _mm_load_ps(base.add(offset).cast::<f32>());
        let (sx, sy, sz) = (r.shear[0], r.shear[1], r.shear[2]);
        let (sub, mul) = (|a, b| _mm_sub_ps(a, b), |a, b| _mm_mul_ps(a, b));
        let fnm = |a, b, c| _mm_fnmadd_ps(a, b, c);
        let a0 = sub(row(r.row[0]), r.origin[0]);
        let a1 = sub(row(r.row[1]), r.origin[1]);
        let a2 = sub(row(r.row[2]), r.origin[2]);
        let e1z = row(48 + r.row[2]);
        let e2z = row(96 + r.row[2]);
        let ax = fnm(sx, a2, a0);
        let ay = fnm(sy, a2, a1);
        let e1x = fnm(sx, e1z, row(48 + r.row[0]));
        let e1y = fnm(sy, e1z, row(48 + r.row[1]));
        let e2x = fnm(sx, e2z, row(96 + r.row[0]));
        let e2y = fnm(sy, e2z, row(96 + r.row[1]));
        let w1 = _mm_fmsub_ps(ax, e2y, mul(ay, e2x));
        let w2 = _mm_fmsub_ps(e1x, ay, mul(e1y, ax));
        let p2 = mul(e2y, e1x);
        let det = _mm_fmsub_ps(e2x, e1y, p2);
        let sign = _mm_set1_ps(-0.0);
        let abs = |v| _mm_andnot_ps(sign, v);
        let bound = mul(abs(p2), _mm_set1_ps(DEGENERATE_RATIO));
        let inv_det = _mm_div_ps(_mm_set1_ps(1.0), det);
        let u = mul(w1, inv_det);
        let v = mul(w2, inv_det);
        let t = mul(_mm_fmadd_ps(v, e2z, _mm_fmadd_ps(u, e1z, a2)), sz);
        let mut ok = _mm_cmpgt_ps(abs(det), bound);
        let slack = _mm_set1_ps(-EDGE_SLACK);
        ok = _mm_and_ps(ok, _mm_cmpge_ps(u, slack));
        ok = _mm_and_ps(ok, _mm_cmpge_ps(v, slack));
        ok = _mm_and_ps(
            ok,
            _mm_cmple_ps(_mm_add_ps(u, v), _mm_set1_ps(1.0 + EDGE_SLACK)),
        );
        ok = _mm_and_ps(ok, _mm_cmpgt_ps(t, r.t_min));
        ok = _mm_and_ps(ok, _mm_cmplt_ps(t, _mm_set1_ps(t_max)));
        (_mm_movemask_ps(ok) as u32, t, u, v)
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
        if let Some(block) = self.blocks.get(payload as usize) {
            let source = self.source;
            let ray = self.ray.get_or_insert_with(|| BlockRay::new(source));
            // SAFETY: module contract.
            let (mask, t, u, v) = unsafe { block_test(block, ray, *t_max) };
            if mask != 0 {
                let (t, u, v) = (lanes(t), lanes(u), lanes(v));
                // The lowest lane among the smallest t, as the scalar loop picks it.
                let mut lane = mask.trailing_zeros() as usize;
                for l in lane + 1..4 {
                    if mask & (1 << l) != 0 && t[l] < t[lane] {
                        lane = l;
                    }
                }
                *t_max = t[lane];
                self.best = Some((t[lane], u[lane], v[lane], block.prim[lane]));
            }
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
        let Some(block) = self.blocks.get(payload as usize) else {
            return false;
        };
        let source = self.source;
        let ray = self.ray.get_or_insert_with(|| BlockRay::new(source));
        // SAFETY: module contract.
        unsafe { block_test(block, ray, *t_max).0 != 0 }
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

#[inline(always)]
fn lanes(v: __m128) -> [f32; 4] {
    // SAFETY: __m128 and [f32; 4] have the same size and any bits are valid f32.
    unsafe { core::mem::transmute::<__m128, [f32; 4]>(v) }
}
