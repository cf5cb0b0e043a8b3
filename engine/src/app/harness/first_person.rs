//! [`FirstPersonLevel`]: one level played in first person ([`FirstPersonGame`]) as the harness
//! runs it — the `playground` tool's configuration, and the simplest a new game starts from.
//! Its one level is the file's; its recordings are the first-person game's
//! ([`FirstPersonGame::open_replay`], [`FirstPersonGame::recorder`]).
//!
//! Main thread. Must not: load anything after [`FirstPersonLevel::load`].

use std::path::{Path, PathBuf};

use super::config::{HarnessError, HarnessGame};
use crate::app::play::FirstPersonGame;
use crate::app::replay::{Recorder, Replay};
use crate::app::runner::{EditTarget, Environment};
use crate::assets::{AssetResult, AssetRoot};
use crate::level::{PlayableLevel, load_level};

/// A level file loaded once, played in first person by every harness mode.
#[derive(Clone, Debug)]
pub struct FirstPersonLevel {
    path: PathBuf,
    root: AssetRoot,
    level: PlayableLevel,
}

impl FirstPersonLevel {
    /// Loads `path` (its paths confined to `root`).
    pub fn load(path: &Path, root: &AssetRoot) -> AssetResult<Self> {
        Ok(Self {
            path: path.to_path_buf(),
            root: root.clone(),
            level: load_level(path, root)?,
        })
    }

    /// A fresh game of the level, F1 editing its file (as [`FirstPersonGame::load`] gives).
    pub fn game(&self) -> FirstPersonGame {
        let mut game = FirstPersonGame::of_level(&self.path, self.level.clone());
        game.set_edit_target(Some(EditTarget::single_file(&self.path, self.root.clone())));
        game
    }
}

impl HarnessGame for FirstPersonLevel {
    type Game = FirstPersonGame;

    fn level_ids(&self) -> Vec<String> {
        // As `FirstPersonGame::level_id` names it: the file's stem.
        let stem = self
            .path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned());
        vec![stem.unwrap_or_default()]
    }

    fn new_game(&self, _index: usize) -> FirstPersonGame {
        self.game()
    }

    fn environment(&self, game: &FirstPersonGame) -> Environment {
        game.environment()
    }

    fn open_replay(&self, path: &Path) -> Result<(Replay, usize), HarnessError> {
        let replay = self
            .game()
            .open_replay(path)
            .map_err(|e| HarnessError::Game(e.to_string()))?;
        Ok((replay, 0))
    }

    fn recorder(&self, _level: &str) -> Result<Recorder, HarnessError> {
        self.game()
            .recorder()
            .map_err(|e| HarnessError::Game(e.to_string()))
    }
}
