// The path tracing pass: one invocation per pixel traces `frame.spp` samples and adds their
// radiance to the film. Twin of engine/src/render/cpu/integrator.rs (same algorithm, same RNG
// draws in the same order). Composed after shared/{types,bindings,rng,sampling,microfacet,
// bsdf,texture,traverse,surface,lines,sky_view,night}.wgsl and shared/light_tree.wgsl by
// engine/src/render/gpu/shaders.rs.

const FAR: f32 = 3.0e38;
// The largest finite f32, and the largest f32 below 1.
const MAX_F32: f32 = 3.4028235e38;
const ONE_BELOW: f32 = 0.99999994;
const NEE_RANDOMS: u32 = 6u;

var<private> count_camera: u32;
var<private> count_bounce: u32;
var<private> count_shadow: u32;

// Twin of `sky_radiance` in engine/src/render/cpu/integrator.rs. A physical sky reads the
// sky-view table (zeros when the scene's table is empty: black, as on the CPU).
fn sky_radiance(d: vec3<f32>) -> vec3<f32> {
    if (frame.sky_kind == SKY_PHYSICAL) {
        return sky_view_radiance(frame.sky_horizon.xyz, d) + night_radiance(d);
    }
    let zenith = frame.sky_zenith.xyz;
    if (frame.sky_kind != SKY_GRADIENT) {
        return zenith;
    }
    let horizon = frame.sky_horizon.xyz;
    let ground = frame.sky_ground.xyz;
    if (d.y >= 0.0) {
        return mix(horizon, zenith, sqrt(min(d.y, 1.0)));
    }
    return mix(horizon, ground, sqrt(min(-d.y, 1.0)));
}

