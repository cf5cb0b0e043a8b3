//! Rigid bodies in the ECS: the components a game puts on an entity, spawning them into
//! rapier, pushing game-driven kinematic poses in, and writing simulated poses back.
//!
//! Owns: [`RigidBody`], [`Collider`], [`BodyHandle`], [`PhysicsPose`]; the entity ↔ body link
//! (an entity's bits in the body's `user_data`). A body's entity is a root entity (no
//! `Parent`): its `Transform` translation and rotation are the body's world pose in metres;
//! its scale is left alone (collider sizes already include it).
//! Who writes what: dynamic bodies and characters are simulated, so physics writes their
//! `Transform` (output only; teleport through `PhysicsWorld::set_pose`); between frames that
//! `Transform` shows the render-interpolated pose, so game rules read the simulated one from
//! [`PhysicsPose::current`] or `PhysicsWorld::pose`. Kinematic bodies
//! without a character controller follow their `Transform` (input only). Only bodies that moved
//! in a step write their `Transform`: sleeping bodies cost no writes. Main thread, inside the
//! fixed step. Must not: convert glam types itself (see `convert`) or run the pipeline.

use std::collections::HashMap;

use glam::{Quat, Vec3};
use hecs::{Entity, With, Without, World};
use rapier3d::prelude::{
    ActiveCollisionTypes, ColliderBuilder, RigidBodyBuilder, RigidBodyHandle, SharedShape,
};

use super::character::CharacterController;
use super::convert::{pose_from_rapier, pose_to_rapier, vec_from_rapier, vec_to_rapier};
use super::shapes::{ColliderShape, ShapeError};
use crate::ecs::Transform;

/// How a body moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BodyKind {
    /// Never moves (level geometry, walls, floors).
    Static,
    /// Simulated: gravity, contacts, impulses.
    Dynamic,
    /// Moved by game code through its `Transform` (doors, elevators) or by a character
    /// controller; pushes dynamic bodies, is not pushed.
    Kinematic,
}

/// A rigid body, spawned into rapier at the next physics step from its entity's `Transform`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidBody {
    pub kind: BodyKind,
    /// Continuous collision detection: sweeps the body between steps so that a fast, small
    /// body cannot pass through thin walls. Costs a little per awake CCD body.
    pub ccd: bool,
    /// Linear velocity at spawn, metres per second (dynamic bodies).
    pub initial_velocity: Vec3,
    /// Fraction of velocity lost per second (1/s), linear and angular.
    pub linear_damping: f32,
    pub angular_damping: f32,
}

impl RigidBody {
    pub fn fixed() -> Self {
        Self::of(BodyKind::Static)
    }
    pub fn dynamic() -> Self {
        Self::of(BodyKind::Dynamic)
    }
    pub fn kinematic() -> Self {
        Self::of(BodyKind::Kinematic)
    }
    fn of(kind: BodyKind) -> Self {
        Self {
            kind,
            ccd: false,
            initial_velocity: Vec3::ZERO,
            linear_damping: 0.0,
            angular_damping: 0.0,
        }
    }
    /// Turns continuous collision detection on.
    pub fn with_ccd(mut self) -> Self {
        self.ccd = true;
        self
    }
    /// Starts the body at `velocity` (m/s).
    pub fn with_velocity(mut self, velocity: Vec3) -> Self {
        self.initial_velocity = velocity;
        self
    }
}

/// The body's collision shape, already checked (build it with [`Collider::new`]).
#[derive(Clone)]
pub struct Collider {
    shape: SharedShape,
    /// Centre of the shape in the body's frame, metres.
    pub offset: Vec3,
    /// Mass in kilograms; `None` derives it from the shape at 1000 kg/m³ (water).
    pub mass_kg: Option<f32>,
    /// Coulomb friction coefficient (rapier's default 0.5).
    pub friction: f32,
    /// Bounciness in [0, 1].
    pub restitution: f32,
    /// A sensor reports overlaps (see `sensors`) and never blocks anything.
    pub sensor: bool,
}

impl std::fmt::Debug for Collider {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Collider")
            .field("shape", &self.shape.shape_type())
            .field("offset", &self.offset)
            .field("mass_kg", &self.mass_kg)
            .field("sensor", &self.sensor)
            .finish()
    }
}

