//! The per-pixel arithmetic every SVGF pass shares (twin: `shaders/shared/denoise.wgsl`):
//! reading a guide safely, demodulation factors, luminance, the screen-space depth gradient and
//! the edge-stopping weight of Schied et al. 2017 (eq. 3–5).
//!
//! Owns: the constants and formulas; both denoisers evaluate them in the same order so that
//! their outputs differ only by f32 rounding (`engine/tests/engine/denoise_gpu_matches_cpu.rs`).
//! Units: depth is the primary hit's distance along the camera ray in metres (0 = sky or no
//! guide); normals are unit world-space vectors facing the camera; colours are linear radiance.
//! Runs on whichever thread calls the CPU denoiser (the render thread).
//! Must not: loop over images (the passes do).

use glam::{Vec2, Vec3, Vec4};

/// A colour channel whose albedo is below this is not demodulated (its factor is 1), so that a
/// black or missing albedo cannot turn radiance into infinity.
pub const ALBEDO_MIN: f32 = 1e-3;
/// Frames of history from which the variance comes from the temporal moments; shorter
/// histories estimate it spatially (7×7, Schied et al. §4.3).
pub const MIN_TEMPORAL_FRAMES: f32 = 4.0;
/// The depth weight's slack as a fraction of the centre's depth (metres per metre): a 1 %
/// depth step at zero gradient costs a factor e⁻¹.
pub const DEPTH_EPS_REL: f32 = 1e-2;
/// Added to the luminance weight's scale (σ_l·√Var) so that a zero variance cannot divide by 0.
pub const LUMINANCE_EPS: f32 = 1e-10;
/// σ_n = 128 = 2⁷: the normal weight max(0, n_p·n_q)^128 is seven squarings, exact in f32 on
/// both sides (no `pow`).
pub const NORMAL_SQUARINGS: u32 = 7;
/// The à-trous kernel (B3 spline), per axis.
pub const KERNEL: [f32; 5] = [1.0 / 16.0, 1.0 / 4.0, 3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0];
/// The 3×3 Gaussian that prefilters the variance, per axis (also the 3×3 à-trous kernel).
pub const GAUSS3: [f32; 3] = [0.25, 0.5, 0.25];

/// The à-trous kernel's weight per axis at tap offset `d` (−radius..=radius): radius 1 is the
/// 3×3 Gaussian ([`GAUSS3`]), radius 2 the 5×5 B3 spline ([`KERNEL`]). Twin: `atrous_tap` in
/// `shaders/shared/denoise.wgsl`.
#[inline(always)]
pub fn atrous_tap(d: i32, radius: i32) -> f32 {
    match radius {
        1 => GAUSS3[(d + 1) as usize],
        _ => KERNEL[(d + 2) as usize],
    }
}

/// Rec. 709 luminance of linear RGB.
pub fn luminance(c: Vec3) -> f32 {
    c.x * 0.2126 + c.y * 0.7152 + c.z * 0.0722
}

/// True when every channel is finite.
pub fn finite3(c: Vec3) -> bool {
    c.x.is_finite() && c.y.is_finite() && c.z.is_finite()
}

/// A guide (normal xyz, depth w) made safe: anything non-finite, or a depth that is not
/// positive, reads as "no surface" (all zero), which the passes neither filter nor use.
pub fn normal_depth(raw: Vec4) -> Vec4 {
    let finite = raw.x.is_finite() && raw.y.is_finite() && raw.z.is_finite() && raw.w.is_finite();
    if finite && raw.w > 0.0 {
        raw
    } else {
        Vec4::ZERO
    }
}

/// What radiance is divided by to demodulate (and multiplied by to remodulate): the albedo per
/// channel, or 1 where it is not finite or below [`ALBEDO_MIN`].
pub fn demodulator(albedo: Vec3) -> Vec3 {
    let channel = |a: f32| {
        if a.is_finite() && a >= ALBEDO_MIN {
            a
        } else {
            1.0
        }
    };
    Vec3::new(channel(albedo.x), channel(albedo.y), channel(albedo.z))
}

/// The depth difference along one axis at the centre (depth `zc`) from its neighbours on the
/// minus (`zm`) and plus (`zp`) side, 0 meaning no surface: the one-sided difference of smaller
/// magnitude (so that an edge next to the pixel does not count as slope), 0 without neighbours.
pub fn axis_gradient(zc: f32, zm: f32, zp: f32) -> f32 {
    let has_m = zm > 0.0;
    let has_p = zp > 0.0;
    let dm = zc - zm;
    let dp = zp - zc;
    if has_m && has_p {
        if dp.abs() < dm.abs() { dp } else { dm }
    } else if has_p {
        dp
    } else if has_m {
        dm
    } else {
        0.0
    }
}

