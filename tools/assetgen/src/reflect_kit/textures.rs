//! The Reflect kit's surface textures, drawn by code: panel faces with seams, bolts and faint
//! grime, the floor tile grid, brushed dark metal and the elevator's hazard-striped deck.
//! The sign textures are drawn in `signs`.
//!
//! Output: 8-bit sRGB RGB images and their PNG bytes ([`png_bytes`]). Deterministic: noise is
//! an integer hash of the texel position and a seed (no floating-point transcendental
//! functions), and PNG encoding uses fixed settings of the `image` crate.
//! Must not: write files (the caller does).

use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use image::{ImageEncoder, Rgb, RgbImage};

/// Every texture of this module as `(file stem, image)`, in a fixed order.
pub fn surface_textures() -> Vec<(&'static str, RgbImage)> {
    vec![
        ("panel_dark", panel_dark()),
        ("panel_white", panel_white()),
        ("floor_tile", floor_tile()),
        ("metal_dark", metal_dark()),
        ("hazard_deck", hazard_deck()),
    ]
}

/// `image` as PNG bytes (best compression, adaptive filters: fixed settings, fixed output).
pub fn png_bytes(image: &RgbImage) -> anyhow::Result<Vec<u8>> {
    let mut out = Vec::new();
    PngEncoder::new_with_quality(&mut out, CompressionType::Best, FilterType::Adaptive)
        .write_image(
            image.as_raw(),
            image.width(),
            image.height(),
            image::ExtendedColorType::Rgb8,
        )?;
    Ok(out)
}

/// A hash of `(x, y, seed)` to `0..1`.
pub(crate) fn hash01(x: i64, y: i64, seed: u64) -> f32 {
    let mut h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ seed.wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^= h >> 31;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 29;
    (h >> 40) as f32 / (1u64 << 24) as f32
}

/// Smooth value noise in `0..1` with cells of `cell` texels, tiling every `period` texels.
pub(crate) fn value_noise(x: u32, y: u32, cell: u32, period: u32, seed: u64) -> f32 {
    let cells = (period / cell).max(1) as i64;
    let (cx, cy) = ((x / cell) as i64, (y / cell) as i64);
    let fx = (x % cell) as f32 / cell as f32;
    let fy = (y % cell) as f32 / cell as f32;
    let corner = |dx: i64, dy: i64| hash01((cx + dx) % cells, (cy + dy) % cells, seed);
    let smooth = |t: f32| t * t * (3.0 - 2.0 * t);
    let (sx, sy) = (smooth(fx), smooth(fy));
    let top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * sx;
    let bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * sx;
    top + (bottom - top) * sy
}

/// `grey` scaled by `factor` (per channel, clamped to 0..255).
pub(crate) fn shade(color: [u8; 3], factor: f32) -> Rgb<u8> {
    Rgb(color.map(|c| (f32::from(c) * factor).round().clamp(0.0, 255.0) as u8))
}

/// Grime: two octaves of value noise, darker towards the bottom of the image.
fn grime(x: u32, y: u32, size: u32, seed: u64, amount: f32) -> f32 {
    let n = 0.65 * value_noise(x, y, 32, size, seed) + 0.35 * value_noise(x, y, 8, size, seed + 1);
    let low = y as f32 / size as f32;
    1.0 - amount * (n * 0.7 + 0.3 * low * low)
}

/// Distance in texels from `(x, y)` to the nearest image edge.
fn edge_distance(x: u32, y: u32, size: u32) -> u32 {
    x.min(y).min(size - 1 - x).min(size - 1 - y)
}

