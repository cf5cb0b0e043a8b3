//! The path tracing integrator of the CPU tracer (twin: `shaders/trace.wgsl`).
//!
//! Owns: one camera sample → its radiance estimate: unidirectional path tracing (Brigade's
//! Algorithm 1) with next-event estimation on emissive triangles (picked by power from the alias
//! table, uniformly, or by importance from the light tree (`light_tree.rs`); point uniform on
//! the triangle) and on the sun, combined with BSDF sampling by multiple importance
//! sampling (power heuristic); Russian roulette after `roulette_start` scattering events;
//! Beer–Lambert absorption inside dielectrics; sky radiance for escaping rays; line emitters
//! seen prefiltered along camera rays and their perfect specular turns (`lines.rs`).
//! Past the ~400-line guide on purpose: the path loop and its next-event estimation are one
//! algorithm read against `shaders/trace.wgsl` line by line (the same random draws in the same
//! order); the pieces that stand alone live beside it (`bsdf`, `light_tree`, `lines`, `surface`).
//! Must not: write the film or know about tiles and threads.

use glam::{Vec2, Vec3};

use super::bsdf::Bsdf;
use super::lines::{LINE_FOOTPRINT_PIXELS, past_lines, seen_lines};
use super::night::{disc_inside, disc_lit, night_radiance};
use super::rng::Rng;
use super::sampling::{
    basis, concentric_disc, power_heuristic, to_local, to_world, uniform_cone, uniform_triangle,
};
use super::surface::{offset_origin, resolve, shade};
use crate::layout::{
    GpuFrameUniforms, GpuLine, INVALID, METHOD_LIGHT_TREE, METHOD_LIGHTS_BY_POWER, METHOD_MIS,
    METHOD_NEE, SKY_GRADIENT, SKY_PHYSICAL,
};
use crate::scene::RenderScene;
use crate::sky::sky_view_radiance;
use crate::trace::{Ray, TraceScene};

/// Rays traced, by kind.
#[derive(Clone, Copy, Debug, Default)]
pub struct RayCounts {
    pub camera: u64,
    pub bounce: u64,
    pub shadow: u64,
    /// Samples whose estimate was not finite and was dropped (counted, never written).
    pub dropped: u64,
}

impl std::ops::AddAssign for RayCounts {
    fn add_assign(&mut self, o: Self) {
        self.camera += o.camera;
        self.bounce += o.bounce;
        self.shadow += o.shadow;
        self.dropped += o.dropped;
    }
}

/// Radiance of the sky in direction `d` (unit); a physical sky reads the scene's sky-view
/// table (`sky_table`, empty: black) and adds the night's second disc, stars and airglow
/// (`night.rs`).
pub fn sky_radiance(u: &GpuFrameUniforms, sky_table: &[[f32; 4]], d: Vec3) -> Vec3 {
    if u.sky_kind == SKY_PHYSICAL {
        if sky_table.is_empty() {
            return Vec3::ZERO;
        }
        return sky_view_radiance(sky_table, Vec3::from_slice(&u.sky_horizon[..3]), d)
            + night_radiance(u, d);
    }
    let zenith = Vec3::from_slice(&u.sky_zenith[..3]);
    if u.sky_kind != SKY_GRADIENT {
        return zenith;
    }
    let horizon = Vec3::from_slice(&u.sky_horizon[..3]);
    let ground = Vec3::from_slice(&u.sky_ground[..3]);
    if d.y >= 0.0 {
        horizon.lerp(zenith, d.y.min(1.0).sqrt())
    } else {
        horizon.lerp(ground, (-d.y).min(1.0).sqrt())
    }
}

/// The camera ray of sample `rng` for pixel (px, py) (box filter: uniform in the pixel).
pub fn camera_ray(u: &GpuFrameUniforms, px: u32, py: u32, rng: &mut Rng) -> Ray {
    let random = Vec2::new(rng.next_f32(), rng.next_f32());
    let jitter = crate::render::jitter::unpack(u.pixel_jitter).map_or(random, Vec2::from);
    let sx = 2.0 * (px as f32 + jitter.x) / u.width as f32 - 1.0;
    let sy = 1.0 - 2.0 * (py as f32 + jitter.y) / u.height as f32;
    let forward = Vec3::from(u.camera_forward);
    let mut direction =
        (forward + Vec3::from(u.camera_right) * sx + Vec3::from(u.camera_up) * sy).normalize();
    let mut origin = Vec3::from(u.camera_position);
    let lens = Vec2::new(rng.next_f32(), rng.next_f32());
    if u.lens_radius > 0.0 {
        let focus = origin + direction * (u.focus_distance / direction.dot(forward));
        let d = concentric_disc(lens) * u.lens_radius;
        let right = Vec3::from(u.camera_right).normalize();
        let up = Vec3::from(u.camera_up).normalize();
        origin += right * d.x + up * d.y;
        direction = (focus - origin).normalize();
    }
    Ray {
        origin,
        t_min: 0.0,
        direction,
        t_max: f32::INFINITY,
    }
}

