//! The row kernels of the CPU compose (`cpu_compose.rs`): the horizontal Catmull-Rom pass of
//! one film row into a window-wide row, and the vertical pass of one window row with the
//! tonemap and the sRGB table. Pixels are RGBx: four floats, the fourth unused, so a pixel is
//! one SSE vector across and a row is one run of contiguous floats down.
//!
//! The vertical pass is compiled for AVX-512, AVX2 and the baseline (SSE2) and the widest the
//! CPU has is chosen at run time (as the denoiser's kernels are, `denoise/planes.rs`). The arithmetic is the old
//! per-channel compose's, term for term in the same order, so the bytes are the same.
//!
//! Owns: the per-row loops. Any thread (called from rayon's workers). Must not: allocate per
//! row or touch the device.

use glam::{Vec3, Vec4};

/// Entries of the sRGB table (see `cpu_compose::srgb_table`).
pub(super) const SRGB_TABLE: usize = 4096;

/// NaN → 0 and ±infinity → ±1e30, as the shader's `finite` (so 0 × inf never spreads).
#[inline(always)]
pub(super) fn finite(c: Vec3) -> Vec4 {
    let c = Vec3::from_array(c.to_array().map(|x| if x.is_nan() { 0.0 } else { x }))
        .clamp(Vec3::splat(-1e30), Vec3::splat(1e30));
    c.extend(0.0)
}

/// One output pixel's taps along an axis: four source indices (clamped to the film) and
/// their Catmull-Rom weights.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Taps {
    pub index: [u32; 4],
    pub weight: [f32; 4],
}

/// `row` (one film row, linear radiance) made finite into `scratch` and widened to
/// `out` (RGBx, `columns.len()` pixels): out pixel x = Σ row[index k] · weight k.
pub(super) fn horizontal(row: &[Vec3], scratch: &mut Vec<Vec4>, columns: &[Taps], out: &mut [f32]) {
    scratch.clear();
    scratch.extend(row.iter().map(|&c| finite(c)));
    let p = &scratch[..];
    for (px, t) in out.chunks_exact_mut(4).zip(columns) {
        let [a, b, c, d] = t
            .index
            .map(|i| p.get(i as usize).copied().unwrap_or(Vec4::ZERO));
        let s = a * t.weight[0] + b * t.weight[1] + c * t.weight[2] + d * t.weight[3];
        px.copy_from_slice(&s.to_array());
    }
}

/// `t` ∈ [0.5, 4095.5] (a clamped, scaled channel; never NaN) truncated to an integer. `as i32`
/// would do the same, but its saturating conversion does not vectorise (LLVM emits one
/// compare and convert per float); this one is a single vector instruction.
#[inline(always)]
fn to_index(t: f32) -> i32 {
    debug_assert!((0.0..=SRGB_TABLE as f32).contains(&t));
    // SAFETY: callers pass min(max(c, 0), 1) · 4095 + 0.5: `max` with a number never returns
    // NaN, so `t` is finite and in [0.5, 4095.5], and its truncation fits an i32.
    unsafe { t.to_int_unchecked::<i32>() }
}

/// The vertical pass of one window row: four widened rows `l0`…`l3` (RGBx floats) weighted
/// by `wy`, times `exposure`, the ACES fit when `filmic`, NaN to 0, clamped to [0, 1], as sRGB
/// table indices into `index` (same length as the rows, shortest wins).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn vertical_kernel(
    l0: &[f32],
    l1: &[f32],
    l2: &[f32],
    l3: &[f32],
    wy: [f32; 4],
    exposure: f32,
    filmic: bool,
    index: &mut [i32],
) {
    let n = index
        .len()
        .min(l0.len())
        .min(l1.len())
        .min(l2.len())
        .min(l3.len());
    let (l0, l1, l2, l3, index) = (&l0[..n], &l1[..n], &l2[..n], &l3[..n], &mut index[..n]);
    let top = (SRGB_TABLE - 1) as f32;
    if filmic {
        for x in 0..n {
            let c = (l0[x] * wy[0] + l1[x] * wy[1] + l2[x] * wy[2] + l3[x] * wy[3]) * exposure;
            let c = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
            // `max` takes the other operand of a NaN: NaN (a huge value's curve) → 0.
            index[x] = to_index(c.max(0.0).min(1.0) * top + 0.5);
        }
    } else {
        for x in 0..n {
            let c = (l0[x] * wy[0] + l1[x] * wy[1] + l2[x] * wy[2] + l3[x] * wy[3]) * exposure;
            index[x] = to_index(c.max(0.0).min(1.0) * top + 0.5);
        }
    }
}

/// The widest vector instructions this CPU has, for [`vertical`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Simd {
    /// AVX-512 (F, VL, BW).
    Avx512,
    Avx2,
    /// As compiled (SSE2 on x86-64).
    Baseline,
}

impl Simd {
    pub(super) fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512vl")
                && std::arch::is_x86_feature_detected!("avx512bw")
            {
                return Simd::Avx512;
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                return Simd::Avx2;
            }
        }
        Simd::Baseline
    }
}

