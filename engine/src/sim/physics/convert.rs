//! The one place where the engine's glam 0.34 types meet rapier's math (glamx on glam 0.33).
//!
//! Owns: lossless conversions of vectors, rotations and poses in both directions. Both sides
//! use the same conventions (right-handed, +Y up, metres, unit quaternions `x, y, z, w`), so
//! each conversion is a copy of the components (`from_array(to_array())`, free after
//! inlining). Must not: be bypassed: no other file names rapier's vector or rotation types
//! together with the engine's.

use glam::{Quat, Vec3};
use rapier3d::math::{Pose, Rotation, Vector};

/// Engine vector (metres or metres per second) → rapier vector.
#[inline]
pub fn vec_to_rapier(v: Vec3) -> Vector {
    Vector::from_array(v.to_array())
}

/// Rapier vector → engine vector.
#[inline]
pub fn vec_from_rapier(v: Vector) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// Engine rotation → rapier rotation.
#[inline]
pub fn quat_to_rapier(q: Quat) -> Rotation {
    Rotation::from_array(q.to_array())
}

/// Rapier rotation → engine rotation.
#[inline]
pub fn quat_from_rapier(q: Rotation) -> Quat {
    Quat::from_array(q.to_array())
}

/// A rigid pose (rotation, then translation in metres) → rapier pose.
#[inline]
pub fn pose_to_rapier(translation: Vec3, rotation: Quat) -> Pose {
    Pose::from_parts(vec_to_rapier(translation), quat_to_rapier(rotation))
}

/// Rapier pose → (translation in metres, rotation).
#[inline]
pub fn pose_from_rapier(pose: &Pose) -> (Vec3, Quat) {
    (
        vec_from_rapier(pose.translation),
        quat_from_rapier(pose.rotation),
    )
}

/// Engine points (metres) → rapier points, for convex hulls and triangle meshes.
pub fn points_to_rapier(points: &[Vec3]) -> Vec<Vector> {
    points.iter().map(|&p| vec_to_rapier(p)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_are_exact() {
        let v = Vec3::new(1.5, -2.25, 1e-7);
        assert_eq!(vec_from_rapier(vec_to_rapier(v)), v);
        let q = Quat::from_rotation_y(0.3) * Quat::from_rotation_x(-1.1);
        assert_eq!(quat_from_rapier(quat_to_rapier(q)), q);
        let (t, r) = pose_from_rapier(&pose_to_rapier(v, q));
        assert_eq!((t, r), (v, q));
    }

    #[test]
    fn rotation_acts_the_same_on_both_sides() {
        let q = Quat::from_rotation_z(0.7) * Quat::from_rotation_y(2.0);
        let p = Vec3::new(0.3, 1.0, -4.0);
        let ours = q * p;
        let theirs = vec_from_rapier(quat_to_rapier(q) * vec_to_rapier(p));
        assert!((ours - theirs).length() < 1e-6, "{ours} vs {theirs}");
    }
}
