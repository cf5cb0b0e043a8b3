//! The kinematic character controller for first- and third-person play: walk, run, jump,
//! gravity, climbing steps and slopes, snapping to the ground, pushing dynamic bodies.
//!
//! Owns: [`CharacterController`] (tuning), [`CharacterInput`] (what game rules want this
//! step), [`CharacterState`] (what happened), and moving every character once per fixed step
//! with rapier's `KinematicCharacterController` (shape casts against the world as of the last
//! step). A character is an entity with these components, a capsule [`super::Collider`] and a
//! kinematic [`super::RigidBody`] ([`character_bundle`] makes one); its `Transform` is the
//! capsule's centre. Standing on a kinematic body moved by the game (a lift) carries the
//! character with it (`ride.rs`). Units: metres, seconds, kilograms; +Y up. Main thread, before the
//! pipeline step. Must not: read devices (game rules fill [`CharacterInput`]).

use glam::Vec3;
use hecs::{Entity, World};
use rapier3d::control::{
    CharacterAutostep, CharacterCollision, CharacterLength, KinematicCharacterController,
};
use rapier3d::prelude::{
    Collider as RapierCollider, ColliderHandle, PhysicsWorld as RapierWorld, QueryFilter,
    RigidBodyHandle, RigidBodySet,
};

use super::bodies::{BodyHandle, Collider, RigidBody};
use super::convert::{vec_from_rapier, vec_to_rapier};
use super::ride::{PlatformMove, ride, walk_queries};
use super::shapes::{ColliderShape, ShapeError};
use crate::ecs::Transform;

/// How a character moves. The defaults fit an adult-sized player.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CharacterController {
    /// Metres per second.
    pub walk_speed: f32,
    /// Metres per second while [`CharacterInput::run`] is held.
    pub run_speed: f32,
    /// Upward speed at take-off, m/s (5 m/s ≈ a 1.27 m jump at 9.81 m/s²).
    pub jump_speed: f32,
    /// Downward acceleration, m/s².
    pub gravity: f32,
    /// Tallest step climbed without jumping, metres. Stairs of 30 cm need a little more than
    /// 0.30 because the controller keeps a small gap (`skin`) to every surface.
    pub max_step_height: f32,
    /// Steepest slope walked up, degrees; steeper ones stop the character and it slides down.
    /// 45° plus a 2° margin so that a 45° ramp built from rotated geometry (normals off by
    /// float rounding) is still walkable.
    pub max_slope_deg: f32,
    /// The character stays on the ground over drops up to this height (metres) instead of
    /// flying off ramps and stairs going down.
    pub snap_to_ground: f32,
    /// Gap kept between the capsule and the world, metres.
    pub skin: f32,
    /// Mass used to push dynamic bodies, kg; 0 pushes nothing.
    pub push_mass_kg: f32,
}

impl Default for CharacterController {
    fn default() -> Self {
        Self {
            walk_speed: 2.0,
            run_speed: 5.0,
            jump_speed: 5.0,
            gravity: 9.81,
            max_step_height: 0.32,
            max_slope_deg: 47.0,
            snap_to_ground: 0.2,
            skin: 0.02,
            push_mass_kg: 80.0,
        }
    }
}

/// What the game wants the character to do this step (filled by game rules each step).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CharacterInput {
    /// Desired horizontal direction in world space; its length (clamped to 1) scales speed.
    /// The vertical part is ignored.
    pub move_direction: Vec3,
    pub run: bool,
    /// Jump if on the ground (held, it jumps again on landing; never in the air).
    pub jump: bool,
}

/// What the controller did in the last step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CharacterState {
    /// Metres per second, + up.
    pub vertical_speed: f32,
    pub grounded: bool,
    /// On a slope too steep to stand on.
    pub sliding: bool,
    /// Metres moved in the last step by the character's own motion (walking, falling).
    pub last_translation: Vec3,
    /// Metres the kinematic platform it stands on (a lift, a moving floor) carried it in the
    /// last step, on top of [`Self::last_translation`] (`sim/physics/ride.rs`).
    pub platform_motion: Vec3,
    /// It walked into a dynamic body from the side in the last step (and pushed it, when its
    /// controller pushes): a game plays its push pose while this holds.
    pub pushing: bool,
}

/// The components of a character with a capsule `height` metres tall (feet to head) and
/// `radius` metres wide, centred on `position`.
pub fn character_bundle(
    position: Vec3,
    height: f32,
    radius: f32,
    controller: CharacterController,
) -> Result<
    (
        Transform,
        RigidBody,
        Collider,
        CharacterController,
        CharacterInput,
        CharacterState,
    ),
    ShapeError,
> {
    let half_height = height * 0.5 - radius;
    let collider = Collider::new(&ColliderShape::Capsule {
        half_height,
        radius,
    })?;
    Ok((
        Transform::from_translation(position),
        RigidBody::kinematic(),
        collider,
        controller,
        CharacterInput::default(),
        CharacterState::default(),
    ))
}

