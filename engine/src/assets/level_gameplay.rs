//! Gameplay in a level file: sounds, music, spatial emitters, animation clips that move named
//! instances (doors, lifts, platforms), light groups switched off at the start, trigger volumes,
//! laser beams, and the rules that turn what happens in volumes into actions.
//!
//! Owns: the serde types of the level's `gameplay` section. Checking the names they use is
//! `level::validate_level` (resolving them, `level/gameplay_plan.rs`); running them is
//! `sim::triggers`. Must not: load files or spawn anything.
//!
//! Names refer to other items: instances by their `name`, level materials, sounds, clips and
//! volumes by theirs. Units: seconds, metres, linear amplitude (volume 1 = as recorded).
//!
//! ```ron
//! gameplay: (
//!     sounds: [(name: "chime", path: "common/sounds/chime.wav")],
//!     animations: [(name: "door_open", tracks: [(target: "door", property: Translation,
//!         interpolation: Linear, keys: [(time_seconds: 0, value: [0, 0, 0]),
//!                                       (time_seconds: 1.2, value: [1.6, 0, 0])])])],
//!     lights_off: [2],
//!     volumes: [(name: "plate", instance: "plate_sensor")],
//!     usables: [(instance: "switch", prompt: "Press E to pull the lever", event: "lever")],
//!     events: ["lever"],
//!     counters: [(name: "pulls")],
//!     rules: [(name: "open", when: Occupied("plate"),
//!              then: [Play(clip: "door_open"), Lights(group: 2, on: true), Sound(sound: "chime")],
//!              otherwise: [Reverse(clip: "door_open")]),
//!             (name: "pulled", when: Event("lever"), then: [Count(counter: "pulls")]),
//!             (name: "third_pull", when: Counter(counter: "pulls", at_least: Some(3)),
//!              then: [Win])],
//! )
//! ```

use serde::{Deserialize, Serialize};

use super::clip_desc::{AuthoredClip, PlayMode};

/// The `gameplay` section of a level. Everything is optional.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GameplayEntry {
    /// Sound files (WAV or OGG, relative to the asset root), each under a name.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub sounds: Vec<SoundEntry>,
    /// Music that starts with the level.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub music: Option<MusicEntry>,
    /// Looping spatial sounds attached to instances (a humming lamp, a waterfall).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub emitters: Vec<EmitterEntry>,
    /// Clips whose track targets are instance names. A track's value is relative to where the
    /// level places the instance: translation is added (metres, world axes), rotation turns
    /// the instance about its own origin (world axes), scale multiplies.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub animations: Vec<AuthoredClip>,
    /// Clips that play from the start (a lift that cycles on its own).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub autoplay: Vec<AutoplayEntry>,
    /// Light groups (`InstanceEntry::light_group`) that start switched off.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub lights_off: Vec<u32>,
    /// Trigger volumes.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub volumes: Vec<VolumeEntry>,
    /// Laser beams, traced every step by ray queries; volumes that detect lasers see them.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub lasers: Vec<LaserEntry>,
    /// Rules, evaluated in this order every fixed step.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rules: Vec<RuleEntry>,
    /// Events the game sends to the rules (a "use" on a switch: `Commands::send_event`), so
    /// that `Event(name)` conditions may wait for them as for clip events.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub events: Vec<String>,
    /// Instances the player can use (a switch, a lever): looking at one shows its prompt, the
    /// use action sends its event to the rules (the event must be declared in `events`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub usables: Vec<UsableEntry>,
    /// Whole-number counters the rules keep (`Count`, `SetCounter` actions; `Counter`
    /// conditions): weights on a scale, offerings made, torches lit.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub counters: Vec<CounterEntry>,
    /// Walls and pillars of pre-fractured pieces (`level_breakable.rs`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub breakables: Vec<super::BreakableEntry>,
}

/// A counter of the rules: `(name: "weights", start: 0)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CounterEntry {
    pub name: String,
    /// Its value when the level starts.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub start: i32,
}

fn is_zero(v: &i32) -> bool {
    *v == 0
}

impl GameplayEntry {
    /// Whether the section declares nothing.
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }
}

