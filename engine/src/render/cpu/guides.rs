//! The denoiser's [`Guides`] from the CPU tracer: either a pass of their own, one ray per pixel
//! through its centre (no jitter, the lens's centre) to the primary hit ([`trace_guides`]), or
//! taken from the integrator's own first hits while it traces the frame ([`FirstHit`],
//! [`first_hit`], [`resolve_first_hit`]: the sample's own camera ray, which goes through the
//! pixel's centre while the denoiser is on, `render/frame_render.rs`; only pixels whose first
//! hit is a mirror or glass trace their guide again, along that same ray).
//!
//! Owns: [`trace_guides`], [`FirstHit`], [`guide_along`]. The normal is the shading normal at
//! the primary hit turned to face the camera, the depth its distance along the ray (metres), the
//! instance the one hit; the albedo follows perfect mirrors (up to [`MAX_SPECULAR`] reflections,
//! multiplying their tints) to the first non-specular surface and takes its base colour; smooth
//! glass and the sky give 1 (not demodulated). A pixel whose primary hit emits is flagged (the
//! filter leaves it alone), and so is one whose primary hit is specular (a mirror or smooth
//! glass: reprojection does not reuse its history, its picture moves unlike its surface).
//! Either way it runs only when the denoiser is on, so the tracer pays nothing for it
//! otherwise: the pass on the render thread (rows on rayon's pool), the first hits on the
//! tracer's tiles.
//! Must not: shade or accumulate radiance (the integrator does), or change the scene.

use glam::Vec3;
use rayon::prelude::*;

use super::lines::past_lines;
use super::microfacet::reflect;
use super::surface::{Shading, Surface, offset_origin, resolve, shade};
use crate::layout::{GpuFrameUniforms, MATERIAL_CONDUCTOR};
use crate::render::denoise::{Guides, NO_INSTANCE};
use crate::scene::RenderScene;
use crate::trace::Ray;

/// One pixel's guide: normal, depth, albedo, instance, emissive, specular first hit.
pub type Guide = (Vec3, f32, Vec3, u32, bool, bool);

/// The guide of the pixel whose ray sees the sky.
pub const SKY_GUIDE: Guide = (Vec3::ZERO, 0.0, Vec3::ONE, NO_INSTANCE, false, false);

/// What the integrator saw of a pixel's guide at its camera ray's first hit.
#[derive(Clone, Copy, Debug)]
pub enum FirstHit {
    /// Not traced yet.
    Open,
    /// The guide is known: a non-specular first hit, or the sky.
    Known(Guide),
    /// The guide follows this camera ray ([`guide_along`]): its first hit is a mirror or glass,
    /// or the path ended before shading it.
    Follow(Ray),
}

/// The guide a traced [`FirstHit`] stands for (tracing the mirrors of a [`FirstHit::Follow`]).
pub fn resolve_first_hit(
    scene: &RenderScene,
    tracer: &crate::trace::TraceScene<'_>,
    first: FirstHit,
) -> Guide {
    match first {
        FirstHit::Open => SKY_GUIDE,
        FirstHit::Known(guide) => guide,
        FirstHit::Follow(ray) => guide_along(scene, tracer, ray),
    }
}

/// The guide of a camera ray `camera` whose first hit (after the line prisms) is `hit`, shaded
/// as `shading` at `surface`: [`FirstHit::Known`] unless that surface is specular. The same
/// values [`guide_along`] gives for that ray, with the albedo at the texture level the
/// integrator shaded it at.
pub fn first_hit(
    camera: Ray,
    hit: &crate::trace::Hit,
    surface: &Surface,
    shading: &Shading,
) -> FirstHit {
    if shading.bsdf.is_delta() {
        return FirstHit::Follow(camera);
    }
    let (n, emits) = facing(camera.direction, surface, shading);
    FirstHit::Known((
        n,
        hit.t,
        shading.bsdf.base_color,
        hit.instance,
        emits,
        false,
    ))
}

/// The shading normal turned to face the ray, and whether the surface emits toward it.
fn facing(direction: Vec3, surface: &Surface, shading: &Shading) -> (Vec3, bool) {
    let wo = -direction;
    let mut n = shading.shading_normal;
    if n.dot(wo) < 0.0 {
        n = -n;
    }
    let front = wo.dot(surface.geometric_normal) > 0.0;
    let emits = shading.emission != Vec3::ZERO && (front || shading.two_sided_emission);
    (n, emits)
}

