//! Replaying a game's recording without a window: [`play_replay`] runs the recording step by
//! step on a tiny CPU-traced frame (16×9: rules that query the scene still see it committed
//! every frame) and hands the engine and the game, once the recording finished, to the game's
//! own summary. The summary line and the exit code are the game binary's.
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
    let (replay, start) = config.open_replay(path)?;
    let recorded = replay.steps() + 1;
    let mut game = config.new_game(start);
    // The sky's table follows a moving sun on a worker thread: the run's outcome never reads
    // the picture, and a sun turned fast would otherwise stall every frame.
    let render = RenderConfig {
        sky_rebuild: crate::scene::SkyRebuild::Background,
        ..RenderConfig::cpu(16, 9)
    };
    let mut engine = Engine::new(render, config.environment(&game))?;
    game.setup(&mut engine)
        .map_err(|e| HarnessError::Setup(e.to_string()))?;
    engine.set_step_input(StepInput::Replay(replay));
    // Every frame runs at least one step (`frame_seconds` ≥ 1/60 s is the caller's to keep).
    let most_frames = recorded.max(pace.at_least_steps) + 1;
    for _ in 0..most_frames {
        engine.frame(pace.frame_seconds, &mut game)?;
        let _ = engine.rendered();
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
