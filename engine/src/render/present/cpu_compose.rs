//! Composing a host film (the CPU tracer's) into window pixels on the CPU: the same Catmull-Rom
//! bicubic upscale with clamped edges and the same tonemap as `shaders/present.wgsl` (exposure, the
//! optional ACES fit, NaN to black, clamp, sRGB encoding), written as 8-bit BGRA or RGBA rows
//! that the presenter copies straight into the surface texture.
//!
//! Why: under Xvfb the only adapter is lavapipe, which runs the present shader on the CPU one
//! fragment at a time; composing here (all cores, a lookup table for the sRGB curve) and
//! copying the bytes is cheaper (docs/PERFORMANCE.md, "Frame phases in a window").
//!
//! How: across first (each film row widened to the window's width, RGBx pixels, one SSE vector
//! each), then down (four widened rows a window row, contiguous floats at the CPU's widest
//! vectors, `cpu_compose_rows.rs`); the taps and weights of both axes are kept while the sizes
//! stay, and so are the buffers ([`HostCompose`]).
//!
//! Owns: [`HostCompose`], [`compose_host_film`] and the sRGB table. Render thread (rayon over
//! rows). Must not: touch the device (the presenter uploads the bytes).

use std::sync::OnceLock;

use glam::Vec4;
use rayon::prelude::*;

use super::cpu_compose_rows::{SRGB_TABLE, Simd, Taps, encode, horizontal, vertical};
use crate::render::film::{Film, TonemapSettings};

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

/// [`srgb_table`] widened to one `u32` an entry, for the AVX-512 encoding's gather.
fn srgb_table_wide() -> &'static [u32; SRGB_TABLE] {
    static TABLE: OnceLock<[u32; SRGB_TABLE]> = OnceLock::new();
    TABLE.get_or_init(|| srgb_table().map(u32::from))
}

/// Catmull-Rom weights of the four film pixels at `base − 1 … base + 2` for a sample `t` ∈ [0, 1)
/// past `base` (they sum to 1; `t = 0` gives `[0, 1, 0, 0]`, so equal sizes copy exactly). The
/// same cubic as `catmull_rom` in `shaders/present.wgsl`.
pub fn catmull_rom(t: f32) -> [f32; 4] {
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
pub struct HostCompose {
    /// (film width, film height, window width, window height) the taps are for.
    sizes: (u32, u32, u32, u32),
    columns: Vec<Taps>,
    rows: Vec<Taps>,
    /// Film row y widened to the window's width: RGBx floats at `y · 4w`.
    wide: Vec<f32>,
    out: Vec<u8>,
    simd: Simd,
}

impl Default for HostCompose {
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

/// How composed pixels lie in memory: four bytes a pixel, rows top to bottom.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelLayout {
    /// R, G, B, 255 (an `Rgba8Unorm` surface texture).
    Rgba8,
    /// B, G, R, 255 (a `Bgra8Unorm` surface texture).
    Bgra8,
    /// softbuffer's native-endian `0RGB` words: B, G, R, 0 on a little-endian machine (the
    /// only kind the presenter uses it on), so the compose writes softbuffer's buffer
    /// directly, with no conversion pass.
    Xrgb32,
}

impl PixelLayout {
    /// Whether blue comes first (B, G, R) rather than red.
    pub fn blue_first(self) -> bool {
        !matches!(self, PixelLayout::Rgba8)
    }

    /// The fourth byte of every pixel.
    fn fourth(self) -> u8 {
        match self {
            PixelLayout::Xrgb32 => 0,
            PixelLayout::Rgba8 | PixelLayout::Bgra8 => 255,
        }
    }
}

impl HostCompose {
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
        let mut out = std::mem::take(&mut self.out);
        out.resize(w * h * 4, 0);
        let layout = if bgra {
            PixelLayout::Bgra8
        } else {
            PixelLayout::Rgba8
        };
        self.compose_into(film, size, tonemap, layout, &mut out);
        self.out = out;
        &mut self.out
    }

    /// [`HostCompose::compose`] into `out` (4 bytes a pixel of `size`, laid out as `layout`):
    /// the presenter's softbuffer path writes the window's buffer this way. Rows beyond what
    /// `out` holds are left out.
    pub fn compose_into(
        &mut self,
        film: &Film,
        size: (u32, u32),
        tonemap: &TonemapSettings,
        layout: PixelLayout,
        out: &mut [u8],
    ) {
        let (w, h) = (size.0.max(1) as usize, size.1.max(1) as usize);
        let rows = (w * h * 4).min(out.len()) / (4 * w);
        let out = &mut out[..rows * 4 * w];
        let (bgra, alpha) = (layout.blue_first(), layout.fourth());
        let (fw, fh) = (film.width as usize, film.height as usize);
        if fw == 0 || fh == 0 || film.mean.len() < fw * fh {
            for px in out.chunks_exact_mut(4) {
                px.copy_from_slice(&[0, 0, 0, alpha]);
            }
            return;
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
        let (filmic, simd, wide) = (tonemap.filmic, self.simd, &self.wide);
        let (table, table_wide) = (srgb_table(), srgb_table_wide());
        out.par_chunks_mut(w * 4 * ROWS_PER_TASK)
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
                        encode(simd, index, table, table_wide, bgra, alpha, line);
                    }
                },
            );
    }
}

