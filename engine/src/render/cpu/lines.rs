//! Thin line emitters (laser beams) as the camera sees them (twin: `shaders/shared/lines.wgsl`).
//!
//! A beam a few millimetres wide covers a fraction of a pixel at game resolutions, so at one
//! sample per pixel its prism is hit by some camera rays and missed by their neighbours: a
//! dotted line. Camera rays (and their perfect mirror and glass continuations) therefore pass
//! through line prisms ([`past_lines`]) and add each line prefiltered over the pixel's
//! footprint ([`seen_lines`]): the radiance times the share of a strip
//! [`LINE_FOOTPRINT_PIXELS`] pixels wide, centred on the ray, that the line's width covers.
//! Where the line is wider than that this is the line itself; where it is thinner, a line two
//! pixels wide of the same total brightness (radiance × width is kept). Every column the line
//! crosses has a sample that sees it, so it is continuous at any resolution and nearly
//! noise-free. Occlusion: only the part of the ray before its hit counts.
//! Bias: the line is widened to two pixels where it is thinner, and box-filtered again by the
//! pixel jitter; its light on other surfaces still comes from the prism (next-event estimation
//! and rough bounces), unchanged.
//! Owns: those two functions and the footprint's width ([`pixel_angle`]: two traced pixels, one
//! when temporal upscaling fixes the frame's sub-pixel offset). Render thread, inside the
//! integrator.
//! Must not: gather the lines (`scene::RenderScene::lines`) or shade surfaces.
//! Units: metres in render space; radiance linear RGB; angles radians.

use glam::Vec3;

use crate::layout::{GpuFrameUniforms, GpuLine, INVALID, MATERIAL_FLAG_LINE};
use crate::scene::RenderScene;
use crate::trace::{Hit, Ray, TraceScene};

/// Width of the prefilter's footprint, in pixels. One sample per pixel is jittered inside its
/// pixel, so a strip one pixel wide misses both rows it straddles in some columns; a strip two
/// pixels wide always holds one whole pixel, whose sample then sees the line: every column
/// (or row) the line crosses shows it. Twin: `LINE_FOOTPRINT_PIXELS` in `lines.wgsl`.
pub const LINE_FOOTPRINT_PIXELS: f32 = 2.0;

/// Width of the prefilter's footprint, in traced pixels, when every sample of the frame sits at
/// one fixed offset in its pixel (temporal upscaling, `render::jitter`): the samples of a
/// column are then exactly one pixel apart, so a strip one pixel wide always holds one of them
/// (the line is still continuous in every frame), and one traced pixel is the two displayed
/// pixels of [`LINE_FOOTPRINT_PIXELS`] at the ×2 upscale's displayed size. With the two-pixel
/// footprint there, the line was drawn four displayed pixels wide at half its brightness,
/// pixels up to two displayed pixels off it lit where a displayed-size picture shows none.
/// Twin: `LINE_FOOTPRINT_FIXED_OFFSET` in `lines.wgsl`.
pub const LINE_FOOTPRINT_FIXED_OFFSET: f32 = 1.0;

/// The prefilter's footprint angle of frame `u` (radians across the footprint at the image's
/// centre): [`LINE_FOOTPRINT_PIXELS`] pixels, or [`LINE_FOOTPRINT_FIXED_OFFSET`] when its
/// samples share one offset (`pixel_jitter` set). Twin: `line_pixel_angle` in `lines.wgsl`.
pub fn pixel_angle(u: &GpuFrameUniforms) -> f32 {
    let pixels = match crate::render::jitter::unpack(u.pixel_jitter) {
        Some(_) => LINE_FOOTPRINT_FIXED_OFFSET,
        None => LINE_FOOTPRINT_PIXELS,
    };
    pixels * 2.0 * Vec3::from(u.camera_up).length() / u.height.max(1) as f32
}

/// Line prisms a camera ray passes through before giving up (and shading what it hit).
pub const MAX_LINE_CROSSINGS: u32 = 8;

/// Rays beyond this distance (metres) are cut there when measuring their distance to a line.
const FAR: f32 = 1.0e4;

