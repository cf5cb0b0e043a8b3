//! One variance-guided à-trous wavelet pass (Schied et al. 2017, §4.4; Dammertz et al. 2010;
//! twin: `shaders/denoise_atrous.wgsl`): a 3×3 Gaussian or 5×5 B3-spline kernel (`radius` 1
//! or 2, `weights::atrous_tap`) with holes of `step` pixels,
//! each tap weighted by depth, normal and luminance (σ_l·√(3×3-prefiltered variance)); the
//! variance is filtered with the squared weights.
//!
//! Owns: [`atrous_pixel`] and the pass over an image. Rows in and out: (demodulated
//! illumination rgb, variance); variance −1 marks a pixel without a valid sample, which weighs
//! nothing as a neighbour and is filled from its neighbours (without the luminance term) when
//! it is the centre. Sky pixels (no guide) pass unchanged. The last pass remodulates: rgb ×
//! albedo, and a pixel still without a sample becomes 0, so nothing non-finite leaves.
//! [`atrous_pixel`] is the per-pixel reference (the WGSL twin's shape); [`filter`] computes the
//! same a row at a time over planes (`planes`), the taps as loops over the row that
//! vectorise. Render thread, rows on rayon's pool.
//! Must not: blend over time.

use glam::{Vec2, Vec3, Vec4};
use rayon::prelude::*;

use super::atrous_block::{LANES, interior, interior_taps};
use super::planes::{ColourPlanes, GuidePlanes, OutRow, RowSums, Simd, dispatch, lane_weight};
use super::weights::{
    GAUSS3, LUMINANCE_EPS, atrous_tap, demodulator, depth_gradient, edge_weight, guide_at,
    luminance,
};

/// The knobs of one pass.
#[derive(Clone, Copy, Debug)]
pub struct Pass {
    /// Distance between taps in pixels (1, 2, 4, …).
    pub step: i32,
    /// The kernel's radius in taps: 1 (3×3 Gaussian) or 2 (5×5 B3 spline).
    pub radius: i32,
    pub sigma_z: f32,
    pub sigma_l: f32,
    /// Multiply by the albedo and write radiance (the last pass).
    pub remodulate: bool,
}

/// The 3×3 Gaussian of the valid variances around (x, y) (−1 when there are none).
fn prefiltered_variance(input: &[Vec4], width: u32, height: u32, x: i32, y: i32) -> f32 {
    let (mut sum, mut weight) = (0.0f32, 0.0f32);
    for dy in -1..=1i32 {
        for dx in -1..=1i32 {
            let (qx, qy) = (x + dx, y + dy);
            if qx < 0 || qy < 0 || qx >= width as i32 || qy >= height as i32 {
                continue;
            }
            let v = input[qy as usize * width as usize + qx as usize].w;
            if v < 0.0 {
                continue;
            }
            let k = GAUSS3[(dx + 1) as usize] * GAUSS3[(dy + 1) as usize];
            sum += k * v;
            weight += k;
        }
    }
    if weight > 0.0 { sum / weight } else { -1.0 }
}

