//! Reflect's mirror gun in play: arming it with the panels of the world as spawned (at setup
//! and after the editor respawned the level), firing it from the step's actions, and the
//! carried cube that turns with the player.
//!
//! Main thread, inside the engine's hooks. Must not: read devices or reach into the renderer.

use candela::app::{FirstPersonGame, Step, player_input};
use candela::ecs::{Renderable, Transform};
use hecs::Entity;

use super::{ReflectEvent, ReflectGame};
use crate::mirror_gun::{GunShot, MirrorGun};

impl ReflectGame {
    /// Aims the gun where the player looks and, on a fresh press, fires it.
    pub(super) fn mirror_gun(&mut self, step: &mut Step<'_>, held_before: bool) {
        let Some(player) = self.inner.player() else {
            return;
        };
        let (eye, view) = (player.eye(step.world), player.view());
        self.aimed = self.gun.aimed(step.world, &step.queries, eye, view);
        if held_before {
            return;
        }
        let input = player_input(
            step.actions,
            step.action_set,
            step.settings,
            step.step_seconds,
        );
        let mirror = match (input.primary_pressed, input.secondary_pressed) {
            (true, _) => true,
            (false, true) => false,
            _ => return,
        };
        let chambers = &self.world.chambers;
        let shot = self
            .gun
            .shoot(step.world, self.aimed, mirror, |c| chambers[c].mirror_cap);
        let event = match shot {
            GunShot::Mirrored(_) => "mirror_on",
            GunShot::Reverted(_) => "mirror_off",
            GunShot::AtCap => "mirror_refused",
            GunShot::Nothing => return,
        };
        step.commands.send_event(event);
        if shot == GunShot::AtCap {
            let text = super::feedback::NO_MIRRORS_LEFT;
            self.feedback.notice(step.index, text, None, step.commands);
        }
        self.note(step.index, ReflectEvent::Shot(shot));
    }

    /// Arms the gun with the panels of the world as spawned (at setup, and after the editor
    /// spawned the level again): every instance of a mirrorable model, so that instances the
    /// editor inserted, removed or duplicated are counted right.
    pub(super) fn arm_gun(&mut self, engine: &candela::app::Engine) {
        let world = engine.world();
        let spawned = self.inner.spawned();
        let models: Vec<_> = self
            .world
            .mirrorable_models
            .iter()
            .filter_map(|&k| spawned.models.get(k).copied())
            .collect();
        let panels: Vec<(Entity, Option<usize>, Option<u32>)> = spawned
            .entities
            .iter()
            .copied()
            .filter_map(|e| {
                let r = world.get::<&Renderable>(e).ok()?;
                models
                    .contains(&r.model)
                    .then_some((e, r.material_override))
            })
            .map(|(e, original)| {
                let at = world
                    .get::<&Transform>(e)
                    .map_or(glam::Vec3::NAN, |t| t.translation);
                let chamber = self.world.chambers.iter().position(|c| c.contains(at));
                (e, chamber, original)
            })
            .collect();
        self.gun = MirrorGun::new(panels, self.world.mirror_material);
    }
}

/// A carried cube turns with the player, corner first: its yaw is the player's plus 45°, so
/// that setting it down facing a beam squarely puts a corner towards it (the glass chamber).
pub(super) fn turn_held_cube(step: &mut Step<'_>, inner: &FirstPersonGame) {
    let Some(player) = inner.player() else {
        return;
    };
    if let Some(held) = player.held(step.world)
        && let Some((at, _)) = step.physics.pose(held)
    {
        let yaw = player.yaw + std::f32::consts::FRAC_PI_4;
        step.physics
            .set_pose(held, at, glam::Quat::from_rotation_y(yaw));
    }
}
