//! Steering a first-person player the way a person at the keyboard would, for the scripted
//! bots that record the games' committed replays: turn towards a yaw and pitch with capped
//! mouse motion, walk forward once facing the target. Only input comes out (mouse counts and
//! the forward key), so a recording made this way is what a player pressing those keys makes.
//!
//! Owns: [`yaw_to`], [`pitch_to`], [`Steer`], [`aim`] and [`walk_to`]. Main thread, between
//! frames. Must not: move the player itself. Units: metres, radians, mouse counts.

use glam::{Vec2, Vec3};

use super::player_input::MOUSE_RADIANS_PER_COUNT;
use crate::player::FirstPersonPlayer;

/// Most mouse counts per step (about 6° a step).
pub const MAX_COUNTS: f32 = 60.0;

/// Wraps an angle to (−π, π].
fn wrap(a: f32) -> f32 {
    (a + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI
}

/// Yaw that looks from `from` towards `to` horizontally (0 looks along −Z).
pub fn yaw_to(from: Vec3, to: Vec3) -> f32 {
    let d = to - from;
    (-d.x).atan2(-d.z)
}

/// Pitch that looks from `eye` at `to` (positive up).
pub fn pitch_to(eye: Vec3, to: Vec3) -> f32 {
    (to.y - eye.y).atan2((to - eye).with_y(0.0).length())
}

/// A step's steering: the forward key and the mouse motion.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Steer {
    pub forward: bool,
    pub mouse: Vec2,
}

/// Turns towards `yaw` and `pitch` (mouse counts, capped at [`MAX_COUNTS`]); returns the
/// remaining yaw and pitch errors.
pub fn aim(player: &FirstPersonPlayer, yaw: f32, pitch: f32, steer: &mut Steer) -> (f32, f32) {
    let dy = wrap(yaw - player.yaw);
    let dp = pitch - player.pitch;
    // Yaw grows with −mouse x, pitch with −mouse y (look y positive down).
    steer.mouse = (Vec2::new(-dy, -dp) / MOUSE_RADIANS_PER_COUNT)
        .clamp(Vec2::splat(-MAX_COUNTS), Vec2::splat(MAX_COUNTS));
    (dy.abs(), dp.abs())
}

/// Walks towards `target` (x, z) looking at `pitch`, forward only once facing it; true once
/// within `within` metres (then it only holds the view).
pub fn walk_to(
    player: &FirstPersonPlayer,
    feet: Vec3,
    target: Vec2,
    pitch: f32,
    within: f32,
    steer: &mut Steer,
) -> bool {
    let to = Vec3::new(target.x, feet.y, target.y);
    if (to - feet).with_y(0.0).length() <= within {
        aim(player, player.yaw, pitch, steer);
        return true;
    }
    let (dy, _) = aim(player, yaw_to(feet, to), pitch, steer);
    steer.forward = dy < 0.15;
    false
}
