//! A level's gameplay after its names were checked: every reference is an index (instances in
//! level order, clips, sounds, volumes, level materials), so running it cannot fail on a name.
//!
//! Owns: [`GameplayPlan`] and its parts, plain data made by the level loader
//! (`level/gameplay_plan.rs`, after `level::validate_level`) or by code. Must not: hold
//! entities (instances become entities at spawn time; [`super::LevelLogic`] maps them) or run
//! anything.

use std::path::PathBuf;

use glam::Vec3;

use crate::assets::Detect;
use crate::sim::animation::{Clip, PlayMode};

/// Everything a level's gameplay does, by index.
#[derive(Clone, Debug, Default)]
pub struct GameplayPlan {
    pub sounds: Vec<PlannedSound>,
    /// Sound index and linear volume of the music.
    pub music: Option<(usize, f32)>,
    pub emitters: Vec<PlannedEmitter>,
    /// Clips whose channel targets index [`Self::clip_targets`].
    pub clips: Vec<Clip>,
    /// The instance each clip target moves.
    pub clip_targets: Vec<usize>,
    /// Clips playing from the start.
    pub autoplay: Vec<(usize, PlayMode)>,
    pub lights_off: Vec<u32>,
    pub volumes: Vec<PlannedVolume>,
    pub lasers: Vec<PlannedLaser>,
    pub rules: Vec<Rule>,
    pub usables: Vec<PlannedUsable>,
    /// The rules' counters: name and starting value, by index.
    pub counters: Vec<(String, i32)>,
    /// Breakable walls and pillars, by index (`Break` actions name them).
    pub breakables: Vec<PlannedBreakable>,
}

/// A breakable with its pieces resolved: instance indices, speed in m/s, mass in kg.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedBreakable {
    pub name: String,
    pub pieces: Vec<usize>,
    pub impact_speed: Option<f32>,
    pub piece_mass: f32,
    pub scatter_speed: f32,
}

/// An instance the player can use: its prompt and the event using it sends.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedUsable {
    pub instance: usize,
    pub usable: Usable,
}

/// On an entity the player can use (spawned from the level's `usables`): what the HUD shows
/// while the player looks at it, and the event (`Event(name)` in the rules) using it sends.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Usable {
    pub prompt: String,
    pub event: String,
}

/// A sound of the level: its name, file, and the decoded sound.
#[derive(Clone, Debug)]
pub struct PlannedSound {
    pub name: String,
    pub path: PathBuf,
    pub sound: crate::audio::Sound,
}

/// A looping sound on an instance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedEmitter {
    pub instance: usize,
    pub sound: usize,
    /// Linear amplitude.
    pub volume: f32,
}

/// A trigger volume on a sensor instance.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedVolume {
    pub name: String,
    pub instance: usize,
    pub detects: Vec<Detect>,
}

/// A laser beam leaving an instance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedLaser {
    pub instance: usize,
    /// Metres, model space of the instance.
    pub origin: Vec3,
    /// Model space of the instance (not necessarily unit length).
    pub direction: Vec3,
    pub max_reflections: u32,
    /// Metres.
    pub max_length: f32,
    /// How the beam is drawn; `None`: invisible (only traced).
    pub beam: Option<PlannedBeam>,
}

/// A laser's visible beam (see `beam_geometry`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedBeam {
    /// Emitted radiance, linear RGB, W·sr⁻¹·m⁻².
    pub radiance: Vec3,
    /// Half the width of the beam's square prism, metres.
    pub radius: f32,
    /// Light group of the beam's emitters.
    pub light_group: Option<u32>,
}

/// A rule: `then` when `when` becomes true, `otherwise` when it becomes false.
#[derive(Clone, Debug, PartialEq)]
pub struct Rule {
    pub name: String,
    pub when: Condition,
    pub then: Vec<Action>,
    pub otherwise: Vec<Action>,
    pub once: bool,
}

/// A condition over volumes (by index) and clip events (by name).
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    Occupied(usize),
    Entered(usize),
    Exited(usize),
    Occupants {
        volume: usize,
        at_least: u32,
    },
    Event(String),
    All(Vec<Condition>),
    Any(Vec<Condition>),
    Not(Box<Condition>),
    AtLeast {
        at_least: u32,
        of: Vec<Condition>,
    },
    Times {
        at_least: u32,
        of: Box<Condition>,
    },
    /// Light group on.
    LightsOn(u32),
    /// Volume (index) centre sees the sun.
    SunLit(usize),
    /// The sun's elevation within `[at_least, at_most]` degrees (open bounds as ±∞).
    SunElevation {
        at_least: f32,
        at_most: f32,
    },
    /// Rule (index) has run its `then` at least once.
    Fired(usize),
    /// Counter (index) within `[at_least, at_most]` (open bounds as `i32::MIN`/`MAX`).
    Counter {
        counter: usize,
        at_least: i32,
        at_most: i32,
    },
    /// Steps risen in order; a wrong step resets (`ConditionEntry::Sequence`).
    Sequence(Vec<Condition>),
}

/// An action with its references resolved.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    Lights {
        group: u32,
        on: bool,
    },
    ToggleLights(u32),
    Play {
        clip: usize,
        mode: PlayMode,
    },
    Reverse {
        clip: usize,
    },
    Pause {
        clip: usize,
    },
    /// `at`: an instance whose position the sound plays at.
    Sound {
        sound: usize,
        at: Option<usize>,
        volume: f32,
    },
    /// `material`: an index into the scene's level materials, `None` for the model's own.
    Material {
        instance: usize,
        material: Option<u32>,
    },
    /// Add to counter (index), saturating.
    Count {
        counter: usize,
        add: i32,
    },
    /// Set counter (index).
    SetCounter {
        counter: usize,
        value: i32,
    },
    /// Break breakable (index) now.
    Break(usize),
    Win,
    Lose,
}
