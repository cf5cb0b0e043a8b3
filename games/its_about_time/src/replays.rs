//! The game's recordings: where the committed ones live and how one is opened against the
//! world as it is now (the level file's hash, the game's actions, 60 steps per second), or
//! started.
//!
//! Main thread. Must not: play them (the harness does).

use std::path::{Path, PathBuf};

use candela::app::{Recorder, Replay};

use crate::game::TimeGame;
use crate::world::RuinsWorld;

/// The committed recording that plays the whole game, start to ending, under `root`.
pub fn full_game(root: &Path) -> PathBuf {
    named(root, "full_game")
}

/// The committed recording named `name` (`full_game`, or a puzzle's: see
/// [`crate::routes::NAMES`]) under `root`.
pub fn named(root: &Path, name: &str) -> PathBuf {
    root.join(format!("its_about_time/replays/{name}.replay"))
}

/// Opens the recording at `path` against `world` (refused, naming the file, when it was made
/// for another game, another version of the level or other actions).
pub fn open_replay(world: &RuinsWorld, path: &Path) -> anyhow::Result<Replay> {
    TimeGame::new(world.clone()).open_replay(path)
}

/// A recorder of a run of the whole game.
pub fn recorder(world: &RuinsWorld) -> anyhow::Result<Recorder> {
    Ok(TimeGame::new(world.clone()).inner().recorder()?)
}
