//! Direct lighting of the CPU tracer's path loop (twin: `next_event` and its helpers in
//! `shaders/direct.wgsl`).
//!
//! Owns: next-event estimation at a non-delta surface (one emissive triangle picked by power,
//! uniformly or by the light tree, and the sun or moon disc), and the MIS weights and pick
//! densities an emitter reached by BSDF sampling needs to match it. Radiance is linear RGB,
//! positions world-space metres, densities per steradian.
//! Runs on the tracer's worker threads, called from `integrator.rs` once per scattering event.
//! Must not: advance the path, write the film, or draw a different number of random numbers
//! than [`NEE_RANDOMS`] (the GPU twin draws the same sequence).

use glam::{Vec2, Vec3};

use super::bsdf::Bsdf;
use super::integrator::RayCounts;
use super::night::disc_lit;
use super::rng::Rng;
use super::sampling::{basis, power_heuristic, to_local, to_world, uniform_cone, uniform_triangle};
use super::surface::offset_origin;
use crate::layout::{
    GpuFrameUniforms, INVALID, METHOD_LIGHT_TREE, METHOD_LIGHTS_BY_POWER, METHOD_MIS, METHOD_NEE,
    METHOD_SINGLE_PICK,
};
use crate::scene::RenderScene;
use crate::scene::materials::luminance;
use crate::trace::{Ray, TraceScene};

/// Uniform numbers [`next_event`] draws, whether or not it uses them all.
pub(super) const NEE_RANDOMS: usize = 6;

