//! The CPU compose as it was on 2026-12-07 before the fused bands and the vector sRGB
//! encoding (`bench present`'s "before" of that change): `render::present::HostCompose` and
//! its row kernels at commit 8f10f79, kept verbatim but for names and visibility, so that the
//! bench times it beside the new code in one run.
//!
//! Owns: nothing the engine uses. Must not: change (it is the before of the table).
#![allow(clippy::manual_clamp)] // as in the engine's code it copies

use std::sync::OnceLock;

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use candela::render::film::{Film, TonemapSettings};

/// The sRGB table over linear [0, 1]: [`SRGB_TABLE`] (4096) steps of 1/4095. The curve's
/// steepest part (slope 12.92 below 0.0031308) moves at most 12.92 · 255 / 4095 ≈ 0.8 of an
/// 8-bit step between entries, so with rounding to the nearest entry an output is within one
/// step of the exact encoding (`linear_to_srgb8`).
fn srgb_table() -> &'static [u8; SRGB_TABLE] {
    static TABLE: OnceLock<[u8; SRGB_TABLE]> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = [0u8; SRGB_TABLE];
        for (i, v) in t.iter_mut().enumerate() {
            let c = i as f32 / (SRGB_TABLE - 1) as f32;
            let s = if c <= 0.003_130_8 {
                12.92 * c
            } else {
                1.055 * c.powf(1.0 / 2.4) - 0.055
            };
            *v = (s * 255.0 + 0.5) as u8;
        }
        t
    })
}

/// Catmull-Rom weights of the four film pixels at `base − 1 … base + 2` for a sample `t` ∈ [0, 1)
/// past `base` (they sum to 1; `t = 0` gives `[0, 1, 0, 0]`, so equal sizes copy exactly). The
/// same cubic as `catmull_rom` in `shaders/present.wgsl`.
fn catmull_rom(t: f32) -> [f32; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        (-t3 + 2.0 * t2 - t) * 0.5,
        (3.0 * t3 - 5.0 * t2 + 2.0) * 0.5,
        (-3.0 * t3 + 4.0 * t2 + t) * 0.5,
        (t3 - t2) * 0.5,
    ]
}

/// The taps of each output pixel along one axis: output pixel `i` of `to` reads film pixels
/// around its centre mapped as the shader maps it, clamped to the film.
fn axis(from: u32, to: u32) -> Vec<Taps> {
    let scale = from as f32 / to.max(1) as f32;
    let last = from.max(1) as i64 - 1;
    (0..to)
        .map(|i| {
            let f = (i as f32 + 0.5) * scale - 0.5;
            let base = f.floor();
            let b = base as i64;
            Taps {
                index: [b - 1, b, b + 1, b + 2].map(|v| v.clamp(0, last) as u32),
                weight: catmull_rom(f - base),
            }
        })
        .collect()
}

/// Window rows a rayon task of the vertical pass takes (fewer, larger tasks than one a row).
const ROWS_PER_TASK: usize = 8;

/// The CPU compose with what it keeps between frames: the taps of both axes for the last
/// film and window sizes, the widened rows and the output bytes. One per presenter.
#[derive(Debug)]
pub struct BeforeCompose {
    /// (film width, film height, window width, window height) the taps are for.
    sizes: (u32, u32, u32, u32),
    columns: Vec<Taps>,
    rows: Vec<Taps>,
    /// Film row y widened to the window's width: RGBx floats at `y · 4w`.
    wide: Vec<f32>,
    out: Vec<u8>,
    simd: Simd,
}

impl Default for BeforeCompose {
    fn default() -> Self {
        Self {
            sizes: (0, 0, 0, 0),
            columns: Vec::new(),
            rows: Vec::new(),
            wide: Vec::new(),
            out: Vec::new(),
            simd: Simd::detect(),
        }
    }
}

