// Direct light for the path tracing pass: next-event estimation (one emissive triangle and the
// sun or moon disc, or one pick of either under METHOD_SINGLE_PICK), the shadow rays it asks
// for, and the MIS weight of an emitter a BSDF ray reaches. Twin of
// engine/src/render/cpu/direct.rs (the same random draws in the same order). Composed by
// engine/src/render/gpu/shaders.rs after the shared pieces and before trace.wgsl, whose
// constants (FAR, MAX_F32, ONE_BELOW) and ray counters it uses (WGSL module scope is
// order-free).

const NEE_RANDOMS: u32 = 6u;

// Shadow rays a surface wants traced, with what each adds to the result when unoccluded.
struct ShadowRays {
    count: u32,
    rays: array<Ray, 2>,
    contribution: array<vec3<f32>, 2>,
}

fn shadow_ray(x: vec3<f32>, ng: vec3<f32>, direction: vec3<f32>, distance: f32) -> Ray {
    let side = select(-ng, ng, dot(direction, ng) >= 0.0);
    return Ray(offset_origin(x, side), 0.0, direction, distance);
}

// Visibility of light point `p` (light normal `ln`) from `x`: both ends offset off their own
// surfaces, so neither can block at any magnitude of coordinates (mirrors the CPU's shadow_to).
fn shadow_ray_to(x: vec3<f32>, ng: vec3<f32>, p: vec3<f32>, ln: vec3<f32>) -> Ray {
    let to = p - x;
    let origin = offset_origin(x, select(-ng, ng, dot(to, ng) >= 0.0));
    let end = offset_origin(p, select(-ln, ln, dot(ln, -to) >= 0.0));
    let span = end - origin;
    let len = length(span);
    if (!(len > 0.0)) {
        return Ray(origin, 0.0, vec3<f32>(0.0, 1.0, 0.0), 0.0);
    }
    return Ray(origin, 0.0, span / len, len);
}

struct LightEmission {
    radiance: vec3<f32>,
    two_sided: bool,
}

fn light_emission(instance: u32, triangle: u32, bary: vec2<f32>) -> LightEmission {
    let inst = instances[instance];
    let tri = triangles[inst.triangle_base + triangle];
    var material = tri.material;
    if (inst.material_override != INVALID) {
        material = inst.material_override;
    }
    let m = materials[material];
    var emission = m.emission.xyz;
    if (m.emission_texture != INVALID) {
        let a = vertices[inst.vertex_base + tri.indices[0]];
        let b = vertices[inst.vertex_base + tri.indices[1]];
        let c = vertices[inst.vertex_base + tri.indices[2]];
        let uv = vec2<f32>(a.u, a.v) * (1.0 - bary.x - bary.y) + vec2<f32>(b.u, b.v) * bary.x + vec2<f32>(c.u, c.v) * bary.y;
        emission *= sample_texture(m.emission_texture, uv).xyz;
    }
    return LightEmission(emission, (m.flags & MATERIAL_FLAG_TWO_SIDED_EMISSION) != 0u);
}

// The chances that next-event estimation samples (the primary disc, the picked triangle): both 1
// without METHOD_SINGLE_PICK, else the disc's share of a cosine-free irradiance estimate (twin of
// pick_chances in render/cpu/direct.rs, which documents the choice).
fn pick_chances() -> vec2<f32> {
    if ((frame.method & METHOD_SINGLE_PICK) == 0u) {
        return vec2<f32>(1.0, 1.0);
    }
    var disc = 0.0;
    if (frame.sun_solid_angle == 0.0) {
        disc = luminance(frame.sun_radiance);
    } else if (frame.sun_solid_angle > 0.0) {
        disc = luminance(frame.sun_radiance) * frame.sun_solid_angle;
    }
    var triangles = 0.0;
    if (frame.light_count > 0u && frame.light_weight_total > 0.0) {
        triangles = frame.light_weight_total;
    }
    let total = disc + triangles;
    if (!(total > 0.0 && total <= MAX_F32 && disc >= 0.0)) {
        return vec2<f32>(0.0, 1.0);
    }
    let disc_chance = disc / total;
    return vec2<f32>(disc_chance, 1.0 - disc_chance);
}

