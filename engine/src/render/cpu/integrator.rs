//! The path tracing integrator of the CPU tracer (twin: `shaders/trace.wgsl`).
//!
//! Owns: one camera sample → its radiance estimate: unidirectional path tracing (Brigade's
//! Algorithm 1) with next-event estimation on emissive triangles (picked by power from the alias
//! table, uniformly, or by importance from the light tree (`light_tree.rs`); point uniform on
//! the triangle) and on the sun, combined with BSDF sampling by multiple importance
//! sampling (power heuristic); Russian roulette after `roulette_start` scattering events;
//! Beer–Lambert absorption along every segment inside an absorbing dielectric (the path tracks
//! the medium it was transmitted into, so light reaching a pool's floor through open water is
//! attenuated on the way); sky radiance for escaping rays, seen through the cloud layer
//! (`clouds.rs`); line emitters
//! seen prefiltered along camera rays and their perfect specular turns (`lines.rs`).
//! The path loop is read against `shaders/trace.wgsl` line by line (the same random draws in the
//! same order); next-event estimation lives in `direct.rs`, and the pieces that stand alone
//! beside it (`bsdf`, `light_tree`, `lines`, `surface`). It also hands the denoiser's guide
//! of the camera ray's first hit to the caller that asks (`guides::first_hit`; CPU only: the
//! GPU tracer's guides come from the CPU guide pass).
//! Must not: write the film or know about tiles and threads.

use glam::{Vec2, Vec3};

use super::clouds;
use super::cone::Cone;
use super::direct::{
    NEE_RANDOMS, bsdf_hit_weight, hit_area, next_event, pick_chances, transmittance,
};
use super::guides::{FirstHit, SKY_GUIDE, first_hit};
use super::interleave::indirect_weight;
use super::lines::{past_lines, pixel_angle, seen_lines};
use super::night::{disc_inside, disc_lit, night_radiance};
use super::rng::Rng;
use super::sampling::{basis, concentric_disc, to_local, to_world};
use super::surface::{can_emit, offset_origin, reads_levels, resolve, shade};
use crate::layout::{
    GpuFrameUniforms, GpuLine, INSTANCE_FLAG_UNSAMPLED, METHOD_LIGHT_TREE, METHOD_LIGHTS_BY_POWER,
    SKY_GRADIENT, SKY_PHYSICAL,
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
            + night_radiance(u, sky_table, d);
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
/// emitters ([`RenderScene::lines`]), seen prefiltered by the camera (`lines.rs`). With `first`,
/// the denoiser's guide is taken from the camera ray's first hit on the way (`guides.rs`).
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
    mut first: Option<&mut FirstHit>,
) -> Vec3 {
    let mut rng = Rng::new(px, py, sample, u.seed);
    let mut ray = camera_ray(u, px, py, &mut rng);
    counts.camera += 1;
    if let Some(f) = first.as_deref_mut() {
        *f = FirstHit::Follow(ray);
    }
    let camera = ray;
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
    // The path's ray cone: picks the texture levels at each hit.
    let mut cone = Cone::camera(u);
    // The path so far is the camera ray and perfect mirror or glass turns: it sees line
    // emitters prefiltered over the pixel, `travelled` metres from the camera.
    let mut camera_chain = !lines.is_empty();
    let mut travelled = 0.0f32;
    // Absorption coefficients (1/m) of the medium the path travels in: set when it is
    // transmitted into an absorbing dielectric's front face, cleared when transmitted out of a
    // back face (one level: a medium inside a medium is left for the outer one's air).
    let mut medium = Vec3::ZERO;
    let pixel_angle = pixel_angle(u);
    // Whether the path has passed its first diffuse or glossy bounce, which interleaved
    // indirect light traces from some pixels only (`interleave.rs`).
    let mut scattered = false;
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
            if bounce == 0
                && let Some(f) = first.as_deref_mut()
            {
                *f = FirstHit::Known(SKY_GUIDE);
            }
            // The cloud layer dims the sky and the disc alike (`clouds.rs`).
            let cloud = clouds::transmittance(u, &scene.sky.clouds, ray.origin, ray.direction);
            let sky = sky_radiance(u, &scene.sky.texels, ray.direction);
            let mut escaped = clouds::through(u, sky, cloud);
            if sun_solid_angle > 0.0
                && disc_inside(ray.direction, sun_direction, u.sun_sin_radius)
                && disc_lit(
                    ray.direction,
                    sun_direction,
                    u.sun_sin_radius,
                    sun_terminator,
                )
            {
                let disc_pdf = pick_chances(u).0 / sun_solid_angle;
                let w = bsdf_hit_weight(u.method, last_delta, last_pdf, disc_pdf);
                escaped += sun_radiance * (w * cloud);
            }
            // Escaping through a medium is an infinite path through it.
            if medium == Vec3::ZERO {
                result += throughput * escaped;
            }
            break;
        };
        // The last hit only adds the light it emits: one that cannot emit ends the path here,
        // unresolved and unshaded (the estimate is the same, bit for bit).
        if bounce >= u.max_bounces && !can_emit(scene, &hit) {
            break;
        }
        let surface = resolve(scene, &hit, ray.direction);
        cone.travel(hit.t);
        let lod_random = if reads_levels(&scene.materials[surface.material as usize]) {
            rng.next_f32()
        } else {
            0.0
        };
        let lod = cone.lod(
            surface.uv_density,
            surface.geometric_normal,
            ray.direction,
            lod_random,
        );
        let shading = shade(scene, &surface, lod);
        if bounce == 0
            && let Some(f) = first.as_deref_mut()
        {
            *f = first_hit(camera, &hit, &surface, &shading);
        }
        let wo = -ray.direction;
        let front = wo.dot(surface.geometric_normal) > 0.0;
        if medium != Vec3::ZERO {
            // Travelled `t` metres through the medium the path is in (to the medium's far side
            // or to anything inside it: a pool's floor under open water).
            throughput *= transmittance(medium, hit.t);
        } else if !front && shading.absorption != Vec3::ZERO {
            // Reached an absorbing dielectric's back face without having been transmitted into
            // it (the camera is inside): the `t` metres ran through it.
            throughput *= (-shading.absorption * hit.t).exp();
        }
        if shading.emission != Vec3::ZERO && (front || shading.two_sided_emission) {
            // An emitter next-event estimation cannot pick (none in the table, or its light
            // group out of sight of the camera's render area) has only this strategy: weight 1.
            let unsampled =
                scene.instances[hit.instance as usize].flags & INSTANCE_FLAG_UNSAMPLED != 0;
            let w = if last_delta || u.light_count == 0 || unsampled {
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
                let light_pdf = select * pick_chances(u).1 * hit.t * hit.t / cos_light.max(1e-30);
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
                    medium,
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
        if !s.delta && !scattered {
            scattered = true;
            let w = indirect_weight(u.method, px, py, sample);
            if w == 0.0 {
                break;
            }
            throughput *= w;
        }
        if throughput == Vec3::ZERO {
            break;
        }
        // Crossed the surface (wo and wi on opposite sides of it): into or out of its medium.
        let crossed = transmitted != (wo_local.z < 0.0);
        if crossed && !bsdf.is_two_sided() {
            medium = if front {
                shading.absorption
            } else {
                Vec3::ZERO
            };
        }
        last_pdf = s.pdf;
        last_delta = s.delta;
        cone.bounce(s.pdf, s.delta);
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
