// Hit resolution and material shading, twin of engine/src/render/cpu/surface.rs.

struct Surface {
    position: vec3<f32>,
    geometric_normal: vec3<f32>,
    shading_normal: vec3<f32>,
    tangent: vec4<f32>,
    uv: vec2<f32>,
    // UV area per world area of the triangle, 1/m² (0 when degenerate).
    uv_density: f32,
    material: u32,
    emits: bool,
}

struct Shading {
    bsdf: Bsdf,
    emission: vec3<f32>,
    shading_normal: vec3<f32>,
    absorption: vec3<f32>,
    two_sided_emission: bool,
}

fn world_point(i: GpuInstance, p: vec3<f32>) -> vec3<f32> {
    let q = vec4<f32>(p, 1.0);
    return vec3<f32>(dot(i.world_from_object[0], q), dot(i.world_from_object[1], q), dot(i.world_from_object[2], q));
}

fn world_vector(i: GpuInstance, v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(i.world_from_object[0].xyz, v), dot(i.world_from_object[1].xyz, v), dot(i.world_from_object[2].xyz, v));
}

// Transpose of object_from_world's 3x3 part.
fn world_normal(i: GpuInstance, n: vec3<f32>) -> vec3<f32> {
    let r = i.object_from_world;
    return r[0].xyz * n.x + r[1].xyz * n.y + r[2].xyz * n.z;
}

fn normalize_or_zero(v: vec3<f32>) -> vec3<f32> {
    let l2 = dot(v, v);
    if (l2 > 0.0 && l2 < 1e38) {
        return v * inverseSqrt(l2);
    }
    return vec3<f32>(0.0);
}

fn v3(a: array<f32, 3>) -> vec3<f32> {
    return vec3<f32>(a[0], a[1], a[2]);
}

// Twin of `scene::surface::can_emit`: the hit's material (after the instance's override) has a
// non-zero emission factor and the instance's light group is on.
fn hit_can_emit(hit: Hit) -> bool {
    let inst = instances[hit.instance];
    if ((inst.flags & INSTANCE_FLAG_EMISSION_OFF) != 0u) {
        return false;
    }
    var material = triangles[inst.triangle_base + hit.triangle].material;
    if (inst.material_override != INVALID) {
        material = inst.material_override;
    }
    return any(materials[material].emission.xyz != vec3<f32>(0.0));
}

fn resolve_surface(hit: Hit, direction: vec3<f32>) -> Surface {
    let inst = instances[hit.instance];
    let tri = triangles[inst.triangle_base + hit.triangle];
    let a = vertices[inst.vertex_base + tri.indices[0]];
    let b = vertices[inst.vertex_base + tri.indices[1]];
    let c = vertices[inst.vertex_base + tri.indices[2]];
    let w = 1.0 - hit.u - hit.v;
    let pa = v3(a.position);
    let pb = v3(b.position);
    let pc = v3(c.position);
    let position = world_point(inst, pa * w + pb * hit.u + pc * hit.v);
    var ng = normalize_or_zero(world_normal(inst, cross(pb - pa, pc - pa)));
    if (all(ng == vec3<f32>(0.0))) {
        ng = -normalize_or_zero(direction);
    }
    var ns = normalize_or_zero(world_normal(inst, v3(a.normal) * w + v3(b.normal) * hit.u + v3(c.normal) * hit.v));
    if (all(ns == vec3<f32>(0.0))) {
        ns = ng;
    } else if (dot(ns, ng) < 0.0) {
        ns = -ns;
    }
    let t_object = a.tangent.xyz * w + b.tangent.xyz * hit.u + c.tangent.xyz * hit.v;
    let tangent = vec4<f32>(normalize_or_zero(world_vector(inst, t_object)), a.tangent.w);
    let uv = vec2<f32>(a.u, a.v) * w + vec2<f32>(b.u, b.v) * hit.u + vec2<f32>(c.u, c.v) * hit.v;
    let world_area = length(cross(world_vector(inst, pb - pa), world_vector(inst, pc - pa)));
    let duv1 = vec2<f32>(b.u - a.u, b.v - a.v);
    let duv2 = vec2<f32>(c.u - a.u, c.v - a.v);
    let uv_area = abs(duv1.x * duv2.y - duv1.y * duv2.x);
    var uv_density = 0.0;
    if (world_area > 0.0 && uv_area < 1e30) {
        uv_density = uv_area / world_area;
    }
    var material = tri.material;
    if (inst.material_override != INVALID) {
        material = inst.material_override;
    }
    return Surface(position, ng, ns, tangent, uv, uv_density, material, (inst.flags & INSTANCE_FLAG_EMISSION_OFF) == 0u);
}

// Whether material m reads a mip-mapped lookup: only then does a path draw the level's random.
fn reads_levels(m: GpuMaterial) -> bool {
    return m.base_color_texture != INVALID || m.metal_rough_texture != INVALID || m.normal_texture != INVALID;
}

// Emission is read on level 0, as light sampling reads it.
fn shade_surface(s: Surface, lod: Lod) -> Shading {
    let m = materials[s.material];
    let base = m.base_color * sample_texture_lod(m.base_color_texture, s.uv, lod);
    var emission = vec3<f32>(0.0);
    if (s.emits) {
        emission = m.emission.xyz * sample_texture(m.emission_texture, s.uv).xyz;
    }
    let mr = sample_texture_lod(m.metal_rough_texture, s.uv, lod);
    let roughness = clamp(m.roughness * mr.y, 0.0, 1.0);
    var ns = s.shading_normal;
    let t = s.tangent;
    if (m.normal_texture != INVALID && any(t.xyz != vec3<f32>(0.0))) {
        let n = ns;
        let tangent = normalize_or_zero(t.xyz - n * dot(n, t.xyz));
        let bitangent = cross(n, tangent) * select(1.0, -1.0, t.w < 0.0);
        let tex = sample_texture_lod(m.normal_texture, s.uv, lod);
        let xy = (tex.xy * 2.0 - vec2<f32>(1.0)) * m.normal_scale;
        let z = max(tex.z * 2.0 - 1.0, 0.0);
        let mapped = normalize_or_zero(tangent * xy.x + bitangent * xy.y + n * z);
        if (any(mapped != vec3<f32>(0.0)) && dot(mapped, s.geometric_normal) > 0.0) {
            ns = mapped;
        }
    }
    var kind = m.kind;
    if (kind == MATERIAL_METAL_ROUGH && m.transmission >= 1.0 && m.metallic <= 0.0) {
        kind = MATERIAL_DIELECTRIC;
    }
    let bsdf = Bsdf(
        kind,
        clamp(base.xyz, vec3<f32>(0.0), vec3<f32>(1.0)),
        roughness * roughness,
        clamp(m.metallic * mr.z, 0.0, 1.0),
        m.ior,
        m.transmission,
    );
    return Shading(bsdf, emission, ns, m.absorption.xyz, (m.flags & MATERIAL_FLAG_TWO_SIDED_EMISSION) != 0u);
}

// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection" (RT Gems ch. 6).
fn offset_origin(p: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let of_i = vec3<i32>(256.0 * n);
    let bits = bitcast<vec3<i32>>(p);
    let moved = bitcast<vec3<f32>>(select(bits + of_i, bits - of_i, p < vec3<f32>(0.0)));
    return select(moved, p + n * (1.0 / 65536.0), abs(p) < vec3<f32>(1.0 / 32.0));
}
