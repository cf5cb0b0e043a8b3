//! The named actions a game reads: each with a kind (a button, an analog axis, or a motion
//! accumulated per step), its default bindings, and a small stable id for per-step frames and
//! recordings. [`ActionSet::standard`] is the engine's set shared by both games (walk, look,
//! jump, run, use, fire, pause, editor); a game adds its own with [`ActionSet::with`].
//!
//! Owns: action names, kinds, ids and default bindings. Data only; main thread. Must not: hold
//! input state (`map.rs`) or the player's choices (`persist/bindings.rs`, in the settings file).

use std::collections::HashMap;

use serde::{Deserialize, Serialize};

use super::map::{Binding, InputMap, KeyCode, MouseButton};
use super::pad::{PadAxis, PadButton};

/// The engine's standard game action names.
pub mod game_actions {
    pub const MOVE_FORWARD: &str = "move_forward";
    pub const MOVE_BACK: &str = "move_back";
    pub const MOVE_LEFT: &str = "move_left";
    pub const MOVE_RIGHT: &str = "move_right";
    /// Analog strafe, [−1, 1], positive right (left stick).
    pub const MOVE_X: &str = "move_x";
    /// Analog walk, [−1, 1], positive forward (left stick).
    pub const MOVE_Y: &str = "move_y";
    /// Mouse look, counts per step, positive right.
    pub const LOOK_X: &str = "look_x";
    /// Mouse look, counts per step, positive **down** (invert-Y is the controller's business).
    pub const LOOK_Y: &str = "look_y";
    /// Stick look rate, [−1, 1], positive right (right stick).
    pub const LOOK_PAD_X: &str = "look_pad_x";
    /// Stick look rate, [−1, 1], positive up (right stick).
    pub const LOOK_PAD_Y: &str = "look_pad_y";
    pub const JUMP: &str = "jump";
    pub const RUN: &str = "run";
    pub const USE: &str = "use";
    pub const PRIMARY_FIRE: &str = "primary_fire";
    pub const SECONDARY_FIRE: &str = "secondary_fire";
    pub const PAUSE: &str = "pause";
    pub const EDITOR_TOGGLE: &str = "editor_toggle";
}

/// What an action reports per fixed step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ActionKind {
    /// Held or not, and whether it went down this step (keys, mouse and gamepad buttons).
    Button,
    /// A value in [−1, 1] sampled at the step (gamepad sticks).
    Axis,
    /// Motion summed over the step (mouse counts, wheel lines).
    Motion,
}

impl ActionKind {
    /// Whether `binding` can drive an action of this kind.
    pub fn accepts(self, binding: &Binding) -> bool {
        match self {
            ActionKind::Button => matches!(
                binding,
                Binding::Key(_) | Binding::Mouse(_) | Binding::Pad(_)
            ),
            ActionKind::Axis => matches!(binding, Binding::PadAxis(_)),
            ActionKind::Motion => {
                matches!(binding, Binding::MouseX | Binding::MouseY | Binding::Wheel)
            }
        }
    }

    /// Lower-case name for messages and the recording header.
    pub fn name(self) -> &'static str {
        match self {
            ActionKind::Button => "button",
            ActionKind::Axis => "axis",
            ActionKind::Motion => "motion",
        }
    }
}

/// One action: its name, kind and default bindings.
#[derive(Clone, Debug, PartialEq)]
pub struct ActionDef {
    pub name: String,
    pub kind: ActionKind,
    pub defaults: Vec<Binding>,
}

/// An action's index in its [`ActionSet`] (stable while the set is: games append, never reorder,
/// though recordings store names and are remapped, so reordering only costs a remap).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ActionId(pub u8);

/// Errors of building an action set.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum ActionSetError {
    #[error("action `{0}` is declared twice")]
    Duplicate(String),
    #[error("action name {0:?} must be non-empty lower-case letters, digits and '_'")]
    BadName(String),
    #[error("more than {max} actions (per-step frames keep buttons in a 64-bit set)")]
    TooMany { max: usize },
    #[error(
        "action `{action}` takes {kind} input; its default binding {binding:?} cannot drive it"
    )]
    WrongKind {
        action: String,
        kind: &'static str,
        binding: Binding,
    },
}

/// The actions of a game, in id order.
#[derive(Clone, Debug, PartialEq)]
pub struct ActionSet {
    defs: Vec<ActionDef>,
    by_name: HashMap<String, ActionId>,
}

/// Most actions in one set (the button bitset of an action frame is a `u64`).
pub const MAX_ACTIONS: usize = 64;

