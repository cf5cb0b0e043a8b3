//! The material resolved where a ray hit (twin: `shaders/shared/surface.wgsl`; resolving the
//! hit itself, [`resolve`], is shared with the game's ray queries in `scene/surface.rs`).
//!
//! Owns: applying textures and normal maps at a resolved [`Surface`], and the
//! self-intersection-free ray origin (Wächter & Binder, Ray Tracing Gems ch. 6).
//! Must not: choose directions or accumulate radiance (the integrator does).

use glam::{Vec2, Vec3, Vec4};

use super::bsdf::Bsdf;
use super::texture::{self, Lod};
use crate::layout::{GpuMaterial, INVALID, MATERIAL_DIELECTRIC, MATERIAL_METAL_ROUGH};
use crate::scene::RenderScene;
pub use crate::scene::surface::{Surface, can_emit, resolve};

/// The material at a surface: its BSDF, emitted radiance, and the shading normal after
/// normal mapping (unchanged without a normal texture or tangent frame).
pub struct Shading {
    pub bsdf: Bsdf,
    pub emission: Vec3,
    pub shading_normal: Vec3,
    pub absorption: Vec3,
    pub two_sided_emission: bool,
}

/// Whether `m` reads a mip-mapped lookup (base colour, metallic-roughness or normal texture):
/// only then does a path draw the random number that picks between levels.
pub fn reads_levels(m: &GpuMaterial) -> bool {
    m.base_color_texture != INVALID
        || m.metal_rough_texture != INVALID
        || m.normal_texture != INVALID
}

/// Applies `material`'s textures at `surface`, on the mip levels `lod` picks. Emission is read
/// on level 0, as light sampling reads it (`direct.rs`), so both MIS strategies see one emitter.
pub fn shade(scene: &RenderScene, surface: &Surface, lod: Lod) -> Shading {
    let m: &GpuMaterial = &scene.materials[surface.material as usize];
    let tex = |index: u32| texture::sample(&scene.textures, &scene.texels, index, surface.uv, lod);
    let base = Vec4::from(m.base_color) * tex(m.base_color_texture);
    let emission = if surface.emits {
        Vec3::from_slice(&m.emission[..3])
            * texture::sample(
                &scene.textures,
                &scene.texels,
                m.emission_texture,
                surface.uv,
                Lod::FINEST,
            )
            .truncate()
    } else {
        Vec3::ZERO
    };
    let metal_rough = tex(m.metal_rough_texture);
    let roughness = (m.roughness * metal_rough.y).clamp(0.0, 1.0);
    let mut shading_normal = surface.shading_normal;
    let t = surface.tangent;
    if m.normal_texture != INVALID && t.truncate() != Vec3::ZERO {
        let n = shading_normal;
        let tangent = (t.truncate() - n * n.dot(t.truncate())).normalize_or_zero();
        let bitangent = n.cross(tangent) * if t.w < 0.0 { -1.0 } else { 1.0 };
        let s = tex(m.normal_texture);
        let xy = (Vec2::new(s.x, s.y) * 2.0 - Vec2::ONE) * m.normal_scale;
        let z = (s.z * 2.0 - 1.0).max(0.0);
        let mapped = (tangent * xy.x + bitangent * xy.y + n * z).normalize_or_zero();
        if mapped != Vec3::ZERO && mapped.dot(surface.geometric_normal) > 0.0 {
            shading_normal = mapped;
        }
    }
    let mut kind = m.kind;
    if kind == MATERIAL_METAL_ROUGH && m.transmission >= 1.0 && m.metallic <= 0.0 {
        kind = MATERIAL_DIELECTRIC;
    }
    Shading {
        bsdf: Bsdf {
            kind,
            base_color: base.truncate().clamp(Vec3::ZERO, Vec3::ONE),
            alpha: roughness * roughness,
            metallic: (m.metallic * metal_rough.z).clamp(0.0, 1.0),
            ior: m.ior,
            transmission: m.transmission,
        },
        emission,
        shading_normal,
        absorption: Vec3::from_slice(&m.absorption[..3]),
        two_sided_emission: m.flags & crate::layout::MATERIAL_FLAG_TWO_SIDED_EMISSION != 0,
    }
}

/// Moves `p` off the surface with normal `n` (pointing to the side the new ray leaves on) by a
/// few ULPs, scaled with the magnitude of `p` so it works far from the origin.
pub fn offset_origin(p: Vec3, n: Vec3) -> Vec3 {
    const ORIGIN: f32 = 1.0 / 32.0;
    const FLOAT_SCALE: f32 = 1.0 / 65536.0;
    const INT_SCALE: f32 = 256.0;
    let offset = |p: f32, n: f32| {
        if p.abs() < ORIGIN {
            return p + FLOAT_SCALE * n;
        }
        let of = (INT_SCALE * n) as i32;
        let bits = p.to_bits() as i32;
        f32::from_bits(if p < 0.0 { bits - of } else { bits + of } as u32)
    };
    Vec3::new(offset(p.x, n.x), offset(p.y, n.y), offset(p.z, n.z))
}
