//! One run of `bench picture-ruins`: an It's About Time puzzle replay through the game's real
//! frame loop, headless — the game (`TimeGame`) on the engine as the harness starts it, the
//! level's render settings (bounces, roulette, render areas unless the world's are cleared), the
//! sky at the replay's time of day — at a fixed traced size (no workload scaling), in frames of
//! 1/30 s of game time (two fixed steps, as `bench picture`), so every run reaches the same game
//! state at the same frame (without a replay: the explorer standing at the spawn). Only the frames in `live` are traced (`picture_skip.rs`); a camera
//! cut starts each frame in `cuts`. The tracer inside is `picture_tracer::ReferencingTracer`,
//! which renders the references `refs` asks for.
//!
//! Owns: [`RuinsRun`], [`play_ruins`]. Main thread (the engine's render thread traces). Must
//! not: change the game or its level beyond what the caller hands in.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::{Arc, Mutex};

use anyhow::Context;
use candela::app::harness::HarnessGame;
use candela::app::{Engine, Game, StepInput};
use candela::render::{RenderConfig, RenderError, Rendered};
use glam::Vec3;
use indicatif::ProgressBar;
use its_about_time::game::NIGHT_MAX_EV;
use its_about_time::world::RuinsWorld;

use super::machine::median;
use super::picture_run::FRAME_SECONDS;
use super::picture_skip::Skipping;
use super::picture_tracer::{References, ReferencingTracer};

/// What one run plays.
pub struct RuinsRun<'a> {
    /// The world (its `level.render_areas` cleared for a run without render areas).
    pub world: &'a RuinsWorld,
    /// The recording that drives the steps; `None`: the explorer stands at the spawn, nothing
    /// pressed (a still view; the day still flows).
    pub replay: Option<&'a Path>,
    /// Size, denoiser, sky rebuild; one sample per pixel per frame.
    pub render: RenderConfig,
    /// At most this many frames (fewer when the replay ends).
    pub frames: u64,
    /// Frames traced (the others skipped).
    pub live: BTreeSet<u64>,
    /// Frames that start with a camera cut (the history restarts).
    pub cuts: BTreeSet<u64>,
    /// Frames whose displayed film is kept.
    pub keep: BTreeSet<u64>,
}

/// What a run kept.
pub struct RuinsPlayed {
    /// The displayed film of the kept frames (frame → linear radiance).
    pub displayed: BTreeMap<u64, Vec<Vec3>>,
    /// The exposure the game shows each kept frame with, stops (`Engine::sky_exposure_ev`
    /// capped at `NIGHT_MAX_EV`, as the window).
    pub exposure_ev: BTreeMap<u64, f32>,
    /// Local solar time at each kept frame, hours.
    pub local_hours: BTreeMap<u64, f64>,
    /// The camera's position after each frame (index: the frame), metres, world space.
    pub cameras: Vec<[f32; 3]>,
    /// Median milliseconds a traced frame spent tracing and denoising.
    pub frame_ms: f64,
}

/// Plays `run`, rendering the references `refs` wants on its traced frames.
pub fn play_ruins(
    run: &RuinsRun<'_>,
    refs: Arc<Mutex<References>>,
    progress: ProgressBar,
) -> anyhow::Result<RuinsPlayed> {
    let world = run.world;
    let (replay, start) = match run.replay {
        Some(path) => {
            let (replay, start) = (world.open_replay(path))
                .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            (Some(replay), start)
        }
        None => (None, 0),
    };
    let mut game = world.new_game(start);
    let open = Skipping::open(ReferencingTracer::open(refs, progress), run.live.clone());
    let mut engine = Engine::with_tracer(run.render, world.environment(&game), open)?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    if let Some(replay) = replay {
        engine.set_step_input(StepInput::Replay(replay));
    }
    let mut played = RuinsPlayed {
        displayed: BTreeMap::new(),
        exposure_ev: BTreeMap::new(),
        local_hours: BTreeMap::new(),
        cameras: Vec::new(),
        frame_ms: f64::NAN,
    };
    let mut times = Vec::new();
    let mut collect = |results: Vec<Result<Rendered, RenderError>>,
                       played: &mut RuinsPlayed|
     -> anyhow::Result<()> {
        for r in results {
            let r = r?;
            if let Some(film) = r.film
                && run.keep.contains(&r.frame)
            {
                played.displayed.insert(r.frame, film.mean);
            }
            if run.live.contains(&r.frame) {
                times.push((r.render_seconds + r.denoise_seconds) * 1e3);
            }
        }
        Ok(())
    };
    for _ in 0..run.frames {
        // The frame the next `Engine::frame` seals.
        let frame = engine.frames();
        if run.cuts.contains(&frame) {
            engine.cut();
        }
        if run.keep.contains(&frame) {
            engine.capture_next();
        }
        engine.frame(FRAME_SECONDS, &mut game)?;
        played.cameras.push(engine.camera_position().to_array());
        if run.keep.contains(&frame) {
            let ev = engine
                .sky_exposure_ev()
                .map_or(0.0, |ev| ev.min(NIGHT_MAX_EV));
            played.exposure_ev.insert(frame, ev);
            let hours =
                (engine.sky_now().as_ref()).and_then(its_about_time::game::day::local_hours);
            played.local_hours.insert(frame, hours.unwrap_or(f64::NAN));
        }
        collect(engine.rendered(), &mut played)?;
        if engine.replay_finished() {
            break;
        }
    }
    collect(engine.shutdown(), &mut played).context("the last frames")?;
    played.frame_ms = median(&times);
    Ok(played)
}