/// The output row of pixel (x, y).
#[allow(clippy::too_many_arguments)]
pub fn atrous_pixel(
    input: &[Vec4],
    guides: &[Vec4],
    albedo: &[Vec4],
    width: u32,
    height: u32,
    x: i32,
    y: i32,
    pass: &Pass,
) -> Vec4 {
    let i = y as usize * width as usize + x as usize;
    let centre = input[i];
    let p = guide_at(guides, width, height, x, y);
    let mut out = centre;
    if p.w > 0.0 {
        let gradient = depth_gradient(guides, width, height, x, y);
        let valid = centre.w >= 0.0;
        let lp = luminance(centre.truncate());
        let var = prefiltered_variance(input, width, height, x, y);
        let lum_scale = if valid && var >= 0.0 {
            pass.sigma_l * var.sqrt() + LUMINANCE_EPS
        } else {
            -1.0
        };
        let (mut sum_c, mut sum_v, mut sum_w) = (Vec3::ZERO, 0.0f32, 0.0f32);
        let r = pass.radius;
        for dy in -r..=r {
            for dx in -r..=r {
                let (qx, qy) = (x + dx * pass.step, y + dy * pass.step);
                if qx < 0 || qy < 0 || qx >= width as i32 || qy >= height as i32 {
                    continue;
                }
                let row = input[qy as usize * width as usize + qx as usize];
                if row.w < 0.0 {
                    continue;
                }
                let k = atrous_tap(dx, r) * atrous_tap(dy, r);
                let w = if dx == 0 && dy == 0 {
                    k
                } else {
                    let q = guide_at(guides, width, height, qx, qy);
                    let offset = Vec2::new((dx * pass.step) as f32, (dy * pass.step) as f32);
                    let lq = luminance(row.truncate());
                    k * edge_weight(p, gradient, q, offset, pass.sigma_z, lp, lq, lum_scale)
                };
                sum_c += row.truncate() * w;
                sum_v += row.w * w * w;
                sum_w += w;
            }
        }
        out = if sum_w > 0.0 {
            (sum_c / sum_w).extend(sum_v / (sum_w * sum_w))
        } else {
            Vec4::new(0.0, 0.0, 0.0, -1.0)
        };
    }
    if pass.remodulate {
        if out.w < 0.0 {
            return Vec4::ZERO;
        }
        return (out.truncate() * demodulator(albedo[i].truncate())).extend(1.0);
    }
    out
}

/// One pass over the whole image from `input` into `out`, row by row on rayon's pool: per
/// pixel what [`atrous_pixel`] gives (up to the exponential, `planes::exp_neg`, and the
/// luminance term's reciprocal).
pub fn filter(input: &ColourPlanes, guides: &GuidePlanes, pass: &Pass, out: &mut ColourPlanes) {
    let w = guides.width;
    out.resize(w * guides.height);
    let simd = Simd::detect();
    out.rows_mut(w).for_each_init(
        || RowSums::new(w),
        |sums, (y, mut row)| row_simd(simd, input, guides, y, pass, sums, &mut row),
    );
}

dispatch!(
    /// [`row_sums`] then [`finish`] at the CPU's vector width.
    fn row_simd => row(
        input: &ColourPlanes,
        g: &GuidePlanes,
        y: usize,
        pass: &Pass,
        sums: &mut RowSums,
        out: &mut OutRow<'_>,
    )
);

#[inline(always)]
fn row(
    input: &ColourPlanes,
    g: &GuidePlanes,
    y: usize,
    pass: &Pass,
    sums: &mut RowSums,
    out: &mut OutRow<'_>,
) {
    row_sums(input, g, y, pass, sums);
    finish(input, g, y, pass.remodulate, sums, out);
}

/// Row `y`'s output from its sums, as [`atrous_pixel`] ends: the weighted mean (no weight: no
/// sample), the input where there is no surface; remodulated (no sample: 0) on the last pass.
#[inline(always)]
fn finish(
    input: &ColourPlanes,
    g: &GuidePlanes,
    y: usize,
    remodulate: bool,
    sums: &RowSums,
    out: &mut OutRow<'_>,
) {
    let w = g.width;
    let c = y * w;
    let (cr, cg, cb, cv) = (
        &input.r[c..c + w],
        &input.g[c..c + w],
        &input.b[c..c + w],
        &input.v[c..c + w],
    );
    let (z, dr, dg, db) = (
        &g.z[c..c + w],
        &g.dr[c..c + w],
        &g.dg[c..c + w],
        &g.db[c..c + w],
    );
    let (sr, sg, sb, sv, sw) = (
        &sums.r[..w],
        &sums.g[..w],
        &sums.b[..w],
        &sums.v[..w],
        &sums.w[..w],
    );
    let (or, og, ob) = (&mut out.r[..w], &mut out.g[..w], &mut out.b[..w]);
    let (ov, ol) = (&mut out.v[..w], &mut out.l[..w]);
    for x in 0..w {
        let s = sw[x];
        let (mut r, mut gr, mut b, mut v) = if z[x] > 0.0 {
            if s > 0.0 {
                (sr[x] / s, sg[x] / s, sb[x] / s, sv[x] / (s * s))
            } else {
                (0.0, 0.0, 0.0, -1.0)
            }
        } else {
            (cr[x], cg[x], cb[x], cv[x])
        };
        if remodulate {
            (r, gr, b, v) = if v < 0.0 {
                (0.0, 0.0, 0.0, 0.0)
            } else {
                (r * dr[x], gr * dg[x], b * db[x], 1.0)
            };
        }
        or[x] = r;
        og[x] = gr;
        ob[x] = b;
        ov[x] = v;
        ol[x] = luminance(Vec3::new(r, gr, b));
    }
}

