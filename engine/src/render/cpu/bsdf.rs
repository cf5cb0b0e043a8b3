//! The scattering models of the path tracer (twin: `shaders/shared/bsdf.wgsl`).
//!
//! Owns: evaluating, sampling and giving the density of each material kind of
//! `layout::GpuMaterial`: Lambert diffuse, conductor (perfect mirror or GGX), dielectric
//! (smooth or GGX; Fresnel; radiance scaled by 1/η² on refraction) and glTF metallic-roughness
//! (diffuse + GGX coat + GGX metal + optional GGX transmission). All directions are local to
//! the shading frame (normal = +z) and point away from the surface; `wo` is towards the viewer.
//! Values returned by `eval` are the BSDF times |cos θi| (the cosine is folded in).
//! Must not: fetch textures or scene data (the caller resolves them into [`Bsdf`]).

use glam::{Vec2, Vec3};

use super::microfacet::{
    fresnel_dielectric, fresnel_schlick, ggx_d, ggx_g2, ggx_sample_vndf, ggx_vndf_pdf, reflect,
    refract,
};
use super::sampling::{PI, cosine_hemisphere, luminance};
use crate::layout::{MATERIAL_CONDUCTOR, MATERIAL_DIELECTRIC, MATERIAL_DIFFUSE};

/// Below this GGX α a conductor or dielectric is treated as perfectly smooth (a delta lobe).
pub const ALPHA_DELTA: f32 = 1e-4;
/// Metallic-roughness surfaces never become delta: their α is clamped to at least this.
pub const ALPHA_MIN_METAL_ROUGH: f32 = 2e-3;

/// A material resolved at one surface point (textures applied).
#[derive(Clone, Copy, Debug)]
pub struct Bsdf {
    pub kind: u32,
    pub base_color: Vec3,
    /// GGX α (roughness²).
    pub alpha: f32,
    pub metallic: f32,
    /// η of the inside relative to the outside.
    pub ior: f32,
    pub transmission: f32,
}

/// One sampled direction.
#[derive(Clone, Copy, Debug)]
pub struct BsdfSample {
    pub wi: Vec3,
    /// BSDF × |cos θi| / density: what the path throughput is multiplied by.
    pub weight: Vec3,
    /// Solid-angle density (the discrete probability for delta lobes).
    pub pdf: f32,
    pub delta: bool,
}

impl Bsdf {
    /// True when every lobe is a delta distribution (no light sampling possible).
    pub fn is_delta(&self) -> bool {
        (self.kind == MATERIAL_CONDUCTOR || self.kind == MATERIAL_DIELECTRIC)
            && self.alpha < ALPHA_DELTA
    }

    /// True when the two sides of the surface behave the same (the caller may flip the frame
    /// so that `wo.z > 0`). Dielectrics and transmissive metal-rough surfaces are not.
    pub fn is_two_sided(&self) -> bool {
        self.kind != MATERIAL_DIELECTRIC && self.transmission <= 0.0
    }

