//! One commit on the render thread: apply it to the render side's scene, update the tracer,
//! trace (and denoise) the frame, and say what happened ([`Rendered`]). When the tracer's GPU
//! device is lost on the way, the CPU tracer takes over and renders the frame again
//! (`device_loss`).
//!
//! Owns: [`render_one`]. Render thread only. Must not: present (the thread's loop does) or
//! touch the ECS.

use std::time::Instant;

use super::denoise_stage::DenoiseStage;
use super::film::{Converge, Film};
use super::jitter;
use super::scaling::Scaling;
use super::thread::{RenderConfig, Rendered};
use super::tracer::{RenderError, RenderStats, Tracer};
use super::{FrameSettings, frame_uniforms};
use crate::commit::Commit;
use crate::scene::RenderScene;

/// One frame's tracing: what [`trace`] measured and made.
struct Traced {
    stats: RenderStats,
    render_seconds: f64,
    denoise_seconds: f64,
    blend: f32,
    film: Option<Film>,
}

/// Traces (and denoises) `commit`'s frame at `size` with the workload `work` over `scene`,
/// already brought up to date; with the denoiser on and `upscale` > 1, the samples are
/// jittered by the frame's offset and the denoiser upscales (`denoise::upscale`).
#[allow(clippy::too_many_arguments)] // the render thread's state, one borrow each
fn trace(
    commit: &Commit,
    config: &RenderConfig,
    work: super::scaling::Workload,
    size: (u32, u32),
    scene: &RenderScene,
    tracer: &mut dyn Tracer,
    converge: &mut Converge,
    denoiser: Option<&mut DenoiseStage>,
    upscale: u32,
) -> Result<Traced, RenderError> {
    // The denoiser reprojects its history per pixel: camera motion need not restart it.
    let blend = if denoiser.is_some() {
        converge.blend_reprojected(&commit.motion)
    } else {
        converge.blend(&commit.motion)
    };
    let mut render = commit.render;
    if let Some(sampling) = config.light_sampling {
        render.light_sampling = sampling;
    }
    if let Some(every) = config.indirect_every {
        render.indirect_every = Some(every);
    }
    let mut settings = FrameSettings::new(size.0, size.1, work.spp, config.seed, &render);
    settings.sample_base = (commit.frame as u32).wrapping_mul(work.spp);
    // With the denoiser on, the tracer's film holds this frame alone; the denoiser blends.
    settings.film_blend = if denoiser.is_some() { 1.0 } else { blend };
    settings.roulette_scale = work.roulette_scale;
    let mut uniforms = frame_uniforms(
        &commit.camera,
        commit.sun.as_ref(),
        &commit.sky,
        &settings,
        &scene.header(),
    );
    let upscale = if denoiser.is_some() { upscale } else { 1 };
    if upscale > 1 {
        uniforms.pixel_jitter = jitter::pack(jitter::frame_jitter(commit.frame));
    }
    // The CPU tracer hands the denoiser the guides of its own first hits (not when upscaling:
    // those guides are at the upscaled size), every sample of the frame at one offset in its
    // pixel (the frame's jitter, which the reprojection knows): each sample is then
    // demodulated by the albedo of the very surface it saw, and over the jitter's frames a
    // pixel's history still covers its whole area (`docs/ACCURACY.md`, "Guides from the first
    // hits"). A tracer that cannot record them gets a guide pass (`denoise_stage`).
    let record = denoiser.is_some() && upscale <= 1 && config.first_hit_guides;
    tracer.record_guides(record);
    if record {
        uniforms.pixel_jitter = jitter::pack(jitter::frame_jitter(commit.frame));
    }
    let started = Instant::now();
    let stats = {
        puffin::profile_scope!("trace");
        tracer.render(scene, &uniforms)?
    };
    let render_seconds = started.elapsed().as_secs_f64();
    let (denoise_seconds, film) = match denoiser {
        Some(d) => {
            puffin::profile_scope!("denoise");
            let seconds = d.run(scene, &uniforms, tracer, blend, upscale)?;
            let film = match commit.capture {
                true => Some(d.capture()?),
                false => None,
            };
            (seconds, film)
        }
        None => (
            0.0,
            if commit.capture {
                Some(tracer.film()?)
            } else {
                None
            },
        ),
    };
    Ok(Traced {
        stats,
        render_seconds,
        denoise_seconds,
        blend,
        film,
    })
}

#[allow(clippy::too_many_arguments)] // the render thread's state, one borrow each
pub(super) fn render_one(
    commit: Commit,
    output: (u32, u32),
    config: &RenderConfig,
    scene: &mut RenderScene,
    tracer: &mut Box<dyn Tracer>,
    converge: &mut Converge,
    scaling: &mut Scaling,
    mut denoiser: Option<&mut DenoiseStage>,
) -> Result<Rendered, RenderError> {
    let started = Instant::now();
    let apply_scope = puffin::profile_scope_custom!("apply commit");
    scene.apply(&commit.writes, &commit.header);
    // A table rebuilt in the background lands frames after the sky changed: the film restarts
    // then (the commit's sky change already restarted it when the change came).
    if scene.sky.update_with(&commit.sky, config.sky_rebuild)
        && config.sky_rebuild == crate::scene::SkyRebuild::Background
    {
        converge.reset();
    }
    let mut notice = None;
    if let Err(e) = tracer.update(scene, &commit.writes) {
        // A lost device: the CPU tracer reads `scene` itself and needs no update.
        notice = Some(super::device_loss::fall_back(tracer, e)?);
        converge.reset();
    }
    let apply_seconds = started.elapsed().as_secs_f64();
    drop(apply_scope);
    let work = scaling.current();
    let shown = work.film_size(output.0, output.1);
    if scaling.resized() {
        converge.reset();
    }
    // Temporal upscaling: the denoiser's film is the size scaling chose, the tracer traces a
    // `upscale`-th of it each way.
    let upscale = match denoiser {
        Some(_) => config
            .temporal_upscale
            .unwrap_or(1)
            .clamp(1, shown.0.min(shown.1).max(1)),
        None => 1,
    };
    let size = (shown.0 / upscale, shown.1 / upscale);
    let mut attempt = |tracer: &mut Box<dyn Tracer>, converge: &mut Converge| {
        let denoiser = denoiser.as_deref_mut();
        trace(
            &commit,
            config,
            work,
            size,
            scene,
            tracer.as_mut(),
            converge,
            denoiser,
            upscale,
        )
    };
    let traced = match attempt(tracer, converge) {
        Ok(traced) => traced,
        Err(e) => {
            notice = Some(super::device_loss::fall_back(tracer, e)?);
            converge.reset();
            attempt(tracer, converge)?
        }
    };
    let view_moving = commit.motion.cut || commit.motion.camera > converge.policy.camera_reset;
    scaling.observe(
        traced.render_seconds + apply_seconds + traced.denoise_seconds,
        view_moving,
    );
    Ok(Rendered {
        frame: commit.frame,
        tracer: tracer.name(),
        stats: traced.stats,
        apply_seconds,
        render_seconds: traced.render_seconds,
        denoise_seconds: traced.denoise_seconds,
        blend: traced.blend,
        spp: work.spp,
        roulette_scale: work.roulette_scale,
        film_size: size,
        commit_bytes: commit.bytes(),
        lights: scene.lights.count,
        film: traced.film,
        present_seconds: 0.0,
        present_skipped: None,
        screenshot: None,
        notice,
    })
}