/// [`HostCompose::compose`] into a new buffer (tests, tools; the presenter keeps a
/// [`HostCompose`] so that nothing is allocated per frame).
pub fn compose_host_film(
    film: &Film,
    size: (u32, u32),
    tonemap: &TonemapSettings,
    bgra: bool,
) -> Vec<u8> {
    let mut compose = HostCompose::default();
    compose.compose(film, size, tonemap, bgra);
    compose.out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::film::linear_to_srgb8;
    use glam::Vec3;

    #[test]
    fn at_equal_size_it_tonemaps_like_the_cpu_within_one_step() {
        let mut film = Film::new(64, 32);
        let n = film.mean.len() as f32;
        for (i, p) in film.mean.iter_mut().enumerate() {
            let t = i as f32 / n;
            *p = Vec3::new(t * 1.2 - 0.1, (1.0 - t) * 0.02, (t * 7.0).fract());
        }
        film.mean[3] = Vec3::new(f32::NAN, 0.5, f32::INFINITY);
        for filmic in [false, true] {
            let settings = TonemapSettings {
                exposure_ev: 0.5,
                filmic,
            };
            let rgba = compose_host_film(&film, (64, 32), &settings, false);
            for (i, c) in film.mean.iter().enumerate() {
                let want = linear_to_srgb8(*c, &settings);
                for k in 0..3 {
                    let got = rgba[i * 4 + k];
                    assert!(
                        got.abs_diff(want[k]) <= 1,
                        "pixel {i} {k}: {got} vs {want:?}"
                    );
                }
                assert_eq!(rgba[i * 4 + 3], 255);
            }
        }
        let bgra = compose_host_film(&film, (64, 32), &TonemapSettings::default(), true);
        let rgba = compose_host_film(&film, (64, 32), &TonemapSettings::default(), false);
        assert_eq!((bgra[40], bgra[42]), (rgba[42], rgba[40]));
    }

    /// The vector encoding (where this CPU has it) gives the scalar one's bytes, for every
    /// table index, in both byte orders, over lengths that leave a remainder.
    #[test]
    fn the_vector_encoding_gives_the_scalar_bytes() {
        use super::super::cpu_compose_rows::{Simd, encode};
        let index: Vec<i32> = (0..4 * 1027).map(|i| (i * 7 + i / 5) % 4096).collect();
        for (bgra, alpha) in [(false, 255), (true, 255), (true, 0)] {
            for pixels in [1027usize, 1024, 3] {
                let mut scalar = vec![7u8; pixels * 4];
                let mut vector = vec![9u8; pixels * 4];
                let i = &index[..pixels * 4];
                let (t, w) = (srgb_table(), srgb_table_wide());
                encode(Simd::Baseline, i, t, w, bgra, alpha, &mut scalar);
                encode(Simd::detect(), i, t, w, bgra, alpha, &mut vector);
                assert_eq!(
                    scalar, vector,
                    "{pixels} pixels, bgra {bgra}, alpha {alpha}"
                );
                assert!(scalar.chunks_exact(4).all(|p| p[3] == alpha));
            }
        }
    }

    /// softbuffer's layout (`0RGB` words) carries the RGBA compose's colours, with the
    /// fourth byte 0, at a size that is not a multiple of the tasks' rows or the vectors.
    #[test]
    #[cfg(target_endian = "little")]
    fn the_softbuffer_layout_carries_the_rgba_colours() {
        let mut film = Film::new(37, 21);
        for (i, p) in film.mean.iter_mut().enumerate() {
            let t = i as f32 * 0.37;
            *p = Vec3::new(
                t.sin().abs() * 1.5,
                (t * 0.7).cos().abs(),
                (t * 3.1).fract(),
            );
        }
        film.mean[5] = Vec3::new(f32::NAN, 2.0, -1.0);
        let size = (101, 43);
        let settings = TonemapSettings::default();
        let rgba = compose_host_film(&film, size, &settings, false);
        let mut words = vec![0xdead_beef_u32; 101 * 43];
        let mut compose = HostCompose::default();
        compose.compose_into(
            &film,
            size,
            &settings,
            PixelLayout::Xrgb32,
            bytemuck::cast_slice_mut(&mut words),
        );
        for (i, (word, p)) in words.iter().zip(rgba.chunks_exact(4)).enumerate() {
            let want = ((p[0] as u32) << 16) | ((p[1] as u32) << 8) | p[2] as u32;
            assert_eq!(*word, want, "pixel {i}: {word:08x} vs {p:?}");
        }
        assert!(words.iter().any(|w| w & 0xff0000 != 0) && words.iter().any(|w| w & 0xff != 0));
    }

    #[test]
    fn upscaling_is_catmull_rom_with_clamped_edges() {
        let mut film = Film::new(2, 1);
        film.mean = vec![Vec3::ZERO, Vec3::ONE];
        let out = compose_host_film(&film, (4, 1), &TonemapSettings::default(), false);
        // Centres at 0.25, 0.75, 1.25, 1.75 film pixels (−0.25, 0.25, 0.75, 1.25 past the first
        // centre); the taps beyond the film repeat its edge pixels.
        let at = |f: f32| {
            let base = f.floor();
            let w = catmull_rom(f - base);
            let texel = |i: f32| if i < 1.0 { 0.0 } else { 1.0 };
            (0..4)
                .map(|k| w[k] * texel(base - 1.0 + k as f32))
                .sum::<f32>()
        };
        let expected = [-0.25f32, 0.25, 0.75, 1.25]
            .map(|f| linear_to_srgb8(Vec3::splat(at(f)), &TonemapSettings::default())[0]);
        for (i, e) in expected.iter().enumerate() {
            assert!(out[i * 4].abs_diff(*e) <= 1, "{i}: {} vs {e}", out[i * 4]);
        }
        // Sharper than bilinear between the two pixels (0.25 → 0.2031, 0.75 → 0.7969).
        assert!((at(0.25) - 0.203125).abs() < 1e-6 && (at(0.75) - 0.796875).abs() < 1e-6);
        for t in [0.0f32, 0.3, 0.5, 0.9] {
            assert!((catmull_rom(t).iter().sum::<f32>() - 1.0).abs() < 1e-6);
        }
        assert_eq!(catmull_rom(0.0), [0.0, 1.0, 0.0, 0.0]);
    }
}

#[cfg(test)]
#[path = "cpu_compose_tests.rs"]
mod scale_tests;
