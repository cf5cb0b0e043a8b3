//! [`PhysicsWorld`]: the rapier pipeline behind the ECS, stepped once per fixed step.
//!
//! Owns: rapier's world (bodies, colliders, broad and narrow phase, islands, CCD solver), the
//! entity ↔ body map, the list of bodies that moved last step (for render interpolation and
//! the "sleeping bodies write nothing" rule) and the per-step counts. One step, in order:
//! spawn new bodies → remove dead ones → game-driven kinematic bodies' motions (`ride`) →
//! carriers → characters (riding those motions) → breakables hit at speed break (`breaking`)
//! → rapier step (gravity −9.81 m/s² on Y, CCD, sleeping) → poses of moved bodies out → sensors. Main thread, in the fixed step after game rules. Deterministic: the same world and
//! inputs give bit-identical results on the same build and machine (rapier runs single-threaded
//! here; every ECS walk is in entity order).
//! Must not: render, read devices, or let rapier's math types out (see `convert`).

use std::collections::HashMap;

use glam::{Quat, Vec3};
use hecs::{Entity, World};
use rapier3d::prelude::{PhysicsWorld as RapierWorld, QueryFilter, Ray, RigidBodyHandle};

use super::bodies::{self, BodyHandle, entity_of};
use super::breaking::{Breakable, Breakables};
use super::convert::{pose_from_rapier, pose_to_rapier, vec_from_rapier, vec_to_rapier};
use super::{carry, character, ride, sensors};

/// Gravity, m/s², along −Y.
pub const GRAVITY: f32 = 9.81;
/// Natural frequency of body–body contact springs, Hz (rapier's default: 30).
pub const CONTACT_HZ: f32 = 90.0;
/// Solver iterations (substeps) per step (rapier's default: 4).
pub const SOLVER_ITERATIONS: usize = 8;

/// What one physics step did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepReport {
    /// Dynamic and kinematic bodies awake after the step (the per-frame work report's "awake
    /// physics bodies").
    pub awake_bodies: usize,
    /// ECS `Transform`s physics wrote in the step (only bodies that moved).
    pub transform_writes: usize,
}

/// The physics simulation of a world of entities.
pub struct PhysicsWorld {
    rapier: RapierWorld,
    handles: HashMap<Entity, RigidBodyHandle>,
    moving: Vec<Entity>,
    last: StepReport,
    steps: u64,
    breakables: Breakables,
}

impl Default for PhysicsWorld {
    fn default() -> Self {
        Self::new()
    }
}

impl PhysicsWorld {
    /// An empty world with gravity −9.81 m/s² on Y.
    pub fn new() -> Self {
        let mut rapier = RapierWorld::new();
        rapier.gravity = rapier3d::math::Vector::Y * -GRAVITY;
        // Stiffer contacts and more substeps than rapier's defaults (30 Hz, 4 iterations): with
        // those, a stack of 10 half-metre boxes sinks 24 mm and its top creeps 7 mm sideways in
        // 10 s; with 90 Hz and 8 iterations the largest drift is 3.5 mm
        // (tests/physics_stability.rs). 120 Hz at 4 iterations goes unstable (the spring gets
        // too stiff for the substep), so frequency and iterations move together.
        rapier
            .integration_parameters
            .contact_softness
            .natural_frequency = CONTACT_HZ;
        rapier.integration_parameters.num_solver_iterations = SOLVER_ITERATIONS;
        Self {
            rapier,
            handles: HashMap::new(),
            moving: Vec::new(),
            last: StepReport::default(),
            steps: 0,
            breakables: Breakables::default(),
        }
    }

