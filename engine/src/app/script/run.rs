//! Running a capture script on the [`Engine`]: spawn the level, then for every frame set the
//! camera, move the scripted instances, switch light groups, run the built-in waves, ask for
//! screenshots, and run the engine's frame; write each screenshot when the render thread sends
//! its film back; report the time per frame split into update, upkeep and render, and the commit
//! bytes.
//!
//! Owns: [`run_script`], [`RunOptions`], [`ScriptReport`]. Main thread (the render thread is the
//! engine's). Must not: render or touch BVH data itself (the engine's frame does).
//!
//! # Why the CPU tracer gives the same images bit for bit
//!
//! Every input of every frame is a pure function of the script and the level:
//! * **Fixed steps.** Frame `n` is evaluated at `n × seconds_per_frame` seconds, never from a
//!   clock; motions, camera and waves are `f32`/`f64` arithmetic on those numbers, so they give the
//!   same bits each run. The render workload is fixed (no scaling by measured frame time).
//! * **Commits.** The engine turns the world into the same writes in the same order (extraction
//!   walks the ECS in its storage order; the upkeep's refits, rebuilds, TLAS and light table are
//!   deterministic builds of the same data; where it walks a hash map it writes disjoint rows, so
//!   the order does not change the result). Every commit is rendered, in order, whatever the
//!   threads' timing: the hand-off queue blocks rather than drops.
//! * **Converging factors.** The blend factor depends only on the commits' motion flags (cuts,
//!   camera motion, moved objects) and the count of frames since the last reset, never on time.
//!   Sample indices are `frame × spp + s` with the script's seed: the same random numbers.
//! * **Sums in sample order.** The CPU tracer gives each 16×16 tile to one rayon task and adds a
//!   pixel's samples in sample order inside that task; tiles are blended into the film in tile
//!   order afterwards. No floating-point sum depends on which thread ran what, or how many
//!   threads there are.
//!
//! The GPU tracer follows the same algorithm but its floating point is the driver's (fused
//! multiply-adds may differ between devices), so its images agree within noise, not in bits.

use std::path::PathBuf;
use std::time::Instant;

use glam::Vec3;

use super::desc::{Script, ScriptError, ScriptTracer};
use super::motion::{apply_motion, camera_at, camera_transform, cut_at};
use crate::accel::UpkeepStats;
use crate::app::runner::FrameReport;
use crate::app::runner::FrameWork;
use crate::app::runner::Step;
use crate::app::runner::TimeChange;
use crate::app::runner::{Engine, Environment};
use crate::assets::Needs;
use crate::ecs::{CameraRig, Transform};
use crate::level::PlayableLevel;
use crate::render::film::{ConvergePolicy, Film, TonemapSettings, write_exr, write_png};
use crate::render::{RenderConfig, RenderError, Rendered, TracerChoice};

/// What the caller changes about a script run.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// Folder for screenshots; `None` keeps them in memory only.
    pub out_dir: Option<PathBuf>,
    /// Replaces the script's tracer.
    pub tracer: Option<ScriptTracer>,
    /// Replaces the script's image size (pixels).
    pub size: Option<(u32, u32)>,
    /// Replaces the script's samples per pixel per frame.
    pub spp: Option<u32>,
    /// Replaces the level's light sampling.
    pub light_sampling: Option<crate::assets::LightSampling>,
}

/// Where one frame's time went (seconds) and what its commit carried.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameTiming {
    pub frame: u32,
    /// Main thread: the script's camera, motions, light switches and waves, plus the engine's
    /// fixed steps and transform propagation.
    pub update_seconds: f64,
    /// Main thread: extraction and BVH upkeep (refits, rebuilds, TLAS, light table).
    pub upkeep_seconds: f64,
    /// Main thread: waiting for the render thread to take the commit.
    pub handoff_seconds: f64,
    /// Render thread: applying the commit (scene copy and GPU upload).
    pub apply_seconds: f64,
    /// Render thread: tracing.
    pub render_seconds: f64,
    pub commit_bytes: usize,
    pub upkeep: UpkeepStats,
    /// What the engine computed this frame (instances, BVH work, lights, bounces).
    pub work: FrameWork,
}

/// A screenshot taken.
#[derive(Clone, Debug)]
pub struct ShotResult {
    pub frame: u32,
    pub stem: String,
    pub png: Option<PathBuf>,
    pub exr: Option<PathBuf>,
    /// The converged film (linear radiance).
    pub film: Film,
}

