//! [`Lanes`]: the f32 vector operations of the triangle-block test, for 4 lanes (`__m128`, one
//! [`crate::layout::GpuTri4`]) and 8 lanes (`__m256`, two consecutive blocks of a leaf), so that
//! `simd_block.rs` writes the test once for both widths.
//!
//! Every method is one x86 instruction with the same rounding at either width (`fmadd`/`fmsub`
//! fused, the rest IEEE single operations), so a lane's result does not depend on the width.
//! Safety: as `simd.rs` — only call these inside a `#[target_feature]` function with AVX2 and FMA
//! enabled (they are `#[inline(always)]` so they compile with those features). Any thread.

use core::arch::x86_64::*;

use crate::layout::GpuTri4;

/// A vector of f32 lanes; see the module docs for the safety contract of every method.
pub(super) trait Lanes: Copy {
    /// Row at byte `offset` of each of the one (4 lanes) or two (8 lanes) consecutive blocks
    /// from `block`.
    ///
    /// # Safety
    /// Those blocks must be valid; AVX2 enabled.
    unsafe fn row(block: *const GpuTri4, offset: usize) -> Self;
    unsafe fn splat(v: f32) -> Self;
    unsafe fn add(self, b: Self) -> Self;
    unsafe fn sub(self, b: Self) -> Self;
    unsafe fn mul(self, b: Self) -> Self;
    unsafe fn div(self, b: Self) -> Self;
    /// `c - self·b`, one rounding.
    unsafe fn fnmadd(self, b: Self, c: Self) -> Self;
    /// `self·b + c`, one rounding.
    unsafe fn fmadd(self, b: Self, c: Self) -> Self;
    /// `self·b - c`, one rounding.
    unsafe fn fmsub(self, b: Self, c: Self) -> Self;
    /// `self & !mask` bitwise (`abs` with `mask = -0.0`).
    unsafe fn andnot(self, mask: Self) -> Self;
    unsafe fn and(self, b: Self) -> Self;
    unsafe fn gt(self, b: Self) -> Self;
    unsafe fn ge(self, b: Self) -> Self;
    unsafe fn le(self, b: Self) -> Self;
    unsafe fn lt(self, b: Self) -> Self;
    /// Sign bits, bit `i` for lane `i`.
    unsafe fn mask(self) -> u32;
    /// The lanes as an array (8 entries; a 4-lane vector leaves the last four zero).
    unsafe fn to_array(self) -> [f32; 8];
}

impl Lanes for __m128 {
    #[inline(always)]
    unsafe fn row(block: *const GpuTri4, offset: usize) -> Self {
        // SAFETY: caller contract (one valid, 16-byte aligned block).
        unsafe { _mm_load_ps(block.cast::<u8>().add(offset).cast()) }
    }
    #[inline(always)]
    unsafe fn splat(v: f32) -> Self {
        unsafe { _mm_set1_ps(v) }
    }
    #[inline(always)]
    unsafe fn add(self, b: Self) -> Self {
        unsafe { _mm_add_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn sub(self, b: Self) -> Self {
        unsafe { _mm_sub_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn mul(self, b: Self) -> Self {
        unsafe { _mm_mul_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn div(self, b: Self) -> Self {
        unsafe { _mm_div_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn fnmadd(self, b: Self, c: Self) -> Self {
        unsafe { _mm_fnmadd_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn fmadd(self, b: Self, c: Self) -> Self {
        unsafe { _mm_fmadd_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn fmsub(self, b: Self, c: Self) -> Self {
        unsafe { _mm_fmsub_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn andnot(self, mask: Self) -> Self {
        unsafe { _mm_andnot_ps(mask, self) }
    }
    #[inline(always)]
    unsafe fn and(self, b: Self) -> Self {
        unsafe { _mm_and_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn gt(self, b: Self) -> Self {
        unsafe { _mm_cmpgt_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn ge(self, b: Self) -> Self {
        unsafe { _mm_cmpge_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn le(self, b: Self) -> Self {
        unsafe { _mm_cmple_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn lt(self, b: Self) -> Self {
        unsafe { _mm_cmplt_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn mask(self) -> u32 {
        unsafe { _mm_movemask_ps(self) as u32 }
    }
    #[inline(always)]
    unsafe fn to_array(self) -> [f32; 8] {
        let mut out = [0.0; 8];
        // SAFETY: `out` has room for four f32 (unaligned store).
        unsafe { _mm_storeu_ps(out.as_mut_ptr(), self) };
        out
    }
}

impl Lanes for __m256 {
    #[inline(always)]
    unsafe fn row(block: *const GpuTri4, offset: usize) -> Self {
        // SAFETY: caller contract (two valid, 16-byte aligned blocks).
        unsafe {
            let low = _mm_load_ps(block.cast::<u8>().add(offset).cast());
            let high = _mm_load_ps(block.add(1).cast::<u8>().add(offset).cast());
            _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(low), high)
        }
    }
    #[inline(always)]
    unsafe fn splat(v: f32) -> Self {
        unsafe { _mm256_set1_ps(v) }
    }
    #[inline(always)]
    unsafe fn add(self, b: Self) -> Self {
        unsafe { _mm256_add_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn sub(self, b: Self) -> Self {
        unsafe { _mm256_sub_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn mul(self, b: Self) -> Self {
        unsafe { _mm256_mul_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn div(self, b: Self) -> Self {
        unsafe { _mm256_div_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn fnmadd(self, b: Self, c: Self) -> Self {
        unsafe { _mm256_fnmadd_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn fmadd(self, b: Self, c: Self) -> Self {
        unsafe { _mm256_fmadd_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn fmsub(self, b: Self, c: Self) -> Self {
        unsafe { _mm256_fmsub_ps(self, b, c) }
    }
    #[inline(always)]
    unsafe fn andnot(self, mask: Self) -> Self {
        unsafe { _mm256_andnot_ps(mask, self) }
    }
    #[inline(always)]
    unsafe fn and(self, b: Self) -> Self {
        unsafe { _mm256_and_ps(self, b) }
    }
    #[inline(always)]
    unsafe fn gt(self, b: Self) -> Self {
        unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(self, b) }
    }
    #[inline(always)]
    unsafe fn ge(self, b: Self) -> Self {
        unsafe { _mm256_cmp_ps::<_CMP_GE_OQ>(self, b) }
    }
    #[inline(always)]
    unsafe fn le(self, b: Self) -> Self {
        unsafe { _mm256_cmp_ps::<_CMP_LE_OQ>(self, b) }
    }
    #[inline(always)]
    unsafe fn lt(self, b: Self) -> Self {
        unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self, b) }
    }
    #[inline(always)]
    unsafe fn mask(self) -> u32 {
        unsafe { _mm256_movemask_ps(self) as u32 }
    }
    #[inline(always)]
    unsafe fn to_array(self) -> [f32; 8] {
        let mut out = [0.0; 8];
        // SAFETY: `out` has room for eight f32 (unaligned store).
        unsafe { _mm256_storeu_ps(out.as_mut_ptr(), self) };
        out
    }
}
