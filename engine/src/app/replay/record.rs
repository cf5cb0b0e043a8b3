//! Recording the player's input per fixed step and playing it back: [`Recorder`] collects one
//! [`ActionFrame`] per step and writes the file atomically (format: `format.rs`);
//! [`Replay`] reads a file, checks it belongs to this game, level and step rate, and yields
//! its frames one step at a time, laid out by the *current* [`ActionSet`] (recordings store
//! action names, so a game may add or reorder actions without breaking its replays).
//!
//! Neither side knows about frames, wall time or rendering: one call per fixed step, so a
//! replay reproduces the same steps however fast or slow it runs. Main thread. Must not: read
//! devices or clocks.

use std::path::{Path, PathBuf};

use super::error::ReplayError;
use super::format::{RecordedAction, RecordedLook, Recording, RecordingHeader, Run};
use crate::app::input::ActionFrame;
use crate::app::input::{ActionKind, ActionSet};

/// Collects the frames of a run being recorded.
#[derive(Clone, Debug)]
pub struct Recorder {
    recording: Recording,
    steps: u64,
}

impl Recorder {
    /// A recorder for `game` on the level `level_id` whose file has content hash
    /// `level_hash` (see `format::level_hash`), stepping `step_hz` times per second,
    /// with frames laid out by `set`.
    pub fn new(game: &str, level_id: &str, level_hash: u64, step_hz: f64, set: &ActionSet) -> Self {
        let actions = set
            .defs()
            .iter()
            .map(|d| RecordedAction {
                name: d.name.clone(),
                kind: d.kind,
            })
            .collect();
        Self {
            recording: Recording {
                header: RecordingHeader {
                    game: game.to_string(),
                    level_id: level_id.to_string(),
                    level_hash,
                    step_hz,
                    look: RecordedLook::default(),
                    actions,
                },
                runs: Vec::new(),
            },
            steps: 0,
        }
    }

    /// Records that the steps are played with `look` (the runner stamps the player's settings
    /// when recording starts).
    pub fn set_look(&mut self, look: RecordedLook) {
        self.recording.header.look = look;
    }

    /// Appends the next step's frame (buttons' values are stored as 0, whatever they hold).
    pub fn push(&mut self, mut frame: ActionFrame) -> Result<(), ReplayError> {
        let actions = &self.recording.header.actions;
        if frame.values.len() != actions.len() {
            return Err(ReplayError::FrameShape {
                game: self.recording.header.game.clone(),
                step: self.steps + 1,
                found: frame.values.len(),
                expected: actions.len(),
            });
        }
        for (v, a) in frame.values.iter_mut().zip(actions) {
            if a.kind == ActionKind::Button {
                *v = 0;
            }
        }
        self.steps += 1;
        match self.recording.runs.last_mut() {
            Some(run) if run.frame == frame && run.steps < u32::MAX => run.steps += 1,
            _ => self.recording.runs.push(Run { steps: 1, frame }),
        }
        Ok(())
    }

    /// Steps recorded so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The recording so far.
    pub fn recording(&self) -> &Recording {
        &self.recording
    }

    /// Writes everything recorded so far to `path`, atomically (call it again later to write
    /// a longer recording over it).
    pub fn write(&self, path: &Path) -> Result<(), ReplayError> {
        self.recording.write(path)
    }
}

/// What a replay must have been recorded on to be played here.
#[derive(Clone, Copy, Debug)]
pub struct ReplayTarget<'a> {
    pub game: &'a str,
    pub level_id: &'a str,
    /// Content hash of the level file now (`format::level_hash`).
    pub level_hash: u64,
    pub step_hz: f64,
    pub actions: &'a ActionSet,
}

/// A recording being played back, one fixed step at a time.
#[derive(Clone, Debug)]
pub struct Replay {
    path: PathBuf,
    recording: Recording,
    /// Recorded action index → the current set's id.
    remap: Vec<u8>,
    actions: usize,
    run: usize,
    step_in_run: u32,
    step: u64,
}

impl Replay {
    /// Reads `path` and checks it against `target`.
    pub fn open(path: &Path, target: &ReplayTarget<'_>) -> Result<Self, ReplayError> {
        Self::new(path, Recording::read(path)?, target)
    }

    /// Checks a recording read from `path` against `target`.
    pub fn new(
        path: &Path,
        recording: Recording,
        target: &ReplayTarget<'_>,
    ) -> Result<Self, ReplayError> {
        let path_buf = path.to_path_buf();
        let h = &recording.header;
        if h.game != target.game {
            return Err(ReplayError::OtherGame {
                path: path_buf,
                recorded: h.game.clone(),
                expected: target.game.to_string(),
            });
        }
        if h.level_id != target.level_id || h.level_hash != target.level_hash {
            return Err(ReplayError::OtherLevel {
                path: path_buf,
                recorded_id: h.level_id.clone(),
                recorded_hash: h.level_hash,
                level_id: target.level_id.to_string(),
                level_hash: target.level_hash,
            });
        }
        if h.step_hz.to_bits() != target.step_hz.to_bits() {
            return Err(ReplayError::StepRate {
                path: path_buf,
                recorded: h.step_hz,
                expected: target.step_hz,
            });
        }
        let mut remap = Vec::with_capacity(h.actions.len());
        for a in &h.actions {
            let Some(id) = target.actions.id(&a.name) else {
                return Err(ReplayError::UnknownAction {
                    path: path_buf,
                    name: a.name.clone(),
                });
            };
            let kind = target.actions.def(id).map(|d| d.kind);
            if kind != Some(a.kind) {
                return Err(ReplayError::ActionKind {
                    path: path_buf,
                    name: a.name.clone(),
                    recorded: a.kind.name(),
                    expected: kind.map_or("nothing", ActionKind::name),
                });
            }
            remap.push(id.0);
        }
        Ok(Self {
            path: path_buf,
            recording,
            remap,
            actions: target.actions.len(),
            run: 0,
            step_in_run: 0,
            step: 0,
        })
    }

    /// The file this replay was read from.
    pub fn path(&self) -> &Path {
        &self.path
    }

    pub fn header(&self) -> &RecordingHeader {
        &self.recording.header
    }

    /// Steps in the recording.
    pub fn steps(&self) -> u64 {
        self.recording.steps()
    }

    /// Steps already played.
    pub fn played(&self) -> u64 {
        self.step
    }

    /// Whether every step has been played.
    pub fn finished(&self) -> bool {
        self.step >= self.steps()
    }

    /// The next step's frame, laid out by the target's action set; `None` after the last.
    pub fn next_frame(&mut self) -> Option<ActionFrame> {
        let run = self.recording.runs.get(self.run)?;
        let recorded = &run.frame;
        let mut frame = ActionFrame {
            held: 0,
            pressed: 0,
            values: vec![0; self.actions],
        };
        for (i, &to) in self.remap.iter().enumerate() {
            frame.held |= ((recorded.held >> i) & 1) << to;
            frame.pressed |= ((recorded.pressed >> i) & 1) << to;
            frame.values[to as usize] = recorded.values.get(i).copied().unwrap_or(0);
        }
        self.step += 1;
        self.step_in_run += 1;
        if self.step_in_run >= run.steps {
            self.run += 1;
            self.step_in_run = 0;
        }
        Some(frame)
    }
}

impl Iterator for Replay {
    type Item = ActionFrame;
    fn next(&mut self) -> Option<ActionFrame> {
        self.next_frame()
    }
}
