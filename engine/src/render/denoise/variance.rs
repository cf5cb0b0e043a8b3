//! SVGF's variance estimate (Schied et al. 2017, §4.2–4.3; twin:
//! `shaders/denoise_variance.wgsl`): the variance of each pixel's luminance estimate, from the
//! temporal moments once a pixel has [`MIN_TEMPORAL_FRAMES`] of history, else from its
//! neighbours in a 7×7 window weighted by depth and normal.
//!
//! Owns: [`variance_pixel`] and the pass over an image. The temporal figure is the variance of
//! the *mean* (moments' variance / (n − 1)), not of one frame, so the filter relaxes as the
//! image converges and adds little blur to a converged image. The spatial figure is the spread
//! of the neighbours' (per-frame mean) values. Output rows: (illumination rgb, variance), with
//! variance −1 for a pixel without any valid sample. [`variance_pixel`] is the per-pixel
//! reference (the WGSL twin's shape); [`estimate`] computes the same a row at a time over
//! planes (`planes`). Render thread, rows on rayon's pool.
//! Must not: blend over time or filter colour.

use glam::{Vec2, Vec4};
use rayon::prelude::*;

use super::planes::{ColourPlanes, GuidePlanes, RowSums, Simd, dispatch, lane_weight};
use super::temporal::History;
use super::weights::{MIN_TEMPORAL_FRAMES, depth_gradient, edge_weight, guide_at, luminance};

/// Half the spatial estimate's window (7×7).
pub const SPATIAL_RADIUS: i32 = 3;

/// The (illumination, variance) row of pixel (x, y).
#[allow(clippy::too_many_arguments)]
pub fn variance_pixel(
    illumination: &[Vec4],
    moments: &[Vec4],
    guides: &[Vec4],
    width: u32,
    height: u32,
    x: i32,
    y: i32,
    sigma_z: f32,
) -> Vec4 {
    let i = y as usize * width as usize + x as usize;
    let h = illumination[i];
    if h.w <= 0.0 {
        return Vec4::new(0.0, 0.0, 0.0, -1.0);
    }
    if h.w >= MIN_TEMPORAL_FRAMES {
        let m = moments[i];
        let var = (m.y - m.x * m.x).max(0.0) / (h.w - 1.0);
        return h.truncate().extend(var);
    }
    let p = guide_at(guides, width, height, x, y);
    if p.w <= 0.0 {
        return h.truncate().extend(0.0);
    }
    let gradient = depth_gradient(guides, width, height, x, y);
    let (mut sum_w, mut s1, mut s2) = (0.0f32, 0.0f32, 0.0f32);
    for dy in -SPATIAL_RADIUS..=SPATIAL_RADIUS {
        for dx in -SPATIAL_RADIUS..=SPATIAL_RADIUS {
            let (qx, qy) = (x + dx, y + dy);
            if qx < 0 || qy < 0 || qx >= width as i32 || qy >= height as i32 {
                continue;
            }
            let j = qy as usize * width as usize + qx as usize;
            let hq = illumination[j];
            if hq.w <= 0.0 {
                continue;
            }
            let q = guide_at(guides, width, height, qx, qy);
            let offset = Vec2::new(dx as f32, dy as f32);
            let w = edge_weight(p, gradient, q, offset, sigma_z, 0.0, 0.0, -1.0);
            let l = luminance(hq.truncate());
            sum_w += w;
            s1 += w * l;
            s2 += w * l * l;
        }
    }
    let var = if sum_w > 0.0 {
        let m1 = s1 / sum_w;
        (s2 / sum_w - m1 * m1).max(0.0)
    } else {
        0.0
    };
    h.truncate().extend(var)
}

/// The history's luminance and length as planes, for the spatial estimate's taps.
#[derive(Clone, Debug, Default)]
pub struct HistoryPlanes {
    lum: Vec<f32>,
    len: Vec<f32>,
}