    /// Advances the simulation by `step_seconds` (the fixed clock's step) and syncs the ECS.
    pub fn step(&mut self, world: &mut World, step_seconds: f64) -> StepReport {
        let dt = step_seconds as f32;
        bodies::spawn_new(&mut self.rapier, world, &mut self.handles);
        bodies::remove_dead(&mut self.rapier, world, &mut self.handles);
        let platforms = ride::platform_moves(&mut self.rapier, world);
        carry::drive_carriers(&mut self.rapier, world, dt);
        character::move_characters(&mut self.rapier, world, &platforms, dt);
        self.rapier.integration_parameters.dt = dt;
        // A little past the step, so a body that arrives exactly at its end breaks the pieces
        // before it touches them, not a step later.
        (self.breakables).break_on_impact(world, &mut self.rapier, &self.handles, dt * 1.25);
        self.rapier.step();
        let transform_writes = bodies::sync_moved(&self.rapier, world, &mut self.moving);
        sensors::update_sensors(&self.rapier, world);
        self.steps += 1;
        self.last = StepReport {
            awake_bodies: self.awake_bodies(),
            transform_writes,
        };
        self.last
    }

    /// Shows moving bodies `alpha` ∈ [0, 1] of the way from their previous to their current
    /// step pose (the fixed clock's `alpha()`); call once per frame after the steps. Returns
    /// how many `Transform`s it wrote.
    pub fn interpolate(&self, world: &mut World, alpha: f64) -> usize {
        bodies::interpolate(world, &self.moving, alpha.clamp(0.0, 1.0) as f32)
    }

    /// Dynamic and kinematic bodies that are awake (not sleeping) now.
    pub fn awake_bodies(&self) -> usize {
        self.rapier.islands.num_active_bodies()
    }

    /// What the last [`Self::step`] did.
    pub fn last_step(&self) -> StepReport {
        self.last
    }

    /// Steps taken since creation.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Bodies in the simulation (every kind).
    pub fn body_count(&self) -> usize {
        self.rapier.bodies.len()
    }

    fn body(&self, entity: Entity) -> Option<&rapier3d::prelude::RigidBody> {
        self.rapier.bodies.get(*self.handles.get(&entity)?)
    }

    /// The simulated pose of `entity`'s body (metres), as of the last step.
    pub fn pose(&self, entity: Entity) -> Option<(Vec3, Quat)> {
        self.body(entity).map(|b| pose_from_rapier(b.position()))
    }

    /// Linear velocity of `entity`'s body, m/s.
    pub fn linear_velocity(&self, entity: Entity) -> Option<Vec3> {
        self.body(entity).map(|b| vec_from_rapier(b.linvel()))
    }

    /// Mass of `entity`'s body, kg, when it is dynamic (`None`: no such body, or a static or
    /// kinematic one, which no push or lift moves).
    pub fn dynamic_mass(&self, entity: Entity) -> Option<f32> {
        self.body(entity)
            .filter(|b| b.is_dynamic())
            .map(|b| b.mass())
    }

    /// Whether `entity`'s body sleeps (`None`: no such body).
    pub fn is_sleeping(&self, entity: Entity) -> Option<bool> {
        self.body(entity).map(|b| b.is_sleeping())
    }

    /// Teleports `entity`'s body (metres), waking it; its `Transform` follows at the next step.
    pub fn set_pose(&mut self, entity: Entity, translation: Vec3, rotation: Quat) -> bool {
        let Some(&handle) = self.handles.get(&entity) else {
            return false;
        };
        let Some(body) = self.rapier.bodies.get_mut(handle) else {
            return false;
        };
        body.set_position(pose_to_rapier(translation, rotation), true);
        true
    }

    /// Adds an impulse (kg·m/s) at the centre of mass of `entity`'s body, waking it.
    pub fn apply_impulse(&mut self, entity: Entity, impulse: Vec3) -> bool {
        let Some(&handle) = self.handles.get(&entity) else {
            return false;
        };
        let Some(body) = self.rapier.bodies.get_mut(handle) else {
            return false;
        };
        body.apply_impulse(vec_to_rapier(impulse), true);
        true
    }

