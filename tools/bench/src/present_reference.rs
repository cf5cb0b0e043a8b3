//! The CPU compose as it was before 2026-12-06's present work (`bench present`'s reference):
//! `render::present::compose_host_film` at commit 4c2b644, kept verbatim but for its name, so
//! that the bench times the old and the new code in one run on the same films and checks that
//! they give the same bytes.
//!
//! Owns: nothing the engine uses. Must not: change (it is the before of the table).

use std::sync::OnceLock;

use glam::Vec3;
use rayon::prelude::*;

use candela::render::film::{Film, TonemapSettings};

/// Entries of the sRGB table over linear [0, 1]. 4096 steps of 1/4095: the curve's steepest
/// part (slope 12.92 below 0.0031308) moves at most 12.92 · 255 / 4095 ≈ 0.8 of an 8-bit step
/// between entries, so with rounding to the nearest entry an output is within one step of
/// the exact encoding (`linear_to_srgb8`).
const SRGB_TABLE: usize = 4096;

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

/// NaN → 0 and ±infinity → ±1e30, as the shader's `finite` (so 0 × inf never spreads).
fn finite(c: Vec3) -> Vec3 {
    Vec3::from_array(c.to_array().map(|x| if x.is_nan() { 0.0 } else { x }))
        .clamp(Vec3::splat(-1e30), Vec3::splat(1e30))
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

/// The four source taps (clamped to the film) and their weights along one axis: output pixel
/// `i` of `to` reads film pixels around its centre mapped as the shader maps it.
fn axis(from: u32, to: u32) -> Vec<([usize; 4], [f32; 4])> {
    let scale = from as f32 / to.max(1) as f32;
    let last = from.max(1) as i64 - 1;
    (0..to)
        .map(|i| {
            let f = (i as f32 + 0.5) * scale - 0.5;
            let base = f.floor();
            let b = base as i64;
            let taps = [b - 1, b, b + 1, b + 2].map(|v| v.clamp(0, last) as usize);
            (taps, catmull_rom(f - base))
        })
        .collect()
}

/// `film` upscaled (Catmull-Rom bicubic, separable, clamped edges) to `size` (physical pixels) and tonemapped with
/// `tonemap`, as rows of 4-byte pixels, top row first; `bgra` orders them B, G, R, A (else
/// R, G, B, A), alpha 255. An empty film gives black.
pub fn compose_reference(
    film: &Film,
    size: (u32, u32),
    tonemap: &TonemapSettings,
    bgra: bool,
) -> Vec<u8> {
    let (w, h) = (size.0.max(1) as usize, size.1.max(1) as usize);
    let mut out = vec![0u8; w * h * 4];
    if film.width == 0 || film.height == 0 || film.mean.len() < (film.width * film.height) as usize
    {
        for px in out.chunks_exact_mut(4) {
            px[3] = 255;
        }
        return out;
    }
    let columns = axis(film.width, w as u32);
    let rows = axis(film.height, h as u32);
    let exposure = tonemap.exposure_ev.exp2();
    let filmic = tonemap.filmic;
    let table = srgb_table();
    let fw = film.width as usize;
    let fh = film.height as usize;
    // Each film pixel made finite once, in three planes (one per channel) so that the loops
    // below run over contiguous floats (the compiler vectorises them).
    let mut planes = vec![0.0f32; 3 * fw * fh];
    {
        let (r, gb) = planes.split_at_mut(fw * fh);
        let (g, b) = gb.split_at_mut(fw * fh);
        for (i, &c) in film.mean[..fw * fh].iter().enumerate() {
            let c = finite(c);
            (r[i], g[i], b[i]) = (c.x, c.y, c.z);
        }
    }
    // Across first: each film row of each plane widened to the window's width (4 taps a
    // pixel), then down. `wide` holds plane k's row y at `(k * fh + y) * w`.
    let mut wide = vec![0.0f32; 3 * w * fh];
    wide.par_chunks_mut(w)
        .zip(planes.par_chunks(fw))
        .for_each(|(line, row)| {
            for (px, (taps, wx)) in line.iter_mut().zip(&columns) {
                *px = row[taps[0]] * wx[0]
                    + row[taps[1]] * wx[1]
                    + row[taps[2]] * wx[2]
                    + row[taps[3]] * wx[3];
            }
        });
    out.par_chunks_mut(w * 4)
        .zip(rows.par_iter())
        .for_each_init(
            || vec![0.0f32; 3 * w],
            |sum, (line, (taps, wy))| {
                for k in 0..3 {
                    let at = |t: usize| &wide[(k * fh + t) * w..][..w];
                    let (l0, l1, l2, l3) = (at(taps[0]), at(taps[1]), at(taps[2]), at(taps[3]));
                    let s = &mut sum[k * w..][..w];
                    for x in 0..w {
                        let mut c = (l0[x] * wy[0] + l1[x] * wy[1] + l2[x] * wy[2] + l3[x] * wy[3])
                            * exposure;
                        if filmic {
                            c = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
                        }
                        // NaN (the filmic curve of a huge value) to 0, then [0, 1] → table index.
                        let c = if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) };
                        s[x] = c * (SRGB_TABLE - 1) as f32 + 0.5;
                    }
                }
                let (r, gb) = sum.split_at(w);
                let (g, b) = gb.split_at(w);
                for (x, px) in line.chunks_exact_mut(4).enumerate() {
                    let [r, g, b] = [r[x], g[x], b[x]].map(|i| table[i as usize]);
                    px.copy_from_slice(&if bgra { [b, g, r, 255] } else { [r, g, b, 255] });
                }
            },
        );
    out
}
