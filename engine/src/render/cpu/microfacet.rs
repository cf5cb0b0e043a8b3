//! Microfacet and Fresnel terms (twin: `shaders/shared/microfacet.wgsl`).
//!
//! Owns: the GGX (Trowbridge–Reitz) distribution with height-correlated Smith masking, visible
//! normal sampling (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 2018) and
//! the Fresnel equations. Everything is in the local shading frame (normal = +z), isotropic,
//! with `alpha` = roughness².
//! Must not: know materials or scene data.

use glam::{Vec2, Vec3};

use super::sampling::PI;

/// GGX normal distribution `D(m)` for a microfacet normal with `m.z = cos θm`.
#[inline]
pub fn ggx_d(m: Vec3, alpha: f32) -> f32 {
    if m.z <= 0.0 {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let t = m.z * m.z * (a2 - 1.0) + 1.0;
    a2 / (PI * t * t)
}

/// Smith Λ for direction `w` (`w.z` may be negative; the slope only depends on |cos θ|).
#[inline]
pub fn ggx_lambda(w: Vec3, alpha: f32) -> f32 {
    let z2 = w.z * w.z;
    if z2 <= 0.0 {
        return f32::INFINITY;
    }
    let tan2 = (w.x * w.x + w.y * w.y) / z2;
    0.5 * (-1.0 + (1.0 + alpha * alpha * tan2).sqrt())
}

/// Smith masking of one direction.
#[inline]
pub fn ggx_g1(w: Vec3, alpha: f32) -> f32 {
    1.0 / (1.0 + ggx_lambda(w, alpha))
}

/// Height-correlated Smith masking-shadowing of a pair of directions.
#[inline]
pub fn ggx_g2(wo: Vec3, wi: Vec3, alpha: f32) -> f32 {
    1.0 / (1.0 + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha))
}

/// Samples a visible microfacet normal for `wo` (which must have `wo.z > 0`).
/// Its density is [`ggx_vndf_pdf`].
#[inline]
pub fn ggx_sample_vndf(wo: Vec3, alpha: f32, u: Vec2) -> Vec3 {
    let vh = Vec3::new(alpha * wo.x, alpha * wo.y, wo.z).normalize();
    let len2 = vh.x * vh.x + vh.y * vh.y;
    let t1 = if len2 > 0.0 {
        Vec3::new(-vh.y, vh.x, 0.0) / len2.sqrt()
    } else {
        Vec3::X
    };
    let t2 = vh.cross(t1);
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    let p1 = r * phi.cos();
    let s = 0.5 * (1.0 + vh.z);
    let p2 = (1.0 - s) * (1.0 - p1 * p1).max(0.0).sqrt() + s * r * phi.sin();
    let nh = t1 * p1 + t2 * p2 + vh * (1.0 - p1 * p1 - p2 * p2).max(0.0).sqrt();
    Vec3::new(alpha * nh.x, alpha * nh.y, nh.z.max(1e-7)).normalize()
}

/// Density of [`ggx_sample_vndf`] over microfacet normals: `G1(wo) max(0, wo·m) D(m) / wo.z`.
#[inline]
pub fn ggx_vndf_pdf(wo: Vec3, m: Vec3, alpha: f32) -> f32 {
    let wo_m = wo.dot(m);
    if wo_m <= 0.0 || wo.z <= 0.0 {
        return 0.0;
    }
    ggx_g1(wo, alpha) * wo_m * ggx_d(m, alpha) / wo.z
}

/// Schlick's approximation of conductor Fresnel reflectance.
#[inline]
pub fn fresnel_schlick(f0: Vec3, cos_theta: f32) -> Vec3 {
    let c = (1.0 - cos_theta.clamp(0.0, 1.0)).powi(5);
    f0 + (Vec3::ONE - f0) * c
}

/// Unpolarised Fresnel reflectance of a dielectric interface. `cos_i` ≥ 0 is the cosine on the
/// incident side, `eta` = η_transmitted / η_incident. Returns (F, cos_t); F = 1 on total
/// internal reflection.
#[inline]
pub fn fresnel_dielectric(cos_i: f32, eta: f32) -> (f32, f32) {
    let sin2_t = (1.0 - cos_i * cos_i).max(0.0) / (eta * eta);
    if sin2_t >= 1.0 {
        return (1.0, 0.0);
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    (0.5 * (rs * rs + rp * rp), cos_t)
}

/// Mirror `w` about the normal `m`.
#[inline]
pub fn reflect(w: Vec3, m: Vec3) -> Vec3 {
    2.0 * w.dot(m) * m - w
}

/// Refracts `w` (pointing away from the surface, `w·m > 0`) through the interface with normal
/// `m`; `eta` = η_t / η_i and `cos_t` from [`fresnel_dielectric`]. Points into the other side.
#[inline]
pub fn refract(w: Vec3, m: Vec3, eta: f32, cos_t: f32) -> Vec3 {
    let cos_i = w.dot(m);
    (-w / eta + m * (cos_i / eta - cos_t)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_limits() {
        let (f, _) = fresnel_dielectric(1.0, 1.5);
        assert!((f - 0.04).abs() < 1e-6, "{f}");
        let (f, _) = fresnel_dielectric(0.1, 1.0 / 1.5);
        assert_eq!(f, 1.0, "total internal reflection");
        let (f, _) = fresnel_dielectric(0.0, 1.5);
        assert!((f - 1.0).abs() < 1e-6);
    }

    #[test]
    fn refraction_obeys_snell() {
        let wo = Vec3::new(0.6, 0.0, 0.8);
        let (_, cos_t) = fresnel_dielectric(wo.z, 1.5);
        let wt = refract(wo, Vec3::Z, 1.5, cos_t);
        assert!(wt.z < 0.0);
        let sin_i = (1.0 - wo.z * wo.z).sqrt();
        let sin_t = (1.0 - wt.z * wt.z).sqrt();
        assert!((sin_i - 1.5 * sin_t).abs() < 1e-5);
        assert!(wt.x < 0.0, "passes to the far side of the normal");
    }

    /// ∫ D(m) cos θm dω = 1 (the projected microfacet area is the macro area).
    #[test]
    fn ggx_is_normalised() {
        for alpha in [0.05f32, 0.3, 1.0] {
            let n = 2000;
            let mut sum = 0.0f64;
            for i in 0..n {
                // Integrate over cos θ with the substitution dω = 2π d(cos θ).
                let c = (i as f32 + 0.5) / n as f32;
                let m = Vec3::new((1.0 - c * c).sqrt(), 0.0, c);
                sum += (ggx_d(m, alpha) * c) as f64 * 2.0 * PI as f64 / n as f64;
            }
            assert!((sum - 1.0).abs() < 0.02, "alpha {alpha}: {sum}");
        }
    }
}
