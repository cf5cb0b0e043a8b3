//! The CPU overlay's triangles (`cpu_overlay.rs`): set up once per frame ([`prepare`]: pixel
//! positions, winding, scissor, bounding rows and columns, one source value where it cannot
//! vary) and drawn into a band of window rows ([`Triangle::draw`]), as egui-wgpu draws into a
//! gamma-space target: vertex colour × texture (premultiplied, gamma-encoded, interpolated in
//! gamma space), `dst = src + dst · (1 − src.a)`, pixel centres on shared edges taken once.
//!
//! Owns: the per-triangle setup and the span loop. Any thread (bands run on rayon's workers).
//! Must not: keep state between frames or touch the device.

use egui::epaint::{Mesh, Vertex};

use super::cpu_overlay::CpuTexture;

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
pub(super) struct Triangle<'a> {
    texture: &'a CpuTexture,
    p: [[f32; 2]; 3],
    area: f32,
    uv: [[f32; 2]; 3],
    colors: [[f32; 4]; 3],
    ties: [bool; 3],
    source: Source,
    /// A constant source's blend of every 8-bit value, per channel, for triangles large
    /// enough to repay it (the same arithmetic as [`blend`], so the same bytes).
    table: Option<Box<[[u8; 256]; 3]>>,
    /// Columns `[x0, x1)` and rows `[y0, y1)` it may touch, inside the scissor rectangle.
    columns: (i64, i64),
    pub(super) rows: (i64, i64),
}

/// A band of window rows to draw into: `pixels` holds rows `rows.0 .. rows.1` of a window
/// `width` pixels wide; `order` maps R, G, B to byte positions.
pub(super) struct Band<'a> {
    pub pixels: &'a mut [u8],
    pub width: i64,
    pub rows: (i64, i64),
    pub order: [usize; 3],
}