/// One sample's radiance estimate (linear RGB) for pixel (px, py). `lines` are the scene's line
/// emitters ([`RenderScene::lines`]), seen prefiltered by the camera (`lines.rs`).
#[allow(clippy::too_many_arguments)]
pub fn radiance(
    scene: &RenderScene,
    tracer: &TraceScene,
    u: &GpuFrameUniforms,
    lines: &[GpuLine],
    px: u32,
    py: u32,
    sample: u32,
    counts: &mut RayCounts,
) -> Vec3 {
    let mut rng = Rng::new(px, py, sample, u.seed);
    let mut ray = camera_ray(u, px, py, &mut rng);
    counts.camera += 1;
    let mut throughput = Vec3::ONE;
    let mut result = Vec3::ZERO;
    // Density of the direction just sampled (for MIS) and whether it was a delta lobe.
    let mut last_pdf = 0.0f32;
    let mut last_delta = true;
    // The shading point and normal the direction was sampled at (the light tree's PMF there).
    let mut last_position = Vec3::ZERO;
    let mut last_normal = Vec3::ZERO;
    let sun_solid_angle = u.sun_solid_angle;
    let sun_direction = Vec3::from(u.sun_direction);
    let sun_radiance = Vec3::from(u.sun_radiance);
    let sun_terminator = Vec3::from(u.sun_terminator);
    let mut bounce = 0u32;
    // The path so far is the camera ray and perfect mirror or glass turns: it sees line
    // emitters prefiltered over the pixel, `travelled` metres from the camera.
    let mut camera_chain = !lines.is_empty();
    let mut travelled = 0.0f32;
    let pixel_angle =
        LINE_FOOTPRINT_PIXELS * 2.0 * Vec3::from(u.camera_up).length() / u.height.max(1) as f32;
    loop {
        let mut hit = tracer.closest(&ray);
        if camera_chain {
            hit = past_lines(scene, tracer, &mut ray, hit);
            let t_end = hit.map_or(f32::INFINITY, |h| h.t);
            let (seen, coverage) = seen_lines(lines, &ray, t_end, travelled, pixel_angle);
            result += throughput * seen;
            throughput *= 1.0 - coverage;
            travelled += t_end;
        }
        let Some(hit) = hit else {
            let mut escaped = sky_radiance(u, &scene.sky.texels, ray.direction);
            if sun_solid_angle > 0.0
                && disc_inside(ray.direction, sun_direction, u.sun_sin_radius)
                && disc_lit(
                    ray.direction,
                    sun_direction,
                    u.sun_sin_radius,
                    sun_terminator,
                )
            {
                let w = bsdf_hit_weight(u.method, last_delta, last_pdf, 1.0 / sun_solid_angle);
                escaped += sun_radiance * w;
            }
            result += throughput * escaped;
            break;
        };
        let surface = resolve(scene, &hit, ray.direction);
        let shading = shade(scene, &surface);
        let wo = -ray.direction;
        let front = wo.dot(surface.geometric_normal) > 0.0;
        if !front && shading.absorption != Vec3::ZERO {
            // Travelled `t` metres inside an absorbing dielectric.
            throughput *= (-shading.absorption * hit.t).exp();
        }
        if shading.emission != Vec3::ZERO && (front || shading.two_sided_emission) {
            let w = if last_delta || u.light_count == 0 {
                1.0
            } else {
                let cos_light = wo.dot(surface.geometric_normal).abs();
                let select = if u.method & METHOD_LIGHT_TREE != 0 {
                    let tree = &scene.lights.tree;
                    let leaf =
                        crate::scene::light_tree::leaf_of(&tree.lookup, hit.instance, hit.triangle);
                    super::light_tree::pmf(&tree.nodes, leaf, last_position, last_normal)
                        / hit_area(scene, &hit)
                } else if u.method & METHOD_LIGHTS_BY_POWER != 0 {
                    // weight/total with weight = area · emission weight: the area cancels.
                    scene.materials[surface.material as usize].emission[3] / u.light_weight_total
                } else {
                    1.0 / (u.light_count as f32 * hit_area(scene, &hit))
                };
                let light_pdf = select * hit.t * hit.t / cos_light.max(1e-30);
                bsdf_hit_weight(u.method, false, last_pdf, light_pdf)
            };
            result += throughput * shading.emission * w;
        }
        if bounce >= u.max_bounces {
            break;
        }
        bounce += 1;

        // The shading frame: two-sided materials see `wo` from the front.
        let mut bsdf = shading.bsdf;
        let mut ng = surface.geometric_normal;
        let mut ns = shading.shading_normal;
        if !bsdf.is_two_sided() && !front && bsdf.kind != crate::layout::MATERIAL_DIELECTRIC {
            // Transmissive metal-rough seen from inside behaves as a plain dielectric.
            bsdf.kind = crate::layout::MATERIAL_DIELECTRIC;
        }
        if bsdf.is_two_sided() && !front {
            ng = -ng;
            ns = -ns;
        }
        if wo.dot(ns) * wo.dot(ng) <= 0.0 {
            ns = ng;
        }
        let (t, b) = basis(ns);
        let wo_local = to_local(wo, t, b, ns);

        if !bsdf.is_delta() {
            result += throughput
                * next_event(
                    scene,
                    tracer,
                    u,
                    &bsdf,
                    &surface,
                    ng,
                    (t, b, ns),
                    wo_local,
                    &mut rng,
                    counts,
                );
        } else {
            // Keep the random sequence aligned with paths that do sample lights.
            for _ in 0..NEE_RANDOMS {
                rng.next_f32();
            }
        }

        let xi = Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
        let Some(s) = bsdf.sample(wo_local, xi) else {
            break;
        };
        let wi = to_world(s.wi, t, b, ns);
        // A direction below the geometric surface must not leak through it (and vice versa).
        let transmitted = s.wi.z < 0.0;
        if (wi.dot(ng) < 0.0) != transmitted {
            break;
        }
        throughput *= s.weight;
        if throughput == Vec3::ZERO {
            break;
        }
        last_pdf = s.pdf;
        last_delta = s.delta;
        camera_chain &= s.delta;
        last_position = surface.position;
        last_normal = ns;
        let side = if transmitted { -ng } else { ng };
        ray = Ray {
            origin: offset_origin(surface.position, side),
            t_min: 0.0,
            direction: wi,
            t_max: f32::INFINITY,
        };
        counts.bounce += 1;

        if bounce >= u.roulette_start {
            let survive = (throughput.max_element() * u.roulette_scale).min(0.95);
            if rng.next_f32() >= survive {
                break;
            }
            throughput /= survive;
        } else {
            rng.next_f32();
        }
        if !throughput.is_finite() {
            break;
        }
    }
    if result.is_finite() {
        result
    } else {
        counts.dropped += 1;
        Vec3::ZERO
    }
}