/// The sanitized guide of pixel (x, y), or "no surface" outside the image.
pub fn guide_at(guides: &[Vec4], width: u32, height: u32, x: i32, y: i32) -> Vec4 {
    if x < 0 || y < 0 || x >= width as i32 || y >= height as i32 {
        return Vec4::ZERO;
    }
    normal_depth(guides[y as usize * width as usize + x as usize])
}

/// The screen-space depth gradient (metres per pixel, x right, y down) at (x, y), from
/// [`axis_gradient`] on each axis.
pub fn depth_gradient(guides: &[Vec4], width: u32, height: u32, x: i32, y: i32) -> Vec2 {
    let zc = guide_at(guides, width, height, x, y).w;
    let z = |dx: i32, dy: i32| guide_at(guides, width, height, x + dx, y + dy).w;
    Vec2::new(
        axis_gradient(zc, z(-1, 0), z(1, 0)),
        axis_gradient(zc, z(0, -1), z(0, 1)),
    )
}

/// The edge-stopping weight between centre p and neighbour q at pixel offset `offset`
/// (Schied et al. 2017, eq. 3–5, without the kernel factor): normal term max(0, n_p·n_q)^128
/// times exp(−|z_p − z_q| / (σ_z·|∇z·offset| + ε·z_p) − |l_p − l_q| / lum_scale). `lum_scale` is
/// σ_l·√(prefiltered variance) + ε; a negative `lum_scale` leaves the luminance term out.
/// p must be a surface (z_p > 0); a neighbour without one weighs 0.
#[allow(clippy::too_many_arguments)]
pub fn edge_weight(
    p: Vec4,
    gradient: Vec2,
    q: Vec4,
    offset: Vec2,
    sigma_z: f32,
    lp: f32,
    lq: f32,
    lum_scale: f32,
) -> f32 {
    if q.w <= 0.0 {
        return 0.0;
    }
    let mut wn = (p.x * q.x + p.y * q.y + p.z * q.z).max(0.0);
    for _ in 0..NORMAL_SQUARINGS {
        wn *= wn;
    }
    let slope = (gradient.x * offset.x + gradient.y * offset.y).abs();
    let dz = (p.w - q.w).abs() / (sigma_z * slope + DEPTH_EPS_REL * p.w);
    let dl = if lum_scale >= 0.0 {
        (lp - lq).abs() / lum_scale
    } else {
        0.0
    };
    wn * (-(dz + dl)).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guides_and_albedo_are_made_safe() {
        assert_eq!(normal_depth(Vec4::new(f32::NAN, 0.0, 1.0, 2.0)), Vec4::ZERO);
        assert_eq!(
            normal_depth(Vec4::new(0.0, 0.0, 1.0, f32::INFINITY)),
            Vec4::ZERO
        );
        assert_eq!(normal_depth(Vec4::new(0.0, 0.0, 1.0, -1.0)), Vec4::ZERO);
        let d = demodulator(Vec3::new(0.5, 0.0, f32::NAN));
        assert_eq!(d, Vec3::new(0.5, 1.0, 1.0));
    }

    #[test]
    fn weights_stop_at_edges() {
        let p = Vec4::new(0.0, 0.0, 1.0, 2.0);
        let same = edge_weight(p, Vec2::ZERO, p, Vec2::X, 1.0, 1.0, 1.0, 1.0);
        assert!((same - 1.0).abs() < 1e-6);
        let turned = Vec4::new(1.0, 0.0, 0.0, 2.0);
        assert_eq!(
            edge_weight(p, Vec2::ZERO, turned, Vec2::X, 1.0, 1.0, 1.0, 1.0),
            0.0
        );
        let far = Vec4::new(0.0, 0.0, 1.0, 3.0);
        assert!(edge_weight(p, Vec2::ZERO, far, Vec2::X, 1.0, 1.0, 1.0, 1.0) < 1e-10);
        // A slope along the offset forgives the depth step it predicts.
        let sloped = edge_weight(p, Vec2::new(1.0, 0.0), far, Vec2::X, 1.0, 1.0, 1.0, 1.0);
        assert!(sloped > 0.3, "{sloped}");
        let sky = Vec4::ZERO;
        assert_eq!(
            edge_weight(p, Vec2::ZERO, sky, Vec2::X, 1.0, 1.0, 1.0, 1.0),
            0.0
        );
    }

    #[test]
    fn gradient_ignores_the_far_side_of_an_edge() {
        assert!((axis_gradient(2.0, 1.9, 10.0) - 0.1).abs() < 1e-6);
        assert_eq!(axis_gradient(2.0, 0.0, 2.5), 0.5);
        assert_eq!(axis_gradient(2.0, 0.0, 0.0), 0.0);
    }
}
