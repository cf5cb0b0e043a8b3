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
    if turned > -PI && turned <= PI {
        return turned;
    }
    let wrapped = (turned + PI).rem_euclid(TAU) - PI;
    if wrapped <= -PI {
        wrapped + TAU
    } else {
        wrapped
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn forward_is_where_the_camera_looks_and_right_is_to_its_right() {
        let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-6;
        assert!(close(camera_relative_move(Vec2::Y, 0.0), Vec3::NEG_Z));
        assert!(close(camera_relative_move(Vec2::X, 0.0), Vec3::X));
        let quarter = std::f32::consts::FRAC_PI_2;
        assert!(close(camera_relative_move(Vec2::Y, quarter), Vec3::X));
        assert!(close(camera_relative_move(Vec2::X, quarter), Vec3::Z));
        let diagonal = camera_relative_move(Vec2::ONE, 0.0);
        assert!((diagonal.length() - 1.0).abs() < 1e-6, "clamped to 1");
        assert_eq!(camera_relative_move(Vec2::NAN, 0.0), Vec3::ZERO);
    }

    #[test]
    fn turning_takes_the_short_way_and_never_overshoots() {
        assert_eq!(turn_towards(0.0, 1.0, 0.25), 0.25);
        assert_eq!(turn_towards(0.0, 0.1, 0.25), 0.1);
        // From 170° to −170° is 20° through 180°, not 340° back through 0.
        let from = 170f32.to_radians();
        let to = -170f32.to_radians();
        let turned = turn_towards(from, to, 0.1);
        assert!((turned - (from + 0.1)).abs() < 1e-6, "{turned}");
        // 170° + 0.3 rad is past 180°: it comes back wrapped, just above −180°.
        let wrapped = turn_towards(from, to, 0.3);
        assert!((wrapped - (from + 0.3 - TAU)).abs() < 1e-5, "{wrapped}");
        let arrived = turn_towards(from, to, 1.0);
        assert!((arrived - to).abs() < 1e-5, "{arrived}");
    }
}
