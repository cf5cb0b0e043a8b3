//! The atmosphere's media: Hillaire's (2020) Earth preset — Rayleigh, Mie (aerosols, scaled by
//! `haze`) and ozone — as scattering and extinction per altitude, and their phase functions.
//!
//! Any thread; pure functions. Lengths here are **kilometres** (coefficients per km): the
//! precomputation works at planet scale; nothing outside `sky` sees them. Colour channels are
//! linear Rec.709 R, G, B taken as 680, 550 and 440 nm (Bruneton 2017's choice).
//! Must not: know about tables or the engine's axes.

use glam::Vec3;

/// Planet radius, km.
pub const GROUND_RADIUS_KM: f32 = 6360.0;
/// Radius of the atmosphere's top, km.
pub const TOP_RADIUS_KM: f32 = 6460.0;
/// Altitude of the viewer the sky is seen from, km (10 m above the ground).
pub const VIEW_ALTITUDE_KM: f32 = 0.01;

const RAYLEIGH_SCATTERING: Vec3 = Vec3::new(5.802e-3, 13.558e-3, 33.1e-3);
const RAYLEIGH_SCALE_HEIGHT_KM: f32 = 8.0;
const MIE_SCATTERING: f32 = 3.996e-3;
const MIE_EXTINCTION: f32 = 4.440e-3;
const MIE_SCALE_HEIGHT_KM: f32 = 1.2;
/// Cornette–Shanks asymmetry of the aerosols.
pub const MIE_G: f32 = 0.8;
const OZONE_ABSORPTION: Vec3 = Vec3::new(0.650e-3, 1.881e-3, 0.085e-3);

/// Solar spectral irradiance at the top of the atmosphere in linear Rec.709 RGB, in the
/// CIE-Y-normalised W·m⁻²·nm⁻¹ of Mitsuba's sunsky (radiance then comes out in
/// W·m⁻²·sr⁻¹·nm⁻¹). Colour: a 5778 K black body (Kim et al.'s Planckian locus: x = 0.3263,
/// y = 0.3357, in Rec.709: 1.1109, 0.9757, 0.9141 at luminance 1). Level: luminance 1.6836,
/// calibrated once so that the direct normal irradiance at 60° elevation with
/// [`super::HAZE_TURBIDITY_3`] matches Mitsuba's turbidity-3 sun (1.2863): 9 % below the
/// measured solar spectrum near 555 nm (≈ 1.85), the gap between Hosek–Wilkie's sun and a
/// plane atmosphere (`docs/ACCURACY.md`, "Physical sky").
pub const SOLAR_IRRADIANCE: Vec3 = Vec3::new(1.8703, 1.6426, 1.5391);

/// The media at one altitude: scattering by molecules and aerosols, and total extinction.
#[derive(Clone, Copy, Debug)]
pub struct Medium {
    pub rayleigh: Vec3,
    pub mie: Vec3,
    pub extinction: Vec3,
}

/// The Earth preset with its two knobs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Atmosphere {
    /// Multiplier of the preset's aerosol density (1 = Hillaire's clear sky), ≥ 0.
    pub haze: f32,
    /// Multiplier of the ozone layer's density (1 = preset), ≥ 0.
    pub ozone: f32,
    /// Lambertian ground reflectance (linear RGB, 0..1).
    pub ground_albedo: Vec3,
}

impl Atmosphere {
    /// The media at altitude `h` km above the ground.
    pub fn medium(&self, h: f32) -> Medium {
        let h = h.max(0.0);
        let rayleigh = RAYLEIGH_SCATTERING * (-h / RAYLEIGH_SCALE_HEIGHT_KM).exp();
        let mie_density = self.haze * (-h / MIE_SCALE_HEIGHT_KM).exp();
        // Ozone: a tent 30 km wide peaking at 25 km.
        let ozone_density = if h < 25.0 {
            h / 15.0 - 2.0 / 3.0
        } else {
            8.0 / 3.0 - h / 15.0
        };
        let ozone = OZONE_ABSORPTION * (self.ozone * ozone_density.max(0.0));
        let mie = Vec3::splat(MIE_SCATTERING * mie_density);
        Medium {
            rayleigh,
            mie,
            extinction: rayleigh + Vec3::splat(MIE_EXTINCTION * mie_density) + ozone,
        }
    }
}

/// Rayleigh phase function (sr⁻¹) at the cosine of the scattering angle.
pub fn rayleigh_phase(cos_theta: f32) -> f32 {
    3.0 / (16.0 * std::f32::consts::PI) * (1.0 + cos_theta * cos_theta)
}

/// Cornette–Shanks phase function (sr⁻¹) with asymmetry [`MIE_G`].
pub fn mie_phase(cos_theta: f32) -> f32 {
    let g = MIE_G;
    let k = 3.0 / (8.0 * std::f32::consts::PI) * (1.0 - g * g) / (2.0 + g * g);
    k * (1.0 + cos_theta * cos_theta) / (1.0 + g * g - 2.0 * g * cos_theta).powf(1.5)
}

/// Distance along a ray from radius `r` (km) with zenith cosine `mu` to the sphere of radius
/// `radius`, or `None` when the ray misses it (the far root for the top, the near for the ground).
pub fn ray_sphere(r: f32, mu: f32, radius: f32, near: bool) -> Option<f32> {
    let disc = r * r * (mu * mu - 1.0) + radius * radius;
    if disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let t = if near { -r * mu - s } else { -r * mu + s };
    (t >= 0.0).then_some(t)
}