/// One 2 m dark metal wall panel: a darker rim (the bevel), an inset groove line with a lit
/// lower lip, four bolts, and grime.
fn panel_dark() -> RgbImage {
    const SIZE: u32 = 256;
    const BASE: [u8; 3] = [92, 96, 102];
    RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let d = edge_distance(x, y, SIZE);
        let mut f = grime(x, y, SIZE, 11, 0.16);
        if d < 3 {
            f *= 0.55;
        } else if d == 18 {
            f *= 0.45;
        } else if d == 19 {
            f *= 1.25;
        }
        // A horizontal service line across the middle (a panel-in-panel look).
        if y == SIZE / 2 || y == SIZE / 2 + 1 {
            f *= if y == SIZE / 2 { 0.6 } else { 1.15 };
        }
        for (bx, by) in [
            (30, 30),
            (SIZE - 31, 30),
            (30, SIZE - 31),
            (SIZE - 31, SIZE - 31),
        ] {
            let r2 = (x as i64 - bx as i64).pow(2) + (y as i64 - by as i64).pow(2);
            if r2 <= 9 {
                f *= 1.5;
            } else if r2 <= 20 {
                f *= 0.5;
            }
        }
        shade(BASE, f)
    })
}

/// The white mirrorable panel (and ceiling panels): off-white, a faint grey border and a faint
/// inner line, very light grime.
fn panel_white() -> RgbImage {
    const SIZE: u32 = 256;
    const BASE: [u8; 3] = [236, 236, 232];
    RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let d = edge_distance(x, y, SIZE);
        let mut f = grime(x, y, SIZE, 23, 0.05);
        if d < 3 {
            f *= 0.82;
        } else if d == 12 {
            f *= 0.9;
        }
        shade(BASE, f)
    })
}

/// One 2 m floor tile: 4 × 4 sub-tiles (0.5 m) with dark grout lines, each sub-tile a
/// slightly different grey, grime.
fn floor_tile() -> RgbImage {
    const SIZE: u32 = 256;
    const BASE: [u8; 3] = [128, 130, 134];
    const SUB: u32 = SIZE / 4;
    RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let (sx, sy) = (x % SUB, y % SUB);
        let line = sx < 2 || sy < 2 || sx >= SUB - 1 || sy >= SUB - 1;
        let tone = 0.94 + 0.08 * hash01(i64::from(x / SUB), i64::from(y / SUB), 31);
        let mut f = tone * grime(x, y, SIZE, 37, 0.18);
        if line {
            f *= 0.55;
        }
        if edge_distance(x, y, SIZE) < 3 {
            f *= 0.7;
        }
        shade(BASE, f)
    })
}

/// Brushed dark metal for trims, frames and housings (tiles every texture width; mapped at
/// 1 m per tile): horizontal streaks.
fn metal_dark() -> RgbImage {
    const SIZE: u32 = 128;
    const BASE: [u8; 3] = [70, 73, 78];
    RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let streak = value_noise(x / 16, y, 1, SIZE / 16, 41);
        let fine = hash01(i64::from(x / 4), i64::from(y), 43);
        shade(BASE, 0.88 + 0.16 * streak + 0.05 * fine)
    })
}

/// The elevator's 3 m deck, mapped 0..1 across its top: a yellow-black hazard border (0.25 m)
/// and a dark metal grate in the middle with a 0.25 m grid.
fn hazard_deck() -> RgbImage {
    const SIZE: u32 = 256;
    const BORDER: u32 = 22;
    const YELLOW: [u8; 3] = [236, 184, 24];
    const BLACK: [u8; 3] = [28, 28, 30];
    const GRATE: [u8; 3] = [74, 77, 82];
    RgbImage::from_fn(SIZE, SIZE, |x, y| {
        let d = edge_distance(x, y, SIZE);
        let g = grime(x, y, SIZE, 53, 0.15);
        if d < 2 || d == BORDER || d == BORDER + 1 {
            return shade(BLACK, 1.0);
        }
        if d < BORDER {
            let stripe = ((x + y) / 12) % 2 == 0;
            return shade(if stripe { YELLOW } else { BLACK }, g);
        }
        let cell = SIZE / 12;
        let grid = x % cell == 0 || y % cell == 0;
        shade(GRATE, if grid { 0.55 * g } else { g })
    })
}