/// What a script run did.
#[derive(Clone, Debug, Default)]
pub struct ScriptReport {
    pub frames: Vec<FrameTiming>,
    pub screenshots: Vec<ShotResult>,
    /// Wall time from the first frame to the last render, seconds.
    pub wall_seconds: f64,
    /// The tracer that rendered.
    pub tracer: ScriptTracer,
    /// Renderer features the level's content uses.
    pub needs: Needs,
}

/// Collects the render thread's results into the report, writing screenshots as films arrive.
struct Collector<'a> {
    script: &'a Script,
    options: &'a RunOptions,
    exposure_ev: f32,
    /// With `render.auto_exposure`: the sky's exposure at each screenshot's frame.
    shot_exposure: std::collections::HashMap<u32, f32>,
    report: ScriptReport,
}

impl Collector<'_> {
    fn take(&mut self, result: Result<Rendered, RenderError>) -> Result<(), ScriptError> {
        let rendered = result.map_err(|source| ScriptError::Render {
            path: self.script.source.clone(),
            source,
        })?;
        if let Some(t) = self.report.frames.get_mut(rendered.frame as usize) {
            t.apply_seconds = rendered.apply_seconds;
            t.render_seconds = rendered.render_seconds;
        }
        let Some(film) = rendered.film else {
            return Ok(());
        };
        for shot in self
            .script
            .screenshots
            .iter()
            .filter(|s| s.frame as u64 == rendered.frame)
        {
            let stem = shot.stem();
            let (mut png, mut exr) = (None, None);
            if let Some(dir) = &self.options.out_dir {
                let image_error = |file: &PathBuf, source| ScriptError::Image {
                    path: self.script.source.clone(),
                    file: file.clone(),
                    source,
                };
                let file = dir.join(format!("{stem}.png"));
                let tonemap = TonemapSettings {
                    exposure_ev: self
                        .shot_exposure
                        .get(&shot.frame)
                        .copied()
                        .unwrap_or(self.exposure_ev)
                        + shot.exposure_compensation_ev,
                    ..Default::default()
                };
                write_png(&file, film.width, film.height, &film.mean, &tonemap)
                    .map_err(|e| image_error(&file, e))?;
                png = Some(file);
                if shot.exr {
                    let file = dir.join(format!("{stem}.exr"));
                    write_exr(&file, film.width, film.height, &film.mean)
                        .map_err(|e| image_error(&file, e))?;
                    exr = Some(file);
                }
            }
            self.report.screenshots.push(ShotResult {
                frame: shot.frame,
                stem,
                png,
                exr,
                film: film.clone(),
            });
        }
        Ok(())
    }
}

