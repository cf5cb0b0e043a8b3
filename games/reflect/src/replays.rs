//! Reflect's recordings: a replay of one chamber (its level id is the chamber's id, it starts
//! at the chamber's start) or of the whole game (`full_game`, from the first chamber to the
//! ending), recorded against the world as it is now (the game file and every level file).
//!
//! Owns: [`open_replay`] and [`recorder`]. Main thread, at start.
//! Must not: play anything (the engine's step input does).

use std::path::Path;

use anyhow::Context;
use candela::app::{ActionSet, Recorder, Recording, Replay, ReplayTarget};

use crate::world::{ReflectWorld, world_hash};

/// The game name Reflect's recordings carry.
pub const REFLECT_GAME: &str = "reflect";

/// The level id of a recording of the whole game.
pub const FULL_GAME: &str = "full_game";

/// Fixed steps per second of every recording.
pub const STEP_HZ: f64 = 60.0;

/// Opens the recording at `path`; returns it with the index of the chamber it starts in.
/// Refused (naming the file) when it was recorded for another game, an unknown chamber or
/// an older version of the world.
pub fn open_replay(world: &ReflectWorld, path: &Path) -> anyhow::Result<(Replay, usize)> {
    let recording = Recording::read(path)?;
    let id = recording.header.level_id.clone();
    let start = if id == FULL_GAME {
        0
    } else {
        world.chamber_index(&id).with_context(|| {
            format!(
                "{}: recorded for chamber {id:?}, which the game does not have",
                path.display()
            )
        })?
    };
    let set = ActionSet::standard();
    let target = ReplayTarget {
        game: REFLECT_GAME,
        level_id: &id,
        level_hash: world_hash(world)?,
        step_hz: STEP_HZ,
        actions: &set,
    };
    Ok((Replay::new(path, recording, &target)?, start))
}

/// A recorder for chamber `id` (or [`FULL_GAME`]).
pub fn recorder(world: &ReflectWorld, id: &str) -> anyhow::Result<Recorder> {
    Ok(Recorder::new(
        REFLECT_GAME,
        id,
        world_hash(world)?,
        STEP_HZ,
        &ActionSet::standard(),
    ))
}
