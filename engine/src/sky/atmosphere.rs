//! The atmosphere's media: Hillaire's (2020) Earth preset — Rayleigh, Mie (aerosols, scaled by
//! `haze`) and ozone — as scattering and extinction per altitude, and their phase functions.
//!
//! Any thread; pure functions. Lengths here are **kilometres** (coefficients per km): the
//! precomputation works at planet scale; nothing outside `sky` sees them. Colour channels are
//! linear Rec.709 R, G, B taken as 680, 550 and 440 nm (Bruneton 2017's choice).
//! Must not: know about tables or the engine's axes.

use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::error::SkyError;
use super::physical::check;

/// Planet radius, km.
pub const GROUND_RADIUS_KM: f32 = 6360.0;
/// Radius of the atmosphere's top, km.
pub const TOP_RADIUS_KM: f32 = 6460.0;
/// Altitude of the viewer the sky is seen from, km (10 m above the ground).
pub const VIEW_ALTITUDE_KM: f32 = 0.01;

/// Rayleigh scattering coefficient at the ground per channel (R, G, B), km⁻¹.
pub const RAYLEIGH_SCATTERING: Vec3 = Vec3::new(5.802e-3, 13.558e-3, 33.1e-3);
/// Scale height of the molecules' exponential density, km.
pub const RAYLEIGH_SCALE_HEIGHT_KM: f32 = 8.0;
/// Wavelengths the three channels are taken at, nm (R, G, B).
const CHANNEL_NM: [f32; 3] = [680.0, 550.0, 440.0];
/// Ozone absorption coefficient per channel at the layer's peak (25 km; density a tent from
/// 10 to 40 km) per unit `ozone`, km⁻¹.
pub const OZONE_ABSORPTION: Vec3 = Vec3::new(0.650e-3, 1.881e-3, 0.085e-3);

/// Solar spectral irradiance at the top of the atmosphere in linear Rec.709 RGB, in the
/// CIE-Y-normalised W·m⁻²·nm⁻¹ of Mitsuba's sunsky (radiance then comes out in
/// W·m⁻²·sr⁻¹·nm⁻¹). Calibrated once, per channel, so that the direct normal irradiance at
/// 60° elevation through [`Aerosol::TURBIDITY_3`] with [`super::HAZE_TURBIDITY_3`] is Mitsuba's
/// turbidity-3 sun in colour and level (Rec.709 (1.4991, 1.2553, 0.9667), luminance 1.2863;
/// `engine/tests/engine/sky_reference.rs`, `docs/ACCURACY.md` "Physical sky"). Luminance
/// 1.7370, 6 % below the measured solar spectrum near 555 nm (≈ 1.85).
pub const SOLAR_IRRADIANCE: Vec3 = Vec3::new(1.7441, 1.7308, 1.8086);

/// The media at one altitude: scattering by molecules and aerosols, and total extinction.
#[derive(Clone, Copy, Debug)]
pub struct Medium {
    pub rayleigh: Vec3,
    pub mie: Vec3,
    pub extinction: Vec3,
}

/// The aerosols (Mie scattering) per unit of `haze`: how much they scatter and absorb, how
/// the scattering depends on the wavelength (Ångström's law, β(λ) = β₅₅₀ (λ / 550 nm)^−α),
/// how high they reach, and how forward their phase function is (Cornette–Shanks).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Aerosol {
    /// Scattering coefficient at 550 nm at the ground per unit haze, km⁻¹, 0..=1.
    pub scattering_per_km: f32,
    /// Absorption coefficient at the ground per unit haze, km⁻¹ (grey), 0..=1.
    pub absorption_per_km: f32,
    /// Ångström exponent α of the scattering, 0..=4 (0: grey, Hillaire's preset).
    pub angstrom: f32,
    /// Scale height of the density's exponential fall-off, km, 0.1..=20.
    pub scale_height_km: f32,
    /// Cornette–Shanks asymmetry g of the broad lobe, 0..=0.99.
    pub g: f32,
    /// Share of the scattering in a second, forward lobe (the coarse particles' circumsolar
    /// glow), 0..=1 (0: one lobe, Hillaire's preset).
    pub forward_share: f32,
    /// Cornette–Shanks asymmetry of the forward lobe, 0..=0.99.
    pub forward_g: f32,
}