/// Appends the triangles of `mesh` (egui points; `ppp` pixels per point) that can touch the
/// window of `size` pixels inside `clip` (egui points, rounded to pixels as egui-wgpu's
/// scissor) to `out`. Degenerate, non-finite and fully transparent constant ones are dropped.
pub(super) fn prepare<'a>(
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
        let table = match source {
            Source::Constant(src) if (y1 - y0) * (x1 - x0) > 1024 => {
                Some(Box::new(std::array::from_fn(|k| {
                    std::array::from_fn(|d| blend(src[k], src[3], d as u8))
                })))
            }
            _ => None,
        };
        out.push(Triangle {
            texture,
            table,
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
    /// Whether the pixel centre `c` is inside: every edge function positive, or zero on an
    /// edge this triangle owns.
    #[inline(always)]
    fn covers(&self, c: [f32; 2]) -> Option<[f32; 3]> {
        let p = self.p;
        let e = [
            edge(p[1], p[2], c),
            edge(p[2], p[0], c),
            edge(p[0], p[1], c),
        ];
        let out = (0..3).any(|k| e[k] < 0.0 || (e[k] == 0.0 && !self.ties[k]));
        (!out).then_some(e)
    }

    /// Blends the triangle into the rows of `band` it covers.
    ///
    /// Along a row each edge function is monotone in x (each float operation in `edge` is
    /// monotone in the pixel centre), so the pixels that pass the exact test form one run:
    /// it is found by testing inwards from the row's estimated span, and its interior is
    /// drawn without tests. The same pixels as testing each one, so the same bytes.
    pub(super) fn draw(&self, band: &mut Band<'_>) {
        let (y0, y1) = (self.rows.0.max(band.rows.0), self.rows.1.min(band.rows.1));
        let (x0, x1) = self.columns;
        let p = self.p;
        let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
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
            let (mut sx0, mut sx1) = ((lo.floor() as i64).max(x0), (hi.ceil() as i64).min(x1));
            let centre = |x: i64| [x as f32 + 0.5, cy];
            while sx0 < sx1 && self.covers(centre(sx0)).is_none() {
                sx0 += 1;
            }
            while sx1 > sx0 && self.covers(centre(sx1 - 1)).is_none() {
                sx1 -= 1;
            }
            if sx0 >= sx1 {
                continue;
            }
            let row = ((y - band.rows.0) * band.width * 4) as usize;
            let Some(run) = band
                .pixels
                .get_mut(row + (sx0 * 4) as usize..row + (sx1 * 4) as usize)
            else {
                continue;
            };
            let (order, unit) = (band.order, unit());
            match (&self.table, self.source) {
                (Some(table), _) => {
                    for px in run.chunks_exact_mut(4) {
                        for (k, &o) in order.iter().enumerate() {
                            px[o] = table[k][px[o] as usize];
                        }
                    }
                }
                (None, Source::Constant(src)) => {
                    for px in run.chunks_exact_mut(4) {
                        blend_pixel(src, order, unit, px);
                    }
                }
                // A transparent texel leaves every pixel (as `source_at`'s `None`).
                (None, Source::Texel(tex)) if tex == [0.0; 4] => {}
                (None, Source::Texel(tex)) => self.texel_run(tex, cy, sx0, order, run),
                (None, _) => {
                    for (px, x) in run.chunks_exact_mut(4).zip(sx0..) {
                        let c = centre(x);
                        let e = [
                            edge(p[1], p[2], c),
                            edge(p[2], p[0], c),
                            edge(p[0], p[1], c),
                        ];
                        // A transparent source leaves the pixel as it is (`blend` of 0 over
                        // any byte gives that byte; tested), so glyphs' empty texels cost
                        // no blend.
                        if let Some(src) = self.source_at(e) {
                            blend_pixel(src, order, unit, px);
                        }
                    }
                }
            }
        }
    }

    /// A run of a [`Source::Texel`] triangle (egui's gradients, the menus' top shade, the
    /// anti-aliasing feathers) from column `x0` of the row whose centres are at `cy`, the
    /// texel `tex` not transparent: [`Triangle::source_at`]'s arithmetic for [`RUN_LANES`]
    /// pixels at a time in arrays the compiler vectorises (each edge function's product that
    /// depends only on the row computed once, the same value), then [`blend_pixel`] per
    /// pixel. The same operations in the same order per pixel, so the same bytes.
    fn texel_run(&self, tex: [f32; 4], cy: f32, x0: i64, order: [usize; 3], run: &mut [u8]) {
        let p = self.p;
        let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
        // edge(a, b, c) = (b.x − a.x)(c.y − a.y) − (b.y − a.y)(c.x − a.x).
        let row = edges.map(|(a, b)| (b[0] - a[0]) * (cy - a[1]));
        let dy = edges.map(|(a, b)| b[1] - a[1]);
        let ax = edges.map(|(a, _)| a[0]);
        let (area, colors, unit) = (self.area, &self.colors, unit());
        let source = |cx: f32| -> [f32; 4] {
            let l: [f32; 3] = std::array::from_fn(|k| (row[k] - dy[k] * (cx - ax[k])) / area);
            std::array::from_fn(|c| {
                (l[0] * colors[0][c] + l[1] * colors[1][c] + l[2] * colors[2][c]) * tex[c]
            })
        };
        // Window columns are far below 2²⁴: as `i32` then `f32`, each is exact, as `x as f32`.
        let mut x = x0 as i32;
        let mut chunks = run.chunks_exact_mut(4 * RUN_LANES);
        for chunk in &mut chunks {
            // One array a quantity, one lane a pixel: the loops over lanes vectorise.
            let cx: [f32; RUN_LANES] = std::array::from_fn(|i| (x + i as i32) as f32 + 0.5);
            let mut l = [[0.0f32; RUN_LANES]; 3];
            for (k, l) in l.iter_mut().enumerate() {
                for (l, cx) in l.iter_mut().zip(cx) {
                    *l = (row[k] - dy[k] * (cx - ax[k])) / area;
                }
            }
            let mut src = [[0.0f32; RUN_LANES]; 4];
            for (c, src) in src.iter_mut().enumerate() {
                for (i, s) in src.iter_mut().enumerate() {
                    *s = (l[0][i] * colors[0][c] + l[1][i] * colors[1][c] + l[2][i] * colors[2][c])
                        * tex[c];
                }
            }
            for (i, px) in chunk.chunks_exact_mut(4).enumerate() {
                blend_pixel(
                    [src[0][i], src[1][i], src[2][i], src[3][i]],
                    order,
                    unit,
                    px,
                );
            }
            x += RUN_LANES as i32;
        }
        for (px, x) in chunks.into_remainder().chunks_exact_mut(4).zip(x..) {
            blend_pixel(source(x as f32 + 0.5), order, unit, px);
        }
    }

    /// The premultiplied source at a pixel whose edge functions are `e`; `None` where it is
    /// exactly transparent (all four channels 0).
    #[inline(always)]
    fn source_at(&self, e: [f32; 3]) -> Option<[f32; 4]> {
        let colors = &self.colors;
        let l = e.map(|e| e / self.area);
        let tex = match self.source {
            Source::Constant(src) => return Some(src),
            Source::Texel(tex) => tex,
            Source::Sampled => {
                let uv = &self.uv;
                let u = l[0] * uv[0][0] + l[1] * uv[1][0] + l[2] * uv[2][0];
                let t = l[0] * uv[0][1] + l[1] * uv[1][1] + l[2] * uv[2][1];
                self.texture.sample(u, t)
            }
        };
        if tex == [0.0; 4] {
            return None;
        }
        Some(std::array::from_fn(|k| {
            (l[0] * colors[0][k] + l[1] * colors[1][k] + l[2] * colors[2][k]) * tex[k]
        }))
    }
}