/// Density used when a collider states no mass: water, kg/m³.
pub const DEFAULT_DENSITY_KG_PER_M3: f32 = 1000.0;

impl Collider {
    /// A collider of `shape` (validated and built now: hulls are computed here).
    pub fn new(shape: &ColliderShape) -> Result<Self, ShapeError> {
        Ok(Self {
            shape: shape.build()?,
            offset: Vec3::ZERO,
            mass_kg: None,
            friction: 0.5,
            restitution: 0.0,
            sensor: false,
        })
    }
    /// Sets the mass (kg); non-positive or non-finite values are refused.
    pub fn with_mass(mut self, mass_kg: f32) -> Result<Self, ShapeError> {
        if !(mass_kg > 0.0 && mass_kg.is_finite()) {
            return Err(ShapeError::NotPositive {
                what: "mass",
                value: mass_kg,
            });
        }
        self.mass_kg = Some(mass_kg);
        Ok(self)
    }
    /// Makes the collider a sensor.
    pub fn as_sensor(mut self) -> Self {
        self.sensor = true;
        self
    }

    /// The shape's axis-aligned bounds in the body's frame, `offset` included: (centre, half
    /// extents), metres. For whatever needs a body's extent without rapier (water waders).
    pub fn local_bounds(&self) -> (Vec3, Vec3) {
        let aabb = self.shape.compute_local_aabb();
        (
            self.offset + vec_from_rapier(aabb.center()),
            vec_from_rapier(aabb.half_extents()),
        )
    }
}

/// The entity's body in the physics world; inserted at spawn. Despawning the entity or
/// removing its [`RigidBody`] removes the body at the next step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BodyHandle(pub(super) RigidBodyHandle);

/// The body's pose after the last two fixed steps (metres), for render interpolation:
/// `Transform` shows `previous → current` at the clock's alpha between steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhysicsPose {
    pub previous: (Vec3, Quat),
    pub current: (Vec3, Quat),
}

pub(super) fn entity_bits(entity: Entity) -> u128 {
    entity.to_bits().get() as u128
}

pub(super) fn entity_of(user_data: u128) -> Option<Entity> {
    Entity::from_bits(u64::try_from(user_data).ok()?)
}

/// Creates rapier bodies for entities that have a [`RigidBody`], a [`Collider`] and a
/// `Transform` but no [`BodyHandle`] yet, in entity order (deterministic).
pub(super) fn spawn_new(
    rapier: &mut rapier3d::prelude::PhysicsWorld,
    world: &mut World,
    handles: &mut HashMap<Entity, RigidBodyHandle>,
) {
    let mut new: Vec<(Entity, RigidBody, Collider, Transform)> = world
        .query::<Without<(Entity, &RigidBody, &Collider, &Transform), &BodyHandle>>()
        .iter()
        .map(|(e, b, c, t)| (e, *b, c.clone(), *t))
        .collect();
    new.sort_by_key(|(e, ..)| e.to_bits());
    for (entity, body, collider, transform) in new {
        let builder = match body.kind {
            BodyKind::Static => RigidBodyBuilder::fixed(),
            BodyKind::Dynamic => RigidBodyBuilder::dynamic(),
            // Characters set their next pose; so do game-driven ones (`ride.rs`).
            BodyKind::Kinematic => RigidBodyBuilder::kinematic_position_based(),
        };
        let rb = builder
            .pose(pose_to_rapier(transform.translation, transform.rotation))
            .linvel(vec_to_rapier(body.initial_velocity))
            .linear_damping(body.linear_damping)
            .angular_damping(body.angular_damping)
            .ccd_enabled(body.ccd)
            .user_data(entity_bits(entity));
        let mut cb = ColliderBuilder::new(collider.shape.clone())
            .position(pose_to_rapier(collider.offset, Quat::IDENTITY))
            .friction(collider.friction)
            .restitution(collider.restitution)
            .sensor(collider.sensor)
            .user_data(entity_bits(entity));
        cb = match collider.mass_kg {
            Some(kg) => cb.mass(kg),
            None => cb.density(DEFAULT_DENSITY_KG_PER_M3),
        };
        if collider.sensor {
            // Sensors see every kind of body, characters (kinematic) included.
            cb = cb.active_collision_types(ActiveCollisionTypes::all());
        }
        let (handle, _) = rapier.insert(rb, cb);
        handles.insert(entity, handle);
        let pose = (transform.translation, transform.rotation);
        let _ = world.insert(
            entity,
            (
                BodyHandle(handle),
                PhysicsPose {
                    previous: pose,
                    current: pose,
                },
            ),
        );
    }
}

