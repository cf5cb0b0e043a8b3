//! Input mapped to actions: the devices' state and the key, mouse and pad bindings of a map
//! ([`InputMap`], [`InputState`]), the game's named actions and their default bindings
//! ([`ActionSet`], `game_actions`), one fixed step's input in fixed point ([`ActionFrame`]),
//! gamepads (gilrs, [`Gamepads`]) and the fly camera's action names (`fly_actions`).
//!
//! One file per job: `pad` (pad button and axis names), `map` (bindings, the input map, the
//! per-frame input state, the runner's own actions), `fly_actions`, `action_set`,
//! `action_frame`, `gamepad`. Main thread. Must not: read or write files (`persist` keeps the
//! player's rebinding), know the recording format (`replay`), or know the engine, a game or
//! the window (the window runner feeds the state from winit events).

mod action_frame;
mod action_set;
pub mod fly_actions;
mod gamepad;
mod map;
mod pad;

pub use action_frame::{AXIS_ONE, ActionFrame, MOTION_PER_COUNT, quantise_axis, quantise_motion};
pub use action_set::{
    ActionDef, ActionId, ActionKind, ActionSet, ActionSetError, MAX_ACTIONS, game_actions,
};
pub use gamepad::{DEFAULT_DEAD_ZONE, Gamepads, apply_dead_zone, pad_button};
pub use map::{Binding, InputMap, InputMapError, InputState, KeyCode, MouseButton, actions};
pub use pad::{PadAxis, PadButton};
