//! What wades in a water: every dynamic or kinematic physics body (characters' capsules
//! included; sensors and static bodies left out) as its bounds after the last physics step,
//! and the push those bounds give a water's grid.
//!
//! Owns: reading bodies' step poses ([`PhysicsPose::current`], not the interpolated
//! `Transform`) and colliders' bounds, and the push kernel. Main thread, inside the fixed
//! steps, after physics. Must not: move bodies (the coupling is one-way: water does not push
//! back) or touch the height field itself.

use glam::{Mat3, Vec3};
use hecs::{Entity, World};

use super::field::GridLayout;
use crate::ecs::Transform;
use crate::sim::physics::{BodyKind, Collider, PhysicsPose, RigidBody};

/// A body that may wade: its bounds in world space (metres), axis-aligned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wader {
    pub centre: Vec3,
    pub half_extents: Vec3,
}

/// Every moving, solid body's bounds as of the last physics step, in entity order.
pub fn waders(world: &World) -> Vec<Wader> {
    let mut found: Vec<(u64, Wader)> = world
        .query::<(Entity, &PhysicsPose, &RigidBody, &Collider)>()
        .iter()
        .filter(|(_, _, body, collider)| body.kind != BodyKind::Static && !collider.sensor)
        .map(|(e, pose, _, collider)| {
            let (position, rotation) = pose.current;
            let (centre, half) = collider.local_bounds();
            let turn = Mat3::from_quat(rotation);
            let wader = Wader {
                centre: position + turn * centre,
                half_extents: abs(turn) * half,
            };
            (e.to_bits().get(), wader)
        })
        .collect();
    found.sort_by_key(|(e, _)| *e);
    found.into_iter().map(|(_, w)| w).collect()
}

/// The matrix of absolute values: maps half extents to the half extents of the turned box.
fn abs(m: Mat3) -> Mat3 {
    Mat3::from_cols(m.x_axis.abs(), m.y_axis.abs(), m.z_axis.abs())
}

/// Adds to `push` (metres per vertex of `layout`) how far `waders` press a water placed by
/// `water` (its grid's object space → world) below its rest surface: `strength` × the
/// wader's depth below the rest surface (at most its height) × `(1 − q²)²`, `q` the
/// horizontal distance from its centre over its horizontal half extent. Edges get none.
pub fn add_push(
    push: &mut [f32],
    layout: &GridLayout,
    water: &Transform,
    waders: &[Wader],
    strength: f32,
) {
    let to_object = water.rotation.inverse();
    let turn = abs(Mat3::from_quat(to_object));
    let scale = water.scale.abs().max(Vec3::splat(1e-6));
    for w in waders {
        let centre = to_object * (w.centre - water.translation) / scale;
        let half = turn * w.half_extents / scale;
        let bottom = centre.y - half.y;
        let depth = (layout.origin.y - bottom).clamp(0.0, 2.0 * half.y);
        let radius = half.x.max(half.z);
        if !(depth > 0.0 && radius > 0.0 && centre.is_finite() && half.is_finite()) {
            continue;
        }
        let span = |c: f32, o: f32, d: f32, n: usize| {
            let lo = ((c - radius - o) / d).floor().max(1.0);
            let hi = ((c + radius - o) / d).ceil().min(n as f32 - 2.0);
            (lo as usize, hi as usize, lo <= hi)
        };
        let (x0, x1, x_in) = span(centre.x, layout.origin.x, layout.dx, layout.columns);
        let (z0, z1, z_in) = span(centre.z, layout.origin.z, layout.dz, layout.rows);
        if !(x_in && z_in) {
            continue;
        }
        for iz in z0..=z1 {
            for ix in x0..=x1 {
                let p = layout.rest(ix, iz);
                let q2 = ((p.x - centre.x).powi(2) + (p.z - centre.z).powi(2)) / (radius * radius);
                if q2 < 1.0
                    && let Some(slot) = push.get_mut(ix + iz * layout.columns)
                {
                    *slot += strength * depth * (1.0 - q2) * (1.0 - q2);
                }
            }
        }
    }
}