/// Removes bodies whose entity was despawned or lost its [`RigidBody`].
pub(super) fn remove_dead(
    rapier: &mut rapier3d::prelude::PhysicsWorld,
    world: &mut World,
    handles: &mut HashMap<Entity, RigidBodyHandle>,
) {
    let mut dead: Vec<Entity> = handles
        .keys()
        .copied()
        .filter(|&e| !world.satisfies::<&RigidBody>(e))
        .collect();
    dead.sort_by_key(|e| e.to_bits());
    for entity in dead {
        if let Some(handle) = handles.remove(&entity) {
            rapier.remove_body(handle);
        }
        let _ = world.remove::<(BodyHandle, PhysicsPose)>(entity);
    }
}

/// Writes the poses of bodies rapier moved this step into the ECS; returns how many
/// `Transform`s were written. `moving` holds the entities written in the previous step and is
/// replaced by this step's; an entity that stopped (or fell asleep) gets one last write: its
/// resting pose.
pub(super) fn sync_moved(
    rapier: &rapier3d::prelude::PhysicsWorld,
    world: &mut World,
    moving: &mut Vec<Entity>,
) -> usize {
    let mut writes = 0;
    let mut now = Vec::new();
    for (_, rb) in rapier.active_bodies() {
        let Some(entity) = entity_of(rb.user_data) else {
            continue;
        };
        let game_driven = match world.get::<&RigidBody>(entity) {
            Ok(body) => {
                body.kind == BodyKind::Kinematic && !world.satisfies::<&CharacterController>(entity)
            }
            Err(_) => continue,
        };
        if game_driven {
            continue;
        }
        let Ok((pose, transform)) =
            world.query_one_mut::<(&mut PhysicsPose, &mut Transform)>(entity)
        else {
            continue;
        };
        let new = pose_from_rapier(rb.position());
        if new == pose.current {
            continue;
        }
        pose.previous = pose.current;
        pose.current = new;
        (transform.translation, transform.rotation) = new;
        writes += 1;
        now.push(entity);
    }
    now.sort_by_key(|e| e.to_bits());
    for &entity in moving.iter() {
        if now
            .binary_search_by_key(&entity.to_bits(), |e| e.to_bits())
            .is_ok()
        {
            continue;
        }
        if let Ok((handle, pose, transform)) =
            world.query_one_mut::<(&BodyHandle, &mut PhysicsPose, &mut Transform)>(entity)
        {
            // Its resting pose: where rapier left it when it fell asleep (or stopped).
            if let Some(rb) = rapier.bodies.get(handle.0) {
                pose.current = pose_from_rapier(rb.position());
            }
            pose.previous = pose.current;
            if (transform.translation, transform.rotation) != pose.current {
                (transform.translation, transform.rotation) = pose.current;
                writes += 1;
            }
        }
    }
    *moving = now;
    writes
}

/// Shows each moving body at `alpha` ∈ [0, 1] of the way from its previous to its current
/// step pose (render interpolation); returns how many `Transform`s were written.
pub(super) fn interpolate(world: &mut World, moving: &[Entity], alpha: f32) -> usize {
    let mut writes = 0;
    for &entity in moving {
        if let Ok((pose, transform)) =
            world.query_one_mut::<With<(&PhysicsPose, &mut Transform), &RigidBody>>(entity)
        {
            let (p0, r0) = pose.previous;
            let (p1, r1) = pose.current;
            transform.translation = p0.lerp(p1, alpha);
            transform.rotation = r0.slerp(r1, alpha);
            writes += 1;
        }
    }
    writes
}