    /// Where the body held by `carrier` (an entity with a [`super::Carrier`]) would rest if
    /// it were dropped now (`place::find`), for a preview; `None` when nothing is held, the
    /// carrier places nothing, or no surface under its view takes the body.
    pub fn placement(&self, world: &World, carrier: Entity) -> Option<super::Placement> {
        let (eye, view, ignore) = super::carry::carrier_view(world, carrier)?;
        let c = *world.get::<&super::Carrier>(carrier).ok()?;
        let held = world.get::<&BodyHandle>(c.held?).ok()?.0;
        super::place::find(&self.rapier, eye, view, c.place_reach, held, ignore)
    }

    /// The first body hit by a ray from `origin` along `direction` (need not be unit length)
    /// within `max_distance` metres, and the distance to it; sensors are ignored.
    pub fn cast_ray(
        &self,
        origin: Vec3,
        direction: Vec3,
        max_distance: f32,
    ) -> Option<(Entity, f32)> {
        let direction = direction.try_normalize()?;
        let queries = self
            .rapier
            .query_pipeline_with_filter(QueryFilter::default().exclude_sensors());
        let ray = Ray::new(vec_to_rapier(origin), vec_to_rapier(direction));
        let (collider, distance) = queries.cast_ray(&ray, max_distance, true)?;
        let body = self.rapier.colliders.get(collider)?.parent()?;
        let entity = entity_of(self.rapier.bodies.get(body)?.user_data)?;
        Some((entity, distance))
    }

    /// Whether the segment from `a` to `b` (metres) passes through a collider of `entity`'s
    /// body (sensors included: a laser crossing a trigger volume).
    pub fn segment_touches(&self, entity: Entity, a: Vec3, b: Vec3) -> bool {
        let Some(body) = self.body(entity) else {
            return false;
        };
        let length = (b - a).length();
        let Some(direction) = (b - a).try_normalize() else {
            return false;
        };
        let ray = Ray::new(vec_to_rapier(a), vec_to_rapier(direction));
        body.colliders().iter().any(|&c| {
            self.rapier.colliders.get(c).is_some_and(|collider| {
                collider
                    .shape()
                    .intersects_ray(collider.position(), &ray, length)
            })
        })
    }

    /// Every body's simulated state as words, in entity order, for state hashes: the entity's
    /// bits, the pose (translation, rotation), linear and angular velocity (f32 bits) and
    /// whether it sleeps.
    pub fn state_words(&self) -> Vec<u64> {
        let mut bodies: Vec<(&Entity, &RigidBodyHandle)> = self.handles.iter().collect();
        bodies.sort_by_key(|(e, _)| e.to_bits());
        let mut out = Vec::with_capacity(bodies.len() * 15);
        for (entity, &handle) in bodies {
            let Some(b) = self.rapier.bodies.get(handle) else {
                continue;
            };
            out.push(entity.to_bits().get());
            let (t, r) = pose_from_rapier(b.position());
            let (v, w) = (vec_from_rapier(b.linvel()), vec_from_rapier(b.angvel()));
            let floats = t
                .to_array()
                .into_iter()
                .chain(r.to_array())
                .chain(v.to_array());
            out.extend(floats.chain(w.to_array()).map(|x| u64::from(x.to_bits())));
            out.push(u64::from(b.is_sleeping()));
        }
        self.breakables.state_words(&mut out);
        out
    }

    /// The level's breakable bodies (replacing any from before): pre-fractured pieces that
    /// stand until a fast body is about to hit one or [`PhysicsWorld::break_now`] is called
    /// (`breaking.rs`).
    pub fn set_breakables(&mut self, list: Vec<Breakable>) {
        self.breakables.set(list);
    }

    /// Breaks breakable `index` now (its pieces fall free from the next step); whether it was
    /// standing.
    pub fn break_now(&mut self, world: &mut World, index: usize) -> bool {
        self.breakables
            .break_now(index, world, &mut self.rapier, &self.handles)
    }

    /// Whether breakable `index` has broken (`None`: no such breakable).
    pub fn broken(&self, index: usize) -> Option<bool> {
        self.breakables.broken(index)
    }

    /// The handle of `entity`'s body, if it has one.
    pub fn handle(&self, entity: Entity) -> Option<BodyHandle> {
        self.handles.get(&entity).map(|&h| BodyHandle(h))
    }
}
