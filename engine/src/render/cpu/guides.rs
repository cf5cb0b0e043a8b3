//! The guide pass of the CPU tracer: one ray per pixel through its centre (no jitter, the
//! lens's centre) to the primary hit, for the denoiser's [`Guides`].
//!
//! Owns: [`trace_guides`]. The normal is the shading normal at the primary hit turned to face
//! the camera, the depth its distance along the ray (metres), the instance the one hit; the
//! albedo follows perfect mirrors (up to [`MAX_SPECULAR`] reflections, multiplying their tints)
//! to the first non-specular surface and takes its base colour; smooth glass and the sky give 1
//! (not demodulated). A pixel whose primary hit emits is flagged (the filter leaves it alone), and
//! so is one whose primary hit is specular (a mirror or smooth glass: reprojection does not
//! reuse its history, its picture moves unlike its surface).
//! It runs only when the denoiser is on, so the tracer pays nothing for it
//! otherwise; render thread, rows on rayon's pool.
//! Must not: shade or accumulate radiance (the integrator does), or change the scene.

use glam::Vec3;
use rayon::prelude::*;

use super::lines::past_lines;
use super::microfacet::reflect;
use super::surface::{offset_origin, resolve, shade};
use crate::layout::{GpuFrameUniforms, MATERIAL_CONDUCTOR};
use crate::render::denoise::{Guides, NO_INSTANCE};
use crate::scene::RenderScene;
use crate::trace::Ray;

/// One pixel's guide: normal, depth, albedo, instance, emissive, specular first hit.
type Guide = (Vec3, f32, Vec3, u32, bool, bool);

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

/// (normal, depth, albedo, instance) of pixel (px, py).
fn guide_pixel(
    scene: &RenderScene,
    tracer: &crate::trace::TraceScene<'_>,
    u: &GpuFrameUniforms,
    px: u32,
    py: u32,
) -> Guide {
    let mut ray = centre_ray(u, px, py);
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
        let mut n = shading.shading_normal;
        if n.dot(wo) < 0.0 {
            n = -n;
        }
        if first.is_none() {
            let front = wo.dot(surface.geometric_normal) > 0.0;
            let emits = shading.emission != Vec3::ZERO && (front || shading.two_sided_emission);
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
        None => (Vec3::ZERO, 0.0, Vec3::ONE, NO_INSTANCE, false, false),
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
                .map(|x| guide_pixel(scene, &tracer, u, x, y))
                .collect()
        })
        .collect();
    for (i, (n, z, a, id, e, spec)) in rows.into_iter().flatten().enumerate() {
        guides.specular[i] = spec;
        guides.normal[i] = n;
        guides.depth[i] = z;
        guides.albedo[i] = a;
        guides.instance[i] = id;
        guides.emissive[i] = e;
    }
    guides
}
