//! The à-trous pass's edge-weighted taps over a block of [`LANES`] neighbouring pixels of a row
//! whose every tap lies inside the row (the interior): the block's centre guides and its five
//! sums stay in vector registers across all the kernel's taps, instead of every tap sweeping
//! the whole row and reloading and storing the sums (`atrous::row_sums` does that for the
//! columns near the row's ends). Each lane adds its taps in the same order with the same
//! operations as the row sweep, so the sums are the same bits.
//!
//! Owns: [`interior_taps`]. Render thread, inside one rayon task's row (compiled at the
//! dispatching kernel's vector width: it is `#[inline(always)]`).
//! Must not: touch columns outside its block or the variance prefilter (computed before).

use super::planes::{ColourPlanes, GuidePlanes, RowSums, lane_weight};
use super::weights::atrous_tap;

/// Pixels per block: one AVX-512 register of `f32` (two AVX2 registers).
pub const LANES: usize = 16;

/// The columns `[lo, hi)` of a row of `width` pixels whose taps up to `reach` pixels away on
/// either side all lie inside the row, rounded to whole blocks from `lo`: (lo, number of
/// blocks).
#[inline(always)]
pub fn interior(width: usize, reach: usize) -> (usize, usize) {
    if width < 2 * reach + LANES {
        return (reach, 0);
    }
    (reach, (width - 2 * reach) / LANES)
}

/// The kernel's weighted sums (rgb, variance with squared weights, weight) at columns
/// `x0..x0 + LANES` of row `y` into `sums`, as `atrous::row_sums` computes them; `sums.lum`
/// and `sums.scale` must hold the row's centre luminances and luminance scales. Every tap's
/// column must lie inside the row (see [`interior`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn interior_taps(
    input: &ColourPlanes,
    g: &GuidePlanes,
    y: usize,
    x0: usize,
    step: isize,
    radius: isize,
    sigma_z: f32,
    sums: &mut RowSums,
) {
    let (w, rows) = (g.width, g.height as isize);
    let c = y * w + x0;
    let lanes = |plane: &[f32], at: usize| -> [f32; LANES] {
        let mut out = [0.0f32; LANES];
        out.copy_from_slice(&plane[at..at + LANES]);
        out
    };
    let (cnx, cny, cnz, cz) = (
        lanes(&g.nx, c),
        lanes(&g.ny, c),
        lanes(&g.nz, c),
        lanes(&g.z, c),
    );
    let (cgx, cgy) = (lanes(&g.gx, c), lanes(&g.gy, c));
    let (lp, inv_scale) = (lanes(&sums.lum, x0), lanes(&sums.scale, x0));
    let mut sr = [0.0f32; LANES];
    let mut sg = [0.0f32; LANES];
    let mut sb = [0.0f32; LANES];
    let mut sv = [0.0f32; LANES];
    let mut sw = [0.0f32; LANES];
    for dy in -radius..=radius {
        let qy = y as isize + dy * step;
        if qy < 0 || qy >= rows {
            continue;
        }
        for dx in -radius..=radius {
            let ox = dx * step;
            let q = (qy as usize * w + x0).wrapping_add_signed(ox);
            let k = atrous_tap(dx as i32, radius as i32) * atrous_tap(dy as i32, radius as i32);
            let (qr, qg, qb, qv) = (
                &input.r[q..q + LANES],
                &input.g[q..q + LANES],
                &input.b[q..q + LANES],
                &input.v[q..q + LANES],
            );
            if dx == 0 && dy == 0 {
                for i in 0..LANES {
                    let wt = if qv[i] < 0.0 { 0.0 } else { k };
                    sr[i] += qr[i] * wt;
                    sg[i] += qg[i] * wt;
                    sb[i] += qb[i] * wt;
                    sv[i] += qv[i] * wt * wt;
                    sw[i] += wt;
                }
                continue;
            }
            let ql = &input.l[q..q + LANES];
            let (qnx, qny, qnz, qz) = (
                &g.nx[q..q + LANES],
                &g.ny[q..q + LANES],
                &g.nz[q..q + LANES],
                &g.z[q..q + LANES],
            );
            let (fx, fy) = (ox as f32, (dy * step) as f32);
            for i in 0..LANES {
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
    }
    sums.r[x0..x0 + LANES].copy_from_slice(&sr);
    sums.g[x0..x0 + LANES].copy_from_slice(&sg);
    sums.b[x0..x0 + LANES].copy_from_slice(&sb);
    sums.v[x0..x0 + LANES].copy_from_slice(&sv);
    sums.w[x0..x0 + LANES].copy_from_slice(&sw);
}