/// Whether `hit` is on a line emitter's triangle.
pub fn is_line(scene: &RenderScene, hit: &Hit) -> bool {
    let inst = &scene.instances[hit.instance as usize];
    let material = if inst.material_override != INVALID {
        inst.material_override
    } else {
        scene.triangles[(inst.triangle_base + hit.triangle) as usize].material
    };
    scene.materials[material as usize].flags & MATERIAL_FLAG_LINE != 0
}

/// The first hit of `ray` that is not on a line prism, moving `ray.t_min` past the prisms it
/// crosses (at most [`MAX_LINE_CROSSINGS`]; after that the prism is shaded as it is).
pub fn past_lines(
    scene: &RenderScene,
    tracer: &TraceScene,
    ray: &mut Ray,
    mut hit: Option<Hit>,
) -> Option<Hit> {
    for _ in 0..MAX_LINE_CROSSINGS {
        match hit {
            Some(h) if is_line(scene, &h) => {
                ray.t_min = h.t;
                hit = tracer.closest(ray);
            }
            _ => break,
        }
    }
    hit
}

/// What the camera sees of `lines` along `ray` (unit direction) before `t_end`, prefiltered over
/// a footprint: (radiance, coverage). The coverage in [0, 1] is the share of the footprint the
/// line hides: the caller weights what lies behind by `1 − coverage`, as an opaque prism covering
/// that share of the pixel would. Where lines overlap (a beam's pieces meet at each turn) the
/// most covering one shows, as the front prism would. `travelled` is the distance the camera
/// path covered before this ray (metres, through mirrors) and `pixel_angle` the footprint's
/// angular size (radians: one pixel's times [`LINE_FOOTPRINT_PIXELS`]), so the footprint at
/// distance `t` along the ray is `(travelled + t) · pixel_angle` metres wide.
pub fn seen_lines(
    lines: &[GpuLine],
    ray: &Ray,
    t_end: f32,
    travelled: f32,
    pixel_angle: f32,
) -> (Vec3, f32) {
    let t_end = t_end.min(FAR);
    let (mut radiance, mut coverage) = (Vec3::ZERO, 0.0f32);
    for line in lines {
        let (a, b) = (Vec3::from(line.start), Vec3::from(line.end));
        let (t, distance) = closest_approach(ray.origin, ray.direction, t_end, a, b - a);
        let footprint = ((travelled + t) * pixel_angle).max(1e-6);
        let covered = (distance + 0.5 * footprint).min(line.radius)
            - (distance - 0.5 * footprint).max(-line.radius);
        let share = (covered / footprint).clamp(0.0, 1.0);
        if share > coverage {
            coverage = share;
            radiance = Vec3::from_slice(&line.radiance[..3]) * share;
        }
    }
    (radiance, coverage)
}

