//! [`Hands`]: what a third-person character picks up, carries, puts down and throws, and the
//! body in front of it that it could take.
//!
//! The character's hands are an entity of their own with a physics `Carrier` (the same one the
//! first-person player holds its cubes with), placed each step at the character's chest and
//! turned to its heading: the held body floats in front of the chest and a wall stops it. A
//! body is taken by choice, not by a ray along the camera's view: the nearest dynamic body
//! whose centre is within reach of the character's centre (horizontally), in front of it (within
//! 70° of its heading or of the camera's view) and light enough to lift. The hands entity is
//! spawned at the first lift, so a level where nothing is ever lifted keeps its entities (and its
//! replays' state hashes) as they were.
//!
//! Main thread, in the game's fixed step, before physics (the physics step acts on the
//! carrier's request). Must not: read devices, move bodies itself, or know the runner.
//! Units: metres, kilograms, m/s; yaw 0 faces −Z, positive turns right.

use glam::{Quat, Vec2, Vec3};
use hecs::{Entity, World};

use crate::ecs::Transform;
use crate::sim::physics::{BodyKind, Carrier, CarryRequest, PhysicsWorld, RigidBody};
use crate::sim::triggers::Usable;

/// Cosine of the widest angle between the character's heading (or the camera's view) and a
/// body it can take (70°, as for usables).
const FACING_COS: f32 = 0.342;

/// How the character carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandsConfig {
    /// Heaviest body it lifts, kg (heavier ones it pushes).
    pub max_mass_kg: f32,
    /// Height of the hold point above the capsule's centre, metres.
    pub hold_height_m: f32,
    /// Distance of the hold point in front of the capsule's centre, metres.
    pub hold_distance_m: f32,
    /// Speed a throw adds along the heading, m/s.
    pub throw_speed_mps: f32,
}

impl Default for HandsConfig {
    fn default() -> Self {
        Self {
            max_mass_kg: 20.0,
            hold_height_m: 0.3,
            hold_distance_m: 0.8,
            throw_speed_mps: 4.0,
        }
    }
}

/// What the hands did this step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum HandsAct {
    #[default]
    Nothing,
    /// Asked to lift this body.
    Take(Entity),
    /// Asked to put the held body down.
    PutDown,
    /// Asked to throw the held body.
    Throw,
}

/// A third-person character's hands.
#[derive(Clone, Debug, Default)]
pub struct Hands {
    pub config: HandsConfig,
    /// The carrier entity, once something was lifted.
    entity: Option<Entity>,
    /// The body in front that a use press would take, as of the last step.
    takeable: Option<Entity>,
    /// Whether it held a body at the last step (for a HUD, which has no world to ask).
    carrying: bool,
}

impl Hands {
    /// The body held now (what the physics step wrote).
    pub fn held(&self, world: &World) -> Option<Entity> {
        let entity = self.entity?;
        world.get::<&Carrier>(entity).ok()?.held
    }

    /// The body a use press would take, as of the last step.
    pub fn takeable(&self) -> Option<Entity> {
        self.takeable
    }

    /// Whether it held a body at its last step (what [`Hands::held`] said then).
    pub fn carrying(&self) -> bool {
        self.carrying
    }

    /// The hands' entity (`None` until the first lift).
    pub fn entity(&self) -> Option<Entity> {
        self.entity
    }

