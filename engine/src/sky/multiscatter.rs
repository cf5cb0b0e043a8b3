//! Hillaire 2020 §5.5: the multiple-scattering table Ψms(altitude, sun zenith cosine) — the
//! radiance that second and higher orders add per unit scattering coefficient, from an
//! isotropic phase approximation summed as the geometric series 1 / (1 − f_ms).
//!
//! Any thread; built once per atmosphere. Kilometres, as in `atmosphere`; radiance per unit
//! solar irradiance. Must not: know about the view or the engine.

use glam::Vec3;

use super::atmosphere::{Atmosphere, GROUND_RADIUS_KM, TOP_RADIUS_KM, ray_sphere};
use super::transmittance::{TransmittanceLut, bilinear};

const SIZE: usize = 32;
/// Directions over the sphere per texel (a Fibonacci lattice) and steps along each.
const DIRECTIONS: usize = 64;
const STEPS: usize = 32;

/// Ψms per (sun zenith cosine, altitude), bilinear.
pub struct MultiScatteringLut {
    texels: Vec<Vec3>,
}

impl MultiScatteringLut {
    pub fn build(atmosphere: &Atmosphere, transmittance: &TransmittanceLut) -> Self {
        let mut texels = Vec::with_capacity(SIZE * SIZE);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let mu_s = x as f32 / (SIZE - 1) as f32 * 2.0 - 1.0;
                let h = y as f32 / (SIZE - 1) as f32 * (TOP_RADIUS_KM - GROUND_RADIUS_KM);
                texels.push(texel(
                    atmosphere,
                    transmittance,
                    GROUND_RADIUS_KM + h.max(1e-3),
                    mu_s,
                ));
            }
        }
        Self { texels }
    }

    /// A table of zeros: no second or higher orders (the single-scattering table of
    /// [`super::SkyTables::build_single_scattering`]).
    pub fn none() -> Self {
        Self {
            texels: vec![Vec3::ZERO; SIZE * SIZE],
        }
    }

    /// Ψms at radius `r` (km) for a sun at zenith cosine `mu_s`.
    pub fn lookup(&self, r: f32, mu_s: f32) -> Vec3 {
        let u = (mu_s * 0.5 + 0.5).clamp(0.0, 1.0);
        let v = ((r - GROUND_RADIUS_KM) / (TOP_RADIUS_KM - GROUND_RADIUS_KM)).clamp(0.0, 1.0);
        bilinear(&self.texels, SIZE, SIZE, u, v)
    }
}

fn texel(atmosphere: &Atmosphere, transmittance: &TransmittanceLut, r: f32, mu_s: f32) -> Vec3 {
    let sun = Vec3::new((1.0 - mu_s * mu_s).max(0.0).sqrt(), 0.0, mu_s);
    let origin = Vec3::new(0.0, 0.0, r);
    let isotropic = 1.0 / (4.0 * std::f32::consts::PI);
    let (mut second, mut f_ms) = (Vec3::ZERO, Vec3::ZERO);
    let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
    for i in 0..DIRECTIONS {
        let z = 1.0 - (2.0 * i as f32 + 1.0) / DIRECTIONS as f32;
        let s = (1.0 - z * z).max(0.0).sqrt();
        let phi = golden * i as f32;
        let dir = Vec3::new(s * phi.cos(), s * phi.sin(), z);
        let ground = ray_sphere(r, z, GROUND_RADIUS_KM, true);
        let length = ground
            .or(ray_sphere(r, z, TOP_RADIUS_KM, false))
            .unwrap_or(0.0);
        let dt = length / STEPS as f32;
        let mut throughput = Vec3::ONE;
        for k in 0..STEPS {
            let p = origin + dir * ((k as f32 + 0.5) * dt);
            let rp = p.length();
            let m = atmosphere.medium(rp - GROUND_RADIUS_KM);
            let scattering = m.rayleigh + m.mie;
            let step = (-m.extinction * dt).exp();
            let sun_t = transmittance.lookup(rp, p.dot(sun) / rp);
            let integrate = |s: Vec3| (s - s * step) / m.extinction.max(Vec3::splat(1e-9));
            second += throughput * integrate(sun_t * scattering * isotropic);
            f_ms += throughput * integrate(scattering);
            throughput *= step;
        }
        if let Some(t) = ground {
            let p = origin + dir * t;
            let normal = p.normalize();
            let sun_t = transmittance.lookup(p.length(), normal.dot(sun));
            second += throughput * sun_t * normal.dot(sun).max(0.0) * atmosphere.ground_albedo
                / std::f32::consts::PI;
        }
    }
    // Each direction carries 4π/N sr, and the isotropic phase 1/4π: a plain average.
    let n = DIRECTIONS as f32;
    let (second, f_ms) = (second / n, f_ms / n);
    second / (Vec3::ONE - f_ms).max(Vec3::splat(1e-3))
}
