//! The third-person character controller: the stick moves the character relative to where the
//! camera looks (forward is away from the camera), the character turns smoothly to face its
//! motion, runs while run is held and jumps.
//!
//! Owns: [`ThirdPersonController`] (tuning) and the per-step drive of a level character's
//! body: it writes the body's `CharacterInput` (the physics controller moves the capsule in
//! the same step) and its `CharacterAnimation::heading_rad` (the drawn model turns with it).
//! Main thread, in the game's fixed step, before physics.
//! Must not: move the body itself, read devices, or place the camera (`follow_camera`).
//! Units: radians, seconds; yaw 0 faces −Z, positive turns right (towards +X).

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};
use hecs::{Entity, World};

use super::input::PlayerInput;
use crate::sim::animation::{CharacterAnimation, heading_direction};
use crate::sim::physics::CharacterInput;

/// How the third-person character responds to input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThirdPersonController {
    /// Fastest turn towards the motion, radians per second.
    pub turn_rate_rad_per_s: f32,
    /// Stick deflection below which the character does not turn, in [0, 1).
    pub turn_dead_zone: f32,
}

impl Default for ThirdPersonController {
    fn default() -> Self {
        Self {
            // Half a turn in 0.3 s: quick, but a reversal is still seen as a turn.
            turn_rate_rad_per_s: 10.0,
            turn_dead_zone: 0.1,
        }
    }
}

impl ThirdPersonController {
    /// One fixed step of `dt_seconds` for the character whose body is `body`, with the camera
    /// looking along `camera_yaw_rad`. Returns the world-space move direction it asked for
    /// (length ≤ 1), or `None` when `body` is not a character.
    pub fn drive(
        &self,
        world: &mut World,
        body: Entity,
        input: &PlayerInput,
        camera_yaw_rad: f32,
        dt_seconds: f32,
    ) -> Option<Vec3> {
        let direction = camera_relative_move(input.move_axes, camera_yaw_rad);
        {
            let mut character = world.get::<&mut CharacterInput>(body).ok()?;
            character.move_direction = direction;
            character.run = input.run;
            character.jump = input.jump;
        }
        if let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body)
            && direction.length() > self.turn_dead_zone
        {
            let target = direction.x.atan2(-direction.z);
            let max_turn = self.turn_rate_rad_per_s * dt_seconds.max(0.0);
            anim.heading_rad = turn_towards(anim.heading_rad, target, max_turn);
        }
        Some(direction)
    }
}

/// The world-space horizontal direction for stick `axes` (x right, y forward) with the camera
/// looking along `camera_yaw_rad`; its length is the stick's, at most 1.
pub fn camera_relative_move(axes: Vec2, camera_yaw_rad: f32) -> Vec3 {
    let axes = if axes.is_finite() {
        axes.clamp_length_max(1.0)
    } else {
        Vec2::ZERO
    };
    let forward = heading_direction(camera_yaw_rad);
    let right = Vec3::new(-forward.z, 0.0, forward.x);
    right * axes.x + forward * axes.y
}

/// `from` turned towards `to` (radians) the short way round by at most `max_step`; the result
/// is wrapped to (−π, π].
pub fn turn_towards(from: f32, to: f32, max_step: f32) -> f32 {
    let mut delta = (to - from).rem_euclid(TAU);
    if delta > PI {
        delta -= TAU;
    }
    let turned = from + delta.clamp(-max_step, max_step);
    let wrapped = (turned + PI).rem_euclid(TAU) - PI;
    if wrapped == -PI { PI } else { wrapped }
}
