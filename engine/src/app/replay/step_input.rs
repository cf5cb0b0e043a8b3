//! Where each fixed step's input comes from: the player (live), the player with every step
//! recorded (`--record FILE`), or a recording (`--replay FILE`). The runner asks
//! [`StepInput::next_step`] once per fixed step and hands the [`ActionFrame`] to the game, so
//! game rules read the same frames live and in a replay.
//!
//! Main thread. Must not: count frames or read clocks (a replay runs step by step, at any
//! speed); know the game.

use std::path::{Path, PathBuf};

use super::error::ReplayError;
use super::format::RecordedLook;
use super::monkey::Monkey;
use super::record::{Recorder, Replay};
use crate::app::input::ActionFrame;
use crate::app::input::ActionSet;
use crate::app::input::InputState;

/// The source of the fixed steps' input.
#[derive(Debug)]
pub enum StepInput {
    /// From the devices.
    Live,
    /// From the devices, every step kept; [`StepInput::finish`] writes `path`.
    Record { recorder: Recorder, path: PathBuf },
    /// From a recording; the devices still feed menus and the runner but not the game.
    Replay(Replay),
    /// From a seeded random source (the soak test); never ends.
    Monkey(Monkey),
}

impl StepInput {
    /// Recording to `path` (written by [`StepInput::finish`]).
    pub fn record(recorder: Recorder, path: &Path) -> Self {
        StepInput::Record {
            recorder,
            path: path.to_path_buf(),
        }
    }

    /// The next step's frame; `None` when a replay has played its last step. Ends the step in
    /// `input` either way (its presses and step motion start again from zero).
    pub fn next_step(
        &mut self,
        input: &mut InputState,
        set: &ActionSet,
    ) -> Result<Option<ActionFrame>, ReplayError> {
        let frame = match self {
            StepInput::Live => Some(ActionFrame::capture(input, set)),
            StepInput::Record { recorder, .. } => {
                let frame = ActionFrame::capture(input, set);
                recorder.push(frame.clone())?;
                Some(frame)
            }
            StepInput::Replay(replay) => replay.next_frame(),
            StepInput::Monkey(monkey) => Some(monkey.frame(set)),
        };
        input.end_step();
        Ok(frame)
    }

    /// The look settings the steps are played with when they are not the player's: a
    /// replay's recorded ones, or those a recording was stamped with when it started.
    pub fn fixed_look(&self) -> Option<RecordedLook> {
        match self {
            StepInput::Record { recorder, .. } => Some(recorder.recording().header.look),
            StepInput::Replay(replay) => Some(replay.header().look),
            StepInput::Live | StepInput::Monkey(_) => None,
        }
    }

    /// Stamps a recording with the look settings its steps are played with.
    pub fn stamp_look(&mut self, look: RecordedLook) {
        if let StepInput::Record { recorder, .. } = self {
            recorder.set_look(look);
        }
    }

    /// Writes the recording, if recording (atomically; the steps so far).
    pub fn finish(&self) -> Result<(), ReplayError> {
        match self {
            StepInput::Record { recorder, path } => recorder.write(path),
            _ => Ok(()),
        }
    }
}
