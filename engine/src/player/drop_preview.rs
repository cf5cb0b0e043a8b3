//! The outline of where a held body will land: the edges of its [`Placement`] box projected
//! into the view, for the HUD to draw over the picture (a ghost of the drop, as players of
//! carrying games expect).
//!
//! Owns: [`outline`], the projection into view-plane units (x right, y up; 1 is the distance
//! from the centre to the top edge of the picture, so the HUD scales by half its height and
//! needs no aspect ratio). Main thread, per frame or step. Must not: draw (the HUD does) or
//! touch physics (the placement comes from `sim::physics::PhysicsWorld::placement`).

use glam::{Quat, Vec3};

use crate::sim::physics::Placement;

/// The twelve edges of `placement`'s box seen from an eye at `eye` (metres) turned by
/// `rotation` (looking along its −Z) with `vertical_fov` radians: each edge's two ends in
/// view-plane units. Empty when a corner lies behind or right at the eye (an edge through the
/// eye has no picture).
pub fn outline(
    placement: &Placement,
    eye: Vec3,
    rotation: Quat,
    vertical_fov: f32,
) -> Vec<[[f32; 2]; 2]> {
    let tan_half = (vertical_fov * 0.5).tan();
    if !(tan_half > 0.0) || !tan_half.is_finite() {
        return Vec::new();
    }
    let h = placement.half_extents;
    let to_view = rotation.inverse();
    let mut corners = [[0.0f32; 2]; 8];
    for (i, corner) in corners.iter_mut().enumerate() {
        let sign = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
        let local = Vec3::new(sign(1) * h.x, sign(2) * h.y, sign(4) * h.z);
        let world = placement.position + placement.rotation * local;
        let v = to_view * (world - eye);
        if !(v.z < -0.05) {
            return Vec::new();
        }
        *corner = [v.x / (-v.z * tan_half), v.y / (-v.z * tan_half)];
    }
    let mut edges = Vec::with_capacity(12);
    for a in 0..8usize {
        for bit in [1usize, 2, 4] {
            if a & bit == 0 {
                edges.push([corners[a], corners[a | bit]]);
            }
        }
    }
    edges
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_straight_ahead_projects_around_the_centre_and_one_behind_not_at_all() {
        let placement = Placement {
            position: Vec3::new(0.0, 0.0, -2.0),
            rotation: Quat::IDENTITY,
            half_extents: Vec3::splat(0.25),
        };
        let fov = 90f32.to_radians();
        let edges = outline(&placement, Vec3::ZERO, Quat::IDENTITY, fov);
        assert_eq!(edges.len(), 12);
        // The near face (z = −1.75) spans ±0.25 / 1.75 of the view plane at 90°.
        let widest = edges
            .iter()
            .flat_map(|e| e.iter())
            .map(|p| p[0].abs())
            .fold(0.0f32, f32::max);
        assert!((widest - 0.25 / 1.75).abs() < 1e-5, "{widest}");
        let behind = outline(
            &placement,
            Vec3::ZERO,
            Quat::from_rotation_y(std::f32::consts::PI),
            fov,
        );
        assert!(behind.is_empty());
    }
}