// Direct light at a non-delta surface: one emissive triangle (picked by power, uniformly or by
// the light tree) and the sun, each weighted against BSDF sampling. Returns the shadow rays to
// trace; `throughput` is folded into their contributions.
fn next_event(bsdf: Bsdf, x: vec3<f32>, ng: vec3<f32>, f: Frame, wo_local: vec3<f32>, throughput: vec3<f32>, medium: vec3<f32>, rng: ptr<function, Rng>) -> ShadowRays {
    var xi: array<f32, 6>;
    for (var i = 0u; i < NEE_RANDOMS; i++) {
        xi[i] = rng_next(rng);
    }
    var out: ShadowRays;
    out.count = 0u;
    let nee = (frame.method & METHOD_NEE) != 0u;
    let mis = (frame.method & METHOD_MIS) != 0u;
    let by_power = (frame.method & METHOD_LIGHTS_BY_POWER) != 0u;
    // Two lights (Brigade §6.2.3): one triangle and the disc. One pick: xi[0] chooses the disc
    // or the triangles, then (rescaled to [0, 1)) which triangle.
    let chances = pick_chances();
    var take_triangle = true;
    var take_disc = true;
    var pick_xi = xi[0];
    if ((frame.method & METHOD_SINGLE_PICK) != 0u) {
        if (xi[0] < chances.x) {
            take_triangle = false;
        } else {
            take_disc = false;
            pick_xi = min((xi[0] - chances.x) / chances.y, ONE_BELOW);
        }
    }
    var picked = LightPick(false, 0u, 0.0);
    if (nee && take_triangle && frame.light_count > 0u && frame.light_weight_total > 0.0) {
        let n_lights = frame.light_count;
        if ((frame.method & METHOD_LIGHT_TREE) != 0u) {
            picked = light_tree_sample(n_lights, x, f.n, pick_xi);
        } else {
            var index = min(u32(pick_xi * f32(n_lights)), n_lights - 1u);
            if (by_power && xi[1] >= lights[index].alias_threshold) {
                index = lights[index].alias_index;
            }
            var chance = 1.0 / f32(n_lights);
            if (by_power) {
                chance = lights[index].weight / frame.light_weight_total;
            }
            picked = LightPick(true, index, chance);
        }
    }
    if (picked.found && picked.light < arrayLength(&lights)) {
        let light = lights[picked.light];
        let bary = uniform_triangle(vec2<f32>(xi[2], xi[3]));
        let p = light.p0 + (light.p1 - light.p0) * bary.x + (light.p2 - light.p0) * bary.y;
        let cr = cross(light.p1 - light.p0, light.p2 - light.p0);
        let area = 0.5 * length(cr);
        let to_light = p - x;
        let dist2 = dot(to_light, to_light);
        if (area > 0.0 && dist2 > 0.0) {
            let dist = sqrt(dist2);
            let wi = to_light / dist;
            let emitter = light_emission(light.instance, light.triangle, bary);
            var cos_light = -dot(wi, cr / (2.0 * area));
            if (emitter.two_sided) {
                cos_light = abs(cos_light);
            }
            if (cos_light > 0.0 && any(emitter.radiance != vec3<f32>(0.0))) {
                let e = bsdf_eval(bsdf, wo_local, to_local(wi, f));
                let light_pdf = picked.pmf * chances.y * dist2 / (cos_light * area);
                if (any(e.value != vec3<f32>(0.0))) {
                    var w = 1.0;
                    if (mis) {
                        w = power_heuristic(light_pdf, e.pdf);
                    }
                    out.rays[out.count] = shadow_ray_to(x, ng, p, cr / (2.0 * area));
                    out.contribution[out.count] = throughput * e.value * emitter.radiance * (w / light_pdf) * transmittance(medium, dist);
                    out.count += 1u;
                }
            }
        }
    }
    // Inside an absorbing medium the sun is infinitely far through it: nothing arrives.
    if (nee && take_disc && frame.sun_solid_angle >= 0.0 && all(medium == vec3<f32>(0.0))) {
        let sun = frame.sun_direction;
        var wi = sun;
        var scale = 1.0 / chances.x;
        if (frame.sun_solid_angle > 0.0) {
            wi = to_world(uniform_cone(vec2<f32>(xi[4], xi[5]), frame.sun_cos_radius), basis(sun));
        }
        let e = bsdf_eval(bsdf, wo_local, to_local(wi, f));
        if (frame.sun_solid_angle > 0.0) {
            let sun_pdf = chances.x / frame.sun_solid_angle;
            var w = 1.0;
            if (mis) {
                w = power_heuristic(sun_pdf, e.pdf);
            }
            scale = w / sun_pdf;
        }
        if (any(e.value != vec3<f32>(0.0))
            && disc_lit(wi, sun, frame.sun_sin_radius, frame.sun_terminator)) {
            out.rays[out.count] = shadow_ray(x, ng, wi, FAR);
            // The cloud layer's transmittance, as the escaping ray that reaches the disc.
            out.contribution[out.count] = throughput * e.value * frame.sun_radiance * scale
                * cloud_transmittance(x, wi);
            out.count += 1u;
        }
    }
    return out;
}

// MIS weight of an emitter reached by BSDF sampling (twin of bsdf_hit_weight in the CPU
// integrator): 1 after a delta bounce or without light sampling, 0 with light sampling but no
// MIS, else the power heuristic.
fn bsdf_hit_weight(last_delta: bool, bsdf_pdf: f32, light_pdf: f32) -> f32 {
    if (last_delta || (frame.method & METHOD_NEE) == 0u) {
        return 1.0;
    }
    if ((frame.method & METHOD_MIS) == 0u) {
        return 0.0;
    }
    return power_heuristic(bsdf_pdf, light_pdf);
}

// World-space area of the triangle a hit lies on.
fn hit_area(hit: Hit) -> f32 {
    let inst = instances[hit.instance];
    let tri = triangles[inst.triangle_base + hit.triangle];
    let a = world_point(inst, v3(vertices[inst.vertex_base + tri.indices[0]].position));
    let b = world_point(inst, v3(vertices[inst.vertex_base + tri.indices[1]].position));
    let c = world_point(inst, v3(vertices[inst.vertex_base + tri.indices[2]].position));
    return 0.5 * length(cross(b - a, c - a));
}

// Beer–Lambert transmittance over `distance` metres of a medium with absorption `sigma` (1/m);
// exactly 1 outside any medium (twin of `transmittance` in direct.rs).
fn transmittance(sigma: vec3<f32>, distance: f32) -> vec3<f32> {
    if (all(sigma == vec3<f32>(0.0))) {
        return vec3<f32>(1.0);
    }
    return exp(-sigma * distance);
}
