//! What a ray hit, in world space: the hit's triangle interpolated on its instance (CPU twin
//! of `resolve_surface` in `shaders/shared/surface.wgsl`; the shading half is
//! `render/cpu/surface.rs`).
//!
//! Owns: interpolating vertex attributes at a hit (position, shading normal, UV, tangent), the
//! front-facing geometric normal (which follows the instance's handedness: a mirroring transform
//! flips the winding, as glTF requires) and the material after the instance's override. The CPU
//! integrator and the game's ray queries both use it. Any thread, pure.
//! Must not: apply textures or choose directions (the integrator does).

use glam::{Vec2, Vec3, Vec4};

use super::RenderScene;
use crate::layout::{GpuInstance, INSTANCE_FLAG_EMISSION_OFF, INVALID};
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
    /// The triangle's UV area per world area, 1/m² (0 when either is degenerate): with a ray
    /// cone's width it gives the texture level of detail (`render/cpu/cone.rs`).
    pub uv_density: f32,
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

/// Whether the surface `hit` lies on can emit at all: its material (after the instance's
/// override) has a non-zero emission factor and the instance's light group is on. When it
/// cannot, [`resolve`] and shading would find zero emission; a path's last hit, which only adds
/// emission, then ends without resolving the hit (`render/cpu/integrator.rs`).
pub fn can_emit(scene: &RenderScene, hit: &Hit) -> bool {
    let inst = &scene.instances[hit.instance as usize];
    if inst.flags & INSTANCE_FLAG_EMISSION_OFF != 0 {
        return false;
    }
    let material = if inst.material_override != INVALID {
        inst.material_override
    } else {
        scene.triangles[(inst.triangle_base + hit.triangle) as usize].material
    };
    let e = &scene.materials[material as usize].emission;
    e[0] != 0.0 || e[1] != 0.0 || e[2] != 0.0
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
    let position = super::lights::world_point(inst, p_object.to_array());
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
    let world_area = world_vector(inst, pb - pa)
        .cross(world_vector(inst, pc - pa))
        .length();
    let uv_area = (Vec2::new(b.u - a.u, b.v - a.v)).perp_dot(Vec2::new(c.u - a.u, c.v - a.v));
    let uv_density = if world_area > 0.0 && uv_area.is_finite() {
        uv_area.abs() / world_area
    } else {
        0.0
    };
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
        uv_density,
        material,
        emits: inst.flags & INSTANCE_FLAG_EMISSION_OFF == 0,
    }
}
