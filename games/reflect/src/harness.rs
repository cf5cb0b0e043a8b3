//! Reflect as the engine's game harness runs it (`candela::app::harness`): its levels are the
//! chambers, a fresh game starts in one, its recordings open against the world as it is now
//! (`replays.rs`). Every headless mode (`--replay --headless`, `--bench`, `--soak`,
//! `--capture`) and recording go through this configuration; the modes' loops are the
//! engine's.
//!
//! Owns: `impl HarnessGame for ReflectWorld`. Main thread. Must not: contain game rules (`game`
//! has them) or loops of its own.

use std::path::Path;

use candela::app::harness::{HarnessError, HarnessGame};
use candela::app::{Environment, Recorder, Replay};

use crate::game::ReflectGame;
use crate::world::ReflectWorld;

/// Reflect's errors (anyhow, with their context) as the harness carries them.
fn game_error(e: anyhow::Error) -> HarnessError {
    HarnessError::Game(format!("{e:#}"))
}

impl HarnessGame for ReflectWorld {
    type Game = ReflectGame;

    fn level_ids(&self) -> Vec<String> {
        self.chambers.iter().map(|c| c.id.clone()).collect()
    }

    fn new_game(&self, index: usize) -> ReflectGame {
        ReflectGame::new(self.clone(), index)
    }

    fn environment(&self, game: &ReflectGame) -> Environment {
        game.inner().environment()
    }

    fn open_replay(&self, path: &Path) -> Result<(Replay, usize), HarnessError> {
        crate::replays::open_replay(self, path).map_err(game_error)
    }

    fn recorder(&self, level: &str) -> Result<Recorder, HarnessError> {
        crate::replays::recorder(self, level).map_err(game_error)
    }
}
