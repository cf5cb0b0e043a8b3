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

/// A march piece across which the sun's transmittance changes by more than this factor in a
/// channel is split in two (twilight: the sun's light grazes the ground; a 64-step piece far
/// out put single scattering 7 % off at −6°, `docs/ACCURACY.md`).
const SPLIT_RATIO: f32 = 1.5;
/// How many times a piece may be halved (into at most 2^SPLIT_DEPTH).
const SPLIT_DEPTH: u32 = 2;

/// Calls `piece(middle, length)` (km) for the piece of a march centred at `t` with length `dt`,
/// or for its halves (recursively, `depth` more times) when `sun_transmittance` at its two ends
/// differs by more than [`SPLIT_RATIO`] in a channel.
fn split_piece(
    t: f32,
    dt: f32,
    depth: u32,
    sun_transmittance: &impl Fn(f32) -> Vec3,
    piece: &mut impl FnMut(f32, f32),
) {
    if depth > 0 {
        let (a, b) = (
            sun_transmittance(t - 0.5 * dt),
            sun_transmittance(t + 0.5 * dt),
        );
        let (lo, hi) = (a.min(b), a.max(b));
        if hi.cmpgt(lo * SPLIT_RATIO).any() {
            split_piece(t - 0.25 * dt, 0.5 * dt, depth - 1, sun_transmittance, piece);
            split_piece(t + 0.25 * dt, 0.5 * dt, depth - 1, sun_transmittance, piece);
            return;
        }
    }
    piece(t, dt);
}

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
    let sun_transmittance = |t: f32| {
        let p = origin + dir * t;
        let rp = p.length();
        transmittance.lookup(rp, p.dot(sun) / rp)
    };
    let mut piece = |t: f32, dt: f32| {
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
    };
    // Quadratic spacing: short steps near the viewer where the air is dense; a step that the
    // planet shadow's edge crosses is cut there, so each piece is lit or dark throughout; a
    // piece across which the sun's transmittance changes steeply (twilight) is split.
    let edges = shadow_edges(origin, dir, sun, length);
    for (t, dt) in march_pieces(length, STEPS, &edges) {
        split_piece(t, dt, SPLIT_DEPTH, &sun_transmittance, &mut piece);
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

/// Radiance (per channel) at or below which a texel counts as dark: single scattering in the
/// planet's shadow is exactly 0, which the log-space interpolation below cannot hold.
pub const DARK: f32 = 1e-30;

/// Catmull–Rom spline through `p0..p3` at `t` in 0..1 between `p1` and `p2`.
fn catmull_rom(p0: Vec3, p1: Vec3, p2: Vec3, p3: Vec3, t: f32) -> Vec3 {
    let (t2, t3) = (t * t, t * t * t);
    0.5 * (2.0 * p1
        + (p2 - p0) * t
        + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2
        + (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3)
}

/// The table's radiance for a view at `elevation` radians and `azimuth` radians from the sun's
/// azimuth (any sign, any turn); the WGSL twin (`sky_lookup_view`) does the same arithmetic.
///
/// Below the horizon: bilinear between nodes. Above it: in each channel, the logarithm of the
/// radiance, linear in azimuth and a Catmull–Rom spline over four rows in elevation. In
/// twilight a faint channel's radiance changes by orders of magnitude between rows (the view's
/// transmittance near the horizon, the planet's shadow), which linear interpolation overshoots
/// by up to 140 % (`docs/ACCURACY.md`, "Brute force against the tables"). A row outside the
/// sky (below the horizon row, past the zenith) or dark is replaced by the straight line through
/// the two inner rows; a channel with a dark inner node stays bilinear (exact zeros stay zero).
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
    let linear = row(y0).lerp(row(y1), ty);
    let horizon = (VIEW_HEIGHT - 1) / 2;
    if y0 < horizon || y1 == y0 {
        return linear;
    }
    let dark_row = |y: usize| at(x0, y).min(at(x1, y)).cmple(Vec3::splat(DARK));
    let log_row = |y: usize| {
        let ln = |l: Vec3| {
            let l = l.max(Vec3::splat(DARK));
            Vec3::new(l.x.ln(), l.y.ln(), l.z.ln())
        };
        ln(at(x0, y)).lerp(ln(at(x1, y)), tx)
    };
    let (q1, q2) = (log_row(y0), log_row(y1));
    let (below, above) = (2.0 * q1 - q2, 2.0 * q2 - q1);
    let q0 = if y0 > horizon {
        Vec3::select(dark_row(y0 - 1), below, log_row(y0 - 1))
    } else {
        below
    };
    let q3 = if y1 + 1 < VIEW_HEIGHT {
        Vec3::select(dark_row(y1 + 1), above, log_row(y1 + 1))
    } else {
        above
    };
    let s = catmull_rom(q0, q1, q2, q3, ty);
    let spline = Vec3::new(s.x.exp(), s.y.exp(), s.z.exp());
    Vec3::select(dark_row(y0) | dark_row(y1), linear, spline)
}