impl Aerosol {
    /// Hillaire's (2020) Earth preset: grey aerosols, 1.2 km high, g = 0.8.
    pub const EARTH: Self = Self {
        scattering_per_km: 3.996e-3,
        absorption_per_km: 0.444e-3,
        angstrom: 0.0,
        scale_height_km: 1.2,
        g: 0.8,
        forward_share: 0.0,
        forward_g: 0.9,
    };

    /// Fitted to Mitsuba's Hosek–Wilkie sky at turbidity 3 (with [`super::HAZE_TURBIDITY_3`],
    /// ground albedo 0.3): fine particles that scatter blue (Ångström α = 3) and do not absorb,
    /// 6 km high, a nearly isotropic broad lobe (g = 0.05) and 30 % of the scattering in a
    /// forward lobe (g = 0.75). Chosen over a grid of g, the forward lobe, α, the scale height
    /// and the absorption by the sky's luminance and zenith colour against the reference
    /// (`docs/ACCURACY.md`, "Physical sky").
    pub const TURBIDITY_3: Self = Self {
        scattering_per_km: 3.996e-3,
        absorption_per_km: 0.0,
        angstrom: 3.0,
        scale_height_km: 6.0,
        g: 0.05,
        forward_share: 0.3,
        forward_g: 0.75,
    };

    /// Whether this is [`Aerosol::EARTH`] (a level that does not write `aerosol` gets it).
    pub fn is_earth(&self) -> bool {
        *self == Self::EARTH
    }

    /// Checks every field; the error names it (`aerosol.g`, …).
    pub fn validate(&self) -> Result<(), SkyError> {
        check(
            "aerosol.scattering_per_km",
            self.scattering_per_km,
            0.0,
            1.0,
            "0..=1",
        )?;
        check(
            "aerosol.absorption_per_km",
            self.absorption_per_km,
            0.0,
            1.0,
            "0..=1",
        )?;
        check("aerosol.angstrom", self.angstrom, 0.0, 4.0, "0..=4")?;
        check(
            "aerosol.scale_height_km",
            self.scale_height_km,
            0.1,
            20.0,
            "0.1..=20",
        )?;
        check("aerosol.g", self.g, 0.0, 0.99, "0..=0.99")?;
        check(
            "aerosol.forward_share",
            self.forward_share,
            0.0,
            1.0,
            "0..=1",
        )?;
        check("aerosol.forward_g", self.forward_g, 0.0, 0.99, "0..=0.99")
    }

    /// The aerosols' phase function (sr⁻¹) at the cosine of the scattering angle: the broad
    /// lobe and the forward lobe mixed by `forward_share`.
    pub fn phase(&self, cos_theta: f32) -> f32 {
        let broad = mie_phase(cos_theta, self.g);
        if self.forward_share == 0.0 {
            return broad;
        }
        broad * (1.0 - self.forward_share)
            + mie_phase(cos_theta, self.forward_g) * self.forward_share
    }

    /// Scattering coefficient per channel at the ground per unit haze, km⁻¹.
    pub fn scattering(&self) -> Vec3 {
        Vec3::from(CHANNEL_NM.map(|nm| self.scattering_per_km * (nm / 550.0).powf(-self.angstrom)))
    }
}

impl Default for Aerosol {
    fn default() -> Self {
        Self::EARTH
    }
}

/// The Earth preset with its knobs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Atmosphere {
    /// Multiplier of the preset's aerosol density (1 = Hillaire's clear sky), ≥ 0.
    pub haze: f32,
    /// Multiplier of the ozone layer's density (1 = preset), ≥ 0.
    pub ozone: f32,
    /// Lambertian ground reflectance (linear RGB, 0..1).
    pub ground_albedo: Vec3,
    /// The aerosols per unit haze.
    pub aerosol: Aerosol,
}

