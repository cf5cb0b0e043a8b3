//! The scattering orders' grid (`orders`): where its nodes and direction cells lie. Altitudes
//! dense near the ground, local sun elevations dense near the horizon and in twilight, and
//! direction cells in elevation laid out about each altitude's local horizon (a cell boundary)
//! and in azimuth from the sun; the maps between angles and the grid's coordinates, and the
//! bilinear position of a value among nodes, and the blend between two sun-elevation nodes
//! (geometric: twilight falls steeply).
//!
//! Any thread. Kilometres, radians; local frame z up, the sun in the x–z plane.
//! Must not: hold or march any radiance (see `orders`).

use std::f32::consts::{FRAC_PI_2, PI};

use glam::Vec3;

use super::atmosphere::{GROUND_RADIUS_KM, TOP_RADIUS_KM};

/// Altitude nodes, h = H·(k/(N−1))² (dense near the ground).
pub(super) const ALTITUDES: usize = 16;
/// Sun elevation nodes, c uniform, elevation = sign(c)·c²·90° from −18° to 90° (dense near the
/// horizon and in twilight).
pub(super) const SUNS: usize = 40;
/// Direction cells in elevation (c-mapped about the local horizon, which is a cell boundary at
/// every altitude: e = e_h + c²(90° − e_h) above it, e_h − c²(90° + e_h) below) and in azimuth
/// from the sun (0..π; the field is symmetric about the sun's vertical plane).
pub(super) const ELEVATIONS: usize = 16;
pub(super) const AZIMUTHS: usize = 12;
pub(super) const DIRECTIONS: usize = ELEVATIONS * AZIMUTHS;
/// The lowest sun node's c (−18°).
pub(super) fn sun_c0() -> f32 {
    -(18.0f32 / 90.0).sqrt()
}

pub(super) fn c_to_angle(c: f32) -> f32 {
    c.signum() * c * c * FRAC_PI_2
}

pub(super) fn angle_to_c(angle: f32) -> f32 {
    angle.signum() * (angle.abs() / FRAC_PI_2).sqrt()
}

pub(super) fn radius(k: usize) -> f32 {
    let u = k as f32 / (ALTITUDES - 1) as f32;
    GROUND_RADIUS_KM + (TOP_RADIUS_KM - GROUND_RADIUS_KM) * u * u
}

pub(super) fn sun_elevation(j: usize) -> f32 {
    let c0 = sun_c0();
    c_to_angle(c0 + (1.0 - c0) * j as f32 / (SUNS - 1) as f32)
}

/// The local horizon's elevation at radius `r` (radians, ≤ 0).
pub(super) fn horizon(r: f32) -> f32 {
    -(GROUND_RADIUS_KM / r).min(1.0).acos()
}

/// Elevation (radians) at cell coordinate `c` ∈ [−1, 1] about a horizon at `e_h`.
pub(super) fn cell_elevation(c: f32, e_h: f32) -> f32 {
    if c >= 0.0 {
        e_h + c * c * (FRAC_PI_2 - e_h)
    } else {
        e_h - c * c * (FRAC_PI_2 + e_h)
    }
}

/// The cell coordinate of elevation `e` (radians) about a horizon at `e_h`.
pub(super) fn cell_c(e: f32, e_h: f32) -> f32 {
    if e >= e_h {
        ((e - e_h) / (FRAC_PI_2 - e_h)).max(0.0).sqrt()
    } else {
        -((e_h - e) / (FRAC_PI_2 + e_h)).max(0.0).sqrt()
    }
}

/// Centre of elevation cell `m` (radians) about a horizon at `e_h`, and the cell's bounds in
/// sin(elevation).
pub(super) fn elevation_cell(m: usize, e_h: f32) -> (f32, f32, f32) {
    let c = |b: f32| -1.0 + 2.0 * b / ELEVATIONS as f32;
    (
        cell_elevation(c(m as f32 + 0.5), e_h),
        cell_elevation(c(m as f32), e_h).sin(),
        cell_elevation(c(m as f32 + 1.0), e_h).sin(),
    )
}

pub(super) fn azimuth_cell(n: usize) -> f32 {
    PI * (n as f32 + 0.5) / AZIMUTHS as f32
}

pub(super) fn direction(elevation: f32, azimuth: f32) -> Vec3 {
    Vec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
    )
}

/// Linear interpolation position: (lower node, upper node, weight of the upper).
pub(super) fn position(f: f32, n: usize) -> (usize, usize, f32) {
    let f = f.clamp(0.0, (n - 1) as f32);
    let i = (f.floor() as usize).min(n - 2);
    (i, i + 1, f - i as f32)
}

/// Azimuth (0..π) between a direction of zenith cosine `mu` and the sun of zenith cosine `mu_s`
/// whose scattering-angle cosine is `nu`.
pub(super) fn local_azimuth(nu: f32, mu: f32, mu_s: f32) -> f32 {
    let d = ((1.0 - mu * mu) * (1.0 - mu_s * mu_s)).max(0.0).sqrt();
    if d < 1e-6 {
        return 0.0;
    }
    ((nu - mu * mu_s) / d).clamp(-1.0, 1.0).acos()
}

/// Between two sun-elevation nodes (`t` the upper's weight): geometric per channel where both
/// are positive, linear where either is 0. In twilight the light of the sunlit upper air falls
/// by about a factor of 4 from one node to the next (1.6° apart at −6°), which a straight line
/// overshoots by up to 28 % (the tables were 5–90 % above the brute force there,
/// `docs/ACCURACY.md` "Brute force against the tables").
pub(super) fn sun_blend(a: Vec3, b: Vec3, t: f32) -> Vec3 {
    let channel = |a: f32, b: f32| {
        if a > 0.0 && b > 0.0 {
            a * ((b / a).ln() * t).exp()
        } else {
            a + (b - a) * t
        }
    };
    Vec3::new(channel(a.x, b.x), channel(a.y, b.y), channel(a.z, b.z))
}
