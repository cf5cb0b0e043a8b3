//! One run of `bench picture`: Reflect's real frame loop, headless, at one configuration (size,
//! denoiser), exactly as the game runs it apart from the tracer's size being fixed: the game's
//! rules, fixed steps, commits, the render thread's converging and temporal accumulation, and
//! with the denoiser its per-pixel reprojection. Every frame's displayed film is captured (the
//! film the window would tonemap and upscale: the denoised one when the denoiser is on); the
//! [`ReferencingTracer`] renders references of the frames asked for on the side.
//!
//! The player is driven by a chamber's committed replay, or stands at the chamber file's own
//! camera, still or turning at a constant mouse rate. Frames are a fixed 1/30 s (the game's
//! 30 fps target, two fixed steps each), so every run of the same drive reaches the same game
//! state at the same frame whatever the render costs.
//!
//! Owns: [`play`]. Main thread (the engine's render thread renders). Must not: change the game.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::{Arc, Mutex};

use anyhow::Context;
use candela::app::{Engine, Game, StepInput};
use candela::assets::Level;
use candela::render::{RenderConfig, RenderError, Rendered};
use glam::Vec3;
use indicatif::ProgressBar;
use reflect::game::ReflectGame;
use reflect::replays::open_replay;
use reflect::world::ReflectWorld;

use super::machine::median;
use super::picture_tracer::{References, ReferencingTracer};

/// Seconds of game time per frame: the game's 30 fps target.
pub const FRAME_SECONDS: f64 = 1.0 / 30.0;

/// A configuration of the renderer: the displayed size (fixed: no workload scaling), the
/// denoiser and temporal upscaling; one sample per pixel per frame and the engine's converging
/// policy, as the game.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// The displayed film's size (the traced size without upscaling).
    pub width: u32,
    pub height: u32,
    pub denoise: bool,
    /// Temporal upscaling factor (`RenderConfig::temporal_upscale`; 1: none): the tracer
    /// traces `width / upscale × height / upscale`.
    pub upscale: u32,
    /// One pixel in this many traces indirect light (`RenderConfig::indirect_every`; 1: all).
    pub indirect_every: u32,
    /// Denoised: guides from the tracer's first hits, samples at the frame's jitter
    /// (`RenderConfig::first_hit_guides`), not a guide pass.
    pub first_hit_guides: bool,
}

impl Config {
    pub fn label(&self) -> String {
        let mut label = self.plain_label();
        if self.indirect_every > 1 {
            label += &format!(", indirect 1 in {}", self.indirect_every);
        }
        if self.first_hit_guides && self.denoise {
            label += ", first-hit guides";
        }
        label
    }

    fn plain_label(&self) -> String {
        let denoiser = if self.denoise { "on" } else { "off" };
        if self.upscale > 1 {
            format!(
                "{}×{} traced, TAAU ×{} to {}×{}, denoiser {denoiser}",
                self.width / self.upscale,
                self.height / self.upscale,
                self.upscale,
                self.width,
                self.height,
            )
        } else {
            format!("{}×{}, denoiser {denoiser}", self.width, self.height)
        }
    }
}

/// How the player is driven.
#[derive(Clone, Copy, Debug)]
pub enum Drive<'a> {
    /// A committed replay of one chamber.
    Replay(&'a Path),
    /// At the chamber file's camera, nothing pressed.
    Still,
    /// At the chamber file's camera, the mouse moving right by this many counts per frame.
    Turn(f32),
}

/// What a run kept.
pub struct Played {
    /// The displayed film of the frames asked for (commit frame number → linear radiance).
    pub displayed: BTreeMap<u64, Vec<Vec3>>,
    /// Median milliseconds a frame spent tracing and denoising (guides included), over the
    /// frames that rendered no reference.
    pub frame_ms: f64,
    /// Frames run.
    pub frames: u64,
}

/// The length of chamber `replay`'s recording in frames of [`FRAME_SECONDS`].
pub fn replay_frames(world: &ReflectWorld, replay: &Path) -> anyhow::Result<u64> {
    let (replay, _) = open_replay(world, replay)?;
    Ok((replay.steps() as f64 / 60.0 / FRAME_SECONDS) as u64)
}

/// Runs chamber `chamber` for at most `frames` frames at `config`, keeping the displayed film
/// of the frames in `keep`; `refs` says which frames want a reference (rendered on the render
/// thread, reused when `refs` already holds one of the same view).
#[allow(clippy::too_many_arguments)] // one run's whole description
pub fn play(
    world: &ReflectWorld,
    chamber: usize,
    drive: Drive<'_>,
    config: Config,
    frames: u64,
    keep: &BTreeSet<u64>,
    refs: Arc<Mutex<References>>,
    progress: ProgressBar,
) -> anyhow::Result<Played> {
    let mut replay = None;
    let mut game = match drive {
        Drive::Replay(path) => {
            let (r, start) = open_replay(world, path)?;
            anyhow::ensure!(
                start == chamber,
                "{}: not chamber {chamber}",
                path.display()
            );
            replay = Some(r);
            ReflectGame::new(world.clone(), start)
        }
        Drive::Still | Drive::Turn(_) => {
            let camera = Level::read(&world.files[chamber + 1])?.camera;
            let mut game = ReflectGame::new(world.clone(), chamber);
            game.start_at_view(&candela::extract::RenderCamera::from_desc(&camera));
            game
        }
    };
    let render = RenderConfig {
        denoise: config.denoise,
        temporal_upscale: (config.upscale > 1).then_some(config.upscale),
        indirect_every: (config.indirect_every > 1).then_some(config.indirect_every),
        first_hit_guides: config.first_hit_guides,
        atrous_kernel: *super::picture::ATROUS_KERNEL
            .get()
            .unwrap_or(&Default::default()),
        ..RenderConfig::cpu(config.width, config.height)
    };
    let wanted = refs.lock().expect("references lock").wanted.clone();
    let open = ReferencingTracer::open(refs, progress);
    let mut engine = Engine::with_tracer(render, game.inner().environment(), open)?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    if let Some(replay) = replay {
        engine.set_step_input(StepInput::Replay(replay));
    }
    let mut played = Played {
        displayed: BTreeMap::new(),
        frame_ms: f64::NAN,
        frames: 0,
    };
    let mut times = Vec::new();
    let mut collect =
        |results: Vec<Result<Rendered, RenderError>>, played: &mut Played| -> anyhow::Result<()> {
            for r in results {
                let r = r?;
                if let Some(film) = r.film
                    && keep.contains(&r.frame)
                {
                    played.displayed.insert(r.frame, film.mean);
                }
                if !wanted.contains(&r.frame) {
                    times.push((r.render_seconds + r.denoise_seconds) * 1e3);
                }
            }
            Ok(())
        };
    for _ in 0..frames {
        if let Drive::Turn(counts) = drive {
            engine.input_mut().mouse_motion(counts, 0.0);
        }
        engine.capture_next();
        engine.frame(FRAME_SECONDS, &mut game)?;
        played.frames += 1;
        collect(engine.rendered(), &mut played)?;
        if matches!(drive, Drive::Replay(_)) && engine.replay_finished() {
            break;
        }
    }
    collect(engine.shutdown(), &mut played).context("the last frames")?;
    played.frame_ms = median(&times);
    Ok(played)
}
