//! Hillaire 2020 §5.3: the sky-view table — the sky's radiance seen from the ground for one sun
//! elevation, over the view's elevation and its azimuth from the sun — and its lookup, the one
//! both tracers evaluate (`render/cpu/integrator.rs` and its WGSL twin read the same texels).
//!
//! Any thread; built on the CPU once per sky (`SkyTables::build`). Layout: [`VIEW_WIDTH`] ×
//! [`VIEW_HEIGHT`] nodes, row-major, RGB + padding per texel. Column x: azimuth from the sun
//! φ = π·x/(W−1) (the sky is symmetric about the sun's vertical plane). Row y: c = 2y/(H−1) − 1,
//! elevation = sign(c)·c²·90° (dense near the horizon; row (H−1)/2 is the horizon). Values:
//! linear RGB radiance, W·m⁻²·sr⁻¹·nm⁻¹ (solar irradiance included). Below the horizon: the
//! air in front of the ground plus the ground (albedo / π × direct sun). Must not: know the
//! engine's axes (the caller gives elevation and azimuth from the sun).

use glam::Vec3;
use rayon::prelude::*;

use super::atmosphere::{
    Atmosphere, GROUND_RADIUS_KM, SOLAR_IRRADIANCE, TOP_RADIUS_KM, VIEW_ALTITUDE_KM, march_pieces,
    ray_sphere, rayleigh_phase, shadow_edges,
};
use super::orders::ScatteringOrders;
use super::transmittance::TransmittanceLut;

/// Columns of the sky-view table (azimuth from the sun, 0..π).
pub const VIEW_WIDTH: usize = 128;
/// Rows of the sky-view table (elevation, nadir to zenith; odd so the horizon is a row).
pub const VIEW_HEIGHT: usize = 129;
/// Steps of the march (128 in twilight moved the brute-force figures by a few points either
/// way at twice the cost: `docs/ACCURACY.md`).
const STEPS: usize = 64;

/// Builds the sky-view texels for a sun at `sun_elevation` radians.
pub fn build_view(
    atmosphere: &Atmosphere,
    transmittance: &TransmittanceLut,
    multiple: Option<&ScatteringOrders>,
    sun_elevation: f32,
) -> Vec<[f32; 4]> {
    let sun = Vec3::new(sun_elevation.cos(), 0.0, sun_elevation.sin());
    // Rows in parallel (each texel is independent, so the bits do not depend on the threads).
    (0..VIEW_HEIGHT)
        .into_par_iter()
        .flat_map_iter(|y| {
            let c = 2.0 * y as f32 / (VIEW_HEIGHT - 1) as f32 - 1.0;
            let elevation = c.signum() * c * c * std::f32::consts::FRAC_PI_2;
            (0..VIEW_WIDTH).map(move |x| {
                let phi = std::f32::consts::PI * x as f32 / (VIEW_WIDTH - 1) as f32;
                let dir = Vec3::new(
                    elevation.cos() * phi.cos(),
                    elevation.cos() * phi.sin(),
                    elevation.sin(),
                );
                let l = march(atmosphere, transmittance, multiple, dir, sun) * SOLAR_IRRADIANCE;
                [l.x, l.y, l.z, 0.0]
            })
        })
        .collect()
}

/// Radiance per unit solar irradiance arriving at the viewer from direction `dir` (z up).
fn march(
    atmosphere: &Atmosphere,
    transmittance: &TransmittanceLut,
    multiple: Option<&ScatteringOrders>,
    dir: Vec3,
    sun: Vec3,
) -> Vec3 {
    let r0 = GROUND_RADIUS_KM + VIEW_ALTITUDE_KM;
    let origin = Vec3::new(0.0, 0.0, r0);
    let ground = ray_sphere(r0, dir.z, GROUND_RADIUS_KM, true);
    let Some(length) = ground.or(ray_sphere(r0, dir.z, TOP_RADIUS_KM, false)) else {
        return Vec3::ZERO;
    };
    let cos_theta = dir.dot(sun);
    let (phase_r, phase_m) = (
        rayleigh_phase(cos_theta),
        atmosphere.aerosol.phase(cos_theta),
    );
    let (mut radiance, mut throughput) = (Vec3::ZERO, Vec3::ONE);
    // Quadratic spacing: short steps near the viewer where the air is dense; a step that the
    // planet shadow's edge crosses is cut there, so each piece is lit or dark throughout.
    let edges = shadow_edges(origin, dir, sun, length);
    for (t, dt) in march_pieces(length, STEPS, &edges) {
        let p = origin + dir * t;
        let rp = p.length();
        let mu_s = p.dot(sun) / rp;
        let m = atmosphere.medium(rp - GROUND_RADIUS_KM);
        let sun_t = transmittance.lookup(rp, mu_s);
        let mut source = sun_t * (m.rayleigh * phase_r + m.mie * phase_m);
        if let Some(orders) = multiple {
            source += orders.source(rp, mu_s, p.dot(dir) / rp, cos_theta, &m);
        }
        let step = (-m.extinction * dt).exp();
        radiance += throughput * (source - source * step) / m.extinction.max(Vec3::splat(1e-9));
        throughput *= step;
    }
    if let Some(t) = ground {
        let p = origin + dir * t;
        let normal = p.normalize();
        let mu_s = normal.dot(sun);
        let sun_t = transmittance.lookup(p.length(), mu_s);
        // The sun's light and (with the orders) the sky's.
        let sky = multiple.map_or(Vec3::ZERO, |o| o.ground_irradiance(mu_s));
        radiance += throughput * (sun_t * mu_s.max(0.0) + sky) * atmosphere.ground_albedo
            / std::f32::consts::PI;
    }
    radiance
}

/// The table's radiance for a view at `elevation` radians and `azimuth` radians from the sun's
/// azimuth (any sign, any turn). Bilinear between nodes; the WGSL twin does the same arithmetic.
pub fn lookup_view(texels: &[[f32; 4]], elevation: f32, azimuth: f32) -> Vec3 {
    let a = azimuth.abs() % std::f32::consts::TAU;
    let phi = if a > std::f32::consts::PI {
        std::f32::consts::TAU - a
    } else {
        a
    };
    let u = phi / std::f32::consts::PI;
    let e = (elevation / std::f32::consts::FRAC_PI_2).clamp(-1.0, 1.0);
    let v = 0.5 + 0.5 * e.signum() * e.abs().sqrt();
    let fx = u.clamp(0.0, 1.0) * (VIEW_WIDTH - 1) as f32;
    let fy = v.clamp(0.0, 1.0) * (VIEW_HEIGHT - 1) as f32;
    let (x0, y0) = (fx.floor() as usize, fy.floor() as usize);
    let (x1, y1) = ((x0 + 1).min(VIEW_WIDTH - 1), (y0 + 1).min(VIEW_HEIGHT - 1));
    let (tx, ty) = (fx - x0 as f32, fy - y0 as f32);
    let at = |x: usize, y: usize| Vec3::from_slice(&texels[y * VIEW_WIDTH + x][..3]);
    let row = |y: usize| at(x0, y).lerp(at(x1, y), tx);
    row(y0).lerp(row(y1), ty)
}