fn good_name(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

impl ActionSet {
    /// A set of `defs`, ids in their order.
    pub fn new(defs: Vec<ActionDef>) -> Result<Self, ActionSetError> {
        let mut set = ActionSet {
            defs: Vec::new(),
            by_name: HashMap::new(),
        };
        for def in defs {
            set = set.with(def)?;
        }
        Ok(set)
    }

    /// This set with `def` appended (the next id).
    pub fn with(mut self, def: ActionDef) -> Result<Self, ActionSetError> {
        if !good_name(&def.name) {
            return Err(ActionSetError::BadName(def.name));
        }
        if self.by_name.contains_key(&def.name) {
            return Err(ActionSetError::Duplicate(def.name));
        }
        if self.defs.len() >= MAX_ACTIONS {
            return Err(ActionSetError::TooMany { max: MAX_ACTIONS });
        }
        if let Some(b) = def.defaults.iter().find(|b| !def.kind.accepts(b)) {
            return Err(ActionSetError::WrongKind {
                action: def.name,
                kind: def.kind.name(),
                binding: *b,
            });
        }
        let id = ActionId(self.defs.len() as u8);
        self.by_name.insert(def.name.clone(), id);
        self.defs.push(def);
        Ok(self)
    }

    /// The engine's standard actions with keyboard + mouse and gamepad defaults: WASD/arrows
    /// and the left stick to move, the mouse and the right stick to look, Space/South to jump,
    /// Shift/left stick click to run, E/West to use, mouse buttons/triggers to fire,
    /// Escape/Start to pause, F1 for the editor.
    pub fn standard() -> Self {
        use ActionKind::*;
        use Binding::{Key, Mouse, MouseX, MouseY, Pad};
        use game_actions as a;
        let axis = |ax| Binding::PadAxis(ax);
        let table: Vec<(&str, ActionKind, Vec<Binding>)> = vec![
            (
                a::MOVE_FORWARD,
                Button,
                vec![Key(KeyCode::KeyW), Key(KeyCode::ArrowUp)],
            ),
            (
                a::MOVE_BACK,
                Button,
                vec![Key(KeyCode::KeyS), Key(KeyCode::ArrowDown)],
            ),
            (
                a::MOVE_LEFT,
                Button,
                vec![Key(KeyCode::KeyA), Key(KeyCode::ArrowLeft)],
            ),
            (
                a::MOVE_RIGHT,
                Button,
                vec![Key(KeyCode::KeyD), Key(KeyCode::ArrowRight)],
            ),
            (a::MOVE_X, Axis, vec![axis(PadAxis::LeftStickX)]),
            (a::MOVE_Y, Axis, vec![axis(PadAxis::LeftStickY)]),
            (a::LOOK_X, Motion, vec![MouseX]),
            (a::LOOK_Y, Motion, vec![MouseY]),
            (a::LOOK_PAD_X, Axis, vec![axis(PadAxis::RightStickX)]),
            (a::LOOK_PAD_Y, Axis, vec![axis(PadAxis::RightStickY)]),
            (
                a::JUMP,
                Button,
                vec![Key(KeyCode::Space), Pad(PadButton::South)],
            ),
            (
                a::RUN,
                Button,
                vec![Key(KeyCode::ShiftLeft), Pad(PadButton::LeftThumb)],
            ),
            (
                a::USE,
                Button,
                vec![Key(KeyCode::KeyE), Pad(PadButton::West)],
            ),
            (
                a::PRIMARY_FIRE,
                Button,
                vec![Mouse(MouseButton::Left), Pad(PadButton::RightTrigger2)],
            ),
            (
                a::SECONDARY_FIRE,
                Button,
                vec![Mouse(MouseButton::Right), Pad(PadButton::LeftTrigger2)],
            ),
            (
                a::PAUSE,
                Button,
                vec![Key(KeyCode::Escape), Pad(PadButton::Start)],
            ),
            (a::EDITOR_TOGGLE, Button, vec![Key(KeyCode::F1)]),
        ];
        let defs = table
            .into_iter()
            .map(|(name, kind, defaults)| ActionDef {
                name: name.to_string(),
                kind,
                defaults,
            })
            .collect();
        // The table above is fixed and checked by a test; a failure here is a broken invariant.
        Self::new(defs).expect("the standard action table is valid")
    }

    /// The id of `name`.
    pub fn id(&self, name: &str) -> Option<ActionId> {
        self.by_name.get(name).copied()
    }

    /// The action of `id` (`None` for an id from another set).
    pub fn def(&self, id: ActionId) -> Option<&ActionDef> {
        self.defs.get(id.0 as usize)
    }

    /// All actions, in id order.
    pub fn defs(&self) -> &[ActionDef] {
        &self.defs
    }

    pub fn len(&self) -> usize {
        self.defs.len()
    }

    pub fn is_empty(&self) -> bool {
        self.defs.is_empty()
    }

    /// Every action with its default bindings.
    pub fn default_map(&self) -> InputMap {
        InputMap {
            actions: self
                .defs
                .iter()
                .map(|d| (d.name.clone(), d.defaults.clone()))
                .collect(),
        }
    }
}
