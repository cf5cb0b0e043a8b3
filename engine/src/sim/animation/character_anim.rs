//! Characters' animation in the world: the link from a character's body (the capsule the
//! controller moves) to the entity that draws its skinned model, the way the character faces,
//! and the state machine that picks its clip from how the body moved in the last physics step.
//!
//! Owns: the [`CharacterAnimation`] component (on the body entity) and [`animate_characters`]
//! (once per fixed step, after physics and before `tick_skinned`): it reads each body's
//! [`CharacterState`], updates the state machine on the visual entity's
//! [`SkinnedAnimator`] player (crossfades, rates) — or plays the action game code asked for
//! ([`request_action`], `action`; a one-shot that yields its legs moves to the upper body,
//! `upper_body`, when the character sets off) — and turns the visual entity to the heading.
//! The visual entity is a child ([`crate::ecs::Parent`]) of the body: its local `Transform`
//! puts the feet at the capsule's bottom and holds the model's scale. Main thread.
//! Must not: move bodies (the controller does) or read input (game rules set the heading).
//! Units: metres, seconds, radians; heading 0 faces −Z, positive turns right (towards +X).

use glam::{Quat, Vec3};
use hecs::{Entity, World};

use super::action::{ActionKind, ActionRequest, ActionSlot};
use super::error::AnimResult;
use super::skinned_entities::SkinnedAnimator;
use super::state_machine::{Locomotion, StateChange, StateMachine};
use super::upper_body::UpperBodySlot;
use crate::ecs::Transform;
use crate::sim::physics::CharacterState;

/// Time constant of the low-pass on the ground speed the states read, seconds: the rapier
/// controller reports no motion for an odd step now and then (seen walking the courtyard of
/// `engine/tests/engine/player_third_person.rs` at 2 m/s: 5 single-step stops in 5 s), which must
/// not flick the state to idle and back; 0.1 s keeps a stop-and-go of a step inside walk and
/// still reaches idle 0.4 s after stopping from a run.
pub const SPEED_SMOOTHING_SECONDS: f32 = 0.1;

/// How long a character may be off the ground without rising before it counts as in the air,
/// seconds: a step down or the first step after spawning is not a fall.
pub const AIR_GRACE_SECONDS: f32 = 0.1;

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
    /// The smoothed ground speed, m/s.
    pub smoothed_speed_mps: f32,
    /// Seconds since the body last stood on the ground.
    pub airborne_seconds: f32,
    /// The action asked for this step and the one playing.
    pub action: ActionSlot,
    /// The clip asked for on the upper body this step and the one playing there.
    pub upper: UpperBodySlot,
}

impl CharacterAnimation {
    /// The animation of a body drawn by `visual`, facing `heading_rad`, before its first step.
    pub fn new(
        visual: Entity,
        heading_rad: f32,
        model_yaw_rad: f32,
        machine: StateMachine,
    ) -> Self {
        Self {
            visual,
            heading_rad,
            model_yaw_rad,
            machine,
            last_change: None,
            last_locomotion: Locomotion::default(),
            smoothed_speed_mps: 0.0,
            airborne_seconds: 0.0,
            action: ActionSlot::default(),
            upper: UpperBodySlot::default(),
        }
    }

    /// Asks for an action this step (see [`ActionSlot::request`]).
    pub fn request_action(&mut self, request: ActionRequest) {
        self.action.request(request);
    }

    /// Words for the engine's state hash: the state, the action and the player's playheads.
    pub fn state_words(&self, player: Option<&super::AnimationPlayer>) -> Vec<u64> {
        let mut words = vec![self.machine.current_index().map_or(u64::MAX, |i| i as u64)];
        words.extend(self.action.state_words());
        let playbacks = player.map(|p| [p.current(), p.fading_out()]);
        for playback in playbacks.into_iter().flatten() {
            words.extend(playback.map_or([u64::MAX; 2], |p| {
                [
                    p.clip as u64 | u64::from(p.finished) << 32,
                    p.time_seconds.to_bits(),
                ]
            }));
        }
        if let Some(player) = player {
            words.extend(self.upper.state_words(player));
        }
        words
    }

