//! The transmittance table (Bruneton & Neyret 2008's parametrization, as Hillaire 2020 uses
//! it): transmittance from a point at radius r along zenith cosine μ to the atmosphere's top,
//! for rays that do not meet the ground (those see zero). The table holds the optical depth and
//! interpolates it (bilinear), so a grazing ray's transmittance, which falls by orders of
//! magnitude across a few texels in twilight, is not overshot.
//!
//! Any thread; built once per atmosphere by [`TransmittanceLut::build`] (rows on the rayon
//! pool). Kilometres, as in `atmosphere`. Must not: know about the sun's position or the engine.

use glam::Vec3;
use rayon::prelude::*;

use super::atmosphere::{Atmosphere, GROUND_RADIUS_KM, TOP_RADIUS_KM, ray_sphere};

/// Columns (μ) and rows (r) of the table: 512 × 128 (256 × 64 put twilight single scattering
/// up to 1.9 % off in blue through haze, `docs/ACCURACY.md` "Brute force against the tables").
const WIDTH: usize = 512;
const HEIGHT: usize = 128;
/// Midpoint steps of [`transmittance_exact`] (the sun disc's irradiance at the viewer).
const STEPS: usize = 64;
/// Midpoint steps per texel of the table (grazing rays, 2 × 1100 km, need more than 64).
const TABLE_STEPS: usize = 128;

/// Optical depth per (μ, r), bilinear.
pub struct TransmittanceLut {
    texels: Vec<Vec3>,
}

fn horizon_length() -> f32 {
    (TOP_RADIUS_KM * TOP_RADIUS_KM - GROUND_RADIUS_KM * GROUND_RADIUS_KM).sqrt()
}

/// Optical depth × extinction integrated exactly enough (midpoint rule, `STEPS` steps) from
/// radius `r` along `mu` to the top; infinite when the ray meets the ground.
pub fn transmittance_exact(atmosphere: &Atmosphere, r: f32, mu: f32) -> Vec3 {
    optical_depth(atmosphere, r, mu, STEPS).map_or(Vec3::ZERO, |d| (-d).exp())
}

/// Optical depth per channel from radius `r` km along zenith cosine `mu` to the top, by the
/// midpoint rule in `steps` steps; `None` when the ray meets the ground.
fn optical_depth(atmosphere: &Atmosphere, r: f32, mu: f32, steps: usize) -> Option<Vec3> {
    if ray_sphere(r, mu, GROUND_RADIUS_KM, true).is_some() {
        return None;
    }
    let Some(length) = ray_sphere(r, mu, TOP_RADIUS_KM, false) else {
        return Some(Vec3::ZERO);
    };
    let aerosol = atmosphere.aerosol.scattering();
    let dt = length / steps as f32;
    let mut depth = Vec3::ZERO;
    for i in 0..steps {
        let t = (i as f32 + 0.5) * dt;
        let ri = (r * r + t * t + 2.0 * r * mu * t).sqrt();
        depth += atmosphere
            .medium_with(ri - GROUND_RADIUS_KM, aerosol)
            .extinction
            * dt;
    }
    Some(depth)
}

impl TransmittanceLut {
    pub fn build(atmosphere: &Atmosphere) -> Self {
        let h = horizon_length();
        let texels = (0..HEIGHT)
            .into_par_iter()
            .flat_map_iter(|y| {
                (0..WIDTH).map(move |x| {
                    let x_mu = x as f32 / (WIDTH - 1) as f32;
                    let x_r = y as f32 / (HEIGHT - 1) as f32;
                    let rho = h * x_r;
                    let r = (rho * rho + GROUND_RADIUS_KM * GROUND_RADIUS_KM).sqrt();
                    let d_min = TOP_RADIUS_KM - r;
                    let d_max = rho + h;
                    let d = d_min + x_mu * (d_max - d_min);
                    let mu = if d == 0.0 {
                        1.0
                    } else {
                        ((h * h - rho * rho - d * d) / (2.0 * r * d)).clamp(-1.0, 1.0)
                    };
                    // The last column grazes the ground: nudge it up so it stays lit.
                    optical_depth(atmosphere, r, mu.max(-1.0) + 1e-6, TABLE_STEPS)
                        .unwrap_or(Vec3::splat(1e4))
                })
            })
            .collect();
        Self { texels }
    }

    /// Transmittance from radius `r` (km) along zenith cosine `mu` to space.
    pub fn lookup(&self, r: f32, mu: f32) -> Vec3 {
        if ray_sphere(r, mu, GROUND_RADIUS_KM, true).is_some() {
            return Vec3::ZERO;
        }
        let h = horizon_length();
        let r = r.clamp(GROUND_RADIUS_KM, TOP_RADIUS_KM);
        let rho = (r * r - GROUND_RADIUS_KM * GROUND_RADIUS_KM)
            .max(0.0)
            .sqrt();
        let disc = r * r * (mu * mu - 1.0) + TOP_RADIUS_KM * TOP_RADIUS_KM;
        let d = (-r * mu + disc.max(0.0).sqrt()).max(0.0);
        let d_min = TOP_RADIUS_KM - r;
        let d_max = rho + h;
        let x_mu = ((d - d_min) / (d_max - d_min)).clamp(0.0, 1.0);
        let x_r = (rho / h).clamp(0.0, 1.0);
        (-bilinear(&self.texels, WIDTH, HEIGHT, x_mu, x_r)).exp()
    }
}

/// Bilinear lookup of a row-major table at normalized node coordinates (0 and 1 are the first
/// and last nodes).
pub fn bilinear(texels: &[Vec3], width: usize, height: usize, u: f32, v: f32) -> Vec3 {
    let fx = u.clamp(0.0, 1.0) * (width - 1) as f32;
    let fy = v.clamp(0.0, 1.0) * (height - 1) as f32;
    let (x0, y0) = (fx.floor() as usize, fy.floor() as usize);
    let (x1, y1) = ((x0 + 1).min(width - 1), (y0 + 1).min(height - 1));
    let (tx, ty) = (fx - x0 as f32, fy - y0 as f32);
    let row = |y: usize| texels[y * width + x0].lerp(texels[y * width + x1], tx);
    row(y0).lerp(row(y1), ty)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_matches_direct_integration() {
        let atmosphere = Atmosphere {
            haze: 1.0,
            ozone: 1.0,
            ground_albedo: Vec3::splat(0.3),
            aerosol: Default::default(),
        };
        let lut = TransmittanceLut::build(&atmosphere);
        let r = GROUND_RADIUS_KM + 0.01;
        for mu in [1.0f32, 0.7, 0.3, 0.1, 0.02] {
            let exact = transmittance_exact(&atmosphere, r, mu);
            let table = lut.lookup(r, mu);
            assert!(
                (exact - table).abs().max_element() < 2e-3 * exact.max_element().max(0.05),
                "mu {mu}: {exact} vs {table}"
            );
        }
        assert_eq!(lut.lookup(r, -0.2), Vec3::ZERO);
    }
}
