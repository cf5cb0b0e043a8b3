//! Playing It's About Time without a window: a recording replayed step by step by the
//! engine's harness (`candela::app::harness::play_replay`, a tiny CPU-traced frame: the sun
//! gate's glyph and the follow camera query the committed scene), summed up in a
//! [`RunSummary`] and one line.
//!
//! Owns: [`play_replay`], [`RunSummary`]. Main thread. Must not: open windows or devices.

use std::path::Path;

use candela::app::harness::{ReplayPace, play_replay_watching};

use crate::game::soundscape::Surface;
use crate::game::{TimeEvent, day};
use crate::world::RuinsWorld;

/// What a headless run did.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// Artifacts taken, in order (their events).
    pub artifacts: Vec<String>,
    /// Artifacts the level holds.
    pub artifacts_total: usize,
    /// Whether the ending was reached.
    pub ending: bool,
    /// Seconds of play until the ending or the recording's end.
    pub seconds: f64,
    /// Local solar time of the sky at the end, hours (when the sky has a time).
    pub local_hours: Option<f64>,
    /// Fixed steps run.
    pub steps: u64,
    /// The engine's state hash after the last step.
    pub state_hash: u64,
    /// Everything that happened, with the step.
    pub log: Vec<(u64, TimeEvent)>,
    /// The level's breakables that have broken (the rolling stone's wall).
    pub broken: usize,
    /// Every footstep the explorer made: the fixed step and the surface it sounded.
    pub footsteps: Vec<(u64, Surface)>,
    /// The name of every sound started, oldest first (the engine keeps the latest
    /// `candela::audio::MAX_PLAYED_RECORDS`; a whole game starts far fewer).
    pub sounds: Vec<String>,
    /// Where the camera stood after each frame (one a fixed step), metres, world space.
    pub camera_path: Vec<[f32; 3]>,
}

impl RunSummary {
    /// Whether the recording reached the ending with every artifact.
    pub fn solved(&self) -> bool {
        self.ending && self.artifacts.len() == self.artifacts_total
    }

    /// The line `its_about_time --replay FILE --headless` prints.
    pub fn line(&self) -> String {
        let names: Vec<String> = self
            .artifacts
            .iter()
            .map(|a| day::artifact_name(a))
            .collect();
        format!(
            "its_about_time: artifacts {}/{} [{}], in-game time {}, real time {}:{:02}, \
             ending {}, {} steps, state hash {:016x}",
            self.artifacts.len(),
            self.artifacts_total,
            names.join(", "),
            self.local_hours
                .map_or_else(|| "-".to_string(), day::clock_label),
            (self.seconds / 60.0) as u64,
            (self.seconds % 60.0) as u64,
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

/// Replays `replay` on `world` headless at 60 frames per second (one fixed step a frame).
pub fn play_replay(world: &RuinsWorld, replay: &Path) -> anyhow::Result<RunSummary> {
    let mut camera_path = Vec::new();
    let watch = |engine: &candela::app::Engine| {
        camera_path.push(engine.camera_position().to_array());
    };
    let mut summary = play_replay_watching(world, replay, ReplayPace::default(), watch, |end| {
        RunSummary {
            artifacts: end.game.artifacts().to_vec(),
            artifacts_total: end.game.artifacts_in_level().len(),
            ending: end.game.ended(),
            seconds: end.game.play_seconds(),
            local_hours: end.engine.sky_now().as_ref().and_then(day::local_hours),
            steps: end.engine.clock().steps,
            state_hash: end.engine.state_hash(),
            log: end.game.log().to_vec(),
            broken: (0..)
                .map_while(|i| end.engine.physics().broken(i))
                .filter(|&b| b)
                .count(),
            footsteps: end.game.soundscape().footsteps().to_vec(),
            sounds: end
                .engine
                .audio()
                .played()
                .iter()
                .map(|p| p.name.to_string())
                .collect(),
            camera_path: Vec::new(),
        }
    })?;
    summary.camera_path = camera_path;
    Ok(summary)
}
