//! The player's progress: which levels are finished, the checkpoint reached in each level
//! under way, and the total play time, kept as RON in `<data>/progress.ron` (see
//! `user_dirs.rs`).
//!
//! Loading never fails: a missing file is a new player; bad RON, an unknown field or an
//! invalid value (negative or NaN play time, an empty id) gives a new player's progress, a
//! warning naming the file and the problem, and the bad file kept as `progress.ron.corrupt`
//! (so a broken save is never overwritten and can be rescued). Every field has a default, so
//! older saves load. Saving is atomic.
//!
//! Owns: the progress values. Main thread. Must not: decide when to save (the runner saves at
//! checkpoints, level ends and on quitting) or know level contents.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::stored::{Loaded, StoreError, load_or_default, save_ron};

/// How far the player got.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Progress {
    /// Ids of the levels finished.
    pub finished: BTreeSet<String>,
    /// Level id → the id of the last checkpoint reached in it (levels under way only).
    pub checkpoints: BTreeMap<String, String>,
    /// Seconds played in total (simulated time while playing, not paused).
    pub play_seconds: f64,
}

impl Progress {
    /// The first invalid value, if any.
    pub fn check(&self) -> Result<(), String> {
        if !(self.play_seconds.is_finite() && self.play_seconds >= 0.0) {
            return Err(format!(
                "play_seconds is {}, not a finite number of seconds >= 0",
                self.play_seconds
            ));
        }
        if self.finished.iter().any(String::is_empty) {
            return Err("finished: an empty level id".into());
        }
        if let Some((level, cp)) = self
            .checkpoints
            .iter()
            .find(|(l, c)| l.is_empty() || c.is_empty())
        {
            return Err(format!(
                "checkpoints: an empty id (level {level:?}, checkpoint {cp:?})"
            ));
        }
        Ok(())
    }

    /// Reads the progress save (see the module doc: never fails, warns instead).
    pub fn load(path: &Path) -> Loaded<Progress> {
        load_or_default(path, Progress::check)
    }

    /// Writes the progress save atomically; invalid values are refused and the previous file
    /// is kept.
    pub fn save(&self, path: &Path) -> Result<(), StoreError> {
        self.check().map_err(|problem| StoreError::Invalid {
            path: path.to_path_buf(),
            problem,
        })?;
        save_ron(path, self)
    }

    /// Marks `level` finished; its checkpoint is dropped (playing it again starts over).
    pub fn finish_level(&mut self, level: &str) {
        self.finished.insert(level.to_string());
        self.checkpoints.remove(level);
    }

    pub fn is_finished(&self, level: &str) -> bool {
        self.finished.contains(level)
    }

    /// Records that the player reached `checkpoint` in `level`.
    pub fn reach_checkpoint(&mut self, level: &str, checkpoint: &str) {
        self.checkpoints
            .insert(level.to_string(), checkpoint.to_string());
    }

    /// The checkpoint to restart `level` from, if one was reached.
    pub fn checkpoint(&self, level: &str) -> Option<&str> {
        self.checkpoints.get(level).map(String::as_str)
    }

    /// Adds `seconds` of play (ignored unless finite and positive).
    pub fn add_play_time(&mut self, seconds: f64) {
        if seconds.is_finite() && seconds > 0.0 {
            self.play_seconds += seconds;
        }
    }
}