/// Direct light at a non-delta surface: one emissive triangle picked by power and the sun,
/// each weighted against BSDF sampling.
#[allow(clippy::too_many_arguments)]
pub(super) fn next_event(
    scene: &RenderScene,
    tracer: &TraceScene,
    u: &GpuFrameUniforms,
    bsdf: &Bsdf,
    surface: &super::surface::Surface,
    ng: Vec3,
    frame: (Vec3, Vec3, Vec3),
    wo_local: Vec3,
    medium: Vec3,
    rng: &mut Rng,
    counts: &mut RayCounts,
) -> Vec3 {
    let (t, b, n) = frame;
    let xi: [f32; NEE_RANDOMS] = std::array::from_fn(|_| rng.next_f32());
    let mut sum = Vec3::ZERO;
    let x = surface.position;
    let shadow = |direction: Vec3, distance: f32, counts: &mut RayCounts| {
        counts.shadow += 1;
        let side = if direction.dot(ng) >= 0.0 { ng } else { -ng };
        let ray = Ray {
            origin: offset_origin(x, side),
            t_min: 0.0,
            direction,
            t_max: distance,
        };
        !tracer.occluded(&ray)
    };
    // Visibility of the light point `p` (light normal `ln`): from x offset off its surface to p
    // offset off the light's, so neither end's own surface can block at any magnitude of
    // coordinates (a fixed fraction of the distance cannot: the offsets grow with |x|).
    let shadow_to = |p: Vec3, ln: Vec3, counts: &mut RayCounts| {
        counts.shadow += 1;
        let to = p - x;
        let side = if to.dot(ng) >= 0.0 { ng } else { -ng };
        let origin = offset_origin(x, side);
        let target = offset_origin(p, if ln.dot(-to) >= 0.0 { ln } else { -ln });
        let span = target - origin;
        let length = span.length();
        if !(length > 0.0) {
            return false;
        }
        let ray = Ray {
            origin,
            t_min: 0.0,
            direction: span / length,
            t_max: length,
        };
        !tracer.occluded(&ray)
    };

    let nee = u.method & METHOD_NEE != 0;
    let mis = u.method & METHOD_MIS != 0;
    // Two lights (Brigade §6.2.3): one triangle and the disc. One pick: xi[0] chooses the disc
    // or the triangles, then (rescaled to [0, 1)) which triangle.
    let (disc_chance, triangle_chance) = pick_chances(u);
    let (take_triangle, take_disc, pick_xi) = if u.method & METHOD_SINGLE_PICK == 0 {
        (true, true, xi[0])
    } else if xi[0] < disc_chance {
        (false, true, xi[0])
    } else {
        let rescaled = (xi[0] - disc_chance) / triangle_chance;
        (true, false, rescaled.min(ONE_BELOW))
    };
    if nee && take_triangle && u.light_count > 0 && u.light_weight_total > 0.0 {
        let n_lights = u.light_count;
        let by_power = u.method & METHOD_LIGHTS_BY_POWER != 0;
        let picked = if u.method & METHOD_LIGHT_TREE != 0 {
            super::light_tree::sample(&scene.lights.tree.nodes, n_lights, x, n, pick_xi)
        } else {
            let pick = ((pick_xi * n_lights as f32) as u32).min(n_lights - 1);
            let mut light = &scene.lights.lights[pick as usize];
            let mut index = pick;
            if by_power && xi[1] >= light.alias_threshold {
                index = light.alias_index;
                light = &scene.lights.lights[index as usize];
            }
            let select = if by_power {
                light.weight / u.light_weight_total
            } else {
                1.0 / n_lights as f32
            };
            Some((index, select))
        };
        if let Some((index, select)) = picked
            && let Some(light) = scene.lights.lights.get(index as usize)
        {
            let (p0, p1, p2) = (
                Vec3::from(light.p0),
                Vec3::from(light.p1),
                Vec3::from(light.p2),
            );
            let bary = uniform_triangle(Vec2::new(xi[2], xi[3]));
            let p = p0 + (p1 - p0) * bary.x + (p2 - p0) * bary.y;
            let cross = (p1 - p0).cross(p2 - p0);
            let area = 0.5 * cross.length();
            let to_light = p - x;
            let dist2 = to_light.length_squared();
            if area > 0.0 && dist2 > 0.0 {
                let dist = dist2.sqrt();
                let wi = to_light / dist;
                let emitter = light_emission(scene, light.instance, light.triangle, bary);
                let mut cos_light = -wi.dot(cross / (2.0 * area));
                if emitter.1 {
                    cos_light = cos_light.abs();
                }
                if cos_light > 0.0 && emitter.0 != Vec3::ZERO {
                    let (f, bsdf_pdf) = bsdf.eval(wo_local, to_local(wi, t, b, n));
                    let light_pdf = select * triangle_chance * dist2 / (cos_light * area);
                    if f != Vec3::ZERO && shadow_to(p, cross / (2.0 * area), counts) {
                        let w = if mis {
                            power_heuristic(light_pdf, bsdf_pdf)
                        } else {
                            1.0
                        };
                        sum += f * emitter.0 * (w / light_pdf) * transmittance(medium, dist);
                    }
                }
            }
        }
    }

    // Inside an absorbing medium the sun is infinitely far through it: nothing arrives.
    if nee && take_disc && u.sun_solid_angle >= 0.0 && medium == Vec3::ZERO {
        let sun = Vec3::from(u.sun_direction);
        let radiance = Vec3::from(u.sun_radiance);
        // The cloud layer's transmittance towards the disc (`clouds.rs`): the same function
        // the escaping ray that reaches the disc is multiplied by.
        let cloud = |wi: Vec3| super::clouds::transmittance(u, &scene.sky.clouds, x, wi);
        if u.sun_solid_angle == 0.0 {
            let (f, _) = bsdf.eval(wo_local, to_local(sun, t, b, n));
            if f != Vec3::ZERO && shadow(sun, f32::INFINITY, counts) {
                sum += f * radiance * cloud(sun) / disc_chance;
            }
        } else {
            let (st, sb) = basis(sun);
            let wi = to_world(
                uniform_cone(Vec2::new(xi[4], xi[5]), u.sun_cos_radius),
                st,
                sb,
                sun,
            );
            let (f, bsdf_pdf) = bsdf.eval(wo_local, to_local(wi, t, b, n));
            let lit = disc_lit(wi, sun, u.sun_sin_radius, Vec3::from(u.sun_terminator));
            if f != Vec3::ZERO && lit && shadow(wi, f32::INFINITY, counts) {
                let sun_pdf = disc_chance / u.sun_solid_angle;
                let w = if mis {
                    power_heuristic(sun_pdf, bsdf_pdf)
                } else {
                    1.0
                };
                sum += f * radiance * (w * cloud(wi) / sun_pdf);
            }
        }
    }
    sum
}

/// The largest `f32` below 1.
const ONE_BELOW: f32 = 1.0 - f32::EPSILON / 2.0;