    /// BSDF × |cos θi| and the density `sample` would produce `wi` with.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> (Vec3, f32) {
        match self.kind {
            MATERIAL_DIFFUSE => {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return (Vec3::ZERO, 0.0);
                }
                (self.base_color * (wi.z / PI), wi.z / PI)
            }
            MATERIAL_CONDUCTOR => {
                if self.alpha < ALPHA_DELTA {
                    return (Vec3::ZERO, 0.0);
                }
                conductor_eval(self.base_color, self.alpha, wo, wi)
            }
            MATERIAL_DIELECTRIC => {
                if self.alpha < ALPHA_DELTA {
                    return (Vec3::ZERO, 0.0);
                }
                let d = rough_dielectric_eval(self.ior, self.alpha, wo, wi);
                let tint = if wo.z * wi.z < 0.0 {
                    self.base_color
                } else {
                    Vec3::ONE
                };
                (tint * d.value, d.pdf_reflect + d.pdf_transmit)
            }
            _ => self.metal_rough_eval(wo, wi),
        }
    }

    /// Samples an incident direction for `wo` from three uniform numbers.
    pub fn sample(&self, wo: Vec3, u: Vec3) -> Option<BsdfSample> {
        match self.kind {
            MATERIAL_DIFFUSE => {
                if wo.z <= 0.0 {
                    return None;
                }
                let wi = cosine_hemisphere(Vec2::new(u.x, u.y));
                Some(BsdfSample {
                    wi,
                    weight: self.base_color,
                    pdf: wi.z / PI,
                    delta: false,
                })
            }
            MATERIAL_CONDUCTOR => {
                if wo.z <= 0.0 {
                    return None;
                }
                if self.alpha < ALPHA_DELTA {
                    let wi = Vec3::new(-wo.x, -wo.y, wo.z);
                    return Some(BsdfSample {
                        wi,
                        weight: fresnel_schlick(self.base_color, wo.z),
                        pdf: 1.0,
                        delta: true,
                    });
                }
                let m = ggx_sample_vndf(wo, self.alpha, Vec2::new(u.x, u.y));
                let wi = reflect(wo, m);
                if wi.z <= 0.0 {
                    return None;
                }
                let (f, pdf) = conductor_eval(self.base_color, self.alpha, wo, wi);
                (pdf > 0.0).then(|| BsdfSample {
                    wi,
                    weight: f / pdf,
                    pdf,
                    delta: false,
                })
            }
            MATERIAL_DIELECTRIC => self.dielectric_sample(wo, u),
            _ => self.metal_rough_sample(wo, u),
        }
    }

    fn dielectric_sample(&self, wo: Vec3, u: Vec3) -> Option<BsdfSample> {
        // Work with wo on the +z side; `sign` maps back.
        let (sign, eta) = if wo.z >= 0.0 {
            (1.0, self.ior)
        } else {
            (-1.0, 1.0 / self.ior)
        };
        let wo_up = Vec3::new(wo.x, wo.y, wo.z * sign);
        if self.alpha < ALPHA_DELTA {
            let (f, cos_t) = fresnel_dielectric(wo_up.z, eta);
            if u.z < f {
                let wi = Vec3::new(-wo.x, -wo.y, wo.z);
                return Some(BsdfSample {
                    wi,
                    weight: Vec3::ONE,
                    pdf: f,
                    delta: true,
                });
            }
            let t = refract(wo_up, Vec3::Z, eta, cos_t);
            return Some(BsdfSample {
                wi: Vec3::new(t.x, t.y, t.z * sign),
                weight: self.base_color / (eta * eta),
                pdf: 1.0 - f,
                delta: true,
            });
        }
        let m = ggx_sample_vndf(wo_up, self.alpha, Vec2::new(u.x, u.y));
        let wo_m = wo_up.dot(m);
        let (f, cos_t) = fresnel_dielectric(wo_m, eta);
        let reflected = u.z < f;
        let wi_up = if reflected {
            reflect(wo_up, m)
        } else {
            refract(wo_up, m, eta, cos_t)
        };
        // A microfacet can send the direction to the other side of the macro surface; such a
        // sample is lost (`eval` would read it as the other event, with another density).
        if (wi_up.z > 0.0) != reflected {
            return None;
        }
        let wi = Vec3::new(wi_up.x, wi_up.y, wi_up.z * sign);
        let (value, pdf) = self.eval(wo, wi);
        (pdf > 0.0 && value.max_element() > 0.0).then(|| BsdfSample {
            wi,
            weight: value / pdf,
            pdf,
            delta: false,
        })
    }

    /// Lobe weights of the metallic-roughness model for `wo`: (specular, diffuse, transmission).
    fn metal_rough_lobes(&self, wo: Vec3) -> (Vec3, [f32; 3]) {
        let f0_dielectric = ((self.ior - 1.0) / (self.ior + 1.0)).powi(2);
        let f0 = Vec3::splat(f0_dielectric).lerp(self.base_color, self.metallic);
        let fresnel = fresnel_schlick(f0, wo.z.abs());
        let dielectric = 1.0 - self.metallic;
        let spec = luminance(fresnel).max(0.05);
        let rest = dielectric * (1.0 - luminance(fresnel)) * luminance(self.base_color).max(0.05);
        let diffuse = rest * (1.0 - self.transmission);
        let trans = rest * self.transmission;
        let total = spec + diffuse + trans;
        (f0, [spec / total, diffuse / total, trans / total])
    }

    fn metal_rough_alpha(&self) -> f32 {
        self.alpha.max(ALPHA_MIN_METAL_ROUGH)
    }

    fn metal_rough_eval(&self, wo: Vec3, wi: Vec3) -> (Vec3, f32) {
        if wo.z <= 0.0 {
            return (Vec3::ZERO, 0.0);
        }
        let alpha = self.metal_rough_alpha();
        let (f0, p) = self.metal_rough_lobes(wo);
        let mut value = Vec3::ZERO;
        let mut pdf = 0.0;
        if wi.z > 0.0 {
            let (spec, spec_pdf) = conductor_eval(f0, alpha, wo, wi);
            let diffuse_scale = (1.0 - self.metallic) * (1.0 - self.transmission);
            let coat_o = Vec3::ONE - fresnel_schlick(f0, wo.z);
            let coat_i = Vec3::ONE - fresnel_schlick(f0, wi.z);
            value += spec + self.base_color * coat_o * coat_i * (diffuse_scale * wi.z / PI);
            pdf += p[0] * spec_pdf + p[1] * wi.z / PI;
        } else if self.transmission > 0.0 {
            let d = rough_dielectric_eval(self.ior, alpha, wo, wi);
            value += self.base_color * d.value * ((1.0 - self.metallic) * self.transmission);
            pdf += p[2] * d.pdf_refract_always;
        }
        (value, pdf)
    }

    fn metal_rough_sample(&self, wo: Vec3, u: Vec3) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let alpha = self.metal_rough_alpha();
        let (_, p) = self.metal_rough_lobes(wo);
        let uv = Vec2::new(u.x, u.y);
        let wi = if u.z < p[0] {
            reflect(wo, ggx_sample_vndf(wo, alpha, uv))
        } else if u.z < p[0] + p[1] {
            cosine_hemisphere(uv)
        } else {
            let m = ggx_sample_vndf(wo, alpha, uv);
            let (f, cos_t) = fresnel_dielectric(wo.dot(m), self.ior);
            if f >= 1.0 {
                return None;
            }
            refract(wo, m, self.ior, cos_t)
        };
        // Reflection lobes must stay above, the transmission lobe below the macro surface;
        // a direction a microfacet sent across is lost (its density is not in `eval`'s mixture).
        if (wi.z > 0.0) != (u.z < p[0] + p[1]) {
            return None;
        }
        let (value, pdf) = self.metal_rough_eval(wo, wi);
        (pdf > 0.0 && value.max_element() > 0.0).then(|| BsdfSample {
            wi,
            weight: value / pdf,
            pdf,
            delta: false,
        })
    }
}

