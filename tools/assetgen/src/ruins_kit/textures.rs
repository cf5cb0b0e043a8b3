//! The ruins kit's textures, drawn by code: weathered sandstone (strata, pits, grain), darker
//! carved stone with glyph reliefs, wind-rippled sand, each as an sRGB colour image and a
//! tangent-space normal map derived from the same height field.
//!
//! Every image tiles (the noise repeats over the image). Normal maps follow glTF (+X towards
//! +u, +Y towards the top of the image, +Z out; `n * 0.5 + 0.5`), from a wrapped Sobel slope
//! of the height field (heights in texels × `relief`). Deterministic: `noise` only.
//! Must not: write files (the caller does).

use image::{Rgb, RgbImage};

use super::glyphs;
use super::noise::{fbm2, hash3, smoothstep, value2xy};

/// Side of the sandstone and carved-stone images, texels (one tile: 2 m of sandstone; 2 × 2
/// glyph cells of carved stone).
pub const STONE_SIZE: u32 = 512;
/// Side of the sand image, texels (one tile: 4 m).
pub const SAND_SIZE: u32 = 256;

/// A height field and a colour per texel, row-major, `size × size`.
struct Surface {
    size: u32,
    height: Vec<f32>,
    color: Vec<[f32; 3]>,
}

impl Surface {
    fn new(size: u32, texel: impl Fn(f32, f32, u32, u32) -> (f32, [f32; 3])) -> Self {
        let n = (size * size) as usize;
        let (mut height, mut color) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for y in 0..size {
            for x in 0..size {
                let (u, v) = (x as f32 / size as f32, y as f32 / size as f32);
                let (h, c) = texel(u, v, x, y);
                height.push(h);
                color.push(c);
            }
        }
        Self {
            size,
            height,
            color,
        }
    }

    fn color_image(&self) -> RgbImage {
        RgbImage::from_fn(self.size, self.size, |x, y| {
            let c = self.color[(y * self.size + x) as usize];
            Rgb(c.map(|v| (v * 255.0).round().clamp(0.0, 255.0) as u8))
        })
    }

    /// The normal map of `height × relief` (relief: texels of height per height unit).
    fn normal_image(&self, relief: f32) -> RgbImage {
        let s = self.size as i64;
        let at = |x: i64, y: i64| self.height[(y.rem_euclid(s) * s + x.rem_euclid(s)) as usize];
        RgbImage::from_fn(self.size, self.size, |x, y| {
            let (x, y) = (i64::from(x), i64::from(y));
            let d_right = (at(x + 1, y - 1) + 2.0 * at(x + 1, y) + at(x + 1, y + 1)
                - at(x - 1, y - 1)
                - 2.0 * at(x - 1, y)
                - at(x - 1, y + 1))
                / 8.0;
            let d_down = (at(x - 1, y + 1) + 2.0 * at(x, y + 1) + at(x + 1, y + 1)
                - at(x - 1, y - 1)
                - 2.0 * at(x, y - 1)
                - at(x + 1, y - 1))
                / 8.0;
            let n = [-d_right * relief, d_down * relief, 1.0];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            Rgb(n.map(|c| ((c / len * 0.5 + 0.5) * 255.0).round().clamp(0.0, 255.0) as u8))
        })
    }
}

fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * t)
}

fn scale(c: [f32; 3], f: f32) -> [f32; 3] {
    c.map(|v| v * f)
}

/// Pits: a depth in `0..1` from round pits scattered over a `cells × cells` grid (wrapping).
fn pits(u: f32, v: f32, cells: i64, chance: f32, seed: u64) -> f32 {
    let (px, py) = (u * cells as f32, v * cells as f32);
    let (cx, cy) = (px.floor() as i64, py.floor() as i64);
    let mut depth: f32 = 0.0;
    for dy in -1..=1 {
        for dx in -1..=1 {
            let (gx, gy) = (cx + dx, cy + dy);
            let (wx, wy) = (gx.rem_euclid(cells), gy.rem_euclid(cells));
            if hash3(wx, wy, 1, seed) > chance {
                continue;
            }
            let sx = gx as f32 + hash3(wx, wy, 2, seed);
            let sy = gy as f32 + hash3(wx, wy, 3, seed);
            let radius = 0.12 + 0.3 * hash3(wx, wy, 4, seed);
            let d2 = (px - sx) * (px - sx) + (py - sy) * (py - sy);
            let t = 1.0 - d2 / (radius * radius);
            depth = depth.max(t.max(0.0));
        }
    }
    depth
}

const SAND_LIGHT: [f32; 3] = [0.86, 0.70, 0.49];
const SAND_OCHRE: [f32; 3] = [0.76, 0.52, 0.33];
const SAND_ROSE: [f32; 3] = [0.82, 0.60, 0.45];

