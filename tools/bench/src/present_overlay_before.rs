//! The CPU overlay as it was on 2026-12-07 before the exact spans and the faster blend
//! (`bench present`'s "before" of that change): `render::present::CpuOverlay` and its
//! rasteriser at commit 8f10f79, kept verbatim but for names and visibility, so that the
//! bench times it beside the new code in one run.
//!
//! Owns: nothing the engine uses. Must not: change (it is the before of the table).

use std::collections::HashMap;

use egui::epaint::{Mesh, Primitive, Vertex};
use egui::{TextureId, TexturesDelta};
use rayon::prelude::*;

use candela::commit::Overlay;

/// An egui texture on the CPU: gamma-encoded premultiplied RGBA in [0, 1] (the 8-bit values
/// over 255, divided once here rather than four times a sample), rows top to bottom.
struct CpuTexture {
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
    fn sample(&self, u: f32, v: f32) -> [f32; 4] {
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
pub struct BeforeOverlay {
    textures: HashMap<TextureId, CpuTexture>,
}

impl BeforeOverlay {
    /// Applies the texture changes of `delta` (new textures and partial updates; frees come
    /// later, `BeforeOverlay::free`).
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

// ---- the rasteriser (`cpu_overlay_raster.rs` at 8f10f79) ----

/// Edge function of `p` against edge `a → b` (positive inside a counter-clockwise triangle
/// in y-down pixels after the winding is normalised).
fn edge(a: [f32; 2], b: [f32; 2], p: [f32; 2]) -> f32 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// Whether a pixel centre exactly on edge `a → b` belongs to this triangle: of two triangles
/// sharing the edge (traversing it in opposite directions) exactly one takes it, so a
/// translucent quad's diagonal is not blended twice.
fn owns_ties(a: [f32; 2], b: [f32; 2]) -> bool {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    dy < 0.0 || (dy == 0.0 && dx > 0.0)
}

/// Where a triangle's source value comes from.
#[derive(Clone, Copy)]
enum Source {
    /// One value everywhere (one colour, one texel): egui's plain shapes.
    Constant([f32; 4]),
    /// One texel, colours interpolated: egui's anti-aliasing feathers and shadows.
    Texel([f32; 4]),
    /// Texture sampled per pixel: glyphs and images.
    Sampled,
}

/// One triangle ready to draw, in window pixels (y down).
struct Triangle<'a> {
    texture: &'a CpuTexture,
    p: [[f32; 2]; 3],
    area: f32,
    uv: [[f32; 2]; 3],
    colors: [[f32; 4]; 3],
    ties: [bool; 3],
    source: Source,
    /// Columns `[x0, x1)` and rows `[y0, y1)` it may touch, inside the scissor rectangle.
    columns: (i64, i64),
    rows: (i64, i64),
}

/// A band of window rows to draw into: `pixels` holds rows `rows.0 .. rows.1` of a window
/// `width` pixels wide; `order` maps R, G, B to byte positions.
struct Band<'a> {
    pub pixels: &'a mut [u8],
    pub width: i64,
    pub rows: (i64, i64),
    pub order: [usize; 3],
}

/// Appends the triangles of `mesh` (egui points; `ppp` pixels per point) that can touch the
/// window of `size` pixels inside `clip` (egui points, rounded to pixels as egui-wgpu's
/// scissor) to `out`. Degenerate, non-finite and fully transparent constant ones are dropped.
fn prepare<'a>(
    mesh: &Mesh,
    texture: &'a CpuTexture,
    clip: egui::Rect,
    ppp: f32,
    size: (u32, u32),
    out: &mut Vec<Triangle<'a>>,
) {
    let (w, h) = (size.0 as i64, size.1 as i64);
    let x_lo = ((clip.min.x * ppp).round() as i64).clamp(0, w);
    let y_lo = ((clip.min.y * ppp).round() as i64).clamp(0, h);
    let x_hi = ((clip.max.x * ppp).round() as i64).clamp(0, w);
    let y_hi = ((clip.max.y * ppp).round() as i64).clamp(0, h);
    if x_lo >= x_hi || y_lo >= y_hi {
        return;
    }
    for tri in mesh.indices.chunks_exact(3) {
        let vertex = |k: usize| mesh.vertices.get(tri[k] as usize).copied();
        let (Some(a), Some(b), Some(c)) = (vertex(0), vertex(1), vertex(2)) else {
            continue;
        };
        let mut v: [Vertex; 3] = [a, b, c];
        let pos = |v: &Vertex| [v.pos.x * ppp, v.pos.y * ppp];
        let mut p = [pos(&v[0]), pos(&v[1]), pos(&v[2])];
        let mut area = edge(p[0], p[1], p[2]);
        if area < 0.0 {
            v.swap(1, 2);
            p.swap(1, 2);
            area = -area;
        }
        if !(area > 0.0 && area.is_finite()) {
            continue;
        }
        let min_x = p.iter().map(|q| q[0]).fold(f32::INFINITY, f32::min);
        let max_x = p.iter().map(|q| q[0]).fold(f32::NEG_INFINITY, f32::max);
        let min_y = p.iter().map(|q| q[1]).fold(f32::INFINITY, f32::min);
        let max_y = p.iter().map(|q| q[1]).fold(f32::NEG_INFINITY, f32::max);
        let x0 = ((min_x - 0.5).floor() as i64).max(x_lo);
        let x1 = ((max_x - 0.5).ceil() as i64 + 1).min(x_hi);
        let y0 = ((min_y - 0.5).floor() as i64).max(y_lo);
        let y1 = ((max_y - 0.5).ceil() as i64 + 1).min(y_hi);
        if x0 >= x1 || y0 >= y1 {
            continue;
        }
        let colors = v.map(|v| v.color.to_array().map(|c| c as f32 / 255.0));
        let same_uv = v[1].uv == v[0].uv && v[2].uv == v[0].uv;
        let same_color = v[1].color == v[0].color && v[2].color == v[0].color;
        let source = if same_uv {
            let tex = texture.sample(v[0].uv.x, v[0].uv.y);
            if same_color {
                let src = std::array::from_fn(|k| colors[0][k] * tex[k]);
                if src == [0.0; 4] {
                    continue;
                }
                Source::Constant(src)
            } else {
                Source::Texel(tex)
            }
        } else {
            Source::Sampled
        };
        out.push(Triangle {
            texture,
            p,
            area,
            uv: v.map(|v| [v.uv.x, v.uv.y]),
            colors,
            ties: [
                owns_ties(p[1], p[2]),
                owns_ties(p[2], p[0]),
                owns_ties(p[0], p[1]),
            ],
            source,
            columns: (x0, x1),
            rows: (y0, y1),
        });
    }
}