/// A sound file under a name.
/// `(instance: "switch", prompt: "Press E to pull the lever", event: "lever")`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UsableEntry {
    /// The instance's `name`.
    pub instance: String,
    /// What the HUD shows while the player looks at it.
    pub prompt: String,
    /// Sent to the rules (`Event(name)`) when the player uses it.
    pub event: String,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SoundEntry {
    pub name: String,
    /// Relative to the asset root.
    pub path: String,
}

/// The level's music.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MusicEntry {
    /// Name of a [`SoundEntry`].
    pub sound: String,
    /// Linear amplitude, 0..=1.
    #[serde(default = "one")]
    pub volume: f32,
}

/// A sound that loops at an instance's position.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EmitterEntry {
    /// Name of the instance it sits on (it follows the instance when it moves).
    pub instance: String,
    /// Name of a [`SoundEntry`].
    pub sound: String,
    /// Linear amplitude, 0..=1.
    #[serde(default = "one")]
    pub volume: f32,
}

fn one() -> f32 {
    1.0
}

/// A clip that starts playing with the level.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AutoplayEntry {
    pub clip: String,
    #[serde(default = "loop_mode")]
    pub mode: PlayMode,
}

fn loop_mode() -> PlayMode {
    PlayMode::Loop
}

/// What a volume notices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Detect {
    /// Characters (entities with a character controller).
    Player,
    /// Dynamic rigid bodies (crates, glass cubes).
    Bodies,
    /// Laser beams passing through the volume.
    Lasers,
}

/// A trigger volume: the shape of an instance whose body is a `Sensor`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VolumeEntry {
    pub name: String,
    /// Name of an instance with `body: Sensor(..)`.
    pub instance: String,
    /// What it notices; all three by default.
    #[serde(default = "all_detect")]
    pub detects: Vec<Detect>,
}

fn all_detect() -> Vec<Detect> {
    vec![Detect::Player, Detect::Bodies, Detect::Lasers]
}

/// A laser beam leaving an instance. It reflects off mirrors (smooth conductors), refracts
/// through glass and stops at anything else.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LaserEntry {
    /// Name of the instance it leaves (it follows the instance).
    pub instance: String,
    /// Start, metres, in the instance's model space.
    #[serde(default)]
    pub origin: [f32; 3],
    /// Direction in the instance's model space (need not be unit length).
    pub direction: [f32; 3],
    /// Most surfaces the beam changes direction at.
    #[serde(default = "default_reflections")]
    pub max_reflections: u32,
    /// Total beam length, metres.
    #[serde(default = "default_laser_length")]
    pub max_length: f32,
    /// How the beam looks: each straight piece drawn as a thin emissive prism that lights
    /// what it passes (on unless `beam: None`).
    #[serde(default = "default_beam")]
    pub beam: Option<BeamEntry>,
}

/// The visible beam of a laser: each straight piece of its path becomes a thin emissive square
/// prism, updated every fixed step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeamEntry {
    /// Linear RGB colour of the emission (multiplied by `strength`).
    #[serde(default = "default_beam_color")]
    pub color: [f32; 3],
    /// Emitted radiance scale, W·sr⁻¹·m⁻² per unit of `color`.
    #[serde(default = "default_beam_strength")]
    pub strength: f32,
    /// Half the prism's width, metres.
    #[serde(default = "default_beam_radius")]
    pub radius: f32,
    /// The light group the beam's emitters belong to (switching it off hides the beam's
    /// light); default: the laser instance's own group, if it has one.
    #[serde(default)]
    pub light_group: Option<u32>,
}

impl Default for BeamEntry {
    fn default() -> Self {
        Self {
            color: default_beam_color(),
            strength: default_beam_strength(),
            radius: default_beam_radius(),
            light_group: None,
        }
    }
}

fn default_beam() -> Option<BeamEntry> {
    Some(BeamEntry::default())
}

fn default_beam_color() -> [f32; 3] {
    [1.0, 0.08, 0.04]
}

fn default_beam_strength() -> f32 {
    40.0
}

fn default_beam_radius() -> f32 {
    0.005
}

fn default_reflections() -> u32 {
    16
}

fn default_laser_length() -> f32 {
    200.0
}

