//! Physics (rapier3d): rigid bodies and colliders for ECS entities, a kinematic character
//! controller, carrying bodies, sensors. Stepped at the fixed clock's rate (60 Hz) after game
//! rules; simulated poses flow back into `Transform`s, and rendering interpolates between the
//! last two steps.
//!
//! Conventions: right-handed, +Y up, metres, seconds, kilograms, radians unless a name says
//! `_deg`. rapier's math (glamx on glam 0.33) never leaves this module: `convert` is the only
//! place the two glam versions meet.

mod bodies;
mod breaking;
mod carry;
mod character;
mod convert;
mod place;
mod ride;
mod sensors;
mod shapes;
mod world;

pub use bodies::{
    BodyHandle, BodyKind, Collider, DEFAULT_DENSITY_KG_PER_M3, PhysicsPose, RigidBody,
};
pub use breaking::Breakable;
pub use carry::{Carrier, CarryRequest};
pub use character::{CharacterController, CharacterInput, CharacterState, character_bundle};
pub use place::Placement;
pub use sensors::SensorContacts;
pub use shapes::{ColliderShape, ShapeError};
pub use world::{GRAVITY, PhysicsWorld, StepReport};
