//! [`PlayerInput`]: what the player asked for in one fixed step, in the units controllers use
//! (no devices, no bindings). `app::player_input` builds it from an `ActionFrame` and the
//! settings (mouse sensitivity, invert Y); tests and bots may fill it directly.
//!
//! Data only. Must not: read devices.

use glam::Vec2;

/// One fixed step of player intent.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlayerInput {
    /// Walk direction in the view's frame: `x` right, `y` forward, each in [−1, 1]; a longer
    /// vector is clamped to length 1.
    pub move_axes: Vec2,
    /// Turn during this step, radians: `x` yaw (positive turns left, counter-clockwise seen
    /// from above, right-handed about +Y), `y` pitch (positive looks up).
    pub look: Vec2,
    /// Jump held (jumps on the ground).
    pub jump: bool,
    /// Run held.
    pub run: bool,
    /// The use action went down this step (use a switch, pick up or drop a body).
    pub use_pressed: bool,
    /// The primary action went down this step (throw the held body).
    pub primary_pressed: bool,
    /// The secondary action went down this step (drop the held body gently).
    pub secondary_pressed: bool,
}