impl BeforeCompose {
    /// `film` upscaled (Catmull-Rom bicubic, separable, clamped edges) to `size` (physical
    /// pixels, each side at least 1) and tonemapped with `tonemap`, as rows of 4-byte pixels,
    /// top row first; `bgra` orders them B, G, R, A (else R, G, B, A), alpha 255. An empty
    /// film (or one whose `mean` is shorter than its size) gives black. The bytes live until
    /// the next call.
    pub fn compose(
        &mut self,
        film: &Film,
        size: (u32, u32),
        tonemap: &TonemapSettings,
        bgra: bool,
    ) -> &mut [u8] {
        let (w, h) = (size.0.max(1) as usize, size.1.max(1) as usize);
        self.out.resize(w * h * 4, 0);
        let (fw, fh) = (film.width as usize, film.height as usize);
        if fw == 0 || fh == 0 || film.mean.len() < fw * fh {
            for px in self.out.chunks_exact_mut(4) {
                px.copy_from_slice(&[0, 0, 0, 255]);
            }
            return &mut self.out;
        }
        let sizes = (film.width, film.height, w as u32, h as u32);
        if self.sizes != sizes {
            self.columns = axis(film.width, w as u32);
            self.rows = axis(film.height, h as u32);
            self.sizes = sizes;
        }
        self.wide.resize(4 * w * fh, 0.0);
        let columns = &self.columns;
        self.wide
            .par_chunks_mut(4 * w)
            .zip(film.mean[..fw * fh].par_chunks(fw))
            .for_each_init(
                || Vec::<Vec4>::with_capacity(fw),
                |scratch, (line, row)| horizontal(row, scratch, columns, line),
            );
        let exposure = tonemap.exposure_ev.exp2();
        let (filmic, simd, table, wide) = (tonemap.filmic, self.simd, srgb_table(), &self.wide);
        self.out
            .par_chunks_mut(w * 4 * ROWS_PER_TASK)
            .zip(self.rows.par_chunks(ROWS_PER_TASK))
            .for_each_init(
                || vec![0i32; 4 * w],
                |index, (lines, taps)| {
                    for (line, t) in lines.chunks_exact_mut(w * 4).zip(taps) {
                        let at = |k: usize| {
                            let y = t.index[k] as usize;
                            wide.get(y * 4 * w..(y + 1) * 4 * w).unwrap_or(&[])
                        };
                        vertical(
                            simd,
                            at(0),
                            at(1),
                            at(2),
                            at(3),
                            t.weight,
                            exposure,
                            filmic,
                            index,
                        );
                        encode(index, table, bgra, line);
                    }
                },
            );
        &mut self.out
    }
}

// ---- the row kernels (`cpu_compose_rows.rs` at 8f10f79) ----

/// Entries of the sRGB table (see `cpu_compose::srgb_table`).
const SRGB_TABLE: usize = 4096;

/// NaN → 0 and ±infinity → ±1e30, as the shader's `finite` (so 0 × inf never spreads).
#[inline(always)]
fn finite(c: Vec3) -> Vec4 {
    let c = Vec3::from_array(c.to_array().map(|x| if x.is_nan() { 0.0 } else { x }))
        .clamp(Vec3::splat(-1e30), Vec3::splat(1e30));
    c.extend(0.0)
}

/// One output pixel's taps along an axis: four source indices (clamped to the film) and
/// their Catmull-Rom weights.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Taps {
    pub index: [u32; 4],
    pub weight: [f32; 4],
}

/// `row` (one film row, linear radiance) made finite into `scratch` and widened to
/// `out` (RGBx, `columns.len()` pixels): out pixel x = Σ row[index k] · weight k.
fn horizontal(row: &[Vec3], scratch: &mut Vec<Vec4>, columns: &[Taps], out: &mut [f32]) {
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
enum Simd {
    /// AVX-512 (F, VL).
    Avx512,
    Avx2,
    /// As compiled (SSE2 on x86-64).
    Baseline,
}

impl Simd {
    fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512vl")
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
fn vertical(
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

/// Table indices (RGBx) to 4-byte pixels: B, G, R, 255 when `bgra`, else R, G, B, 255.
fn encode(index: &[i32], table: &[u8; SRGB_TABLE], bgra: bool, out: &mut [u8]) {
    let at = |i: i32| table[i as usize & (SRGB_TABLE - 1)];
    let pixels = out.chunks_exact_mut(4).zip(index.chunks_exact(4));
    if bgra {
        for (px, i) in pixels {
            px.copy_from_slice(&[at(i[2]), at(i[1]), at(i[0]), 255]);
        }
    } else {
        for (px, i) in pixels {
            px.copy_from_slice(&[at(i[0]), at(i[1]), at(i[2]), 255]);
        }
    }
}