    /// One step for the character `body` at `centre` with heading `heading_rad`: place the
    /// hands, find the takeable body (`facing`: unit horizontal directions that count as in
    /// front) and act on the presses. `use_free`: the use press was not taken by a usable.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        world: &mut World,
        physics: &PhysicsWorld,
        body: Entity,
        centre: Vec3,
        heading_rad: f32,
        facing: &[Vec3],
        reach_m: f32,
        use_free: bool,
        throw_pressed: bool,
    ) -> HandsAct {
        let held = self.held(world);
        self.carrying = held.is_some();
        self.place(world, centre, heading_rad);
        self.takeable = match held {
            Some(_) => None,
            None => nearest_takeable(
                world,
                physics,
                centre,
                facing,
                reach_m,
                self.config.max_mass_kg,
            ),
        };
        let (request, act) = match (held, self.takeable) {
            (Some(_), _) if throw_pressed => (
                Some(CarryRequest::Throw {
                    speed: self.config.throw_speed_mps,
                }),
                HandsAct::Throw,
            ),
            (Some(_), _) if use_free => (Some(CarryRequest::Drop), HandsAct::PutDown),
            (None, Some(target)) if use_free => {
                (Some(CarryRequest::Take(target)), HandsAct::Take(target))
            }
            _ => (None, HandsAct::Nothing),
        };
        if let Some(request) = request {
            let entity = self.spawn(world, body, centre, heading_rad);
            if let Ok(mut carrier) = world.get::<&mut Carrier>(entity) {
                carrier.request = Some(request);
            }
        }
        act
    }

    /// Moves the hands to the chest, turned to the heading (when they exist).
    fn place(&self, world: &mut World, centre: Vec3, heading_rad: f32) {
        if let Some(entity) = self.entity
            && let Ok(mut t) = world.get::<&mut Transform>(entity)
        {
            *t = hands_transform(&self.config, centre, heading_rad);
        }
    }

    /// The hands' entity, spawned at the chest on first use.
    fn spawn(&mut self, world: &mut World, body: Entity, centre: Vec3, heading_rad: f32) -> Entity {
        if let Some(entity) = self.entity
            && world.contains(entity)
        {
            return entity;
        }
        let carrier = Carrier {
            // The eye is the chest, pulled back to the capsule's axis: the hold point sits
            // `hold_distance_m` in front of it.
            hold_distance: self.config.hold_distance_m,
            hold_offset: Vec2::ZERO,
            hold_pitch_min: 0.0,
            // Put down where it is held: it drops the last few decimetres in front of the feet.
            place_reach: 0.0,
            reach: 0.0,
            max_mass_kg: self.config.max_mass_kg,
            ignore: Some(body),
            ..Carrier::default()
        };
        let entity = world.spawn((hands_transform(&self.config, centre, heading_rad), carrier));
        self.entity = Some(entity);
        entity
    }

    /// Forgets the hands (the level was spawned again: the entity is gone).
    pub fn forget(&mut self) {
        self.entity = None;
        self.takeable = None;
        self.carrying = false;
    }
}

/// Where the hands are: on the capsule's axis at hold height, looking along the heading.
fn hands_transform(config: &HandsConfig, centre: Vec3, heading_rad: f32) -> Transform {
    Transform {
        translation: centre + Vec3::Y * config.hold_height_m,
        rotation: Quat::from_rotation_y(-heading_rad),
        ..Transform::IDENTITY
    }
}

/// The dynamic body nearest `centre` (horizontally) within `reach` metres, in front (within
/// 70° of one of the unit horizontal `facing` directions, or under 0.3 m away), of at most
/// `max_mass` kg, and not a usable (a usable is used, not lifted).
pub fn nearest_takeable(
    world: &World,
    physics: &PhysicsWorld,
    centre: Vec3,
    facing: &[Vec3],
    reach: f32,
    max_mass: f32,
) -> Option<Entity> {
    let mut best: Option<(f32, Entity)> = None;
    for (entity, body) in world
        .query::<(Entity, &RigidBody)>()
        .without::<&Usable>()
        .iter()
    {
        if body.kind != BodyKind::Dynamic {
            continue;
        }
        let Some(mass) = physics.dynamic_mass(entity) else {
            continue;
        };
        if mass > max_mass {
            continue;
        }
        let Some((position, _)) = physics.pose(entity) else {
            continue;
        };
        let mut to = position - centre;
        to.y = 0.0;
        let distance = to.length();
        if !distance.is_finite() || distance > reach {
            continue;
        }
        let ahead = distance < 0.3 || facing.iter().any(|f| to.dot(*f) >= FACING_COS * distance);
        if ahead && best.is_none_or(|b| distance < b.0) {
            best = Some((distance, entity));
        }
    }
    best.map(|(_, e)| e)
}
