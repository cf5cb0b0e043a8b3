//! [`PlayerInput`]: what one player asks for in one fixed step, in game terms (move, look,
//! jump, run), whatever device or replay it came from.
//!
//! Owns: the type only. Main thread. Must not: read devices (game code fills it from the
//! step's `app::ActionFrame`, which replays reproduce exactly).
//! Units: move axes in [−1, 1]; look in radians for the step.

use glam::Vec2;

/// One player's input for one fixed step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlayerInput {
    /// x: right, y: forward, each in [−1, 1] (a stick, or WASD as ±1).
    pub move_axes: Vec2,
    /// Look motion this step, radians: x turns right (yaw), y looks up (pitch).
    pub look: Vec2,
    /// Jump (held: jumps again on landing).
    pub jump: bool,
    /// Run while held.
    pub run: bool,
}
