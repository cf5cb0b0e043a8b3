//! Replaying a game's recording without a window: [`play_replay`] runs the recording step by
//! step on a tiny CPU-traced frame (16×9: rules that query the scene still see it committed
//! every frame) and hands the engine and the game, once the recording finished, to the game's
//! own summary; [`play_replay_watching`] also shows the engine to the caller after every frame
//! (the camera's way through a level). The summary line and the exit code are the game binary's.
//!
//! Main thread (the render thread renders). Must not: open windows or devices, or judge what
//! the run did (the game's summary does).

use std::path::Path;

use super::config::{HarnessError, HarnessGame};
use crate::app::replay::StepInput;
use crate::app::runner::{Engine, Game};
use crate::render::RenderConfig;

/// How a headless replay is played.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReplayPace {
    /// Wall-clock seconds per frame (1/60: one fixed step a frame; 0.1: six).
    pub frame_seconds: f64,
    /// Frames without input after the recording until at least this many fixed steps ran
    /// (runs at different frame rates compared after the same steps).
    pub at_least_steps: u64,
}

impl Default for ReplayPace {
    fn default() -> Self {
        Self {
            frame_seconds: 1.0 / 60.0,
            at_least_steps: 0,
        }
    }
}

/// What a finished headless replay leaves for the game's summary.
pub struct ReplayEnd<'a, G> {
    /// The engine after the last step (the render thread still up).
    pub engine: &'a Engine,
    /// The game after the last step.
    pub game: &'a G,
    /// Index of the level the recording starts in.
    pub start: usize,
}

/// Replays the recording at `path` of `config`'s game headless at `pace`; `summarise` reads
/// the engine and the game once the recording finished. Errors when the recording does not
/// fit the game or does not finish.
pub fn play_replay<C: HarnessGame, S>(
    config: &C,
    path: &Path,
    pace: ReplayPace,
    summarise: impl FnOnce(ReplayEnd<'_, C::Game>) -> S,
) -> Result<S, HarnessError> {
    play_replay_watching(config, path, pace, |_| {}, summarise)
}

/// [`play_replay`], calling `watch` with the engine after every frame (read-only: the
/// camera's position, the clock).
pub fn play_replay_watching<C: HarnessGame, S>(
    config: &C,
    path: &Path,
    pace: ReplayPace,
    mut watch: impl FnMut(&Engine),
    summarise: impl FnOnce(ReplayEnd<'_, C::Game>) -> S,
) -> Result<S, HarnessError> {
    let Started {
        mut engine,
        mut game,
        start,
        recorded,
    } = start_headless(config, Some(path), headless_render())?;
    let recorded = recorded.unwrap_or(0) + 1;
    // Every frame runs at least one step (`frame_seconds` ≥ 1/60 s is the caller's to keep).
    let most_frames = recorded.max(pace.at_least_steps) + 1;
    for _ in 0..most_frames {
        engine.frame(pace.frame_seconds, &mut game)?;
        let _ = engine.rendered();
        watch(&engine);
        if engine.replay_finished() && engine.clock().steps >= pace.at_least_steps {
            break;
        }
    }
    if !engine.replay_finished() {
        return Err(HarnessError::ReplayUnfinished {
            frames: most_frames,
        });
    }
    let summary = summarise(ReplayEnd {
        engine: &engine,
        game: &game,
        start,
    });
    let _ = engine.shutdown();
    Ok(summary)
}

/// The render configuration of the headless modes that only simulate: a 16×9 film on the CPU
/// tracer, the sky's table following a moving sun on a worker thread (a run's outcome never
/// reads the picture, and a sun turned fast would otherwise stall every frame).
pub(super) fn headless_render() -> RenderConfig {
    RenderConfig {
        sky_rebuild: crate::scene::SkyRebuild::Background,
        ..RenderConfig::cpu(16, 9)
    }
}

/// An engine with a game set up in it, ready for its first frame.
pub(super) struct Started<G> {
    pub engine: Engine,
    pub game: G,
    /// Index of the level the game starts in (the recording's, else 0).
    pub start: usize,
    /// The recording's length in fixed steps, when a recording drives the steps.
    pub recorded: Option<u64>,
}

/// Opens the recording at `path` (when there is one) against `config`'s game, starts the
/// engine with `render` and a fresh game in the level the recording starts in, and hands the
/// recording the steps. Every headless mode begins here.
pub(super) fn start_headless<C: HarnessGame>(
    config: &C,
    path: Option<&Path>,
    render: RenderConfig,
) -> Result<Started<C::Game>, HarnessError> {
    let (replay, start) = match path {
        Some(path) => {
            let (replay, start) = config.open_replay(path)?;
            (Some(replay), start)
        }
        None => (None, 0),
    };
    let recorded = replay.as_ref().map(|r| r.steps());
    let mut game = config.new_game(start);
    let mut engine = Engine::new(render, config.environment(&game))?;
    game.setup(&mut engine)
        .map_err(|e| HarnessError::Setup(e.to_string()))?;
    if let Some(replay) = replay {
        engine.set_step_input(StepInput::Replay(replay));
    }
    Ok(Started {
        engine,
        game,
        start,
        recorded,
    })
}