/// A rule: when its condition becomes true, `then` runs; when it becomes false again,
/// `otherwise` runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RuleEntry {
    pub name: String,
    pub when: ConditionEntry,
    #[serde(default)]
    pub then: Vec<ActionEntry>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub otherwise: Vec<ActionEntry>,
    /// Fire `then` at most once.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub once: bool,
}

/// A condition, true or false at each fixed step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ConditionEntry {
    /// Something the volume detects is inside it (true while it stays).
    Occupied(String),
    /// Something entered the volume during this step.
    Entered(String),
    /// Something left the volume during this step.
    Exited(String),
    /// At least `at_least` things are inside the volume.
    Occupants {
        volume: String,
        at_least: u32,
    },
    /// A clip event with this name fired during this step.
    Event(String),
    /// Every condition holds.
    All(Vec<ConditionEntry>),
    /// Any condition holds.
    Any(Vec<ConditionEntry>),
    Not(Box<ConditionEntry>),
    /// At least `at_least` of the conditions hold (a door that needs two of three plates).
    AtLeast {
        at_least: u32,
        of: Vec<ConditionEntry>,
    },
    /// The condition has become true at least `at_least` times since the level started
    /// (three artefacts collected).
    Times {
        at_least: u32,
        of: Box<ConditionEntry>,
    },
    /// Light group `group` is on (rules, the game or the level's `lights_off` switch it).
    LightsOn(u32),
    /// The named volume's centre sees the sun: a query ray from it towards the sun (on the
    /// last commit's BVH, the one the picture is traced on) meets nothing but the volume's own
    /// instance. False in a level without a sun.
    SunLit(String),
    /// The sun's centre stands between `at_least` and `at_most` degrees above the horizon
    /// (a bound left out is open; at least one must be given): `SunElevation(at_most:
    /// Some(-6.0))` holds after civil dusk, a night shrine's torches. False in a level
    /// without a sun (a `sun`, or a physical sky that places one).
    SunElevation {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        at_least: Option<f32>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        at_most: Option<f32>,
    },
    /// The named rule has run its `then` at least once since the level started (earlier
    /// rules in level order count in the same step).
    Fired(String),
    /// The counter's value lies in `[at_least, at_most]` (a bound left out is open; at least
    /// one must be given).
    Counter {
        counter: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        at_least: Option<i32>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        at_most: Option<i32>,
    },
    /// The steps became true in this order: each step's rising edge advances the sequence
    /// when it is the next one, and any other step's rising edge is a wrong step, which
    /// resets it (to the first step done, if the wrong step is the first). True from the
    /// step the last one rises, and stays true (a shrine's braziers lit in order).
    Sequence(Vec<ConditionEntry>),
}

/// Something a rule does.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ActionEntry {
    /// Switch a light group on or off: a group that is off leaves the light sampling
    /// distribution.
    Lights { group: u32, on: bool },
    /// Switch a light group to its other state.
    ToggleLights(u32),
    /// Play a clip forward from where its playhead is (the start, the first time).
    Play {
        clip: String,
        #[serde(default = "once_mode")]
        mode: PlayMode,
    },
    /// Play a clip backward from where its playhead is (a door closing).
    Reverse { clip: String },
    /// Stop a clip where it is.
    Pause { clip: String },
    /// Play a sound once: at an instance's position, or everywhere (`at` left out).
    Sound {
        sound: String,
        #[serde(default)]
        at: Option<String>,
        #[serde(default = "one")]
        volume: f32,
    },
    /// Give an instance a level material, or its model's own materials back (`None`).
    Material {
        instance: String,
        material: Option<String>,
    },
    /// Add `add` (negative: take away) to a counter; later rules in the same step see the
    /// new value. Saturates at the `i32` bounds.
    Count {
        counter: String,
        #[serde(default = "one_count")]
        add: i32,
    },
    /// Set a counter to `value`.
    SetCounter { counter: String, value: i32 },
    /// Break a breakable (by name) now: its pieces fall free.
    Break(String),
    /// The player wins the level.
    Win,
    /// The player loses the level.
    Lose,
}

fn one_count() -> i32 {
    1
}

fn once_mode() -> PlayMode {
    PlayMode::Once
}
