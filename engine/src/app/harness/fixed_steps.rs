//! A headless run of a set number of fixed steps: [`run_fixed_steps`] plays a game for
//! [`FixedSteps::steps`] steps, [`FixedSteps::per_frame`] of them a rendered 16×9 CPU frame
//! (one: a frame a step; eight: the least rendering, to time how fast the simulation replays),
//! driven by a recording when there is one and without input after it, and hands the engine,
//! the game and the wall-clock time of the steps to the game's own summary. The playground's
//! `--headless` and `--bench`; a game whose replays must stop where they were recorded uses
//! [`super::play_replay`] instead.
//!
//! Main thread (the render thread renders). Must not: open windows or devices, or judge what
//! the run did (the summary does: whether the recording finished is in [`StepsEnd`]).

use std::path::Path;
use std::time::Instant;

use super::config::{HarnessError, HarnessGame};
use super::replay_run::{Started, headless_render, start_headless};
use crate::app::runner::Engine;

/// How many fixed steps a headless run takes, and how many a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedSteps {
    /// Fixed steps (1/60 s each) to run; `None`: the recording's length and the one step past
    /// it that finds it finished, or [`FixedSteps::without_recording`] when there is none.
    pub steps: Option<u64>,
    /// The steps to run when neither [`FixedSteps::steps`] nor a recording says.
    pub without_recording: u64,
    /// Fixed steps per rendered frame (at least 1; the last frame takes what is left).
    pub per_frame: u64,
}

/// What a finished fixed-step run leaves for the game's summary.
pub struct StepsEnd<'a, G> {
    /// The engine after the last step (the render thread still up).
    pub engine: &'a Engine,
    /// The game after the last step.
    pub game: &'a G,
    /// Index of the level the run starts in (the recording's, else 0).
    pub start: usize,
    /// Fixed steps run.
    pub steps: u64,
    /// Wall-clock seconds the steps took (frames and their rendering; not the start-up).
    pub seconds: f64,
    /// The recording's length in fixed steps, when one drove the run.
    pub recorded: Option<u64>,
    /// Whether a step found the recording finished (false without one).
    pub replay_finished: bool,
}

/// Runs `config`'s game headless for `run`'s steps, driven by the recording at `replay` when
/// given; `summarise` reads the engine and the game after the last step. Errors when the
/// recording does not fit the game or the engine fails.
pub fn run_fixed_steps<C: HarnessGame, S>(
    config: &C,
    replay: Option<&Path>,
    run: FixedSteps,
    summarise: impl FnOnce(StepsEnd<'_, C::Game>) -> S,
) -> Result<S, HarnessError> {
    let Started {
        mut engine,
        mut game,
        start,
        recorded,
    } = start_headless(config, replay, headless_render())?;
    let steps = run
        .steps
        .or(recorded.map(|r| r + 1))
        .unwrap_or(run.without_recording);
    let per_frame = run.per_frame.max(1);
    let begun = Instant::now();
    let mut done = 0;
    while done < steps {
        let n = per_frame.min(steps - done);
        engine.frame(n as f64 / 60.0, &mut game)?;
        let _ = engine.rendered();
        done += n;
    }
    let seconds = begun.elapsed().as_secs_f64();
    let summary = summarise(StepsEnd {
        engine: &engine,
        game: &game,
        start,
        steps: done,
        seconds,
        recorded,
        replay_finished: engine.replay_finished(),
    });
    let _ = engine.shutdown();
    Ok(summary)
}
