//! Skinned characters in level files: the serde types of the `characters` list — the glTF
//! model, its scale and facing, where it spawns, its capsule and controller tuning, and the
//! animation states that choose its clips.
//!
//! Owns: [`CharacterEntry`], [`CapsuleEntry`], [`ControllerEntry`], [`AnimStateEntry`], [`BlendEntry`],
//! [`Contact`]. Plain data: loading the model, checking clip names and numbers is
//! `level::character`'s job; the state machine is `sim::animation::StateMachine`.
//! Must not: read files. Units: metres, seconds, metres per second, degrees where a field says
//! `_deg`; the model path is relative to the asset root, like every level path.
//!
//! ```ron
//! characters: [(
//!     name: "hero",
//!     model: "common/hero/hero.glb",
//!     scale: 1, model_yaw_deg: 180, spawn: (0, 0, 6),
//!     capsule: (height: 1.8, radius: 0.3),
//!     controller: (walk_speed: 2, run_speed: 5),
//!     states: [
//!         (name: "idle", clip: "idle", contact: Grounded, max_speed_mps: 0.2),
//!         (name: "walk", clip: "walk", contact: Grounded, min_speed_mps: 0.2,
//!          max_speed_mps: 3.5, reference_speed_mps: 1.45),
//!     ],
//! )]
//! ```

use serde::{Deserialize, Serialize};

use super::clip_desc::PlayMode;

/// Where the character must be for an animation state to be chosen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Contact {
    /// Anywhere.
    #[default]
    Any,
    /// On the ground.
    Grounded,
    /// In the air (rising or falling).
    Airborne,
    /// In the air, moving up (a jump's first half).
    Rising,
    /// In the air, not moving up.
    Falling,
}

/// A skinned character the level spawns: a glTF file with one skinned mesh, a capsule body
/// moved by the character controller, and its animation states.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CharacterEntry {
    /// Game code finds the character by this name (`SpawnedLevel::characters`).
    pub name: String,
    /// The glTF file (`.gltf` or `.glb`), relative to the asset root.
    pub model: String,
    /// Uniform scale of the model (1 for the hero, which is in metres; a model in centimetres
    /// takes 0.01).
    #[serde(default = "one")]
    pub scale: f32,
    /// Turns the model about +Y so that it faces −Z, the engine's forward (glTF characters
    /// usually face +Z: 180), degrees.
    #[serde(default)]
    pub model_yaw_deg: f32,
    /// Where the character's feet stand at the start, metres.
    pub spawn: [f32; 3],
    /// The way it faces at the start, degrees about +Y from −Z (90 faces −X).
    #[serde(default)]
    pub yaw_deg: f32,
    #[serde(default)]
    pub capsule: CapsuleEntry,
    #[serde(default)]
    pub controller: ControllerEntry,
    /// The animation states, in the order they are tried.
    pub states: Vec<AnimStateEntry>,
    /// The current state stays while the speed is within this much of its range, m/s.
    #[serde(default = "default_hysteresis")]
    pub hysteresis_mps: f32,
}

/// The character's collision capsule.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CapsuleEntry {
    /// Feet to head, metres.
    pub height: f32,
    /// Metres; at most half the height.
    pub radius: f32,
}

impl Default for CapsuleEntry {
    fn default() -> Self {
        Self {
            height: 1.8,
            radius: 0.3,
        }
    }
}

/// Controller tuning; an absent field keeps the engine's default
/// (`sim::physics::CharacterController::default()`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ControllerEntry {
    /// m/s.
    pub walk_speed: Option<f32>,
    /// m/s.
    pub run_speed: Option<f32>,
    /// Upward speed at take-off, m/s.
    pub jump_speed: Option<f32>,
    /// m/s².
    pub gravity: Option<f32>,
    /// Metres.
    pub max_step_height: Option<f32>,
    /// Degrees.
    pub max_slope_deg: Option<f32>,
}

/// One animation state: the clip it plays and when it is chosen.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnimStateEntry {
    pub name: String,
    /// A clip of the model, by name (or index in decimal).
    pub clip: String,
    #[serde(default = "default_mode")]
    pub mode: PlayMode,
    #[serde(default)]
    pub contact: Contact,
    /// Lowest ground speed for the state, m/s.
    #[serde(default)]
    pub min_speed_mps: f32,
    /// Ground speed the state stops at, m/s; absent: no limit.
    #[serde(default)]
    pub max_speed_mps: Option<f32>,
    /// Ground speed at which the clip plays at its own rate, m/s; absent: always rate 1.
    #[serde(default)]
    pub reference_speed_mps: Option<f32>,
    #[serde(default = "default_min_rate")]
    pub min_rate: f32,
    #[serde(default = "default_max_rate")]
    pub max_rate: f32,
    /// Crossfade into this state, seconds.
    #[serde(default = "default_fade")]
    pub fade_seconds: f64,
    /// A second clip blended in by ground speed, phase-synchronised (a walk state that turns
    /// into a run without a crossfade); absent: the state's clip alone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub blend: Option<BlendEntry>,
}

/// A clip blended into a state by speed: weight 0 at `from_speed_mps`, rising linearly to 1
/// at `to_speed_mps`.
///
/// ```ron
/// (name: "move", clip: "walk", contact: Grounded, min_speed_mps: 0.3,
///  reference_speed_mps: 1.45,
///  blend: (clip: "run", reference_speed_mps: 3.35, from_speed_mps: 2, to_speed_mps: 4.5)),
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlendEntry {
    /// A clip of the model, by name (or index in decimal).
    pub clip: String,
    /// Ground speed at which that clip plays at its own rate, m/s.
    pub reference_speed_mps: f32,
    /// m/s.
    pub from_speed_mps: f32,
    /// m/s.
    pub to_speed_mps: f32,
}

fn one() -> f32 {
    1.0
}
fn default_hysteresis() -> f32 {
    0.2
}
fn default_mode() -> PlayMode {
    PlayMode::Loop
}
fn default_min_rate() -> f32 {
    0.5
}
fn default_max_rate() -> f32 {
    2.0
}
fn default_fade() -> f64 {
    0.25
}
