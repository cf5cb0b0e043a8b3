//! An instance's `body` from its level file, turned into the physics components its entity
//! gets.
//!
//! Owns: [`InstanceBody`] and [`resolve_body`], which checks the numbers, derives boxes, hulls
//! and triangle meshes from the instance's model (scaled by the instance's transform) and
//! builds the collider, so that bad data fails at load time with a message naming the item.
//! Main thread (level loading). Must not: spawn entities or step physics.

use glam::{Mat4, Vec3};

use crate::assets::{BodyEntry, Model, ShapeEntry};
use crate::sim::physics::{BodyKind, Collider, ColliderShape, RigidBody};

/// The physics components of an instance, ready to insert on its entity.
#[derive(Clone, Debug)]
pub struct InstanceBody {
    pub body: RigidBody,
    pub collider: Collider,
}

impl InstanceBody {
    /// Whether the body can move (so its instance is not static for rendering).
    pub fn moves(&self) -> bool {
        self.body.kind != BodyKind::Static
    }
}

/// Builds the body of an instance of `model` placed by `world_from_model`. The error is a
/// sentence about the body only; the caller adds the level file and the instance.
pub fn resolve_body(
    entry: &BodyEntry,
    model: &Model,
    world_from_model: Mat4,
) -> Result<InstanceBody, String> {
    let (scale, _, _) = world_from_model.to_scale_rotation_translation();
    let (shape_entry, body) = match entry {
        BodyEntry::Static { shape } => (shape, RigidBody::fixed()),
        BodyEntry::Dynamic { shape, ccd, .. } => {
            if *shape == ShapeEntry::Trimesh {
                return Err(
                    "a dynamic body cannot use Trimesh (use Box, Cuboid, Sphere, Capsule or ConvexHull)"
                        .into(),
                );
            }
            let body = RigidBody::dynamic();
            (shape, if *ccd { body.with_ccd() } else { body })
        }
        BodyEntry::Kinematic { shape } => (shape, RigidBody::kinematic()),
        BodyEntry::Sensor { shape } => (shape, RigidBody::fixed()),
    };
    let mut offset = Vec3::ZERO;
    let shape = match shape_entry {
        ShapeEntry::Box => {
            let (shape, centre) = ColliderShape::bounds_of(model, scale)
                .ok_or_else(|| "shape Box: the model has no vertices".to_string())?;
            offset = centre;
            shape
        }
        ShapeEntry::Cuboid { half_extents } => ColliderShape::Box {
            half_extents: Vec3::from(*half_extents),
        },
        ShapeEntry::Sphere { radius } => ColliderShape::Sphere { radius: *radius },
        ShapeEntry::Capsule {
            half_height,
            radius,
        } => ColliderShape::Capsule {
            half_height: *half_height,
            radius: *radius,
        },
        ShapeEntry::ConvexHull => ColliderShape::hull_of(model, scale),
        ShapeEntry::Trimesh => ColliderShape::trimesh_of(model, scale),
    };
    let mut collider = Collider::new(&shape).map_err(|e| format!("shape {shape_entry:?}: {e}"))?;
    collider.offset = offset;
    if let BodyEntry::Dynamic { mass, .. } = entry {
        collider = collider.with_mass(*mass).map_err(|e| e.to_string())?;
    }
    if let BodyEntry::Sensor { .. } = entry {
        collider = collider.as_sensor();
    }
    Ok(InstanceBody { body, collider })
}