/// The variance pass over the whole image into `out`, row by row on rayon's pool: per pixel
/// what [`variance_pixel`] gives (up to the exponential, `planes::exp_neg`). The 7×7 spatial
/// estimate runs only on rows with a surface pixel whose history is shorter than
/// [`MIN_TEMPORAL_FRAMES`].
pub fn estimate(
    history: &History,
    guides: &GuidePlanes,
    sigma_z: f32,
    scratch: &mut HistoryPlanes,
    out: &mut ColourPlanes,
) {
    let w = guides.width;
    let n = w * guides.height;
    out.resize(n);
    let m = history.illumination.len();
    scratch.lum.resize(m, 0.0);
    scratch.len.resize(m, 0.0);
    (scratch.lum.par_iter_mut().zip(scratch.len.par_iter_mut()))
        .zip(history.illumination.par_iter())
        .for_each(|((lum, len), h)| {
            *lum = luminance(h.truncate());
            *len = h.w;
        });
    let planes = &*scratch;
    let simd = Simd::detect();
    out.rows_mut(w).for_each_init(
        || RowSums::new(w),
        |sums, (y, mut row)| {
            let c = y * w;
            let ill = &history.illumination[c..c + w];
            let z = &guides.z[c..c + w];
            // The columns that read the spatial estimate: from the first to the last such
            // pixel (a camera turn uncovers a band at one side, a moved object its edges).
            let short =
                |x: &usize| ill[*x].w > 0.0 && ill[*x].w < MIN_TEMPORAL_FRAMES && z[*x] > 0.0;
            if let Some(lo) = (0..w).find(short) {
                let hi = (lo..w).rev().find(short).map_or(lo + 1, |x| x + 1);
                spatial_row_simd(simd, planes, guides, y, (lo, hi), sigma_z, sums);
            }
            for x in 0..w {
                let h = ill[x];
                let value = if h.w <= 0.0 {
                    Vec4::new(0.0, 0.0, 0.0, -1.0)
                } else if h.w >= MIN_TEMPORAL_FRAMES {
                    let m = history.moments[c + x];
                    h.truncate()
                        .extend((m.y - m.x * m.x).max(0.0) / (h.w - 1.0))
                } else if z[x] <= 0.0 {
                    h.truncate().extend(0.0)
                } else {
                    let sum_w = sums.w[x];
                    let var = if sum_w > 0.0 {
                        let m1 = sums.r[x] / sum_w;
                        (sums.g[x] / sum_w - m1 * m1).max(0.0)
                    } else {
                        0.0
                    };
                    h.truncate().extend(var)
                };
                row.set(x, value);
            }
        },
    );
}

dispatch!(
    /// [`spatial_row`] at the CPU's vector width.
    fn spatial_row_simd => spatial_row(
        h: &HistoryPlanes,
        g: &GuidePlanes,
        y: usize,
        span: (usize, usize),
        sigma_z: f32,
        sums: &mut RowSums,
    )
);

/// The spatial estimate's sums for row `y`'s columns `span.0..span.1` (the rest stay 0):
/// `sums.w` the weights, `sums.r` the weighted luminance, `sums.g` the weighted squared
/// luminance (7×7 taps in [`variance_pixel`]'s order; each column's sums are the same bits
/// whatever the span).
#[inline(always)]
fn spatial_row(
    h: &HistoryPlanes,
    g: &GuidePlanes,
    y: usize,
    (lo, hi): (usize, usize),
    sigma_z: f32,
    sums: &mut RowSums,
) {
    let (w, rows) = (g.width as isize, g.height as isize);
    let c = y * g.width;
    let e = c + g.width;
    let (pnx, pny, pnz, pz) = (&g.nx[c..e], &g.ny[c..e], &g.nz[c..e], &g.z[c..e]);
    let (pgx, pgy) = (&g.gx[c..e], &g.gy[c..e]);
    sums.clear();
    for dy in -SPATIAL_RADIUS as isize..=SPATIAL_RADIUS as isize {
        let qy = y as isize + dy;
        if qy < 0 || qy >= rows {
            continue;
        }
        for dx in -SPATIAL_RADIUS as isize..=SPATIAL_RADIUS as isize {
            let (x0, x1) = ((-dx).max(lo as isize), (w - dx).min(w).min(hi as isize));
            if x1 <= x0 {
                continue;
            }
            let (x0, n) = (x0 as usize, (x1 - x0) as usize);
            let q = (qy * w + x0 as isize + dx) as usize;
            let (qnx, qny, qnz, qz) = (
                &g.nx[q..q + n],
                &g.ny[q..q + n],
                &g.nz[q..q + n],
                &g.z[q..q + n],
            );
            let (ql, qlen) = (&h.lum[q..q + n], &h.len[q..q + n]);
            let (cnx, cny, cnz, cz) = (
                &pnx[x0..x0 + n],
                &pny[x0..x0 + n],
                &pnz[x0..x0 + n],
                &pz[x0..x0 + n],
            );
            let (cgx, cgy) = (&pgx[x0..x0 + n], &pgy[x0..x0 + n]);
            let sw = &mut sums.w[x0..x0 + n];
            let s1 = &mut sums.r[x0..x0 + n];
            let s2 = &mut sums.g[x0..x0 + n];
            let (ox, oy) = (dx as f32, dy as f32);
            for i in 0..n {
                let dot = cnx[i] * qnx[i] + cny[i] * qny[i] + cnz[i] * qnz[i];
                let slope = (cgx[i] * ox + cgy[i] * oy).abs();
                let wt = lane_weight(dot, cz[i], qz[i], slope, sigma_z, 0.0);
                let l = ql[i];
                // A pixel without history holds zeros: a zero weight drops it.
                let wt = if qlen[i] > 0.0 && qz[i] > 0.0 {
                    wt
                } else {
                    0.0
                };
                sw[i] += wt;
                s1[i] += wt * l;
                s2[i] += wt * l * l;
            }
        }
    }
}