/// The columns `x0..x0 + n` of row `y` whose neighbours `dx` pixels away lie in a row of
/// `width` pixels: (x0, n), `None` when there are none.
#[inline(always)]
fn span(width: usize, dx: isize) -> Option<(usize, usize)> {
    let w = width as isize;
    let (x0, x1) = ((-dx).max(0), w.min(w - dx));
    (x1 > x0).then_some((x0 as usize, (x1 - x0) as usize))
}

/// Row `y`'s centre luminance (`sums.lum`), the reciprocal of the luminance weight's scale
/// (`sums.scale`: 1 / (σ_l·√(3×3-prefiltered variance) + ε), 0 without one) and weighted sums
/// of the kernel's taps, in [`atrous_pixel`]'s order.
#[inline(always)]
fn row_sums(input: &ColourPlanes, g: &GuidePlanes, y: usize, pass: &Pass, sums: &mut RowSums) {
    let (w, rows) = (g.width, g.height as isize);
    let c = y * w;
    // The prefiltered variance: sum in `sums.r`, weight in `sums.g`.
    sums.clear();
    for dy in -1..=1isize {
        let qy = y as isize + dy;
        if qy < 0 || qy >= rows {
            continue;
        }
        for dx in -1..=1isize {
            let Some((x0, n)) = span(w, dx) else {
                continue;
            };
            let q = (qy as usize * w + x0).wrapping_add_signed(dx);
            let k = GAUSS3[(dx + 1) as usize] * GAUSS3[(dy + 1) as usize];
            let qv = &input.v[q..q + n];
            let (sum, weight) = (&mut sums.r[x0..x0 + n], &mut sums.g[x0..x0 + n]);
            for i in 0..n {
                let v = qv[i];
                sum[i] += if v < 0.0 { 0.0 } else { k * v };
                weight[i] += if v < 0.0 { 0.0 } else { k };
            }
        }
    }
    let (cl, cv) = (&input.l[c..c + w], &input.v[c..c + w]);
    for x in 0..w {
        let (sum, weight) = (sums.r[x], sums.g[x]);
        let var = if weight > 0.0 { sum / weight } else { -1.0 };
        sums.lum[x] = cl[x];
        sums.scale[x] = if cv[x] >= 0.0 && var >= 0.0 {
            1.0 / (pass.sigma_l * var.sqrt() + LUMINANCE_EPS)
        } else {
            0.0
        };
    }
    sums.clear();
    let (step, r) = (pass.step as isize, pass.radius as isize);
    // The interior's blocks keep their sums in registers (`atrous_block`); the columns near
    // the row's ends sweep tap by tap below.
    let (lo, blocks) = interior(w, (r * step) as usize);
    let hi = lo + blocks * LANES;
    for b in 0..blocks {
        interior_taps(input, g, y, lo + b * LANES, step, r, pass.sigma_z, sums);
    }
    for dy in -r..=r {
        let qy = y as isize + dy * step;
        if qy < 0 || qy >= rows {
            continue;
        }
        for dx in -r..=r {
            let Some((x0, n)) = span(w, dx * step) else {
                continue;
            };
            let tap = Tap {
                qy: qy as usize,
                dx,
                dy,
                step,
                radius: r,
            };
            // The span less the interior's blocks: up to two runs of columns.
            let left = (x0, n.min(lo.saturating_sub(x0)));
            let start = x0.max(hi);
            let right = (start, (x0 + n).saturating_sub(start));
            for (a, m) in [left, right] {
                if m > 0 {
                    tap_columns(input, g, y, &tap, pass.sigma_z, (a, m), sums);
                }
            }
        }
    }
}

