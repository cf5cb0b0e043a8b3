//! Physics in a level file: an instance's optional `body`, as the file spells it.
//!
//! Owns: the serde types [`BodyEntry`] and [`ShapeEntry`]. Turning them into physics
//! components (checking the numbers, deriving shapes from the model, building the collider)
//! is `level::body`'s, at load time. Must not: build colliders, spawn entities or step
//! physics.
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

use serde::{Deserialize, Serialize};

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
