//! What a ray hit, in world space, and the material resolved there (twin:
//! `shaders/shared/surface.wgsl`).
//!
//! Owns: interpolating vertex attributes at a hit (position, shading normal, UV, tangent), the
//! front-facing geometric normal (which follows the instance's handedness: a mirroring transform
//! flips the winding, as glTF requires), applying textures and normal maps, and the
//! self-intersection-free ray origin (Wächter & Binder, Ray Tracing Gems ch. 6).
//! Must not: choose directions or accumulate radiance (the integrator does).

use glam::{Vec2, Vec3, Vec4};

use super::bsdf::Bsdf;
use super::texture;
use crate::layout::{
    GpuInstance, GpuMaterial, INSTANCE_FLAG_EMISSION_OFF, INVALID, MATERIAL_DIELECTRIC,
    MATERIAL_METAL_ROUGH,
};
use crate::render::scene::RenderScene;
use crate::trace::Hit;

/// A hit resolved in world space.
#[derive(Clone, Copy, Debug)]
pub struct Surface {
    pub position: Vec3,
    /// Unit normal of the triangle's front face (counter-clockwise winding in object space).
    pub geometric_normal: Vec3,
    /// Unit interpolated vertex normal (the geometric normal when the mesh has none), on the
    /// same side as `geometric_normal`.
    pub shading_normal: Vec3,
    /// World tangent (xyz) and bitangent sign (w); zero when there is no tangent frame.
    pub tangent: Vec4,
    pub uv: Vec2,
    pub material: u32,
    /// False when the instance's light group is off (`INSTANCE_FLAG_EMISSION_OFF`).
    pub emits: bool,
}

/// Object-space vector to world space with the instance's 3×3 part.
fn world_vector(i: &GpuInstance, v: Vec3) -> Vec3 {
    let r = &i.world_from_object;
    Vec3::new(
        r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
        r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
        r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z,
    )
}

/// Object-space normal to world space: transpose of `object_from_world`'s 3×3 part.
fn world_normal(i: &GpuInstance, n: Vec3) -> Vec3 {
    let r = &i.object_from_world;
    Vec3::new(
        r[0][0] * n.x + r[1][0] * n.y + r[2][0] * n.z,
        r[0][1] * n.x + r[1][1] * n.y + r[2][1] * n.z,
        r[0][2] * n.x + r[1][2] * n.y + r[2][2] * n.z,
    )
}

/// Resolves `hit` of a ray with direction `direction`.
pub fn resolve(scene: &RenderScene, hit: &Hit, direction: Vec3) -> Surface {
    let inst = &scene.instances[hit.instance as usize];
    let tri = scene.triangles[(inst.triangle_base + hit.triangle) as usize];
    let vertex = |k: usize| scene.vertices[(inst.vertex_base + tri.indices[k]) as usize];
    let (a, b, c) = (vertex(0), vertex(1), vertex(2));
    let (w, u, v) = (1.0 - hit.u - hit.v, hit.u, hit.v);
    let (pa, pb, pc) = (
        Vec3::from(a.position),
        Vec3::from(b.position),
        Vec3::from(c.position),
    );
    let p_object = pa * w + pb * u + pc * v;
    let position = super::super::lights::world_point(inst, p_object.to_array());
    let mut geometric_normal = world_normal(inst, (pb - pa).cross(pc - pa)).normalize_or_zero();
    if geometric_normal == Vec3::ZERO {
        geometric_normal = -direction.normalize_or_zero();
    }
    let n_object = Vec3::from(a.normal) * w + Vec3::from(b.normal) * u + Vec3::from(c.normal) * v;
    let mut shading_normal = world_normal(inst, n_object).normalize_or_zero();
    if shading_normal == Vec3::ZERO {
        shading_normal = geometric_normal;
    } else if shading_normal.dot(geometric_normal) < 0.0 {
        shading_normal = -shading_normal;
    }
    let t_object = Vec3::from_slice(&a.tangent[..3]) * w
        + Vec3::from_slice(&b.tangent[..3]) * u
        + Vec3::from_slice(&c.tangent[..3]) * v;
    let tangent = world_vector(inst, t_object)
        .normalize_or_zero()
        .extend(a.tangent[3]);
    let uv = Vec2::new(a.u, a.v) * w + Vec2::new(b.u, b.v) * u + Vec2::new(c.u, c.v) * v;
    let material = if inst.material_override != INVALID {
        inst.material_override
    } else {
        tri.material
    };
    Surface {
        position,
        geometric_normal,
        shading_normal,
        tangent,
        uv,
        material,
        emits: inst.flags & INSTANCE_FLAG_EMISSION_OFF == 0,
    }
}

/// The material at a surface: its BSDF, emitted radiance, and the shading normal after
/// normal mapping (unchanged without a normal texture or tangent frame).
pub struct Shading {
    pub bsdf: Bsdf,
    pub emission: Vec3,
    pub shading_normal: Vec3,
    pub absorption: Vec3,
    pub two_sided_emission: bool,
}

/// Applies `material`'s textures at `surface`.
pub fn shade(scene: &RenderScene, surface: &Surface) -> Shading {
    let m: &GpuMaterial = &scene.materials[surface.material as usize];
    let tex = |index: u32| texture::sample(&scene.textures, &scene.texels, index, surface.uv);
    let base = Vec4::from(m.base_color) * tex(m.base_color_texture);
    let emission = if surface.emits {
        Vec3::from_slice(&m.emission[..3]) * tex(m.emission_texture).truncate()
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
