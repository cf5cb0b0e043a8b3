//! The present pass's upscale, shown: a 320×180 film (chamber 1's converged picture from
//! `docs/reflect/chamber_1.png`, box-filtered down to the internal resolution Reflect traces at
//! in a 1280×720 window) upscaled to 1280×720 by the bilinear filter the present pass used until
//! 2026-12-06 and by its Catmull-Rom bicubic now (`render::present::compose_host_film`). Writes
//! `docs/upscale.png`: the same crop of both, bilinear left, bicubic right, each pixel shown 2×;
//! and `docs/present_upscale.png`: nearest (each film pixel a 4×4 block) left, bicubic right.
//!
//! Also prints the compose's median time. Run:
//! `cargo run --release -p candela --example upscale_compare`. Units: linear radiance in
//! the film, sRGB 8-bit in the files.

use anyhow::Context;
use candela::render::film::{Film, TonemapSettings, linear_to_srgb8};
use candela::render::present::compose_host_film;
use glam::Vec3;

/// sRGB 8-bit → linear.
fn linear(v: u8) -> f32 {
    let c = f32::from(v) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The old present filter: bilinear with clamped edges, centres mapped as the shader maps them.
fn bilinear(film: &Film, w: u32, h: u32, tonemap: &TonemapSettings) -> Vec<u8> {
    let (fw, fh) = (film.width as i32, film.height as i32);
    let texel = |x: i32, y: i32| film.mean[(y.clamp(0, fh - 1) * fw + x.clamp(0, fw - 1)) as usize];
    let mut out = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let fx = (x as f32 + 0.5) * fw as f32 / w as f32 - 0.5;
            let fy = (y as f32 + 0.5) * fh as f32 / h as f32 - 0.5;
            let (bx, by) = (fx.floor(), fy.floor());
            let (tx, ty) = (fx - bx, fy - by);
            let (bx, by) = (bx as i32, by as i32);
            let top = texel(bx, by).lerp(texel(bx + 1, by), tx);
            let bottom = texel(bx, by + 1).lerp(texel(bx + 1, by + 1), tx);
            let [r, g, b] = linear_to_srgb8(top.lerp(bottom, ty), tonemap);
            out.extend_from_slice(&[r, g, b, 255]);
        }
    }
    out
}

/// Nearest: each window pixel shows the film pixel its centre falls in.
fn nearest(film: &Film, w: u32, h: u32, tonemap: &TonemapSettings) -> Vec<u8> {
    let mut out = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let fx = ((x as f32 + 0.5) * film.width as f32 / w as f32) as u32;
            let fy = ((y as f32 + 0.5) * film.height as f32 / h as f32) as u32;
            let c =
                film.mean[(fy.min(film.height - 1) * film.width + fx.min(film.width - 1)) as usize];
            let [r, g, b] = linear_to_srgb8(c, tonemap);
            out.extend_from_slice(&[r, g, b, 255]);
        }
    }
    out
}

/// The same crop (`cx`, `cy`, `cw`×`ch` window pixels) of `left` and `right` (RGBA rows of a
/// window `w` wide), each pixel shown 2×, side by side with an 8-pixel gap.
fn side_by_side(left: &[u8], right: &[u8], w: u32, crop: (u32, u32, u32, u32)) -> image::RgbImage {
    let (cx, cy, cw, ch) = crop;
    let mut out = image::RgbImage::new(cw * 4 + 8, ch * 2);
    for (k, pixels) in [left, right].iter().enumerate() {
        for y in 0..ch * 2 {
            for x in 0..cw * 2 {
                let i = (((cy + y / 2) * w + cx + x / 2) * 4) as usize;
                let px = image::Rgb([pixels[i], pixels[i + 1], pixels[i + 2]]);
                out.put_pixel(k as u32 * (cw * 2 + 8) + x, y, px);
            }
        }
    }
    out
}

fn main() -> anyhow::Result<()> {
    let repo = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let source = repo.join("docs/reflect/chamber_1.png");
    let picture = image::open(&source)
        .with_context(|| format!("reading {}", source.display()))?
        .to_rgb8();
    let (sw, sh) = picture.dimensions();
    let (fw, fh) = (320u32, 180u32);
    let mut film = Film::new(fw, fh);
    for y in 0..fh {
        for x in 0..fw {
            // Box filter over the source pixels this film pixel covers.
            let (x0, x1) = (x * sw / fw, ((x + 1) * sw / fw).max(x * sw / fw + 1));
            let (y0, y1) = (y * sh / fh, ((y + 1) * sh / fh).max(y * sh / fh + 1));
            let mut sum = Vec3::ZERO;
            for sy in y0..y1 {
                for sx in x0..x1 {
                    let p = picture.get_pixel(sx, sy).0;
                    sum += Vec3::new(linear(p[0]), linear(p[1]), linear(p[2]));
                }
            }
            film.mean[(y * fw + x) as usize] = sum / ((x1 - x0) * (y1 - y0)) as f32;
        }
    }
    let tonemap = TonemapSettings::default();
    let (w, h) = (1280u32, 720u32);
    let old = bilinear(&film, w, h, &tonemap);
    let new = compose_host_film(&film, (w, h), &tonemap, false);
    // The compose's time (both cores, rayon): median of 21 runs.
    let mut ms: Vec<f64> = (0..21)
        .map(|_| {
            let started = std::time::Instant::now();
            std::hint::black_box(compose_host_film(&film, (w, h), &tonemap, true));
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    ms.sort_by(f64::total_cmp);
    println!(
        "compose 320×180 → 1280×720 (bicubic, tonemap, sRGB): median {:.2} ms",
        ms[10]
    );
    // The door and the plate: 320×180 window pixels, shown 2×.
    let crop = (480u32, 240u32, 320u32, 180u32);
    let out = side_by_side(&old, &new, w, crop);
    let path = repo.join("docs/upscale.png");
    out.save(&path)
        .with_context(|| format!("writing {}", path.display()))?;
    println!("wrote {}", path.display());
    let path = repo.join("docs/present_upscale.png");
    side_by_side(&nearest(&film, w, h, &tonemap), &new, w, crop)
        .save(&path)
        .with_context(|| format!("writing {}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}