/// Pixels a [`Triangle::texel_run`] computes together.
const RUN_LANES: usize = 8;

/// `d / 255` for each 8-bit value `d` (the same floats `blend` divided for before).
fn unit() -> &'static [f32; 256] {
    static UNIT: std::sync::OnceLock<[f32; 256]> = std::sync::OnceLock::new();
    UNIT.get_or_init(|| std::array::from_fn(|d| d as f32 / 255.0))
}

/// `src` (premultiplied R, G, B, A) blended over the pixel `px`, whose R, G and B bytes are at
/// `order`, as [`blend`] does (`unit` is [`unit`]); alpha untouched.
#[inline(always)]
#[allow(clippy::manual_clamp)] // `clamp` keeps a NaN, which the unchecked conversion must not see
fn blend_pixel(src: [f32; 4], order: [usize; 3], unit: &[f32; 256], px: &mut [u8]) {
    let keep = 1.0 - src[3];
    for (k, &o) in order.iter().enumerate() {
        let out = src[k] + unit[px[o] as usize] * keep;
        // `clamp` then `as u8` as in `blend`, without the saturating conversion's checks: a
        // NaN (`max` gives 0, as `clamp` then `as u8` gave 0) and every number land in
        // [0.5, 255.5], whose truncation is the same byte.
        let t = out.max(0.0).min(1.0) * 255.0 + 0.5;
        // SAFETY: `t` is finite and in [0.5, 255.5] (above), so its truncation fits an i32.
        px[o] = unsafe { t.to_int_unchecked::<i32>() } as u8;
    }
}

/// One channel blended: `src + dst · (1 − alpha)` in [0, 1], back to 8 bits.
fn blend(src: f32, alpha: f32, dst: u8) -> u8 {
    let out = src + dst as f32 / 255.0 * (1.0 - alpha);
    (out.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Skipping a transparent source is exact: blending 0 over any byte gives that byte, and
    /// the blend through [`unit`] is [`blend`] byte for byte.
    #[test]
    fn a_transparent_source_leaves_every_byte_and_the_unit_table_blends_alike() {
        let unit = unit();
        for d in 0..=255u8 {
            assert_eq!(blend(0.0, 0.0, d), d, "{d}");
            for src in [
                [0.0f32, 0.0, 0.0, 0.0],
                [0.1, 0.5, 0.9, 0.7],
                [0.3, 0.0, 1.0, 0.51],
                [f32::NAN, 1.5, -0.2, 0.1],
                [2.0, -1.0, 0.0, -0.5],
            ] {
                let mut px = [d, d, d, 9];
                blend_pixel(src, [2, 1, 0], unit, &mut px);
                let want = [blend(src[2], src[3], d), blend(src[1], src[3], d)];
                assert_eq!([px[0], px[1], px[3]], [want[0], want[1], 9], "{d} {src:?}");
            }
        }
    }
}
