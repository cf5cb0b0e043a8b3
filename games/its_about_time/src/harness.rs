//! It's About Time as the engine's game harness runs it (`candela::app::harness`): one level,
//! the ruins; a fresh game starts at the explorer's spawn; recordings open against the level
//! as it is now. The headless replay and recording go through this configuration; the modes'
//! loops are the engine's.
//!
//! Owns: `impl HarnessGame for RuinsWorld`. Main thread. Must not: contain game rules.

use std::path::Path;

use candela::app::harness::{HarnessError, HarnessGame};
use candela::app::{Environment, Recorder, Replay};

use crate::game::TimeGame;
use crate::world::{LEVEL_ID, RuinsWorld};

fn game_error(e: anyhow::Error) -> HarnessError {
    HarnessError::Game(format!("{e:#}"))
}

impl HarnessGame for RuinsWorld {
    type Game = TimeGame;

    fn level_ids(&self) -> Vec<String> {
        vec![LEVEL_ID.into()]
    }

    fn new_game(&self, _index: usize) -> TimeGame {
        TimeGame::new(self.clone())
    }

    fn environment(&self, game: &TimeGame) -> Environment {
        game.inner().environment()
    }

    fn open_replay(&self, path: &Path) -> Result<(Replay, usize), HarnessError> {
        Ok((
            crate::replays::open_replay(self, path).map_err(game_error)?,
            0,
        ))
    }

    fn recorder(&self, _level: &str) -> Result<Recorder, HarnessError> {
        crate::replays::recorder(self).map_err(game_error)
    }
}