/// Runs `script` on `level` (checked and bound first). `on_frame(n)` is called after
/// frame `n` was handed to the render thread (for progress bars).
pub fn run_script(
    script: &Script,
    level: &PlayableLevel,
    options: &RunOptions,
    on_frame: &mut dyn FnMut(u32),
) -> Result<ScriptReport, ScriptError> {
    script.validate()?;
    let desc = &level.scene;
    let bound = script.bind(desc)?;
    let tracer = options.tracer.unwrap_or(script.render.tracer);
    let (width, height) = options
        .size
        .unwrap_or((script.render.width, script.render.height));
    let config = RenderConfig {
        tracer: match tracer {
            ScriptTracer::Cpu => TracerChoice::Cpu,
            ScriptTracer::Gpu => TracerChoice::Gpu,
        },
        width,
        height,
        spp: options.spp.unwrap_or(script.render.spp).max(1),
        seed: script.render.seed,
        converge: ConvergePolicy::default(),
        scaling: None,
        denoise: false,
        light_sampling: options.light_sampling,
        indirect_every: None,
        first_hit_guides: false,
        atrous_kernel: Default::default(),
        sky_rebuild: crate::scene::SkyRebuild::Blocking,
        temporal_upscale: None,
    };
    let render_error = |source| ScriptError::Render {
        path: script.source.clone(),
        source,
    };
    let mut engine = Engine::new(config, Environment::of(desc))
        .map_err(|crate::app::runner::EngineError::Render(e)| render_error(e))?;
    let spawned = engine.spawn_level(level);
    let entity_of = |k: usize| {
        desc.instances[k]
            .name
            .as_ref()
            .and_then(|n| spawned.by_name.get(n).copied())
    };
    // Rest transforms, and for each motion entry its (entity, stagger index) targets.
    let rest: Vec<Transform> = desc
        .instances
        .iter()
        .map(|i| Transform::from_matrix(i.world_from_model))
        .collect();
    let mut moved: Vec<usize> = bound.motion_targets.iter().flatten().copied().collect();
    moved.sort_unstable();
    moved.dedup();
    let camera = (!script.camera.is_empty()).then(|| {
        let view = camera_at(&script.camera, 0, &desc.camera);
        engine.world_mut().spawn((
            camera_transform(&view),
            CameraRig {
                vertical_fov: view.vertical_fov_deg.to_radians(),
                ..Default::default()
            },
        ))
    });

    let mut collector = Collector {
        script,
        options,
        exposure_ev: script.render.exposure_ev,
        shot_exposure: Default::default(),
        report: ScriptReport {
            frames: Vec::with_capacity(script.frames as usize),
            tracer,
            needs: Needs::of_scene(desc),
            ..Default::default()
        },
    };
    let started = Instant::now();
    let spf = script.seconds_per_frame;
    for frame in 0..script.frames {
        let update_started = Instant::now();
        let seconds = frame as f64 * spf;
        if let Some(entity) = camera {
            let view = camera_at(&script.camera, frame, &desc.camera);
            if let Ok(mut rig) = engine.world_mut().get::<&mut CameraRig>(entity) {
                rig.vertical_fov = view.vertical_fov_deg.to_radians();
                rig.focus_distance =
                    (Vec3::from(view.look_at) - Vec3::from(view.position)).length();
            }
            if let Ok(mut t) = engine.world_mut().get::<&mut Transform>(entity) {
                *t = camera_transform(&view);
            }
        }
        if cut_at(&script.camera, frame) {
            engine.cut();
        }
        for &k in &moved {
            let mut t = rest[k];
            for (entry, targets) in script.motions.iter().zip(&bound.motion_targets) {
                let Some(order) = targets.iter().position(|&x| x == k) else {
                    continue;
                };
                let ahead = entry.stagger_seconds as f64 * order as f64;
                let frame_at = (frame as f64 + ahead / spf) as f32;
                t = apply_motion(
                    &entry.motion,
                    &rest[k],
                    t,
                    frame_at,
                    (seconds + ahead) as f32,
                );
            }
            if let Some(entity) = entity_of(k)
                && let Ok(mut current) = engine.world_mut().get::<&mut Transform>(entity)
            {
                *current = t;
            }
        }
        for switch in script.lights.iter().filter(|s| s.frame == frame) {
            engine.set_light_group(switch.group, switch.on);
        }
        for key in script.times.iter().filter(|k| k.frame == frame) {
            engine
                .change_time(TimeChange::Hours(key.utc_hours))
                .map_err(|e| ScriptError::Invalid {
                    path: script.source.clone(),
                    item: format!("times (frame {frame})"),
                    message: e.to_string(),
                })?;
        }
        if script.screenshots.iter().any(|s| s.frame == frame) {
            engine.capture_next();
        }
        if script.hold_from_frame == Some(frame) {
            engine.set_paused(true);
        }
        let script_seconds = update_started.elapsed().as_secs_f64();
        let report: FrameReport = match engine.frame(spf, &mut |_: &mut Step<'_>| {}) {
            Ok(r) => r,
            Err(crate::app::runner::EngineError::Render(e)) => {
                // The render thread's own error explains a failed hand-off better.
                for r in engine.shutdown() {
                    r.map_err(render_error)?;
                }
                return Err(render_error(e));
            }
        };
        // The exposure of the sky this frame's commit carried (a function of the time alone).
        if script.render.auto_exposure
            && script.screenshots.iter().any(|s| s.frame == frame)
            && let Some(ev) = engine.sky_exposure_ev()
        {
            let cap = script.render.max_exposure_ev.unwrap_or(f32::INFINITY);
            collector.shot_exposure.insert(frame, ev.min(cap));
        }
        collector.report.frames.push(FrameTiming {
            frame,
            update_seconds: script_seconds + report.update_seconds(),
            upkeep_seconds: report.upkeep_seconds(),
            handoff_seconds: report.handoff_seconds(),
            commit_bytes: report.commit_bytes,
            upkeep: report.upkeep,
            work: report.work,
            ..Default::default()
        });
        for r in engine.rendered() {
            collector.take(r)?;
        }
        on_frame(frame);
    }
    for r in engine.shutdown() {
        collector.take(r)?;
    }
    collector.report.wall_seconds = started.elapsed().as_secs_f64();
    Ok(collector.report)
}