    /// What the state machine reads after a step of `dt` seconds in which the body did
    /// `state`: the ground speed low-passed (`SPEED_SMOOTHING_SECONDS`) and short spells off
    /// the ground (`AIR_GRACE_SECONDS`) counted as grounded unless rising.
    pub fn observe(&mut self, state: &CharacterState, dt: f32) -> Locomotion {
        if dt <= 0.0 || !dt.is_finite() {
            return self.last_locomotion;
        }
        let raw = state.last_translation.with_y(0.0).length() / dt;
        let raw = if raw.is_finite() { raw } else { 0.0 };
        let blend = 1.0 - (-dt / SPEED_SMOOTHING_SECONDS).exp();
        self.smoothed_speed_mps += (raw - self.smoothed_speed_mps) * blend;
        self.airborne_seconds = if state.grounded {
            0.0
        } else {
            self.airborne_seconds + dt
        };
        let rising = !state.grounded && state.vertical_speed > 0.0;
        let locomotion = Locomotion {
            horizontal_speed_mps: self.smoothed_speed_mps,
            vertical_speed_mps: state.vertical_speed,
            grounded: state.grounded || (!rising && self.airborne_seconds < AIR_GRACE_SECONDS),
        };
        self.last_locomotion = locomotion;
        locomotion
    }

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
/// moved in the last step ([`CharacterAnimation::observe`]) of `dt_seconds`, crossfades the visual entity's player and sets the
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
        let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body) else {
            continue;
        };
        let locomotion = anim.observe(&state, dt);
        let visual = anim.visual;
        let rotation = anim.visual_rotation();
        let change = match world.get::<&mut SkinnedAnimator>(visual) {
            Ok(mut animator) => {
                let anim = &mut *anim;
                let animator = &mut *animator;
                anim.upper.update(&mut animator.player, dt_seconds);
                anim.action.update_layered(
                    &mut anim.machine,
                    &mut animator.player,
                    &locomotion,
                    dt_seconds,
                    Some((&animator.model, &mut anim.upper)),
                )
            }
            Err(_) => None,
        };
        anim.last_change = change;
        drop(anim);
        if let Ok(mut t) = world.get::<&mut Transform>(visual) {
            t.rotation = rotation;
        }
    }
}

/// Asks the character `body` to play its model's clip `clip` (by name, or index in decimal) as
/// `kind` this step — for game code in its fixed step: a one-shot (`"pick_up"`,
/// `"celebrate"`) once, a held action (`"push"`) every step it should go on. Returns whether
/// `body` is an animated character (false: nothing to do); a clip the model lacks is
/// [`AnimError::NoSuchClip`](super::AnimError::NoSuchClip), naming the model's file.
pub fn request_action(
    world: &mut World,
    body: Entity,
    clip: &str,
    kind: ActionKind,
) -> AnimResult<bool> {
    let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body) else {
        return Ok(false);
    };
    let Ok(animator) = world.get::<&SkinnedAnimator>(anim.visual) else {
        return Ok(false);
    };
    let index = animator.model.find_clip(clip)?;
    anim.request_action(ActionRequest::new(index, kind));
    Ok(true)
}

/// Asks the character `body` to play its model's clip `clip` (by name, or index in decimal) on
/// its upper body this step, over its locomotion (`upper_body`): held, so ask every step it
/// should go on. Returns whether `body` is an animated character; a clip the model lacks, or a
/// model without the upper body's joint, is an error naming the model's file.
pub fn request_upper_body(world: &mut World, body: Entity, clip: &str) -> AnimResult<bool> {
    let Ok(mut anim) = world.get::<&mut CharacterAnimation>(body) else {
        return Ok(false);
    };
    let Ok(animator) = world.get::<&SkinnedAnimator>(anim.visual) else {
        return Ok(false);
    };
    let index = animator.model.find_clip(clip)?;
    anim.upper.request(&animator.model, index)?;
    Ok(true)
}