fn rapier_controller(c: &CharacterController) -> KinematicCharacterController {
    let slope = c.max_slope_deg.to_radians();
    KinematicCharacterController {
        up: rapier3d::math::Vector::Y,
        offset: CharacterLength::Absolute(c.skin),
        slide: true,
        autostep: Some(CharacterAutostep {
            max_height: CharacterLength::Absolute(c.max_step_height),
            min_width: CharacterLength::Absolute(0.1),
            include_dynamic_bodies: false,
        }),
        max_slope_climb_angle: slope,
        min_slope_slide_angle: slope,
        snap_to_ground: Some(CharacterLength::Absolute(c.snap_to_ground)),
        ..KinematicCharacterController::default()
    }
}

/// Moves every character by one step of `dt` seconds (entity order: deterministic) and sets
/// its body's next kinematic pose; pushes the dynamic bodies it ran into; carries it by the
/// motion of the platform in `platforms` it stands on.
pub(super) fn move_characters(
    rapier: &mut RapierWorld,
    world: &mut World,
    platforms: &[PlatformMove],
    dt: f32,
) {
    let mut characters: Vec<Entity> = world
        .query::<(Entity, &CharacterController, &BodyHandle)>()
        .iter()
        .map(|(e, ..)| e)
        .collect();
    characters.sort_by_key(|e| e.to_bits());
    // What each character carries: its own held body never blocks its walk.
    let carried: Vec<(Entity, RigidBodyHandle)> = world
        .query::<&super::Carrier>()
        .iter()
        .filter_map(|c| {
            let held = world.get::<&BodyHandle>(c.held?).ok()?.0;
            Some((c.ignore?, held))
        })
        .collect();
    let no_bodies = RigidBodySet::new();
    for entity in characters {
        let Ok((controller, input, state, handle)) = world.query_one_mut::<(
            &CharacterController,
            Option<&CharacterInput>,
            &mut CharacterState,
            &BodyHandle,
        )>(entity) else {
            continue;
        };
        let input = input.copied().unwrap_or_default();
        let Some(body) = rapier.bodies.get(handle.0) else {
            continue;
        };
        let Some(shape) = body
            .colliders()
            .first()
            .and_then(|&c| rapier.colliders.get(c))
            .map(|c| c.shared_shape().clone())
        else {
            continue;
        };
        let pose = *body.position();

        let mut horizontal = input.move_direction.with_y(0.0);
        if horizontal.length_squared() > 1.0 {
            horizontal = horizontal.normalize();
        }
        if !horizontal.is_finite() {
            horizontal = Vec3::ZERO;
        }
        let speed = if input.run {
            controller.run_speed
        } else {
            controller.walk_speed
        };
        if state.grounded {
            state.vertical_speed = if input.jump {
                controller.jump_speed
            } else {
                0.0
            };
        }
        state.vertical_speed -= controller.gravity * dt;
        let desired = horizontal * speed * dt + Vec3::Y * state.vertical_speed * dt;

        let kcc = rapier_controller(controller);
        let mut collisions: Vec<CharacterCollision> = Vec::new();
        let holding = carried
            .iter()
            .find(|(carrier, _)| *carrier == entity)
            .map(|&(_, held)| held);
        let not_held =
            |_: ColliderHandle, c: &RapierCollider| holding.is_none() || c.parent() != holding;
        let filter = QueryFilter::default()
            .exclude_rigid_body(handle.0)
            .exclude_sensors()
            .predicate(&not_held);
        let movement = {
            let queries = walk_queries(rapier, &no_bodies, filter);
            kcc.move_shape(dt, &queries, &*shape, &pose, vec_to_rapier(desired), |c| {
                collisions.push(c)
            })
        };
        let moved = vec_from_rapier(movement.translation);
        state.pushing = collisions.iter().any(|c| {
            let side = c.hit.normal1.y.abs() < 0.5;
            let parent = rapier.colliders.get(c.handle).and_then(|c| c.parent());
            side && parent
                .and_then(|p| rapier.bodies.get(p))
                .is_some_and(|b| b.is_dynamic())
        });
        state.grounded = movement.grounded;
        state.sliding = movement.is_sliding_down_slope;
        state.last_translation = moved;
        // A ceiling (or the ground) stopped the vertical motion: do not keep accelerating.
        if (movement.grounded && state.vertical_speed < 0.0)
            || (state.vertical_speed > 0.0 && moved.y < desired.y * 0.5)
        {
            state.vertical_speed = 0.0;
        }

        if controller.push_mass_kg > 0.0 && !collisions.is_empty() {
            let mut queries = rapier.broad_phase.as_query_pipeline_mut(
                rapier.narrow_phase.query_dispatcher(),
                &mut rapier.bodies,
                &mut rapier.colliders,
                filter,
            );
            kcc.solve_character_collision_impulses(
                dt,
                &mut queries,
                &*shape,
                controller.push_mass_kg,
                &collisions,
            );
        }
        // Standing on a lift or a moving door: carried by its motion of this step.
        let mut after = pose;
        after.translation += movement.translation;
        let ridden = ride(
            rapier,
            platforms,
            &*shape,
            &after,
            handle.0,
            controller.skin,
            dt,
        );
        state.platform_motion = ridden;
        if let Some(body) = rapier.bodies.get_mut(handle.0) {
            body.set_next_kinematic_translation(after.translation + vec_to_rapier(ridden));
        }
    }
}
