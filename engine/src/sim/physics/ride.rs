//! Kinematic platforms — doors, lifts, moving floors driven by the game or by level clips —
//! and characters riding them.
//!
//!
//! Owns: moving game-driven kinematic bodies to their `Transform` ([`PlatformMove`]: rapier's
//! next kinematic pose, from which rapier derives the velocity, so contacts and friction carry
//! the dynamic bodies resting on it) and carrying the characters that stand on them. A
//! character first walks against the world as it is (the platform at its current pose) and is
//! then carried by the platform's motion of this step — a second shape cast that ignores the
//! platform, so a wall or ceiling still stops it — and the rapier step moves the platform by
//! the same amount: the character keeps its gap to the deck exactly, going up, down or
//! sideways. The walk itself sees the world through [`walk_queries`], without rapier's body
//! set: rapier's controller would otherwise treat kinematic floors specially (its "kinematic
//! friction": a platform's velocity added one step late, and walking blocked on a kinematic
//! floor after two steps in rapier 0.36 — `tests/physics_ride.rs` walks on and off a lift).
//! Units: metres, seconds, radians. Main thread, inside the physics step.
//! Must not: write `Transform`s (the game or the level's clips do).

use glam::{Quat, Vec3};
use hecs::{Without, World};
use rapier3d::control::{CharacterLength, KinematicCharacterController};
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::parry::shape::Shape;
use rapier3d::prelude::{
    PhysicsWorld as RapierWorld, Pose, QueryFilter, QueryPipeline, RigidBodyHandle, RigidBodySet,
};

use super::bodies::{BodyHandle, BodyKind, RigidBody};
use super::character::CharacterController;
use super::convert::{pose_from_rapier, pose_to_rapier, vec_from_rapier, vec_to_rapier};
use crate::ecs::Transform;

/// How far below the capsule a platform still counts as stood on, metres beyond the skin.
const STAND_MARGIN: f32 = 0.05;

/// A game-driven kinematic body's motion in this step: from its pose to its `Transform`.
#[derive(Clone, Copy, Debug)]
pub(super) struct PlatformMove {
    handle: RigidBodyHandle,
    from: (Vec3, Quat),
    to: (Vec3, Quat),
}

impl PlatformMove {
    /// Where the platform's motion takes the world point `p` (metres).
    fn carry(&self, p: Vec3) -> Vec3 {
        let ((t0, r0), (t1, r1)) = (self.from, self.to);
        t1 + r1 * (r0.inverse() * (p - t0))
    }
}

/// Sets every game-driven kinematic body (no character controller) on its way to its
/// `Transform` (rapier's next kinematic pose) and returns the motions of those that move, in
/// handle order.
pub(super) fn platform_moves(rapier: &mut RapierWorld, world: &World) -> Vec<PlatformMove> {
    let mut moves = Vec::new();
    for (body, handle, transform) in world
        .query::<Without<(&RigidBody, &BodyHandle, &Transform), &CharacterController>>()
        .iter()
    {
        if body.kind != BodyKind::Kinematic {
            continue;
        }
        let Some(rb) = rapier.bodies.get_mut(handle.0) else {
            continue;
        };
        let from = pose_from_rapier(rb.position());
        let to = (transform.translation, transform.rotation);
        if from != to && to.0.is_finite() && to.1.is_finite() {
            rb.set_next_kinematic_position(pose_to_rapier(to.0, to.1));
            moves.push(PlatformMove {
                handle: handle.0,
                from,
                to,
            });
        }
    }
    moves.sort_by_key(|m| m.handle.into_raw_parts());
    moves
}

/// Queries for a character's own walk: the world's colliders without rapier's body set, so
/// the controller treats every solid collider alike (see the module doc). `empty` is an empty
/// body set that outlives the queries.
pub(super) fn walk_queries<'a>(
    rapier: &'a RapierWorld,
    empty: &'a RigidBodySet,
    filter: QueryFilter<'a>,
) -> QueryPipeline<'a> {
    rapier.broad_phase.as_query_pipeline(
        rapier.narrow_phase.query_dispatcher(),
        empty,
        &rapier.colliders,
        filter,
    )
}

/// The moving platform right under a character whose shape is at `pose` (ignoring the
/// character's own body `me` and sensors), if any.
fn platform_under<'m>(
    rapier: &RapierWorld,
    moves: &'m [PlatformMove],
    shape: &dyn Shape,
    pose: &Pose,
    me: RigidBodyHandle,
    skin: f32,
) -> Option<&'m PlatformMove> {
    if moves.is_empty() {
        return None;
    }
    let filter = QueryFilter::default()
        .exclude_rigid_body(me)
        .exclude_sensors();
    let queries = rapier.query_pipeline_with_filter(filter);
    let options = ShapeCastOptions {
        max_time_of_impact: skin + STAND_MARGIN,
        target_distance: 0.0,
        stop_at_penetration: true,
        compute_impact_geometry_on_penetration: false,
    };
    let (collider, _) = queries.cast_shape(pose, vec_to_rapier(Vec3::NEG_Y), shape, options)?;
    let body = rapier.colliders.get(collider)?.parent()?;
    moves.iter().find(|m| m.handle == body)
}

/// The motion (metres) the platform under a character adds this step, after the character's
/// own move brought its shape to `pose`: the platform's motion at the character's position,
/// cut short by whatever else (walls, ceilings, other bodies) is in the way.
pub(super) fn ride(
    rapier: &RapierWorld,
    moves: &[PlatformMove],
    shape: &dyn Shape,
    pose: &Pose,
    me: RigidBodyHandle,
    skin: f32,
    dt: f32,
) -> Vec3 {
    let Some(platform) = platform_under(rapier, moves, shape, pose, me, skin) else {
        return Vec3::ZERO;
    };
    let at = vec_from_rapier(pose.translation);
    let motion = platform.carry(at) - at;
    if !motion.is_finite() || motion.length_squared() < 1e-14 {
        return Vec3::ZERO;
    }
    let carry = KinematicCharacterController {
        up: rapier3d::math::Vector::Y,
        offset: CharacterLength::Absolute(skin),
        slide: true,
        autostep: None,
        snap_to_ground: None,
        ..KinematicCharacterController::default()
    };
    let deck = platform.handle;
    let not_deck = |_, c: &rapier3d::prelude::Collider| c.parent() != Some(deck);
    let filter = QueryFilter::default()
        .exclude_rigid_body(me)
        .exclude_sensors()
        .predicate(&not_deck);
    let empty = RigidBodySet::new();
    let queries = walk_queries(rapier, &empty, filter);
    let moved = carry.move_shape(dt, &queries, shape, pose, vec_to_rapier(motion), |_| {});
    vec_from_rapier(moved.translation)
}