/// The chances that next-event estimation samples (the primary disc, the picked triangle):
/// both 1 without [`METHOD_SINGLE_PICK`] (each is sampled at every hit: Brigade §6.2.3's two
/// lights). With it, one pick among all lights, the disc (sun or moon) chosen by its share of a
/// cosine-free irradiance estimate: the disc gives luminance(radiance) × solid angle (W/m² at
/// normal incidence; a delta sun's `sun_radiance` is that irradiance already), the triangles
/// `light_weight_total` (Σ area × emitted luminance) × 1 m⁻², the irradiance they would give a
/// surface facing them all from one metre. Any split is unbiased as long as the light pdf (here
/// and at emitters reached by BSDF sampling) divides by it; this one needs no new uniform.
/// Twin: `pick_chances` in `shaders/direct.wgsl`.
pub(super) fn pick_chances(u: &GpuFrameUniforms) -> (f32, f32) {
    if u.method & METHOD_SINGLE_PICK == 0 {
        return (1.0, 1.0);
    }
    let disc = if u.sun_solid_angle < 0.0 {
        0.0
    } else if u.sun_solid_angle == 0.0 {
        luminance(Vec3::from(u.sun_radiance))
    } else {
        luminance(Vec3::from(u.sun_radiance)) * u.sun_solid_angle
    };
    let triangles = if u.light_count > 0 && u.light_weight_total > 0.0 {
        u.light_weight_total
    } else {
        0.0
    };
    let total = disc + triangles;
    if !(total > 0.0 && total.is_finite() && disc >= 0.0) {
        return (0.0, 1.0);
    }
    let disc_chance = disc / total;
    (disc_chance, 1.0 - disc_chance)
}

/// MIS weight of an emitter (triangle or sun disc) reached by BSDF sampling with density
/// `bsdf_pdf`, against light sampling with density `light_pdf`, for estimator `method`: 1 after
/// a delta bounce or without light sampling; 0 with light sampling but no MIS (the light
/// sample already counted it); the power heuristic otherwise.
pub(super) fn bsdf_hit_weight(method: u32, last_delta: bool, bsdf_pdf: f32, light_pdf: f32) -> f32 {
    if last_delta || method & METHOD_NEE == 0 {
        1.0
    } else if method & METHOD_MIS == 0 {
        0.0
    } else {
        power_heuristic(bsdf_pdf, light_pdf)
    }
}

/// World-space area of the triangle `hit` lies on.
pub(super) fn hit_area(scene: &RenderScene, hit: &crate::trace::Hit) -> f32 {
    let inst = &scene.instances[hit.instance as usize];
    let tri = scene.triangles[(inst.triangle_base + hit.triangle) as usize];
    let p = tri.indices.map(|i| {
        crate::scene::lights::world_point(
            inst,
            scene.vertices[(inst.vertex_base + i) as usize].position,
        )
    });
    0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length()
}

/// Emitted radiance of a light triangle at barycentrics `bary` (b1, b2), and whether it emits
/// from both faces.
fn light_emission(scene: &RenderScene, instance: u32, triangle: u32, bary: Vec2) -> (Vec3, bool) {
    let Some(inst) = scene.instances.get(instance as usize) else {
        return (Vec3::ZERO, false);
    };
    let tri = scene.triangles[(inst.triangle_base + triangle) as usize];
    let material_index = if inst.material_override != INVALID {
        inst.material_override
    } else {
        tri.material
    };
    let m = &scene.materials[material_index as usize];
    let mut emission = Vec3::from_slice(&m.emission[..3]);
    if m.emission_texture != INVALID {
        let uv = |k: usize| {
            let v = scene.vertices[(inst.vertex_base + tri.indices[k]) as usize];
            Vec2::new(v.u, v.v)
        };
        let uv = uv(0) * (1.0 - bary.x - bary.y) + uv(1) * bary.x + uv(2) * bary.y;
        emission *= super::texture::sample(
            &scene.textures,
            &scene.texels,
            m.emission_texture,
            uv,
            super::texture::Lod::FINEST,
        )
        .truncate();
    }
    (
        emission,
        m.flags & crate::layout::MATERIAL_FLAG_TWO_SIDED_EMISSION != 0,
    )
}

/// Beer–Lambert transmittance over `distance` metres of a medium with absorption coefficients
/// `sigma` (1/m, per channel); exactly 1 outside any medium (`sigma` zero), so paths that never
/// enter one keep their bits.
pub(super) fn transmittance(sigma: Vec3, distance: f32) -> Vec3 {
    if sigma == Vec3::ZERO {
        Vec3::ONE
    } else {
        (-sigma * distance).exp()
    }
}
