//! One variance-guided à-trous wavelet pass (Schied et al. 2017, §4.4; Dammertz et al. 2010;
//! twin: `shaders/denoise_atrous.wgsl`): a 5×5 B3-spline kernel with holes of `step` pixels,
//! each tap weighted by depth, normal and luminance (σ_l·√(3×3-prefiltered variance)); the
//! variance is filtered with the squared weights.
//!
//! Owns: [`atrous_pixel`] and the pass over an image. Rows in and out: (demodulated
//! illumination rgb, variance); variance −1 marks a pixel without a valid sample, which weighs
//! nothing as a neighbour and is filled from its neighbours (without the luminance term) when
//! it is the centre. Sky pixels (no guide) pass unchanged. The last pass remodulates: rgb ×
//! albedo, and a pixel still without a sample becomes 0, so nothing non-finite leaves. Render
//! thread.
//! Must not: blend over time.

use glam::{Vec2, Vec3, Vec4};
use rayon::prelude::*;

use super::weights::{
    GAUSS3, KERNEL, LUMINANCE_EPS, demodulator, depth_gradient, edge_weight, guide_at, luminance,
};

/// The knobs of one pass.
#[derive(Clone, Copy, Debug)]
pub struct Pass {
    /// Distance between taps in pixels (1, 2, 4, …).
    pub step: i32,
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
        for dy in -2..=2i32 {
            for dx in -2..=2i32 {
                let (qx, qy) = (x + dx * pass.step, y + dy * pass.step);
                if qx < 0 || qy < 0 || qx >= width as i32 || qy >= height as i32 {
                    continue;
                }
                let row = input[qy as usize * width as usize + qx as usize];
                if row.w < 0.0 {
                    continue;
                }
                let k = KERNEL[(dx + 2) as usize] * KERNEL[(dy + 2) as usize];
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

/// One pass over the whole image from `input` into `out`.
pub fn filter(
    input: &[Vec4],
    guides: &[Vec4],
    albedo: &[Vec4],
    width: u32,
    height: u32,
    pass: &Pass,
    out: &mut [Vec4],
) {
    out.par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(y, row)| {
            for (x, o) in row.iter_mut().enumerate() {
                *o = atrous_pixel(
                    input, guides, albedo, width, height, x as i32, y as i32, pass,
                );
            }
        });
}
