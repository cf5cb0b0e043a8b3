//! Kinematic platforms — doors, lifts, moving floors driven by the game or by level clips —
//! and characters riding them.
//!
//! Owns: moving game-driven kinematic bodies to their `Transform` ([`PlatformMove`]) and
//! carrying the characters that stand on them. Such a body is velocity-based: each step it
//! gets the velocity that takes it from its pose to its `Transform` in one step, so contacts
//! and friction carry the dynamic bodies resting on it. The velocity is given only after the
//! characters moved: rapier's own controller would otherwise add the platform's velocity too
//! (its "kinematic friction"), one step late for a lift that starts or stops. Instead, a
//! character first walks against the world as it is (the platform at its current pose) and is
//! then carried by the platform's motion of this step — a second shape cast that ignores the
//! platform, so a wall or ceiling still stops it — and the rapier step moves the platform by
//! the same amount: the character keeps its gap to the deck exactly, going up, down or
//! sideways. Units: metres, seconds, radians. Main thread, inside the physics step.
//! Must not: write `Transform`s (the game or the level's clips do).

use glam::{Quat, Vec3};
use hecs::{Without, World};
use rapier3d::control::{CharacterLength, KinematicCharacterController};
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::parry::shape::Shape;
use rapier3d::prelude::{PhysicsWorld as RapierWorld, Pose, QueryFilter, RigidBodyHandle};

use super::bodies::{BodyHandle, BodyKind, RigidBody};
use super::character::CharacterController;
use super::convert::{pose_from_rapier, vec_from_rapier, vec_to_rapier};
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

/// This step's motion of every game-driven kinematic body (no character controller) whose
/// `Transform` moved away from its simulated pose, in handle order; their velocities are
/// zero until [`start_platforms`].
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
        rb.set_linvel(vec_to_rapier(Vec3::ZERO), false);
        rb.set_angvel(vec_to_rapier(Vec3::ZERO), false);
        let from = pose_from_rapier(rb.position());
        let to = (transform.translation, transform.rotation);
        if from != to && to.0.is_finite() && to.1.is_finite() {
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

/// Gives each moving platform the velocity that takes it to its target in `dt` seconds (about
/// its centre of mass, as rapier integrates), waking it.
pub(super) fn start_platforms(rapier: &mut RapierWorld, moves: &[PlatformMove], dt: f32) {
    for m in moves {
        let Some(rb) = rapier.bodies.get_mut(m.handle) else {
            continue;
        };
        let com0 = vec_from_rapier(rb.center_of_mass());
        let linvel = (m.carry(com0) - com0) / dt;
        let mut turn = m.to.1 * m.from.1.inverse();
        if turn.w < 0.0 {
            turn = -turn;
        }
        let (axis, angle) = turn.to_axis_angle();
        let angvel = if angle.is_finite() && angle > 0.0 {
            axis * (angle / dt)
        } else {
            Vec3::ZERO
        };
        rb.set_linvel(vec_to_rapier(linvel), true);
        rb.set_angvel(vec_to_rapier(angvel), true);
    }
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
    let queries = rapier.query_pipeline_with_filter(filter);
    let moved = carry.move_shape(dt, &queries, shape, pose, vec_to_rapier(motion), |_| {});
    vec_from_rapier(moved.translation)
}