impl Triangle<'_> {
    /// Blends the triangle into the rows of `band` it covers.
    fn draw(&self, band: &mut Band<'_>) {
        let (y0, y1) = (self.rows.0.max(band.rows.0), self.rows.1.min(band.rows.1));
        let (x0, x1) = self.columns;
        let p = self.p;
        let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
        // A constant source blends each 8-bit value the same way: a table per channel when
        // the triangle is large enough to repay building it (same arithmetic, same bytes).
        let table = match self.source {
            Source::Constant(src) if (y1 - y0) * (x1 - x0) > 1024 => {
                Some(std::array::from_fn::<[u8; 256], 3, _>(|k| {
                    std::array::from_fn(|d| blend(src[k], src[3], d as u8))
                }))
            }
            _ => None,
        };
        for y in y0..y1 {
            let cy = y as f32 + 0.5;
            // The row's span: each edge function is linear in x; a pixel more on each side,
            // the exact test below decides.
            let (mut lo, mut hi) = (x0 as f32, x1 as f32);
            for (a, b) in edges {
                let slope = -(b[1] - a[1]);
                let at_zero = (b[0] - a[0]) * (cy - a[1]) + (b[1] - a[1]) * a[0];
                if slope > 0.0 {
                    lo = lo.max(-at_zero / slope - 0.5 - 1.0);
                } else if slope < 0.0 {
                    hi = hi.min(-at_zero / slope - 0.5 + 2.0);
                } else if at_zero < 0.0 {
                    hi = lo;
                }
            }
            let (sx0, sx1) = ((lo.floor() as i64).max(x0), (hi.ceil() as i64).min(x1));
            let row = ((y - band.rows.0) * band.width * 4) as usize;
            for x in sx0..sx1 {
                let c = [x as f32 + 0.5, cy];
                let e = [
                    edge(p[1], p[2], c),
                    edge(p[2], p[0], c),
                    edge(p[0], p[1], c),
                ];
                if (0..3).any(|k| e[k] < 0.0 || (e[k] == 0.0 && !self.ties[k])) {
                    continue;
                }
                let at = row + (x * 4) as usize;
                let Some(px) = band.pixels.get_mut(at..at + 4) else {
                    continue;
                };
                if let Some(table) = &table {
                    for (k, &o) in band.order.iter().enumerate() {
                        px[o] = table[k][px[o] as usize];
                    }
                    continue;
                }
                let src = self.source_at(e);
                for (k, &o) in band.order.iter().enumerate() {
                    px[o] = blend(src[k], src[3], px[o]);
                }
            }
        }
    }

    /// The premultiplied source at a pixel whose edge functions are `e`.
    fn source_at(&self, e: [f32; 3]) -> [f32; 4] {
        let colors = &self.colors;
        let l = e.map(|e| e / self.area);
        let tex = match self.source {
            Source::Constant(src) => return src,
            Source::Texel(tex) => tex,
            Source::Sampled => {
                let uv = &self.uv;
                let u = l[0] * uv[0][0] + l[1] * uv[1][0] + l[2] * uv[2][0];
                let t = l[0] * uv[0][1] + l[1] * uv[1][1] + l[2] * uv[2][1];
                self.texture.sample(u, t)
            }
        };
        std::array::from_fn(|k| {
            (l[0] * colors[0][k] + l[1] * colors[1][k] + l[2] * colors[2][k]) * tex[k]
        })
    }
}

/// One channel blended: `src + dst · (1 − alpha)` in [0, 1], back to 8 bits.
fn blend(src: f32, alpha: f32, dst: u8) -> u8 {
    let out = src + dst as f32 / 255.0 * (1.0 - alpha);
    (out.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}
