//! The physical sky's spherical atmosphere rewritten in f64 for the brute-force reference
//! (`sky_brute_force`): the media per altitude (Rayleigh, the level's aerosols, ozone), the
//! phase functions, ray–sphere distances and the optical depth to space by fine quadrature.
//!
//! Test thread (rayon workers); pure functions. Kilometres and km⁻¹ as in
//! `engine/src/sky/atmosphere.rs`, whose *parameters* it takes (`candela::sky` constants and the
//! level's `PhysicalSky` fields); the density profiles and phase functions are written here
//! again from their definitions (Hillaire 2020's preset: exponential Rayleigh and aerosols,
//! ozone a tent from 10 to 40 km peaking at 25 km; Rayleigh and Cornette–Shanks phases).
//! Channels are the engine's R, G, B. Must not: use the engine's tables, its transmittance,
//! multiple-scattering or sky-view code (it is what they are checked against).

use std::f64::consts::PI;

use candela::sky::{
    GROUND_RADIUS_KM, OZONE_ABSORPTION, PhysicalSky, RAYLEIGH_SCALE_HEIGHT_KM, RAYLEIGH_SCATTERING,
    TOP_RADIUS_KM,
};
use glam::DVec3;

/// Planet radius, km.
pub fn ground_radius() -> f64 {
    GROUND_RADIUS_KM as f64
}

/// Radius of the atmosphere's top, km.
pub fn top_radius() -> f64 {
    TOP_RADIUS_KM as f64
}

/// Altitudes where the ozone tent's density has a kink, km.
const OZONE_KINKS_KM: [f64; 3] = [10.0, 25.0, 40.0];

/// Scattering and extinction at one point, per channel, km⁻¹.
#[derive(Clone, Copy, Debug)]
pub struct Media {
    pub rayleigh: DVec3,
    pub aerosol: DVec3,
    pub extinction: DVec3,
}

impl Media {
    pub fn scattering(&self) -> DVec3 {
        self.rayleigh + self.aerosol
    }
}

/// One atmosphere in f64: what `PhysicalSky` declares, nothing precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Air {
    rayleigh: DVec3,
    rayleigh_height: f64,
    /// Aerosol scattering at the ground (haze included), km⁻¹ per channel.
    aerosol: DVec3,
    /// Aerosol absorption at the ground (haze included), km⁻¹, grey.
    aerosol_absorption: f64,
    aerosol_height: f64,
    ozone: DVec3,
    g: f64,
    forward_share: f64,
    forward_g: f64,
    /// Lambertian ground reflectance per channel.
    pub albedo: DVec3,
    /// Largest extinction anywhere in the shell over the channels (a majorant), km⁻¹.
    pub majorant: f64,
}

impl Air {
    pub fn new(sky: &PhysicalSky) -> Self {
        let a = sky.aerosol;
        let haze = sky.haze as f64;
        // Ångström's law about 550 nm at the channels' wavelengths (680, 550, 440 nm).
        let angstrom =
            |nm: f64| (a.scattering_per_km as f64) * (nm / 550.0).powf(-a.angstrom as f64);
        let aerosol = DVec3::new(angstrom(680.0), angstrom(550.0), angstrom(440.0)) * haze;
        let aerosol_absorption = a.absorption_per_km as f64 * haze;
        let rayleigh = RAYLEIGH_SCATTERING.as_dvec3();
        let ozone = OZONE_ABSORPTION.as_dvec3() * sky.ozone as f64;
        let peak = rayleigh + aerosol + DVec3::splat(aerosol_absorption) + ozone;
        Self {
            rayleigh,
            rayleigh_height: RAYLEIGH_SCALE_HEIGHT_KM as f64,
            aerosol,
            aerosol_absorption,
            aerosol_height: a.scale_height_km as f64,
            ozone,
            g: a.g as f64,
            forward_share: a.forward_share as f64,
            forward_g: a.forward_g as f64,
            albedo: DVec3::from(sky.ground_albedo.map(f64::from)),
            majorant: peak.max_element(),
        }
    }

    /// The media at altitude `h` km (below the ground counts as the ground).
    pub fn media(&self, h: f64) -> Media {
        let h = h.max(0.0);
        let rayleigh = self.rayleigh * (-h / self.rayleigh_height).exp();
        let aerosol_density = (-h / self.aerosol_height).exp();
        let ozone_density = (1.0 - (h - OZONE_KINKS_KM[1]).abs() / 15.0).max(0.0);
        let aerosol = self.aerosol * aerosol_density;
        Media {
            rayleigh,
            aerosol,
            extinction: rayleigh
                + aerosol
                + DVec3::splat(self.aerosol_absorption * aerosol_density)
                + self.ozone * ozone_density,
        }
    }

    /// Extinction at radius `r` km.
    fn extinction(&self, r: f64) -> DVec3 {
        self.media(r - ground_radius()).extinction
    }

