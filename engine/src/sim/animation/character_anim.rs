//! Characters' animation in the world: the link from a character's body (the capsule the
//! controller moves) to the entity that draws its skinned model, the way the character faces,
//! and the state machine that picks its clip from how the body moved in the last physics step.
//!
//! Owns: the [`CharacterAnimation`] component (on the body entity) and [`animate_characters`]
//! (once per fixed step, after physics and before `tick_skinned`): it reads each body's
//! [`CharacterState`], updates the state machine on the visual entity's
//! [`SkinnedAnimator`] player (crossfades, rates) and turns the visual entity to the heading.
//! The visual entity is a child ([`crate::ecs::Parent`]) of the body: its local `Transform`
//! puts the feet at the capsule's bottom and holds the model's scale. Main thread.
//! Must not: move bodies (the controller does) or read input (game rules set the heading).
//! Units: metres, seconds, radians; heading 0 faces −Z, positive turns right (towards +X).

use glam::{Quat, Vec3};
use hecs::{Entity, World};

use super::skinned_entities::SkinnedAnimator;
use super::state_machine::{Locomotion, StateChange, StateMachine};
use crate::ecs::Transform;
use crate::sim::physics::CharacterState;

/// On a character's body: its drawn model's entity, its heading and its animation states.
#[derive(Clone, Debug)]
pub struct CharacterAnimation {
    /// The entity with the [`SkinnedAnimator`] (a child of the body).
    pub visual: Entity,
    /// Which way the character faces, radians about +Y from −Z (game rules turn it).
    pub heading_rad: f32,
    /// The model's own turn so that it faces −Z, radians.
    pub model_yaw_rad: f32,
    pub machine: StateMachine,
    /// The change of state in the last step, if any.
    pub last_change: Option<StateChange>,
    /// What the machine read in the last step.
    pub last_locomotion: Locomotion,
}

impl CharacterAnimation {
    /// The rotation of the visual entity for a heading.
    pub fn visual_rotation(&self) -> Quat {
        Quat::from_rotation_y(-self.heading_rad) * Quat::from_rotation_y(self.model_yaw_rad)
    }

    /// The name of the state now (`None` before the first step).
    pub fn state_name(&self) -> Option<&str> {
        self.machine.current().map(|s| s.name.as_str())
    }
}

/// The unit vector a heading faces (horizontal).
pub fn heading_direction(heading_rad: f32) -> Vec3 {
    Vec3::new(heading_rad.sin(), 0.0, -heading_rad.cos())
}

/// For every character (body order: deterministic): the state machine reads how the body
/// moved in the last step of `dt_seconds`, crossfades the visual entity's player and sets the
/// clip's rate, and the visual entity turns to the heading.
pub fn animate_characters(world: &mut World, dt_seconds: f64) {
    let mut bodies: Vec<Entity> = world
        .query::<(Entity, &CharacterAnimation)>()
        .iter()
        .map(|(e, _)| e)
        .collect();
    bodies.sort_by_key(|e| e.to_bits());
    let dt = dt_seconds as f32;
    for body in bodies {
        let state = world
            .get::<&CharacterState>(body)
            .map(|s| *s)
            .unwrap_or_default();
        let horizontal = state.last_translation.with_y(0.0).length();
        let locomotion = Locomotion {
            horizontal_speed_mps: if dt > 0.0 { horizontal / dt } else { 0.0 },
            vertical_speed_mps: state.vertical_speed,
            grounded: state.grounded,
        };
        let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body) else {
            continue;
        };
        let visual = anim.visual;
        let rotation = anim.visual_rotation();
        anim.last_locomotion = locomotion;
        let change = match world.get::<&mut SkinnedAnimator>(visual) {
            Ok(mut animator) => anim
                .machine
                .update(&mut animator.player, &locomotion, dt_seconds),
            Err(_) => None,
        };
        anim.last_change = change;
        drop(anim);
        if let Ok(mut t) = world.get::<&mut Transform>(visual) {
            t.rotation = rotation;
        }
    }
}
