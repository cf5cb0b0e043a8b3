//! The CPU overlay as it was before 2026-12-06's present work (`bench present`'s reference):
//! `render::present::CpuOverlay` at commit 4c2b644 (one thread, each triangle set up and
//! drawn in turn), kept verbatim but for its name, so that the bench times the old and the new
//! rasteriser in one run and checks that they give the same bytes.
//!
//! Owns: nothing the engine uses. Must not: change (it is the before of the table).

use std::collections::HashMap;

use egui::epaint::{Primitive, Vertex};
use egui::{TextureId, TexturesDelta};

use candela::commit::Overlay;

/// An egui texture on the CPU: gamma-encoded premultiplied RGBA, rows top to bottom.
struct CpuTexture {
    size: [usize; 2],
    pixels: Vec<[u8; 4]>,
    nearest: bool,
}

impl CpuTexture {
    fn texel(&self, x: i64, y: i64) -> [f32; 4] {
        let x = x.clamp(0, self.size[0] as i64 - 1) as usize;
        let y = y.clamp(0, self.size[1] as i64 - 1) as usize;
        self.pixels[y * self.size[0] + x].map(|c| c as f32 / 255.0)
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
pub struct ReferenceOverlay {
    textures: HashMap<TextureId, CpuTexture>,
}

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

impl ReferenceOverlay {
    /// Applies the texture changes of `delta` (new textures and partial updates; frees come
    /// later, `CpuOverlay::free`).
    pub fn apply(&mut self, delta: &TexturesDelta) {
        for (id, change) in delta
            .set
            .iter()
            .flat_map(|(id, list)| list.iter().map(move |c| (id, c)))
        {
            let egui::ImageData::Color(image) = &change.image;
            let nearest = change.options.magnification == egui::TextureFilter::Nearest;
            let pixels: Vec<[u8; 4]> = image.pixels.iter().map(|c| c.to_array()).collect();
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
    /// else R, G, B, A, gamma-encoded).
    pub fn draw(&self, pixels: &mut [u8], size: (u32, u32), bgra: bool, overlay: &Overlay) {
        let ppp = overlay.pixels_per_point.max(0.1);
        let (w, h) = (size.0 as i64, size.1 as i64);
        for clipped in &overlay.primitives {
            let Primitive::Mesh(mesh) = &clipped.primitive else {
                continue;
            };
            let Some(texture) = self.textures.get(&mesh.texture_id) else {
                continue;
            };
            // The scissor rectangle egui-wgpu sets: rounded to pixels, inside the target.
            let clip = clipped.clip_rect;
            let x_lo = ((clip.min.x * ppp).round() as i64).clamp(0, w);
            let y_lo = ((clip.min.y * ppp).round() as i64).clamp(0, h);
            let x_hi = ((clip.max.x * ppp).round() as i64).clamp(0, w);
            let y_hi = ((clip.max.y * ppp).round() as i64).clamp(0, h);
            if x_lo >= x_hi || y_lo >= y_hi {
                continue;
            }
            for tri in mesh.indices.chunks_exact(3) {
                let Some(v) = tri
                    .iter()
                    .map(|&i| mesh.vertices.get(i as usize).copied())
                    .collect::<Option<Vec<Vertex>>>()
                else {
                    continue;
                };
                let mut v = [v[0], v[1], v[2]];
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
                let ties = [
                    owns_ties(p[1], p[2]),
                    owns_ties(p[2], p[0]),
                    owns_ties(p[0], p[1]),
                ];
                let colors = v.map(|v| v.color.to_array().map(|c| c as f32 / 255.0));
                // Untextured shapes (egui's white texel) with one colour: one source value.
                let same_uv = v[1].uv == v[0].uv && v[2].uv == v[0].uv;
                let same_color = v[1].color == v[0].color && v[2].color == v[0].color;
                let constant = (same_uv && same_color).then(|| {
                    let tex = texture.sample(v[0].uv.x, v[0].uv.y);
                    std::array::from_fn::<f32, 4, _>(|k| colors[0][k] * tex[k])
                });
                if constant.is_some_and(|c| c == [0.0; 4]) {
                    continue;
                }
                let order = if bgra { [2, 1, 0] } else { [0, 1, 2] };
                let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
                for y in y0..y1 {
                    let cy = y as f32 + 0.5;
                    // The row's span: each edge function is linear in x; a pixel more on
                    // each side, the exact test below decides.
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
                    for x in sx0..sx1 {
                        let c = [x as f32 + 0.5, cy];
                        let e = [
                            edge(p[1], p[2], c),
                            edge(p[2], p[0], c),
                            edge(p[0], p[1], c),
                        ];
                        if (0..3).any(|k| e[k] < 0.0 || (e[k] == 0.0 && !ties[k])) {
                            continue;
                        }
                        let src = match constant {
                            Some(src) => src,
                            None => {
                                let l = e.map(|e| e / area);
                                let u = l[0] * v[0].uv.x + l[1] * v[1].uv.x + l[2] * v[2].uv.x;
                                let t = l[0] * v[0].uv.y + l[1] * v[1].uv.y + l[2] * v[2].uv.y;
                                let tex = texture.sample(u, t);
                                std::array::from_fn(|k| {
                                    (l[0] * colors[0][k]
                                        + l[1] * colors[1][k]
                                        + l[2] * colors[2][k])
                                        * tex[k]
                                })
                            }
                        };
                        let at = ((y * w + x) * 4) as usize;
                        let px = &mut pixels[at..at + 4];
                        for (k, &o) in order.iter().enumerate() {
                            let dst = px[o] as f32 / 255.0;
                            let out = src[k] + dst * (1.0 - src[3]);
                            px[o] = (out.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
                        }
                    }
                }
            }
        }
    }
}