impl Atmosphere {
    /// The media at altitude `h` km above the ground.
    pub fn medium(&self, h: f32) -> Medium {
        self.medium_with(h, self.aerosol.scattering())
    }

    /// [`Atmosphere::medium`] with the aerosols' scattering per unit haze given
    /// (`self.aerosol.scattering()`, hoisted out of a loop).
    pub fn medium_with(&self, h: f32, aerosol_scattering: Vec3) -> Medium {
        let h = h.max(0.0);
        let rayleigh = RAYLEIGH_SCATTERING * (-h / RAYLEIGH_SCALE_HEIGHT_KM).exp();
        let mie_density = self.haze * (-h / self.aerosol.scale_height_km).exp();
        // Ozone: a tent 30 km wide peaking at 25 km.
        let ozone_density = if h < 25.0 {
            h / 15.0 - 2.0 / 3.0
        } else {
            8.0 / 3.0 - h / 15.0
        };
        let ozone = OZONE_ABSORPTION * (self.ozone * ozone_density.max(0.0));
        let mie = aerosol_scattering * mie_density;
        let mie_absorption = self.aerosol.absorption_per_km * mie_density;
        Medium {
            rayleigh,
            mie,
            extinction: rayleigh + mie + Vec3::splat(mie_absorption) + ozone,
        }
    }
}

/// Rayleigh phase function (sr⁻¹) at the cosine of the scattering angle.
pub fn rayleigh_phase(cos_theta: f32) -> f32 {
    3.0 / (16.0 * std::f32::consts::PI) * (1.0 + cos_theta * cos_theta)
}

/// Cornette–Shanks phase function (sr⁻¹) with asymmetry `g`.
pub fn mie_phase(cos_theta: f32, g: f32) -> f32 {
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

/// Distances along the ray from `origin` along `dir` (both unit-free km, planet centred) within
/// (0, `length`) where it enters or leaves the planet's shadow (a cylinder of the ground's
/// radius behind the planet, away from `sun`), in increasing order.
pub fn shadow_edges(origin: Vec3, dir: Vec3, sun: Vec3, length: f32) -> Vec<f32> {
    // |p|² − (p·s)² = R² with p = o + t·d, in f64: |o|² and R² are 4·10⁷ km² apart by ~100.
    let (o, d, s) = (origin.as_dvec3(), dir.as_dvec3(), sun.as_dvec3());
    let (ds, os) = (d.dot(s), o.dot(s));
    let a = 1.0 - ds * ds;
    let b = 2.0 * (o.dot(d) - os * ds);
    let ground = GROUND_RADIUS_KM as f64;
    let c = o.length_squared() - os * os - ground * ground;
    let disc = b * b - 4.0 * a * c;
    if a < 1e-12 || disc < 0.0 {
        return Vec::new();
    }
    let q = disc.sqrt();
    let mut edges: Vec<f32> = [(-b - q) / (2.0 * a), (-b + q) / (2.0 * a)]
        .into_iter()
        .filter(|&t| t > 0.0 && t < length as f64 && os + t * ds < 0.0)
        .map(|t| t as f32)
        .collect();
    edges.sort_by(f32::total_cmp);
    edges
}

/// The pieces of a march over [0, `length`] km in `steps` quadratically spaced steps (short near
/// the origin, where the air is dense), each step cut where it crosses one of `edges` (km along
/// the ray, e.g. [`shadow_edges`]) so that every piece is lit or dark throughout: (the piece's
/// middle, its length), km, in order.
pub fn march_pieces(length: f32, steps: usize, edges: &[f32]) -> impl Iterator<Item = (f32, f32)> {
    let (mut k, mut t_prev) = (0usize, 0.0f32);
    std::iter::from_fn(move || {
        while k < steps {
            let t_end = length * ((k + 1) as f32 / steps as f32).powi(2);
            if t_prev < t_end {
                let t_next = edges
                    .iter()
                    .copied()
                    .find(|&e| e > t_prev && e < t_end)
                    .unwrap_or(t_end);
                let piece = (0.5 * (t_prev + t_next), t_next - t_prev);
                t_prev = t_next;
                return Some(piece);
            }
            k += 1;
        }
        None
    })
}