/// One kernel tap: the neighbours' row and the tap's offset in taps (× `step` pixels).
struct Tap {
    qy: usize,
    dx: isize,
    dy: isize,
    step: isize,
    radius: isize,
}

/// Adds one tap to the sums of columns `x0..x0 + n` of row `y` (each neighbour inside the row).
#[inline(always)]
fn tap_columns(
    input: &ColourPlanes,
    g: &GuidePlanes,
    y: usize,
    tap: &Tap,
    sigma_z: f32,
    (x0, n): (usize, usize),
    sums: &mut RowSums,
) {
    let w = g.width;
    let c = y * w;
    let Tap {
        qy,
        dx,
        dy,
        step,
        radius: r,
    } = *tap;
    let ox = dx * step;
    let q = (qy * w + x0).wrapping_add_signed(ox);
    let k = atrous_tap(dx as i32, r as i32) * atrous_tap(dy as i32, r as i32);
    let (qr, qg, qb, qv, ql) = (
        &input.r[q..q + n],
        &input.g[q..q + n],
        &input.b[q..q + n],
        &input.v[q..q + n],
        &input.l[q..q + n],
    );
    let sr = &mut sums.r[x0..x0 + n];
    let sg = &mut sums.g[x0..x0 + n];
    let sb = &mut sums.b[x0..x0 + n];
    let sv = &mut sums.v[x0..x0 + n];
    let sw = &mut sums.w[x0..x0 + n];
    if dx == 0 && dy == 0 {
        for i in 0..n {
            let wt = if qv[i] < 0.0 { 0.0 } else { k };
            sr[i] += qr[i] * wt;
            sg[i] += qg[i] * wt;
            sb[i] += qb[i] * wt;
            sv[i] += qv[i] * wt * wt;
            sw[i] += wt;
        }
        return;
    }
    let (qnx, qny, qnz, qz) = (
        &g.nx[q..q + n],
        &g.ny[q..q + n],
        &g.nz[q..q + n],
        &g.z[q..q + n],
    );
    let p = c + x0;
    let (cnx, cny, cnz, cz) = (
        &g.nx[p..p + n],
        &g.ny[p..p + n],
        &g.nz[p..p + n],
        &g.z[p..p + n],
    );
    let (cgx, cgy) = (&g.gx[p..p + n], &g.gy[p..p + n]);
    let (lp, inv_scale) = (&sums.lum[x0..x0 + n], &sums.scale[x0..x0 + n]);
    let (fx, fy) = (ox as f32, (dy * step) as f32);
    for i in 0..n {
        let dot = cnx[i] * qnx[i] + cny[i] * qny[i] + cnz[i] * qnz[i];
        let slope = (cgx[i] * fx + cgy[i] * fy).abs();
        let dl = (lp[i] - ql[i]).abs() * inv_scale[i];
        let wt = k * lane_weight(dot, cz[i], qz[i], slope, sigma_z, dl);
        // A neighbour without a sample is (0, 0, 0, −1): a zero weight drops it.
        let wt = if qv[i] >= 0.0 && qz[i] > 0.0 { wt } else { 0.0 };
        sr[i] += qr[i] * wt;
        sg[i] += qg[i] * wt;
        sb[i] += qb[i] * wt;
        sv[i] += qv[i] * wt * wt;
        sw[i] += wt;
    }
}
