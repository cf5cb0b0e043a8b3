//! [`HarnessGame`]: what a game hands the harness so every mode (headless replay, bench, soak,
//! converged captures, recording) runs it the same way — a fresh game for a level, the
//! environment to start the engine with, its recordings opened against its world — and
//! [`HarnessError`], why a mode stopped.
//!
//! The game's own rules and summaries stay in the game's crate; this is the configuration
//! only. Main thread. Must not: name a particular game.

use std::path::Path;

use crate::app::persist::UserDirsError;
use crate::app::replay::{Recorder, Replay};
use crate::app::runner::{EngineError, Environment, Game};
use crate::app::window::WindowError;
use crate::render::RenderError;
use crate::render::film::ImageIoError;

/// A game as the harness runs it: its levels, a fresh game for one, its recordings.
pub trait HarnessGame {
    /// The game the engine runs.
    type Game: Game;

    /// The ids of the game's levels (chambers), in play order.
    fn level_ids(&self) -> Vec<String>;

    /// A fresh game that starts in level `index` (an index into [`HarnessGame::level_ids`]).
    fn new_game(&self, index: usize) -> Self::Game;

    /// The environment the engine starts with for `game` (its level's sun and sky).
    fn environment(&self, game: &Self::Game) -> Environment;

    /// Opens the recording at `path` against the game's world: the replay and the index of
    /// the level it starts in. Refused (naming the file) when it does not fit.
    fn open_replay(&self, path: &Path) -> Result<(Replay, usize), HarnessError>;

    /// A recorder for a run of level id `level` (a game may accept ids of its own, such as a
    /// whole game's), with the game's name, world hash and step rate.
    fn recorder(&self, level: &str) -> Result<Recorder, HarnessError>;

    /// The index of level `id`, or an error listing the ids the game has.
    fn level_index(&self, id: &str) -> Result<usize, HarnessError> {
        let ids = self.level_ids();
        ids.iter()
            .position(|l| l == id)
            .ok_or_else(|| HarnessError::NoLevel {
                id: id.to_string(),
                ids,
            })
    }
}

/// Why a harness mode stopped.
#[derive(Debug, thiserror::Error)]
pub enum HarnessError {
    #[error("the engine: {0}")]
    Engine(#[from] EngineError),
    #[error("rendering failed: {0}")]
    Render(#[from] RenderError),
    #[error("the game's setup failed: {0}")]
    Setup(String),
    #[error("{0}")]
    Game(String),
    #[error("the game has no level {id:?}; it has {ids:?}")]
    NoLevel { id: String, ids: Vec<String> },
    #[error("the replay did not finish in {frames} frames")]
    ReplayUnfinished { frames: u64 },
    #[error("{level}: the render thread stopped before a film came back")]
    NoFilm { level: String },
    #[error("soak of {level} (seed {seed}): {source}")]
    Soak {
        level: String,
        seed: u64,
        source: super::soak::SoakError,
    },
    #[error(transparent)]
    Image(#[from] ImageIoError),
    #[error(transparent)]
    Window(#[from] WindowError),
    #[error(transparent)]
    Dirs(#[from] UserDirsError),
}