    /// The aerosols' phase function (sr⁻¹): the broad and forward Cornette–Shanks lobes.
    pub fn aerosol_phase(&self, cos_theta: f64) -> f64 {
        (1.0 - self.forward_share) * cornette_shanks(cos_theta, self.g)
            + self.forward_share * cornette_shanks(cos_theta, self.forward_g)
    }

    /// The lobes the aerosol phase function is sampled by: (share, Henyey–Greenstein g).
    pub fn aerosol_lobes(&self) -> [(f64, f64); 2] {
        [
            (1.0 - self.forward_share, self.g),
            (self.forward_share, self.forward_g),
        ]
    }

    /// Radiance per unit solar irradiance scattered towards the viewer per km at a point with
    /// media `m`, for scattering-angle cosine `cos_theta`: σ_R p_R + σ_A p_A, km⁻¹ sr⁻¹.
    pub fn phase_scattering(&self, m: &Media, cos_theta: f64) -> DVec3 {
        m.rayleigh * rayleigh_phase(cos_theta) + m.aerosol * self.aerosol_phase(cos_theta)
    }

    /// Optical depth per channel from radius `r` km along zenith cosine `mu` to the top, or
    /// `None` when the ray meets the ground (the planet's shadow). The ray is cut where the
    /// altitude turns (its lowest point) and where it crosses the ozone tent's kinks (10, 25,
    /// 40 km); each piece by composite Simpson in u with t = t_low + (t_high − t_low)·u², the
    /// nodes dense at its lower end where the air is densest. `intervals` per piece;
    /// `sky_brute_force::brute_force_quadrature_is_converged` checks it against 8× as many.
    pub fn optical_depth(&self, r: f64, mu: f64, intervals: usize) -> Option<DVec3> {
        if ray_sphere(r, mu, ground_radius(), true).is_some() {
            return None;
        }
        let length = ray_sphere(r, mu, top_radius(), false).unwrap_or(0.0);
        let at = |t: f64| self.extinction((r * r + t * t + 2.0 * r * mu * t).max(0.0).sqrt());
        // The lowest point (perhaps behind the start) and its radius squared.
        let lowest = -r * mu;
        let lowest_r2 = r * r * (1.0 - mu * mu);
        let mut cuts = vec![0.0, length, lowest.clamp(0.0, length)];
        for h in OZONE_KINKS_KM {
            let k = (ground_radius() + h).powi(2) - lowest_r2;
            if k > 0.0 {
                let d = k.sqrt();
                cuts.extend(
                    [lowest - d, lowest + d]
                        .into_iter()
                        .filter(|t| (0.0..length).contains(t)),
                );
            }
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        let mut depth = DVec3::ZERO;
        for w in cuts.windows(2) {
            depth += if w[1] <= lowest {
                simpson_squared(&at, w[1], w[0], intervals)
            } else {
                simpson_squared(&at, w[0], w[1], intervals)
            };
        }
        Some(depth)
    }

    /// Transmittance to space from radius `r` along `mu` (zero in the planet's shadow).
    pub fn transmittance(&self, r: f64, mu: f64, intervals: usize) -> DVec3 {
        self.optical_depth(r, mu, intervals)
            .map_or(DVec3::ZERO, |d| (-d).exp())
    }
}

/// ∫ f(t) dt over [from, to] (either order) with t = from + (to − from)·u², Simpson in u.
fn simpson_squared(f: &impl Fn(f64) -> DVec3, from: f64, to: f64, intervals: usize) -> DVec3 {
    let n = intervals.max(2) & !1;
    let span = to - from;
    let mut sum = DVec3::ZERO;
    for i in 0..=n {
        let u = i as f64 / n as f64;
        // dt = 2·span·u du
        let value = f(from + span * u * u) * (2.0 * span * u);
        let weight = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        sum += value * weight;
    }
    (sum / (3.0 * n as f64)).abs()
}

/// Rayleigh phase function, sr⁻¹.
pub fn rayleigh_phase(cos_theta: f64) -> f64 {
    3.0 / (16.0 * PI) * (1.0 + cos_theta * cos_theta)
}

/// Cornette–Shanks phase function with asymmetry `g`, sr⁻¹.
pub fn cornette_shanks(cos_theta: f64, g: f64) -> f64 {
    let k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
    k * (1.0 + cos_theta * cos_theta) / (1.0 + g * g - 2.0 * g * cos_theta).powf(1.5)
}

/// Henyey–Greenstein phase function (the proposal that samples a Cornette–Shanks lobe), sr⁻¹.
pub fn henyey_greenstein(cos_theta: f64, g: f64) -> f64 {
    (1.0 - g * g) / (4.0 * PI * (1.0 + g * g - 2.0 * g * cos_theta).powf(1.5))
}

/// Distance from radius `r` along zenith cosine `mu` to the sphere of `radius` (the near root
/// for the ground, the far one for the top), or `None` when missed or behind (≤ 1 mm ahead).
pub fn ray_sphere(r: f64, mu: f64, radius: f64, near: bool) -> Option<f64> {
    let disc = r * r * (mu * mu - 1.0) + radius * radius;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let t = if near { -r * mu - s } else { -r * mu + s };
    (t > 1e-6).then_some(t)
}