/// Uniform numbers [`next_event`] draws, whether or not it uses them all.
const NEE_RANDOMS: usize = 6;

/// Direct light at a non-delta surface: one emissive triangle picked by power and the sun,
/// each weighted against BSDF sampling.
#[allow(clippy::too_many_arguments)]
fn next_event(
    scene: &RenderScene,
    tracer: &TraceScene,
    u: &GpuFrameUniforms,
    bsdf: &Bsdf,
    surface: &super::surface::Surface,
    ng: Vec3,
    frame: (Vec3, Vec3, Vec3),
    wo_local: Vec3,
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
    if nee && u.light_count > 0 && u.light_weight_total > 0.0 {
        let n_lights = u.light_count;
        let by_power = u.method & METHOD_LIGHTS_BY_POWER != 0;
        let picked = if u.method & METHOD_LIGHT_TREE != 0 {
            super::light_tree::sample(&scene.lights.tree.nodes, n_lights, x, n, xi[0])
        } else {
            let pick = ((xi[0] * n_lights as f32) as u32).min(n_lights - 1);
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
                    let light_pdf = select * dist2 / (cos_light * area);
                    if f != Vec3::ZERO && shadow_to(p, cross / (2.0 * area), counts) {
                        let w = if mis {
                            power_heuristic(light_pdf, bsdf_pdf)
                        } else {
                            1.0
                        };
                        sum += f * emitter.0 * (w / light_pdf);
                    }
                }
            }
        }
    }

    if nee && u.sun_solid_angle >= 0.0 {
        let sun = Vec3::from(u.sun_direction);
        let radiance = Vec3::from(u.sun_radiance);
        if u.sun_solid_angle == 0.0 {
            let (f, _) = bsdf.eval(wo_local, to_local(sun, t, b, n));
            if f != Vec3::ZERO && shadow(sun, f32::INFINITY, counts) {
                sum += f * radiance;
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
                let sun_pdf = 1.0 / u.sun_solid_angle;
                let w = if mis {
                    power_heuristic(sun_pdf, bsdf_pdf)
                } else {
                    1.0
                };
                sum += f * radiance * (w / sun_pdf);
            }
        }
    }
    sum
}

/// MIS weight of an emitter (triangle or sun disc) reached by BSDF sampling with density
/// `bsdf_pdf`, against light sampling with density `light_pdf`, for estimator `method`: 1 after
/// a delta bounce or without light sampling; 0 with light sampling but no MIS (the light
/// sample already counted it); the power heuristic otherwise.
fn bsdf_hit_weight(method: u32, last_delta: bool, bsdf_pdf: f32, light_pdf: f32) -> f32 {
    if last_delta || method & METHOD_NEE == 0 {
        1.0
    } else if method & METHOD_MIS == 0 {
        0.0
    } else {
        power_heuristic(bsdf_pdf, light_pdf)
    }
}

/// World-space area of the triangle `hit` lies on.
fn hit_area(scene: &RenderScene, hit: &crate::trace::Hit) -> f32 {
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
        emission *= super::texture::sample(&scene.textures, &scene.texels, m.emission_texture, uv)
            .truncate();
    }
    (
        emission,
        m.flags & crate::layout::MATERIAL_FLAG_TWO_SIDED_EMISSION != 0,
    )
}
