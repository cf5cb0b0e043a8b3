//! Playing Reflect without a window: a recording replayed step by step by the engine's
//! harness (`candela::app::harness::play_replay`: a tiny CPU-traced frame, since the lasers and
//! the mirror gun query the committed scene), summed up in a [`RunSummary`] and one line.
//!
//! Owns: [`play_replay`] and [`RunSummary`] (what Reflect reads of a finished run). Main thread. Must not: open windows or devices.

use std::path::Path;

use candela::app::Engine;
use candela::app::harness::{ReplayPace, play_replay as play_replay_with};
use candela::sim::triggers::LaserPath;

use crate::game::{ReflectEvent, ReflectGame};
use crate::world::ReflectWorld;

/// What a headless run did.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// Index of the chamber the recording starts in (0 for the whole game).
    pub start: usize,
    /// Chambers finished, in order.
    pub finished: Vec<usize>,
    /// Whether the ending was reached.
    pub ending: bool,
    /// Seconds of play (fixed steps × step length) until the ending or the recording's end.
    pub seconds: f64,
    /// Mirrors the gun made.
    pub mirrors: u32,
    /// Times a laser sent the player back.
    pub sent_back: u32,
    /// Fixed steps run.
    pub steps: u64,
    /// The engine's state hash after the last step.
    pub state_hash: u64,
    /// Everything that happened, with the step.
    pub log: Vec<(u64, ReflectEvent)>,
    /// Every laser's beam after the last step.
    pub beams: Vec<Beam>,
}

/// A laser's beam as traced in the last step.
#[derive(Clone, Debug, PartialEq)]
pub struct Beam {
    /// The emitter instance's name.
    pub laser: String,
    /// Where it starts, turns and stops (world space, metres).
    pub points: Vec<glam::Vec3>,
    /// The name of the instance it stopped at, if it has one.
    pub stopped_at: Option<String>,
}

/// The beams of every named laser in `engine`'s world.
fn beams(engine: &Engine, game: &ReflectGame) -> Vec<Beam> {
    let names: std::collections::HashMap<hecs::Entity, &str> = game
        .inner()
        .spawned()
        .by_name
        .iter()
        .map(|(n, &e)| (e, n.as_str()))
        .collect();
    let mut out: Vec<Beam> = engine
        .world()
        .query::<(hecs::Entity, &LaserPath)>()
        .iter()
        .filter_map(|(e, path)| {
            Some(Beam {
                laser: names.get(&e)?.to_string(),
                points: path.points.clone(),
                stopped_at: path
                    .stopped_at
                    .and_then(|s| names.get(&s).map(|n| n.to_string())),
            })
        })
        .collect();
    out.sort_by(|a, b| a.laser.cmp(&b.laser));
    out
}

impl RunSummary {
    /// Whether the recording did what it is for: the ending for the whole game, its chamber
    /// finished for a chamber.
    pub fn solved(&self, whole_game: bool) -> bool {
        if whole_game {
            self.ending
        } else {
            self.finished.contains(&self.start)
        }
    }

    /// The summary line `reflect --replay FILE --headless` prints.
    pub fn line(&self, world: &ReflectWorld) -> String {
        let names: Vec<&str> = self
            .finished
            .iter()
            .map(|&i| world.chambers[i].id.as_str())
            .collect();
        format!(
            "reflect: chambers finished {}/{} [{}], time {}:{:02}, mirrors used {}, sent back {}, \
             ending {}, {} steps, state hash {:016x}",
            self.finished.len(),
            world.chambers.len(),
            names.join(", "),
            (self.seconds / 60.0) as u64,
            (self.seconds % 60.0) as u64,
            self.mirrors,
            self.sent_back,
            if self.ending {
                "reached"
            } else {
                "not reached"
            },
            self.steps,
            self.state_hash
        )
    }
}

/// Replays `replay` on `world` headless at 60 frames per second (one fixed step a frame);
/// errors when the recording does not fit the world.
pub fn play_replay(world: &ReflectWorld, replay: &Path) -> anyhow::Result<RunSummary> {
    play_replay_at(world, replay, 1.0 / 60.0, 0)
}

/// Replays `replay` on `world` headless in frames of `frame_seconds` (seconds of wall-clock
/// time each; 0.1 runs six 1/60 s steps a frame), then goes on with frames without input
/// until at least `at_least_steps` fixed steps ran (so runs at different frame rates can be
/// compared after the same steps); errors when the recording does not fit the world.
pub fn play_replay_at(
    world: &ReflectWorld,
    replay: &Path,
    frame_seconds: f64,
    at_least_steps: u64,
) -> anyhow::Result<RunSummary> {
    let pace = ReplayPace {
        frame_seconds,
        at_least_steps,
    };
    let summary = play_replay_with(world, replay, pace, |end| RunSummary {
        start: end.start,
        finished: end.game.finished(),
        ending: end.game.ended(),
        seconds: end.game.play_seconds(),
        mirrors: end.game.gun().made,
        sent_back: end.game.sent_back(),
        steps: end.engine.clock().steps,
        state_hash: end.engine.state_hash(),
        log: end.game.log().to_vec(),
        beams: beams(end.engine, end.game),
    })?;
    Ok(summary)
}