/// The closest approach of the ray piece `o + t·d`, `t` in [0, `t_end`] (`d` unit), to the
/// segment `a + s·e`, `s` in [0, 1]: (`t` there, the distance). After Ericson, "Real-Time
/// Collision Detection" §5.1.9.
pub fn closest_approach(o: Vec3, d: Vec3, t_end: f32, a: Vec3, e: Vec3) -> (f32, f32) {
    let r = o - a;
    let ee = e.dot(e);
    let f = e.dot(r);
    let c = d.dot(r);
    let (t, s) = if ee <= 1e-12 {
        ((-c).clamp(0.0, t_end), 0.0)
    } else {
        let b = d.dot(e);
        let denom = ee - b * b;
        let mut t = if denom > 1e-12 {
            ((b * f - c * ee) / denom).clamp(0.0, t_end)
        } else {
            0.0
        };
        let mut s = (b * t + f) / ee;
        if s < 0.0 {
            s = 0.0;
            t = (-c).clamp(0.0, t_end);
        } else if s > 1.0 {
            s = 1.0;
            t = (b - c).clamp(0.0, t_end);
        }
        (t, s)
    };
    (t, (o + d * t - (a + e * s)).length())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: Vec3, d: Vec3) -> Ray {
        Ray {
            origin: o,
            t_min: 0.0,
            direction: d.normalize(),
            t_max: f32::INFINITY,
        }
    }

    fn line(a: Vec3, b: Vec3, radius: f32) -> GpuLine {
        GpuLine {
            start: a.to_array(),
            radius,
            end: b.to_array(),
            _padding: 0,
            radiance: [10.0, 1.0, 0.5, 0.0],
        }
    }

    #[test]
    fn closest_approach_of_crossing_and_parallel_pieces() {
        // The ray along −z from (0, 0, 5) passes 0.2 m from a beam along x at y = 0.2, z = 0.
        let (t, d) = closest_approach(
            Vec3::new(0.0, 0.0, 5.0),
            Vec3::NEG_Z,
            100.0,
            Vec3::new(-1.0, 0.2, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        );
        assert!((t - 5.0).abs() < 1e-5 && (d - 0.2).abs() < 1e-5, "{t} {d}");
        // Cut at t_end = 3: the nearest point of the piece is its end, 2 m from the beam.
        let (t, d) = closest_approach(
            Vec3::new(0.0, 0.0, 5.0),
            Vec3::NEG_Z,
            3.0,
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        );
        assert!((t - 3.0).abs() < 1e-5 && (d - 2.0).abs() < 1e-5, "{t} {d}");
        // Past the segment's end: the distance to its end point.
        let (_, d) = closest_approach(
            Vec3::new(3.0, 0.0, 5.0),
            Vec3::NEG_Z,
            100.0,
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        );
        assert!((d - 2.0).abs() < 1e-5, "{d}");
        // Parallel: any point works, the distance is the gap.
        let (_, d) = closest_approach(
            Vec3::new(0.0, 0.3, 0.0),
            Vec3::X,
            100.0,
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        );
        assert!((d - 0.3).abs() < 1e-5, "{d}");
    }

    /// Across a line thinner than a pixel, the seen radiance integrated over the image plane
    /// equals the line's (radiance × width): brightness is kept, spread over a pixel-wide strip.
    #[test]
    fn a_thin_line_keeps_its_brightness_spread_over_a_pixel() {
        let l = [line(
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            0.002,
        )];
        let pixel_angle = 0.01; // 2 cm at 2 m: ten times the line's 4 mm.
        let n = 2000;
        let mut integral = 0.0;
        let mut lit = 0;
        for k in 0..n {
            let y = -0.05 + 0.1 * (k as f32 + 0.5) / n as f32;
            let r = ray(Vec3::new(0.0, y, 2.0), Vec3::NEG_Z);
            let (seen, coverage) = seen_lines(&l, &r, f32::INFINITY, 0.0, pixel_angle);
            assert!((seen.x - 10.0 * coverage).abs() < 1e-4);
            integral += seen.x * 0.1 / n as f32;
            lit += usize::from(seen.x > 0.0);
        }
        assert!((integral - 10.0 * 0.004).abs() < 1e-4, "{integral}");
        // Lit over a pixel-wide strip (plus the line's width): 2.4 cm of the 10 cm swept.
        let strip = lit as f32 / n as f32 * 0.1;
        assert!((strip - 0.024).abs() < 1e-3, "{strip}");
        // Behind the hit: nothing.
        let r = ray(Vec3::new(0.0, 0.0, 2.0), Vec3::NEG_Z);
        assert_eq!(seen_lines(&l, &r, 1.0, 0.0, pixel_angle), (Vec3::ZERO, 0.0));
    }

    /// A line wider than the footprint is seen at its full radiance inside and not outside.
    #[test]
    fn a_wide_line_is_itself() {
        let l = [line(
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            0.05,
        )];
        let at = |y: f32| {
            let r = ray(Vec3::new(0.0, y, 1.0), Vec3::NEG_Z);
            seen_lines(&l, &r, f32::INFINITY, 0.0, 0.001).0.x
        };
        assert!((at(0.0) - 10.0).abs() < 1e-4);
        assert!((at(0.04) - 10.0).abs() < 1e-4);
        assert_eq!(at(0.06), 0.0);
    }
}
