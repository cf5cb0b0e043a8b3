//! [`ItemRef`]: one item of a level by its kind (the list it is in) and its index there — what
//! a [`super::LevelProblem`] names, and what the editor's outliner and problems panel select.
//!
//! Any thread (plain data). Must not: hold references into the level (indices only, checked on
//! use).

use std::fmt;

/// An item of a [`crate::assets::Level`] by position in its list (`gameplay.rules[2]` is
/// `Rule(2)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ItemRef {
    /// The level as a whole (the camera, the models' names, a problem of no single item).
    Level,
    Model(usize),
    Material(usize),
    /// An engine-made model: grids, boxes, terrains and cities share the model namespace.
    Grid(usize),
    Box(usize),
    Instance(usize),
    Camera,
    Sound(usize),
    Music,
    Emitter(usize),
    Clip(usize),
    Autoplay(usize),
    LightsOff(usize),
    Volume(usize),
    Laser(usize),
    Rule(usize),
    Usable(usize),
    /// A name in `gameplay.events`.
    Event(usize),
    Counter(usize),
    Breakable(usize),
}

impl ItemRef {
    /// Whether the item is in the level's `gameplay` section.
    pub fn is_gameplay(self) -> bool {
        !matches!(
            self,
            ItemRef::Level
                | ItemRef::Model(_)
                | ItemRef::Material(_)
                | ItemRef::Grid(_)
                | ItemRef::Box(_)
                | ItemRef::Instance(_)
                | ItemRef::Camera
        )
    }
}

impl fmt::Display for ItemRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ItemRef::Level => write!(f, "level"),
            ItemRef::Model(i) => write!(f, "models[{i}]"),
            ItemRef::Material(i) => write!(f, "materials[{i}]"),
            ItemRef::Grid(i) => write!(f, "grids[{i}]"),
            ItemRef::Box(i) => write!(f, "boxes[{i}]"),
            ItemRef::Instance(i) => write!(f, "instances[{i}]"),
            ItemRef::Camera => write!(f, "camera"),
            ItemRef::Sound(i) => write!(f, "gameplay.sounds[{i}]"),
            ItemRef::Music => write!(f, "gameplay.music"),
            ItemRef::Emitter(i) => write!(f, "gameplay.emitters[{i}]"),
            ItemRef::Clip(i) => write!(f, "gameplay.animations[{i}]"),
            ItemRef::Autoplay(i) => write!(f, "gameplay.autoplay[{i}]"),
            ItemRef::LightsOff(i) => write!(f, "gameplay.lights_off[{i}]"),
            ItemRef::Volume(i) => write!(f, "gameplay.volumes[{i}]"),
            ItemRef::Laser(i) => write!(f, "gameplay.lasers[{i}]"),
            ItemRef::Rule(i) => write!(f, "gameplay.rules[{i}]"),
            ItemRef::Usable(i) => write!(f, "gameplay.usables[{i}]"),
            ItemRef::Event(i) => write!(f, "gameplay.events[{i}]"),
            ItemRef::Counter(i) => write!(f, "gameplay.counters[{i}]"),
            ItemRef::Breakable(i) => write!(f, "gameplay.breakables[{i}]"),
        }
    }
}