fn camera_ray(px: u32, py: u32, rng: ptr<function, Rng>) -> Ray {
    var jx = rng_next(rng);
    var jy = rng_next(rng);
    // A fixed offset for temporal upscaling (`render::jitter`): bit 31, x and y in 1/32768.
    if ((frame.pixel_jitter & 0x80000000u) != 0u) {
        jx = f32(frame.pixel_jitter & 0x7fffu) / 32768.0;
        jy = f32((frame.pixel_jitter >> 15u) & 0x7fffu) / 32768.0;
    }
    let sx = 2.0 * (f32(px) + jx) / f32(frame.width) - 1.0;
    let sy = 1.0 - 2.0 * (f32(py) + jy) / f32(frame.height);
    let forward = frame.camera_forward;
    var direction = normalize(forward + frame.camera_right * sx + frame.camera_up * sy);
    var origin = frame.camera_position;
    let lx = rng_next(rng);
    let ly = rng_next(rng);
    if (frame.lens_radius > 0.0) {
        let focus = origin + direction * (frame.focus_distance / dot(direction, forward));
        let disc = concentric_disc(vec2<f32>(lx, ly)) * frame.lens_radius;
        origin += normalize(frame.camera_right) * disc.x + normalize(frame.camera_up) * disc.y;
        direction = normalize(focus - origin);
    }
    return Ray(origin, 0.0, direction, FAR);
}

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
fn next_event(bsdf: Bsdf, x: vec3<f32>, ng: vec3<f32>, f: Frame, wo_local: vec3<f32>, throughput: vec3<f32>, rng: ptr<function, Rng>) -> ShadowRays {
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
                    out.contribution[out.count] = throughput * e.value * emitter.radiance * (w / light_pdf);
                    out.count += 1u;
                }
            }
        }
    }
    if (nee && take_disc && frame.sun_solid_angle >= 0.0) {
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
            out.contribution[out.count] = throughput * e.value * frame.sun_radiance * scale;
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

fn is_finite3(v: vec3<f32>) -> bool {
    return all(v == v) && all(abs(v) <= vec3<f32>(3.4e38));
}

// One sample's radiance estimate. A small state machine around a single `trace_ray` call
// site: each iteration traces either the path's next extension ray or one of the shadow rays
// its last surface asked for (lavapipe inlines every call, so one call site keeps the compiled
// shader small). The random numbers are drawn in the same order as the CPU twin.
fn radiance(px: u32, py: u32, sample: u32) -> vec3<f32> {
    var rng = rng_new(vec2<u32>(px, py), sample, frame.seed);
    var ray = camera_ray(px, py, &rng);
    count_camera += 1u;
    var throughput = vec3<f32>(1.0);
    var result = vec3<f32>(0.0);
    var last_pdf = 0.0;
    var last_delta = true;
    // The shading point and normal the direction was sampled at (the light tree's PMF there).
    var last_position = vec3<f32>(0.0);
    var last_normal = vec3<f32>(0.0);
    var bounce = 0u;
    var shadows: ShadowRays;
    shadows.count = 0u;
    var shadow_index = 0u;
    var tracing_shadow = false;
    var have_next = true;
    var next_ray = ray;
    // The path so far is the camera ray and perfect mirror or glass turns: it sees line
    // emitters prefiltered over the pixel, `travelled` metres from the camera (lines.wgsl).
    var camera_chain = has_lines();
    var travelled = 0.0;
    let pixel_angle = LINE_FOOTPRINT_PIXELS * 2.0 * length(frame.camera_up) / f32(max(frame.height, 1u));
    var crossings = 0u;
    loop {
        var current = next_ray;
        if (tracing_shadow) {
            current = shadows.rays[shadow_index];
        }
        let hit = trace_ray(current, tracing_shadow);
        if (tracing_shadow) {
            count_shadow += 1u;
            if (!hit.found) {
                result += shadows.contribution[shadow_index];
            }
            shadow_index += 1u;
            if (shadow_index < shadows.count) {
                continue;
            }
            tracing_shadow = false;
            if (!have_next) {
                break;
            }
            continue;
        }
        ray = current;
        if (camera_chain) {
            if (hit.found && crossings < MAX_LINE_CROSSINGS && is_line(hit)) {
                // Through the line prism (from the one trace call site): the same ray past it.
                crossings += 1u;
                next_ray = Ray(current.origin, hit.t, current.direction, current.t_max);
                continue;
            }
            crossings = 0u;
            var t_end = LINE_FAR;
            if (hit.found) {
                t_end = hit.t;
            }
            let seen = seen_lines(ray, t_end, travelled, pixel_angle);
            result += throughput * seen.xyz;
            throughput *= 1.0 - seen.w;
            travelled += t_end;
        }
        if (!hit.found) {
            var escaped = sky_radiance(ray.direction);
            if (frame.sun_solid_angle > 0.0 && disc_inside(ray.direction, frame.sun_direction, frame.sun_sin_radius)
                && disc_lit(ray.direction, frame.sun_direction, frame.sun_sin_radius, frame.sun_terminator)) {
                let w = bsdf_hit_weight(last_delta, last_pdf, pick_chances().x / frame.sun_solid_angle);
                escaped += frame.sun_radiance * w;
            }
            result += throughput * escaped;
            break;
        }
        let surface = resolve_surface(hit, ray.direction);
        let shading = shade_surface(surface);
        let wo = -ray.direction;
        let front = dot(wo, surface.geometric_normal) > 0.0;
        if (!front && any(shading.absorption != vec3<f32>(0.0))) {
            throughput *= exp(-shading.absorption * hit.t);
        }
        if (any(shading.emission != vec3<f32>(0.0)) && (front || shading.two_sided_emission)) {
            var w = 1.0;
            if (!last_delta && frame.light_count > 0u) {
                let cos_light = abs(dot(wo, surface.geometric_normal));
                var chance = 0.0;
                if ((frame.method & METHOD_LIGHT_TREE) != 0u) {
                    let leaf = light_leaf_of(hit.instance, hit.triangle);
                    chance = light_tree_pmf(leaf, last_position, last_normal) / hit_area(hit);
                } else if ((frame.method & METHOD_LIGHTS_BY_POWER) != 0u) {
                    chance = materials[surface.material].emission.w / frame.light_weight_total;
                } else {
                    chance = 1.0 / (f32(frame.light_count) * hit_area(hit));
                }
                let light_pdf = chance * pick_chances().y * hit.t * hit.t / max(cos_light, 1e-30);
                w = bsdf_hit_weight(false, last_pdf, light_pdf);
            }
            result += throughput * shading.emission * w;
        }
        if (bounce >= frame.max_bounces) {
            break;
        }
        bounce += 1u;

        var bsdf = shading.bsdf;
        var ng = surface.geometric_normal;
        var ns = shading.shading_normal;
        if (!bsdf_is_two_sided(bsdf) && !front && bsdf.kind != MATERIAL_DIELECTRIC) {
            bsdf.kind = MATERIAL_DIELECTRIC;
        }
        if (bsdf_is_two_sided(bsdf) && !front) {
            ng = -ng;
            ns = -ns;
        }
        if (dot(wo, ns) * dot(wo, ng) <= 0.0) {
            ns = ng;
        }
        let f = basis(ns);
        let wo_local = to_local(wo, f);

        shadows.count = 0u;
        shadow_index = 0u;
        if (!bsdf_is_delta(bsdf)) {
            shadows = next_event(bsdf, surface.position, ng, f, wo_local, throughput, &rng);
        } else {
            for (var i = 0u; i < NEE_RANDOMS; i++) {
                rng_next(&rng);
            }
        }
        tracing_shadow = shadows.count > 0u;

        let x0 = rng_next(&rng);
        let x1 = rng_next(&rng);
        let x2 = rng_next(&rng);
        let s = bsdf_sample(bsdf, wo_local, vec3<f32>(x0, x1, x2));
        have_next = s.valid;
        if (have_next) {
            let wi = to_world(s.wi, f);
            let below = s.wi.z < 0.0;
            throughput *= s.weight;
            if ((dot(wi, ng) < 0.0) != below || all(throughput == vec3<f32>(0.0))) {
                have_next = false;
            } else {
                last_pdf = s.pdf;
                last_delta = s.delta;
                camera_chain = camera_chain && s.delta;
                last_position = surface.position;
                last_normal = ns;
                next_ray = Ray(offset_origin(surface.position, select(ng, -ng, below)), 0.0, wi, FAR);
                count_bounce += 1u;
                let xr = rng_next(&rng);
                if (bounce >= frame.roulette_start) {
                    let survive = min(max(throughput.x, max(throughput.y, throughput.z)) * frame.roulette_scale, 0.95);
                    if (xr >= survive) {
                        have_next = false;
                    } else {
                        throughput /= survive;
                    }
                }
                if (!is_finite3(throughput)) {
                    have_next = false;
                }
            }
        }
        if (!tracing_shadow && !have_next) {
            break;
        }
    }
    if (is_finite3(result)) {
        return result;
    }
    atomicAdd(&counters[3], 1u);
    return vec3<f32>(0.0);
}

@compute @workgroup_size(8, 8, 1)
fn trace_main(@builtin(global_invocation_id) id: vec3<u32>) {
    // id.y counts rows of the listed work units; y is the film row it stands for.
    let slot = id.y / UNIT_ROWS;
    if (slot >= work_units[0]) {
        return;
    }
    let y = work_units[1u + slot] * UNIT_ROWS + id.y % UNIT_ROWS;
    if (id.x >= frame.width || y >= frame.height) {
        return;
    }
    count_camera = 0u;
    count_bounce = 0u;
    count_shadow = 0u;
    var sum = vec3<f32>(0.0);
    for (var s = 0u; s < frame.spp; s++) {
        sum += radiance(id.x, y, frame.sample_base + s);
    }
    let index = y * frame.width + id.x;
    let new_mean = vec4<f32>(sum / f32(max(frame.spp, 1u)), 0.0);
    film[index] = mix(film[index], new_mean, frame.film_blend);
    atomicAdd(&counters[0], count_camera);
    atomicAdd(&counters[1], count_bounce);
    atomicAdd(&counters[2], count_shadow);
}