/// GGX conductor with Schlick Fresnel: (BSDF × cos θi, density of VNDF sampling).
fn conductor_eval(f0: Vec3, alpha: f32, wo: Vec3, wi: Vec3) -> (Vec3, f32) {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return (Vec3::ZERO, 0.0);
    }
    let m = (wo + wi).normalize();
    let d = ggx_d(m, alpha);
    let value = fresnel_schlick(f0, wo.dot(m)) * (d * ggx_g2(wo, wi, alpha) / (4.0 * wo.z));
    let pdf = ggx_vndf_pdf(wo, m, alpha) / (4.0 * wo.dot(m));
    (value, pdf)
}

/// What [`rough_dielectric_eval`] returns.
struct DielectricEval {
    /// BSDF × |cos θi|, without the transmission tint.
    value: Vec3,
    /// Density of sampling `wi` by reflection (VNDF × Fresnel choice).
    pdf_reflect: f32,
    /// Density of sampling `wi` by refraction (VNDF × (1 − Fresnel) choice).
    pdf_transmit: f32,
    /// Density of `wi` when every sampled normal refracts (no Fresnel choice).
    pdf_refract_always: f32,
}

const NO_DIELECTRIC: DielectricEval = DielectricEval {
    value: Vec3::ZERO,
    pdf_reflect: 0.0,
    pdf_transmit: 0.0,
    pdf_refract_always: 0.0,
};

/// Rough dielectric (Walter et al. 2007; η of the viewer side in the numerator, so it is the
/// radiance BTDF: refraction into a denser medium scales radiance by 1/η²). `wo` may be on
/// either side; `ior` is η inside / η outside; the normal points outside.
fn rough_dielectric_eval(ior: f32, alpha: f32, wo: Vec3, wi: Vec3) -> DielectricEval {
    if wo.z == 0.0 || wi.z == 0.0 {
        return NO_DIELECTRIC;
    }
    let (sign, eta) = if wo.z > 0.0 {
        (1.0, ior)
    } else {
        (-1.0, 1.0 / ior)
    };
    let wo = Vec3::new(wo.x, wo.y, wo.z * sign);
    let wi = Vec3::new(wi.x, wi.y, wi.z * sign);
    if wi.z > 0.0 {
        let m = (wo + wi).normalize();
        let wo_m = wo.dot(m);
        if wo_m <= 0.0 {
            return NO_DIELECTRIC;
        }
        let (f, _) = fresnel_dielectric(wo_m, eta);
        let value = f * ggx_d(m, alpha) * ggx_g2(wo, wi, alpha) / (4.0 * wo.z);
        let pdf = f * ggx_vndf_pdf(wo, m, alpha) / (4.0 * wo_m);
        return DielectricEval {
            value: Vec3::splat(value),
            pdf_reflect: pdf,
            ..NO_DIELECTRIC
        };
    }
    let mut m = -(wo + wi * eta).normalize();
    if m.z < 0.0 {
        m = -m;
    }
    let wo_m = wo.dot(m);
    let wi_m = wi.dot(m);
    if wo_m <= 0.0 || wi_m >= 0.0 {
        return NO_DIELECTRIC;
    }
    let (f, _) = fresnel_dielectric(wo_m, eta);
    let denom = wo_m + eta * wi_m;
    let denom2 = denom * denom;
    let value =
        (1.0 - f) * ggx_d(m, alpha) * ggx_g2(wo, wi, alpha) * wo_m * (-wi_m) / (wo.z * denom2);
    let pdf_always = ggx_vndf_pdf(wo, m, alpha) * (-wi_m) * eta * eta / denom2;
    DielectricEval {
        value: Vec3::splat(value),
        pdf_reflect: 0.0,
        pdf_transmit: (1.0 - f) * pdf_always,
        pdf_refract_always: pdf_always,
    }
}

#[cfg(test)]
#[path = "bsdf_tests.rs"]
mod tests;
