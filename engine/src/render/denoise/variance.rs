//! SVGF's variance estimate (Schied et al. 2017, §4.2–4.3; twin:
//! `shaders/denoise_variance.wgsl`): the variance of each pixel's luminance estimate, from the
//! temporal moments once a pixel has [`MIN_TEMPORAL_FRAMES`] of history, else from its
//! neighbours in a 7×7 window weighted by depth and normal.
//!
//! Owns: [`variance_pixel`] and the pass over an image. The temporal figure is the variance of
//! the *mean* (moments' variance / (n − 1)), not of one frame, so the filter relaxes as the
//! image converges and adds little blur to a converged image. The spatial figure is the spread
//! of the neighbours' (per-frame mean) values. Output rows: (illumination rgb, variance), with
//! variance −1 for a pixel without any valid sample. Render thread.
//! Must not: blend over time or filter colour.

use glam::{Vec2, Vec4};
use rayon::prelude::*;

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

/// The variance pass over the whole image into `out` (one row per pixel).
pub fn estimate(
    illumination: &[Vec4],
    moments: &[Vec4],
    guides: &[Vec4],
    width: u32,
    height: u32,
    sigma_z: f32,
    out: &mut [Vec4],
) {
    out.par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(y, row)| {
            for (x, o) in row.iter_mut().enumerate() {
                *o = variance_pixel(
                    illumination,
                    moments,
                    guides,
                    width,
                    height,
                    x as i32,
                    y as i32,
                    sigma_z,
                );
            }
        });
}
