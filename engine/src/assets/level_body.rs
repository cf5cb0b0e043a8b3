//! Physics in a level file: an instance's optional `body`, and turning it into the physics
//! components the instance's entity gets.
//!
//! Owns: the serde types [`BodyEntry`] and [`ShapeEntry`], and [`resolve_body`], which checks
//! the numbers, derives boxes, hulls and triangle meshes from the instance's model (scaled by
//! the instance's transform) and builds the collider, so that bad data fails at load time with
//! a message naming the item. Must not: spawn entities or step physics.
//!
//! ```ron
//! instances: [
//!     (model: "floor", body: Static(shape: Trimesh)),
//!     (model: "crate", body: Dynamic(shape: Box, mass: 20)),
//!     (model: "ball", body: Dynamic(shape: Sphere(radius: 0.1), mass: 0.5, ccd: true)),
//!     (model: "zone", body: Sensor(shape: Box)),
//! ]
//! ```
//! Sizes given explicitly (`Cuboid`, `Sphere`, `Capsule`) are metres in the world and are not
//! scaled by the instance; shapes taken from the model (`Box`, `ConvexHull`, `Trimesh`) are.

use glam::{Mat4, Vec3};
use serde::{Deserialize, Serialize};

use super::model::Model;
use crate::sim::physics::{Collider, ColliderShape, RigidBody};

/// How an instance takes part in physics.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum BodyEntry {
    /// Never moves: walls, floors, level geometry.
    Static { shape: ShapeEntry },
    /// Simulated.
    Dynamic {
        shape: ShapeEntry,
        /// Kilograms.
        #[serde(default = "default_mass")]
        mass: f32,
        /// Continuous collision detection, for small fast bodies.
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        ccd: bool,
    },
    /// Moved by game code (doors, elevators).
    Kinematic { shape: ShapeEntry },
    /// Reports what overlaps it; blocks nothing.
    Sensor { shape: ShapeEntry },
}

fn default_mass() -> f32 {
    1.0
}

/// A collider's shape in a level.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ShapeEntry {
    /// The model's bounding box, scaled by the instance.
    Box,
    /// A box of the given half extents, metres, centred on the instance's origin.
    Cuboid { half_extents: [f32; 3] },
    /// A sphere, metres, centred on the instance's origin.
    Sphere { radius: f32 },
    /// A capsule along the instance's +Y, metres.
    Capsule { half_height: f32, radius: f32 },
    /// The convex hull of the model's vertices, scaled by the instance.
    ConvexHull,
    /// The model's triangles, scaled by the instance (static and kinematic bodies only).
    Trimesh,
}

/// The physics components of an instance, ready to insert on its entity.
#[derive(Clone, Debug)]
pub struct InstanceBody {
    pub body: RigidBody,
    pub collider: Collider,
}

impl InstanceBody {
    /// Whether the body can move (so its instance is not static for rendering).
    pub fn moves(&self) -> bool {
        self.body.kind != crate::sim::physics::BodyKind::Static
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