/// Weathered sandstone: strata of uneven thickness along the image's rows (warped), broken
/// bedding lines, mottling, erosion, clustered pits and grain.
fn sandstone() -> Surface {
    Surface::new(STONE_SIZE, |u, v, x, y| {
        let warp = fbm2(u, v, 3, 3, 0.5, 11) - 0.5;
        let w = v + 0.05 * warp;
        // 10 strata per tile, their boundaries pushed about so they differ in thickness.
        let s = w * 10.0 + 0.8 * (value2xy(0.5, w * 5.0, 1, 5, 17) - 0.5);
        let layer = value2xy(0.5, s.floor() + 0.5, 1, 10, 12);
        let fine = value2xy(u * 6.0, w * 60.0, 6, 60, 13);
        let f = s.rem_euclid(1.0);
        let broken = smoothstep(0.35, 0.6, value2xy(u * 6.0, s, 6, 10, 18));
        let groove = (1.0 - smoothstep(0.0, 0.06, f.min(1.0 - f))) * broken;
        let erosion = fbm2(u, v, 4, 5, 0.6, 14);
        let mottle = fbm2(u + 0.3, v, 2, 4, 0.55, 19);
        let cluster = smoothstep(0.5, 0.75, fbm2(u, v, 3, 2, 0.5, 20));
        let pit = pits(u, v, 40, 0.5, 15) * cluster;
        let grain = hash3(i64::from(x), i64::from(y), 5, 16);
        let height = 0.6 * erosion + 0.1 * fine - 0.25 * groove - 0.7 * pit * pit + 0.06 * grain;
        let mut c = if layer < 0.5 {
            mix(SAND_OCHRE, SAND_ROSE, layer * 2.0)
        } else {
            mix(SAND_ROSE, SAND_LIGHT, (layer - 0.5) * 2.0)
        };
        c = mix(c, SAND_LIGHT, 0.35 * smoothstep(0.55, 0.8, erosion));
        c = scale(c, 0.8 + 0.32 * mottle + 0.08 * fine);
        c = scale(c, 1.0 - 0.12 * groove - 0.25 * pit);
        c = scale(c, 0.94 + 0.12 * grain);
        (height, c)
    })
}

const CARVED_BASE: [f32; 3] = [0.58, 0.38, 0.25];
const CARVED_DIRT: [f32; 3] = [0.33, 0.21, 0.14];

/// Darker carved stone: 2 × 2 cells per tile, each a raised frame around a sunken field with a
/// raised glyph (glyphs 0–3), worn by erosion and pits.
fn carved() -> Surface {
    Surface::new(STONE_SIZE, |u, v, x, y| {
        let (cu, cv) = ((u * 2.0).floor(), (v * 2.0).floor());
        let cell = (cv as usize) * 2 + cu as usize;
        // Cell-local coordinates in [-1, 1], y up.
        let lx = (u * 2.0 - cu) * 2.0 - 1.0;
        let ly = 1.0 - (v * 2.0 - cv) * 2.0;
        let square = lx.abs().max(ly.abs());
        let frame = smoothstep(0.97, 0.93, square) * smoothstep(0.8, 0.84, square);
        let glyph = glyphs::covers(cell, lx / 0.74, ly / 0.74);
        let raised = if glyph || frame > 0.5 { 1.0 } else { 0.0 };
        let erosion = fbm2(u, v, 8, 5, 0.55, 21);
        let pit = pits(u, v, 40, 0.35, 22) * smoothstep(0.5, 0.75, fbm2(u, v, 3, 2, 0.5, 24));
        let grain = hash3(i64::from(x), i64::from(y), 5, 23);
        let seam = if square > 0.985 { 1.0 } else { 0.0 };
        let height = 0.9 * raised + 0.3 * erosion - 0.5 * pit * pit - 0.6 * seam + 0.04 * grain;
        let mut c = mix(CARVED_DIRT, CARVED_BASE, 0.45 + 0.55 * raised);
        c = scale(c, 0.86 + 0.25 * erosion);
        c = scale(
            c,
            (1.0 - 0.3 * pit) * (1.0 - 0.5 * seam) * (0.95 + 0.1 * grain),
        );
        (height, c)
    })
}

/// Wind-rippled sand: ripples across the rows (warped), grains, a faint tone drift.
fn sand() -> Surface {
    Surface::new(SAND_SIZE, |u, v, x, y| {
        let warp = fbm2(u, v, 2, 3, 0.5, 31) - 0.5;
        let phase = (v * 18.0 + 3.0 * warp + u).rem_euclid(1.0);
        // An asymmetric ripple: a long windward slope, a short lee face.
        let ripple = if phase < 0.75 {
            phase / 0.75
        } else {
            (1.0 - phase) / 0.25
        };
        let ripple = smoothstep(0.0, 1.0, ripple);
        let tone = fbm2(u, v, 4, 3, 0.5, 32);
        let grain = hash3(i64::from(x), i64::from(y), 5, 33);
        let height = 0.6 * ripple + 0.08 * grain;
        let mut c = mix([0.80, 0.60, 0.39], [0.90, 0.74, 0.52], tone);
        c = scale(c, (0.97 + 0.05 * ripple) * (0.9 + 0.2 * grain));
        (height, c)
    })
}

/// Every texture as `(file stem, image)`, in a fixed order: colour then normal map of
/// sandstone, carved stone and sand.
pub fn textures() -> Vec<(&'static str, RgbImage)> {
    let (stone, carved, sand) = (sandstone(), carved(), sand());
    vec![
        ("sandstone", stone.color_image()),
        ("sandstone_normal", stone.normal_image(5.0)),
        ("carved", carved.color_image()),
        ("carved_normal", carved.normal_image(4.0)),
        ("sand", sand.color_image()),
        ("sand_normal", sand.normal_image(1.0)),
    ]
}
