//! The egui overlay drawn on the CPU into composed window pixels (the CPU tracer's present
//! path, `cpu_compose.rs`), as egui-wgpu draws it into a gamma-space target: per triangle,
//! vertex colour × texture (both premultiplied, gamma-encoded, interpolated in gamma space),
//! blended `dst = src + dst · (1 − src.a)`, clipped to the primitive's scissor rectangle.
//!
//! Why: on lavapipe the overlay's render pass cost about 59 ms of a 62 ms `queue.present` on
//! the 2-core machine under load; rasterised here (row spans, one source value for untextured
//! one-colour triangles, bands of rows on all cores) it costs a few milliseconds
//! (docs/PERFORMANCE.md, "Presenting the CPU tracer's film", `bench present`).
//!
//! Owns: [`CpuOverlay`]: CPU copies of egui's textures (font atlas, images) kept in step with
//! every overlay's texture changes, and the rasteriser. Render thread. Must not: run egui
//! (the main thread does) or touch the device.

use std::collections::HashMap;

use egui::epaint::Primitive;
use egui::{TextureId, TexturesDelta};
use rayon::prelude::*;

use super::cpu_overlay_raster::{Band, prepare};

use crate::commit::Overlay;

/// An egui texture on the CPU: gamma-encoded premultiplied RGBA in [0, 1] (the 8-bit values
/// over 255, divided once here rather than four times a sample), rows top to bottom.
pub(super) struct CpuTexture {
    size: [usize; 2],
    pixels: Vec<[f32; 4]>,
    nearest: bool,
}

impl CpuTexture {
    fn texel(&self, x: i64, y: i64) -> [f32; 4] {
        let x = x.clamp(0, self.size[0] as i64 - 1) as usize;
        let y = y.clamp(0, self.size[1] as i64 - 1) as usize;
        self.pixels[y * self.size[0] + x]
    }

    /// Clamped to the edge, bilinear unless the texture asks for nearest (egui's defaults).
    pub(super) fn sample(&self, u: f32, v: f32) -> [f32; 4] {
        let (x, y) = (u * self.size[0] as f32, v * self.size[1] as f32);
        if self.nearest {
            return self.texel(x.floor() as i64, y.floor() as i64);
        }
        let (x, y) = (x - 0.5, y - 0.5);
        let (bx, by) = (x.floor(), y.floor());
        let (tx, ty) = (x - bx, y - by);
        let (bx, by) = (bx as i64, by as i64);
        let [a, b, c, d] = [
            self.texel(bx, by),
            self.texel(bx + 1, by),
            self.texel(bx, by + 1),
            self.texel(bx + 1, by + 1),
        ];
        std::array::from_fn(|k| {
            let top = a[k] + (b[k] - a[k]) * tx;
            let bottom = c[k] + (d[k] - c[k]) * tx;
            top + (bottom - top) * ty
        })
    }
}

/// egui's textures on the CPU and the overlay rasteriser.
#[derive(Default)]
pub struct CpuOverlay {
    textures: HashMap<TextureId, CpuTexture>,
}

impl CpuOverlay {
    /// Applies the texture changes of `delta` (new textures and partial updates; frees come
    /// later, [`CpuOverlay::free`]).
    pub fn apply(&mut self, delta: &TexturesDelta) {
        for (id, change) in delta
            .set
            .iter()
            .flat_map(|(id, list)| list.iter().map(move |c| (id, c)))
        {
            let egui::ImageData::Color(image) = &change.image;
            let nearest = change.options.magnification == egui::TextureFilter::Nearest;
            let pixels: Vec<[f32; 4]> = image
                .pixels
                .iter()
                .map(|c| c.to_array().map(|c| c as f32 / 255.0))
                .collect();
            match change.pos {
                None => {
                    self.textures.insert(
                        *id,
                        CpuTexture {
                            size: image.size,
                            pixels,
                            nearest,
                        },
                    );
                }
                Some([x0, y0]) => {
                    let Some(t) = self.textures.get_mut(id) else {
                        continue;
                    };
                    for y in 0..image.size[1] {
                        for x in 0..image.size[0] {
                            let (tx, ty) = (x0 + x, y0 + y);
                            if tx < t.size[0] && ty < t.size[1] {
                                t.pixels[ty * t.size[0] + tx] = pixels[y * image.size[0] + x];
                            }
                        }
                    }
                }
            }
        }
    }

    /// Forgets the textures egui let go of in `delta`.
    pub fn free<'a>(&mut self, delta_free: impl IntoIterator<Item = &'a TextureId>) {
        for id in delta_free {
            self.textures.remove(id);
        }
    }

    /// Draws `overlay` over `pixels` (rows of 4-byte pixels of `size`, B, G, R, A when `bgra`
    /// else R, G, B, A, gamma-encoded). Each triangle is set up once (`cpu_overlay_raster.rs`),
    /// then bands of rows are drawn on rayon's threads, every band all its triangles in
    /// egui's order.
    pub fn draw(&self, pixels: &mut [u8], size: (u32, u32), bgra: bool, overlay: &Overlay) {
        let (w, h) = (size.0 as usize, size.1 as usize);
        if w == 0 || h == 0 || pixels.len() < w * h * 4 {
            return;
        }
        let mut triangles = Vec::new();
        let ppp = overlay.pixels_per_point.max(0.1);
        for clipped in &overlay.primitives {
            let Primitive::Mesh(mesh) = &clipped.primitive else {
                continue;
            };
            let Some(texture) = self.textures.get(&mesh.texture_id) else {
                continue;
            };
            prepare(mesh, texture, clipped.clip_rect, ppp, size, &mut triangles);
        }
        let (Some(top), Some(bottom)) = (
            triangles.iter().map(|t| t.rows.0).min(),
            triangles.iter().map(|t| t.rows.1).max(),
        ) else {
            return;
        };
        let order = if bgra { [2, 1, 0] } else { [0, 1, 2] };
        let band = BAND_ROWS * w * 4;
        pixels[..w * h * 4]
            .par_chunks_mut(band)
            .enumerate()
            .skip(top as usize / BAND_ROWS)
            .take((bottom as usize).div_ceil(BAND_ROWS) - top as usize / BAND_ROWS)
            .for_each(|(i, rows)| {
                let y0 = (i * BAND_ROWS) as i64;
                let y1 = y0 + (rows.len() / (w * 4)) as i64;
                let mut target = Band {
                    pixels: rows,
                    width: w as i64,
                    rows: (y0, y1),
                    order,
                };
                for t in &triangles {
                    t.draw(&mut target);
                }
            });
    }
}

/// Window rows a rayon task draws.
const BAND_ROWS: usize = 16;
