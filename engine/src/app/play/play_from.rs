//! "Play from here" for the first-person game: leaving the editor, the player stands on the
//! floor below the editor camera's eye and looks where it looked ([`FirstPersonGame`]'s
//! `EditHooks::play_from`, called by `app::edit::EditMode::play_from_here`).
//!
//! Main thread, between frames (the engine is not stepping). Must not: touch the level (the
//! world is as the editor left it) or the renderer.

use glam::Vec3;
use hecs::Entity;

use super::FirstPersonGame;
use crate::app::runner::Engine;
use crate::sim::physics::PhysicsWorld;

/// How far below the eye a floor is looked for, metres.
pub const FLOOR_SEARCH_METRES: f32 = 200.0;

/// The first surface straight below `eye` (metres) that is not `ignore` (the player's own
/// capsule), within [`FLOOR_SEARCH_METRES`]; `None` over the void.
pub fn floor_below(physics: &PhysicsWorld, eye: Vec3, ignore: Entity) -> Option<Vec3> {
    let mut from = eye;
    let mut left = FLOOR_SEARCH_METRES;
    // A few tries: each hit of the player's own capsule is stepped through.
    for _ in 0..4 {
        let (entity, distance) = physics.cast_ray(from, Vec3::NEG_Y, left)?;
        let hit = from + Vec3::NEG_Y * distance;
        if entity != ignore {
            return Some(hit);
        }
        from = hit + Vec3::NEG_Y * 0.01;
        left -= distance + 0.01;
        if left <= 0.0 {
            return None;
        }
    }
    None
}

impl FirstPersonGame {
    /// Puts the player on the floor below `eye` (metres; over the void, with its eye at
    /// `eye`), facing `forward` (any length; its horizontal part gives the yaw, its slope the
    /// pitch).
    pub fn play_from_view(&mut self, engine: &mut Engine, eye: Vec3, forward: Vec3) {
        let Some(player) = self.player_mut() else {
            return;
        };
        let feet = floor_below(&engine.physics, eye, player.body)
            .unwrap_or(eye - Vec3::Y * player.config.eye_height);
        let flat = forward.with_y(0.0);
        let yaw = if flat.length_squared() > 1e-12 {
            (-flat.x).atan2(-flat.z)
        } else {
            player.yaw
        };
        let pitch = forward.y.atan2(flat.length());
        player.stand_at(&mut engine.world, &mut engine.physics, feet, yaw, pitch);
        engine.cut();
    }
}
