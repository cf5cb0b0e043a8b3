//! Shared helpers of the physics tests: a world with a ground plane, spawning helpers, and
//! stepping at the engine's fixed rate (60 Hz).
#![allow(dead_code)]

use candela::ecs::Transform;
use candela::sim::physics::{Collider, ColliderShape, PhysicsWorld, RigidBody};
use glam::{Quat, Vec3};
use hecs::{Entity, World};

/// The engine's fixed step (`FixedClock::default()`), seconds.
pub const STEP_SECONDS: f64 = 1.0 / 60.0;

/// A world and its physics, with a static ground slab whose top is at y = 0.
pub struct Sim {
    pub world: World,
    pub physics: PhysicsWorld,
}

impl Sim {
    pub fn new() -> Self {
        let mut sim = Self {
            world: World::new(),
            physics: PhysicsWorld::new(),
        };
        sim.fixed_box(Vec3::new(0.0, -0.5, 0.0), Vec3::new(50.0, 0.5, 50.0));
        sim
    }

    /// A static box centred at `centre` (metres).
    pub fn fixed_box(&mut self, centre: Vec3, half_extents: Vec3) -> Entity {
        self.fixed(centre, Quat::IDENTITY, ColliderShape::Box { half_extents })
    }

    pub fn fixed(&mut self, centre: Vec3, rotation: Quat, shape: ColliderShape) -> Entity {
        let collider = Collider::new(&shape).expect("valid test shape");
        let transform = Transform {
            rotation,
            ..Transform::from_translation(centre)
        };
        self.world.spawn((transform, RigidBody::fixed(), collider))
    }

    /// A dynamic body of `shape` and `mass_kg` at `centre`.
    pub fn dynamic(&mut self, centre: Vec3, shape: ColliderShape, mass_kg: f32) -> Entity {
        self.dynamic_with(centre, shape, mass_kg, RigidBody::dynamic())
    }

    pub fn dynamic_with(
        &mut self,
        centre: Vec3,
        shape: ColliderShape,
        mass_kg: f32,
        body: RigidBody,
    ) -> Entity {
        let collider = Collider::new(&shape)
            .and_then(|c| c.with_mass(mass_kg))
            .expect("valid test shape");
        self.world
            .spawn((Transform::from_translation(centre), body, collider))
    }

    pub fn step(&mut self) -> candela::sim::physics::StepReport {
        self.physics.step(&mut self.world, STEP_SECONDS)
    }

    pub fn steps(&mut self, n: usize) {
        for _ in 0..n {
            self.step();
        }
    }

    pub fn position(&self, entity: Entity) -> Vec3 {
        self.world
            .get::<&Transform>(entity)
            .map(|t| t.translation)
            .expect("entity has a Transform")
    }
}