/// [`vertical_kernel`] compiled for `simd`'s vector width (its loops vectorise for it).
#[allow(clippy::too_many_arguments)]
pub(super) fn vertical(
    simd: Simd,
    l0: &[f32],
    l1: &[f32],
    l2: &[f32],
    l3: &[f32],
    wy: [f32; 4],
    exposure: f32,
    filmic: bool,
    index: &mut [i32],
) {
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512vl,avx2")]
    #[allow(clippy::too_many_arguments)]
    fn avx512(
        a: &[f32],
        b: &[f32],
        c: &[f32],
        d: &[f32],
        w: [f32; 4],
        e: f32,
        f: bool,
        i: &mut [i32],
    ) {
        vertical_kernel(a, b, c, d, w, e, f, i)
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[allow(clippy::too_many_arguments)]
    fn avx2(
        a: &[f32],
        b: &[f32],
        c: &[f32],
        d: &[f32],
        w: [f32; 4],
        e: f32,
        f: bool,
        i: &mut [i32],
    ) {
        vertical_kernel(a, b, c, d, w, e, f, i)
    }
    match simd {
        // SAFETY: `Simd::detect` found these features on this CPU.
        #[cfg(target_arch = "x86_64")]
        Simd::Avx512 => unsafe { avx512(l0, l1, l2, l3, wy, exposure, filmic, index) },
        // SAFETY: as above.
        #[cfg(target_arch = "x86_64")]
        Simd::Avx2 => unsafe { avx2(l0, l1, l2, l3, wy, exposure, filmic, index) },
        _ => vertical_kernel(l0, l1, l2, l3, wy, exposure, filmic, index),
    }
}

/// Table indices (RGBx) to 4-byte pixels: B, G, R, `alpha` when `bgra`, else R, G, B,
/// `alpha` (255 for a surface texture; 0 for softbuffer's `0RGB` words, which are B, G, R, 0
/// in a little-endian machine's memory). `wide` is the same table widened to one `u32` an
/// entry (the AVX-512 path gathers from it).
pub(super) fn encode(
    simd: Simd,
    index: &[i32],
    table: &[u8; SRGB_TABLE],
    wide: &[u32; SRGB_TABLE],
    bgra: bool,
    alpha: u8,
    out: &mut [u8],
) {
    let done = match simd {
        // SAFETY: `Simd::detect` found AVX-512 (F, BW, VL) on this CPU.
        #[cfg(target_arch = "x86_64")]
        Simd::Avx512 => unsafe { encode_avx512(index, wide, bgra, alpha, out) },
        _ => 0,
    };
    encode_scalar(&index[done * 4..], table, bgra, alpha, &mut out[done * 4..]);
}

/// [`encode`] one pixel at a time (the baseline, and the pixels the vector path leaves).
fn encode_scalar(index: &[i32], table: &[u8; SRGB_TABLE], bgra: bool, alpha: u8, out: &mut [u8]) {
    let at = |i: i32| table[i as usize & (SRGB_TABLE - 1)];
    let pixels = out.chunks_exact_mut(4).zip(index.chunks_exact(4));
    if bgra {
        for (px, i) in pixels {
            px.copy_from_slice(&[at(i[2]), at(i[1]), at(i[0]), alpha]);
        }
    } else {
        for (px, i) in pixels {
            px.copy_from_slice(&[at(i[0]), at(i[1]), at(i[2]), alpha]);
        }
    }
}

/// [`encode`] four pixels at a time: sixteen indices (masked to the table, as the scalar
/// path's) gathered from `wide` in one instruction, truncated to bytes, reordered and given
/// `alpha` (a `perf` profile of `bench present` had the scalar loop at about a third of
/// the compose). Returns how many pixels it wrote (a multiple of four); the scalar path
/// writes the rest. The same table entries, so the same bytes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512bw,avx512vl,avx2")]
fn encode_avx512(
    index: &[i32],
    wide: &[u32; SRGB_TABLE],
    bgra: bool,
    alpha: u8,
    out: &mut [u8],
) -> usize {
    use std::arch::x86_64::*;
    let pixels = (index.len() / 4).min(out.len() / 4) / 4 * 4;
    let mask = _mm512_set1_epi32((SRGB_TABLE - 1) as i32);
    let alpha = _mm_set1_epi32(((alpha as u32) << 24) as i32);
    // Each pixel's fourth byte is zeroed (-128: the shuffle's "zero" lane), then `alpha` set.
    let order = if bgra {
        _mm_setr_epi8(
            2, 1, 0, -128, 6, 5, 4, -128, 10, 9, 8, -128, 14, 13, 12, -128,
        )
    } else {
        _mm_setr_epi8(
            0, 1, 2, -128, 4, 5, 6, -128, 8, 9, 10, -128, 12, 13, 14, -128,
        )
    };
    for p in (0..pixels).step_by(4) {
        // SAFETY: `p + 4 ≤ pixels`, so indices `4p .. 4p + 16` and bytes `4p .. 4p + 16` are
        // in `index` and `out`; every gathered offset is masked below `SRGB_TABLE`.
        unsafe {
            let i = _mm512_loadu_si512(index.as_ptr().add(p * 4).cast());
            let i = _mm512_and_si512(i, mask);
            let v = _mm512_i32gather_epi32::<4>(i, wide.as_ptr().cast());
            let bytes = _mm_or_si128(_mm_shuffle_epi8(_mm512_cvtepi32_epi8(v), order), alpha);
            _mm_storeu_si128(out.as_mut_ptr().add(p * 4).cast(), bytes);
        }
    }
    pixels
}
