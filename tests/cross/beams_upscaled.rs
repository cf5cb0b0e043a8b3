//! A laser beam under temporal upscaling (TAAU ×2, `engine/src/render/denoise/upscale.rs`) is
//! drawn as wide and as bright as at the displayed size.
//!
//! TAAU traces half the displayed size each way, every sample of a frame at one sub-pixel
//! offset (`render::jitter`), and each sample lands in the displayed pixel its offset falls in.
//! The beam's prefilter (`render/cpu/lines.rs`, twin `shaders/shared/lines.wgsl`) was two
//! *traced* pixels wide there, i.e. four displayed pixels at half the brightness: in Reflect's
//! chambers (`bench picture --quick`) pixels two displayed pixels off a beam showed 6–7 where
//! the displayed-size reference has 0–0.1, most of the frame's relative MSE. With one offset
//! per frame a strip one traced pixel wide still holds a sample in every column, so the
//! footprint is one traced pixel there: the displayed size's two.
//!
//! Checked on the beam scene of `beams.rs` at 64×36 (traced 32×18): the beam accumulated over
//! the jitter's 16 frames, as the upscaler's splat accumulates a still view, against a
//! 64-spp render at 64×36: the same energy across the beam (within 10 %) and the same spread
//! (RMS width within 0.25 displayed pixels: 0.59 against 0.63; 1.21 with the old footprint).
//! And the GPU tracer draws the jittered frame as the CPU tracer does.

use candela::render::jitter::{JITTER_FRAMES, frame_jitter, pack};
use candela::render::{FrameSettings, frame_uniforms};
use candela::scene::RenderScene;
use candela_tests::{Which, open, render_batches};
use glam::Vec3;

use super::beams::beam_scene;

/// The displayed size and the upscaling factor.
const W: u32 = 64;
const H: u32 = 36;
const FACTOR: u32 = 2;

/// Frame `frame` of the beam scene traced at `W / FACTOR × H / FACTOR`, one sample per pixel
/// at that frame's offset: (the film, the offset).
fn jittered_frames(which: Which, frames: u64) -> Vec<(Vec<Vec3>, (f32, f32))> {
    let desc = beam_scene();
    let scene = RenderScene::build(&desc);
    let mut tracer = open(which, &scene).expect("a tracer");
    (0..frames)
        .map(|frame| {
            let mut settings = FrameSettings::new(W / FACTOR, H / FACTOR, 1, 7, &desc.render);
            settings.sample_base = frame as u32;
            let mut uniforms = frame_uniforms(
                &desc.camera,
                desc.sun.as_ref(),
                &desc.sky,
                &settings,
                &scene.header(),
            );
            let jitter = frame_jitter(frame);
            uniforms.pixel_jitter = pack(jitter);
            tracer.render(&scene, &uniforms).expect("render");
            (tracer.film().expect("film").mean, jitter)
        })
        .collect()
}

/// The displayed picture of a still view after the jitter's frames: each traced sample
/// averaged into the displayed pixel its offset falls in (the upscaler's splat, still camera).
fn upscaled() -> Vec<Vec3> {
    let (tw, th) = (W / FACTOR, H / FACTOR);
    let mut sum = vec![Vec3::ZERO; (W * H) as usize];
    let mut count = vec![0u32; (W * H) as usize];
    for (film, (jx, jy)) in jittered_frames(Which::Cpu, JITTER_FRAMES) {
        let (dx, dy) = (
            (jx * FACTOR as f32) as u32 % FACTOR,
            (jy * FACTOR as f32) as u32 % FACTOR,
        );
        for y in 0..th {
            for x in 0..tw {
                let i = ((y * FACTOR + dy) * W + x * FACTOR + dx) as usize;
                sum[i] += film[(y * tw + x) as usize];
                count[i] += 1;
            }
        }
    }
    assert!(
        count.iter().all(|&n| n > 0),
        "every displayed pixel got a sample"
    );
    sum.iter()
        .zip(&count)
        .map(|(s, &n)| *s / n as f32)
        .collect()
}

/// The red channel's mean per row over the columns well inside the beam's span.
fn row_profile(image: &[Vec3]) -> Vec<f32> {
    let span = (0.18 * W as f32) as u32;
    let columns = W / 2 - span..W / 2 + span;
    (0..H)
        .map(|y| {
            let sum: f32 = columns.clone().map(|x| image[(y * W + x) as usize].x).sum();
            sum / columns.len() as f32
        })
        .collect()
}

/// (energy, centroid row, RMS width in rows) of `profile` over rows `peak ± 4`, the
/// background (the window's dimmest row) taken off.
fn spread(profile: &[f32], peak: usize) -> (f32, f32, f32) {
    let rows = peak.saturating_sub(4)..(peak + 5).min(profile.len());
    let background = rows
        .clone()
        .map(|y| profile[y])
        .fold(f32::INFINITY, f32::min);
    let weight = |y: usize| profile[y] - background;
    let energy: f32 = rows.clone().map(weight).sum();
    let centre = rows.clone().map(|y| y as f32 * weight(y)).sum::<f32>() / energy;
    let variance = rows
        .map(|y| (y as f32 - centre).powi(2) * weight(y))
        .sum::<f32>()
        / energy;
    (energy, centre, variance.sqrt())
}

#[test]
fn an_upscaled_beam_is_as_wide_as_at_the_displayed_size() {
    let reference = render_batches(Which::Cpu, &beam_scene(), W, H, 16, 4, 11)
        .expect("cpu render")
        .mean();
    let reference = row_profile(&reference);
    let shown = row_profile(&upscaled());
    // The direct beam: the brightest row (its mirror image is farther, so dimmer).
    let peak = (0..H as usize)
        .max_by(|&a, &b| reference[a].total_cmp(&reference[b]))
        .expect("rows");
    let (e_ref, c_ref, w_ref) = spread(&reference, peak);
    let (e, c, w) = spread(&shown, peak);
    eprintln!(
        "displayed size: energy {e_ref:.3}, centre {c_ref:.2}, width {w_ref:.2}; \
         TAAU ×2: energy {e:.3}, centre {c:.2}, width {w:.2}"
    );
    eprintln!("rows {reference:.3?}\nTAAU {shown:.3?}");
    assert!(
        (e - e_ref).abs() < 0.1 * e_ref,
        "beam energy {e} against {e_ref}"
    );
    assert!((c - c_ref).abs() < 0.5, "beam centre {c} against {c_ref}");
    assert!(
        w < w_ref + 0.25,
        "the upscaled beam is {w:.2} rows wide (RMS) against {w_ref:.2} at the displayed size"
    );
}

/// The GPU tracer's twin (`line_pixel_angle` in `lines.wgsl`) draws a jittered frame's beam
/// as the CPU tracer does: the beam part is deterministic, so agreement to rounding there.
#[test]
fn both_tracers_draw_a_jittered_beam_alike() {
    let cpu = jittered_frames(Which::Cpu, 3);
    let gpu = jittered_frames(Which::Gpu, 3);
    for ((c, _), (g, _)) in cpu.iter().zip(&gpu) {
        let beam: Vec<(f32, f32)> = c
            .iter()
            .zip(g)
            .filter(|(c, _)| c.x > 1.0)
            .map(|(c, g)| (c.x, g.x))
            .collect();
        // About 14 columns of the direct beam and as many of its mirror image.
        assert!(beam.len() >= 10, "the beam shows ({} pixels)", beam.len());
        let worst = beam
            .iter()
            .map(|(c, g)| (c - g).abs() / c)
            .fold(0.0f32, f32::max);
        assert!(worst < 1e-3, "the beam differs by {worst}");
    }
}