/// Mirror reflections the albedo follows before giving up (and taking 1).
pub const MAX_SPECULAR: u32 = 3;

/// The camera ray through the centre of pixel (px, py) from the lens's centre.
fn centre_ray(u: &GpuFrameUniforms, px: u32, py: u32) -> Ray {
    let sx = 2.0 * (px as f32 + 0.5) / u.width as f32 - 1.0;
    let sy = 1.0 - 2.0 * (py as f32 + 0.5) / u.height as f32;
    let direction = (Vec3::from(u.camera_forward)
        + Vec3::from(u.camera_right) * sx
        + Vec3::from(u.camera_up) * sy)
        .normalize();
    Ray {
        origin: Vec3::from(u.camera_position),
        t_min: 0.0,
        direction,
        t_max: f32::INFINITY,
    }
}

/// The guide of the camera ray `ray` (a pixel's centre ray in the guide pass, the sample's own
/// camera ray for a specular first hit of the integrator).
pub fn guide_along(
    scene: &RenderScene,
    tracer: &crate::trace::TraceScene<'_>,
    mut ray: Ray,
) -> Guide {
    let mut first: Option<(Vec3, f32, u32, bool)> = None;
    let mut tint = Vec3::ONE;
    for k in 0..=MAX_SPECULAR {
        // Line emitters are seen prefiltered, not as surfaces (`lines.rs`): look past them.
        let hit = tracer.closest(&ray);
        let Some(hit) = past_lines(scene, tracer, &mut ray, hit) else {
            break;
        };
        let surface = resolve(scene, &hit, ray.direction);
        let shading = shade(scene, &surface, super::texture::Lod::FINEST);
        let wo = -ray.direction;
        let (n, emits) = facing(ray.direction, &surface, &shading);
        if first.is_none() {
            first = Some((n, hit.t, hit.instance, emits));
        }
        let bsdf = shading.bsdf;
        if !bsdf.is_delta() {
            tint *= bsdf.base_color;
            let (normal, depth, instance, emits) = first.unwrap_or((n, hit.t, hit.instance, false));
            return (normal, depth, tint, instance, emits, k > 0);
        }
        if bsdf.kind != MATERIAL_CONDUCTOR {
            break;
        }
        tint *= bsdf.base_color;
        let wi = reflect(wo, n);
        let side = if wi.dot(surface.geometric_normal) >= 0.0 {
            surface.geometric_normal
        } else {
            -surface.geometric_normal
        };
        ray = Ray {
            origin: offset_origin(surface.position, side),
            t_min: 0.0,
            direction: wi,
            t_max: f32::INFINITY,
        };
    }
    match first {
        Some((normal, depth, instance, emits)) => (normal, depth, Vec3::ONE, instance, emits, true),
        None => SKY_GUIDE,
    }
}

/// The guides of the frame `u` describes (its size, camera) over `scene`.
pub fn trace_guides(scene: &RenderScene, u: &GpuFrameUniforms) -> Guides {
    let mut guides = Guides::sky(u.width, u.height);
    if u.width == 0 || u.height == 0 {
        return guides;
    }
    let tracer = scene.trace_scene();
    let rows: Vec<Vec<Guide>> = (0..u.height)
        .into_par_iter()
        .map(|y| {
            (0..u.width)
                .map(|x| guide_along(scene, &tracer, centre_ray(u, x, y)))
                .collect()
        })
        .collect();
    fill(&mut guides, rows.into_iter().flatten());
    guides
}

/// Writes `values` (rows top to bottom) into `guides`.
fn fill(guides: &mut Guides, values: impl Iterator<Item = Guide>) {
    for (i, guide) in values.enumerate() {
        set(guides, i, guide);
    }
}

/// Writes `values` into `guides` at the pixel indices `at` (one each, in order).
pub fn fill_at(guides: &mut Guides, at: &[usize], values: Vec<Guide>) {
    for (&i, guide) in at.iter().zip(values) {
        set(guides, i, guide);
    }
}

/// Writes pixel `i`'s guide.
fn set(guides: &mut Guides, i: usize, (n, z, a, id, e, spec): Guide) {
    guides.specular[i] = spec;
    guides.normal[i] = n;
    guides.depth[i] = z;
    guides.albedo[i] = a;
    guides.instance[i] = id;
    guides.emissive[i] = e;
}
