// The path tracing pass: one invocation per pixel traces `frame.spp` samples and adds their
// radiance to the film. Twin of engine/src/render/cpu/integrator.rs (same algorithm, same RNG
// draws in the same order). Composed after shared/{types,bindings,rng,sampling,microfacet,
// bsdf,texture,traverse,surface,lines,sky_view,night}.wgsl, shared/light_tree.wgsl and
// direct.wgsl (next-event estimation) by engine/src/render/gpu/shaders.rs.

const FAR: f32 = 3.0e38;
// The largest finite f32, and the largest f32 below 1.
const MAX_F32: f32 = 3.4028235e38;
const ONE_BELOW: f32 = 0.99999994;

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
    // The path's ray cone: picks the texture levels at each hit.
    var cone = cone_camera();
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
    // Absorption (1/m) of the medium the path travels in (twin of `medium` in integrator.rs).
    var medium = vec3<f32>(0.0);
    let pixel_angle = line_pixel_angle();
    var crossings = 0u;
    // Whether the path has passed its first diffuse or glossy bounce, which interleaved
    // indirect light traces from some pixels only (interleave.wgsl).
    var scattered = false;
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
            // The cloud layer dims the sky and the disc alike (shared/clouds.wgsl).
            let cloud = cloud_transmittance(ray.origin, ray.direction);
            var escaped = cloud_through(sky_radiance(ray.direction), cloud);
            if (frame.sun_solid_angle > 0.0 && disc_inside(ray.direction, frame.sun_direction, frame.sun_sin_radius)
                && disc_lit(ray.direction, frame.sun_direction, frame.sun_sin_radius, frame.sun_terminator)) {
                let w = bsdf_hit_weight(last_delta, last_pdf, pick_chances().x / frame.sun_solid_angle);
                escaped += frame.sun_radiance * (w * cloud);
            }
            if (all(medium == vec3<f32>(0.0))) {
                result += throughput * escaped;
            }
            break;
        }
        // The last hit only adds the light it emits: one that cannot emit ends the path here.
        if (bounce >= frame.max_bounces && !hit_can_emit(hit)) {
            break;
        }
        let surface = resolve_surface(hit, ray.direction);
        cone.width += cone.spread * max(hit.t, 0.0);
        var lod_random = 0.0;
        if (reads_levels(materials[surface.material])) {
            lod_random = rng_next(&rng);
        }
        let lod = cone_lod(cone, surface.uv_density, surface.geometric_normal, ray.direction, lod_random);
        let shading = shade_surface(surface, lod);
        let wo = -ray.direction;
        let front = dot(wo, surface.geometric_normal) > 0.0;
        if (any(medium != vec3<f32>(0.0))) {
            throughput *= transmittance(medium, hit.t);
        } else if (!front && any(shading.absorption != vec3<f32>(0.0))) {
            throughput *= exp(-shading.absorption * hit.t);
        }
        if (any(shading.emission != vec3<f32>(0.0)) && (front || shading.two_sided_emission)) {
            var w = 1.0;
            // An emitter next-event estimation cannot pick (none in the table, or its light
            // group out of sight of the camera's render area) has only this strategy: weight 1.
            let unsampled = (instances[hit.instance].flags & INSTANCE_FLAG_UNSAMPLED) != 0u;
            if (!last_delta && frame.light_count > 0u && !unsampled) {
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
            shadows = next_event(bsdf, surface.position, ng, f, wo_local, throughput, medium, &rng);
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
            var indirect = 1.0;
            if (!s.delta && !scattered) {
                scattered = true;
                indirect = indirect_weight(frame.method, px, py, sample);
            }
            throughput *= indirect;
            if ((dot(wi, ng) < 0.0) != below || indirect == 0.0 || all(throughput == vec3<f32>(0.0))) {
                have_next = false;
            } else {
                // Crossed the surface (wo and wi on opposite sides): into or out of its medium.
                if (below != (wo_local.z < 0.0) && !bsdf_is_two_sided(bsdf)) {
                    if (front) {
                        medium = shading.absorption;
                    } else {
                        medium = vec3<f32>(0.0);
                    }
                }
                last_pdf = s.pdf;
                last_delta = s.delta;
                cone = cone_bounce(cone, s.pdf, s.delta);
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
