//! Placing a carried body where its carrier looks: a drop that puts a Reflect cube on the floor
//! spot under the crosshair, upright, instead of letting it fall from the hold point.
//!
//! Owns: [`Placement`] and [`find`], the one rule for where a dropped body rests, shared by the
//! drop itself (`carry`) and the game's preview of it (`PhysicsWorld::placement`). The rule: a
//! ray from the eye along the view, within the carrier's `place_reach`, ignoring the held body,
//! the carrier's character and sensors, must hit a surface facing up (normal at most about 45°
//! from +Y); the body then rests on that spot with its yaw kept and its tilt removed, a
//! centimetre above the surface, pulled back towards the eye in 10 cm steps (up to 50 cm) when
//! it would overlap a wall. No such spot: `None` (the drop lets go where the body is held).
//! Units: metres, radians. Main thread (fixed step, or a frame's read-only preview).
//! Must not: move anything (the caller places the body).

use glam::{Quat, Vec3};
use rapier3d::prelude::{
    Collider, ColliderHandle, PhysicsWorld as RapierWorld, QueryFilter, Ray, RigidBodyHandle,
};

use super::convert::{pose_to_rapier, quat_from_rapier, vec_from_rapier, vec_to_rapier};

/// Where a dropped body comes to rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// The body's centre, world space, metres.
    pub position: Vec3,
    /// Upright: the body's yaw about +Y only.
    pub rotation: Quat,
    /// Half the body's bounding box in its own frame, metres.
    pub half_extents: Vec3,
}

/// Smallest +Y component of the normal of a surface a body may be placed on (cos 45.6°).
const FLOOR_NORMAL_Y: f32 = 0.7;
/// Gap left between the placed body and the surface, metres.
const CLEARANCE: f32 = 0.01;
/// Steps of pulling the body back towards the eye when it would overlap, and their length.
const PULL_BACK_STEPS: usize = 5;
const PULL_BACK_STEP: f32 = 0.1;

/// The yaw part of `rotation`: its +X (or, if that points up or down, its +Z) axis laid flat.
fn upright(rotation: Quat) -> Quat {
    let x = rotation * Vec3::X;
    let z = rotation * Vec3::Z;
    let yaw = if x.x * x.x + x.z * x.z >= z.x * z.x + z.z * z.z {
        (-x.z).atan2(x.x)
    } else {
        z.x.atan2(z.z)
    };
    Quat::from_rotation_y(yaw)
}

/// Where `held` would rest if dropped by a carrier whose eye is at `eye` looking along unit
/// `view`, within `reach` metres; `ignore` is the carrier's own character.
pub(super) fn find(
    rapier: &RapierWorld,
    eye: Vec3,
    view: Vec3,
    reach: f32,
    held: RigidBodyHandle,
    ignore: Option<RigidBodyHandle>,
) -> Option<Placement> {
    if !(reach > 0.0) || !eye.is_finite() || !view.is_finite() {
        return None;
    }
    let body = rapier.bodies.get(held)?;
    let collider = rapier.colliders.get(*body.colliders().first()?)?;
    let aabb = collider.shape().compute_local_aabb();
    let half_extents = vec_from_rapier(aabb.half_extents());
    let centre = vec_from_rapier(aabb.center());
    let rotation = upright(quat_from_rapier(*body.rotation()));
    let keep = |_: ColliderHandle, c: &Collider| {
        let parent = c.parent();
        parent != Some(held) && (ignore.is_none() || parent != ignore)
    };
    let queries = rapier
        .query_pipeline_with_filter(QueryFilter::default().exclude_sensors().predicate(&keep));
    let ray = Ray::new(vec_to_rapier(eye), vec_to_rapier(view));
    let (_, hit) = queries.cast_ray_and_get_normal(&ray, reach, true)?;
    if hit.normal.y < FLOOR_NORMAL_Y {
        return None;
    }
    let spot = eye + view * hit.time_of_impact;
    let lift = half_extents.y + CLEARANCE;
    let back = Vec3::new(view.x, 0.0, view.z).normalize_or_zero();
    (0..=PULL_BACK_STEPS).find_map(|k| {
        let ground = spot - back * (k as f32 * PULL_BACK_STEP);
        // Still over a surface facing up (the spot itself, or the floor it was pulled onto).
        let down = Ray::new(
            vec_to_rapier(ground + Vec3::Y * lift),
            vec_to_rapier(Vec3::NEG_Y),
        );
        let (_, support) = queries.cast_ray_and_get_normal(&down, lift + 0.05, true)?;
        if support.normal.y < FLOOR_NORMAL_Y {
            return None;
        }
        let floor = ground + Vec3::Y * (lift - support.time_of_impact);
        let position = floor + Vec3::Y * lift - rotation * centre;
        let pose = pose_to_rapier(position, rotation);
        let free = queries
            .intersect_shape(pose, collider.shape())
            .next()
            .is_none();
        free.then_some(Placement {
            position,
            rotation,
            half_extents,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn upright_keeps_the_yaw_and_drops_the_tilt() {
        for yaw in [0.0f32, 0.7, -2.1, 3.0] {
            let tilted = Quat::from_rotation_y(yaw) * Quat::from_rotation_x(0.3);
            let u = upright(tilted);
            let expected = Quat::from_rotation_y(yaw);
            assert!(u.dot(expected).abs() > 0.9999, "yaw {yaw}: {u:?}");
        }
        // Lying on its side (+X up): the yaw comes from +Z.
        let side = Quat::from_rotation_y(0.5) * Quat::from_rotation_z(std::f32::consts::FRAC_PI_2);
        let u = upright(side);
        assert!((u * Vec3::Y).y > 0.9999);
    }
}
