//! Picking up, carrying and dropping a dynamic body (Reflect's glass cubes).
//!
//! Owns: [`Carrier`] (on the entity whose view carries: a root entity looking along its local
//! −Z, e.g. the first-person camera) and driving the held body each fixed step. The held body
//! stays dynamic, so it still collides with walls and other bodies: each step its velocity is
//! set to close the gap to the hold point (a critically damped spring in velocity form, capped
//! in speed), its spin is damped and gravity is off; dropping restores gravity and keeps its
//! velocity; throwing also gives it a speed along the view. Because it stays a dynamic body
//! driven by velocity, a wall stops it (and the carrier lets go once the body is stuck more
//! than `break_distance` behind it). Units: metres, seconds, kilograms. Main thread, before the pipeline step.
//! Must not: read devices (game rules set [`Carrier::request`]).

use glam::{Quat, Vec3};
use hecs::{Entity, World};
use rapier3d::prelude::{PhysicsWorld as RapierWorld, QueryFilter, Ray};

use super::bodies::{BodyHandle, entity_of};
use super::convert::{pose_to_rapier, vec_from_rapier, vec_to_rapier};
use crate::ecs::Transform;

/// What the game asks of a [`Carrier`] this step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CarryRequest {
    /// Pick up the dynamic body under the view's centre, within reach.
    Pick,
    /// Pick up this entity's dynamic body, wherever it is (the game chose it: a third-person
    /// character takes the body in front of it, not the one along its camera's view). Refused,
    /// like [`CarryRequest::Pick`], when the body is not dynamic or heavier than
    /// [`Carrier::max_mass_kg`].
    Take(Entity),
    /// Let go: gravity back on, the body keeps its velocity.
    Drop,
    /// Let go and throw: the body leaves along the view at `speed` m/s (added to the
    /// carrier's motion the body already had).
    Throw { speed: f32 },
}

/// Carries at most one body at a point in front of its entity's view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Carrier {
    /// Hold point: this many metres along the hold direction (the view, its pitch limited to
    /// `hold_pitch_min`).
    pub hold_distance: f32,
    /// Hold point offset across the hold direction, metres: +X to the view's right, +Y up
    /// (a first-person hold low and to the side keeps the crosshair clear).
    pub hold_offset: glam::Vec2,
    /// Lowest pitch of the hold direction, radians (looking further down does not pull the
    /// held body into the carrier's own feet).
    pub hold_pitch_min: f32,
    /// A drop places the body upright on the surface under the view's centre within this
    /// many metres (`place::find`); 0, or no such surface, lets go where it is held.
    pub place_reach: f32,
    /// Longest pick ray, metres.
    pub reach: f32,
    /// Heaviest body it lifts, kg.
    pub max_mass_kg: f32,
    /// Fastest the held body is moved towards the hold point, m/s.
    pub max_speed: f32,
    /// Drops the body if it ends up farther than this from the hold point (stuck behind a
    /// wall), metres.
    pub break_distance: f32,
    /// An entity the pick ray ignores (the carrier's own character).
    pub ignore: Option<Entity>,
    /// Set by game rules, consumed by the next physics step.
    pub request: Option<CarryRequest>,
    /// The body being carried (written by physics).
    pub held: Option<Entity>,
}

impl Default for Carrier {
    fn default() -> Self {
        Self {
            hold_distance: 1.5,
            hold_offset: glam::Vec2::ZERO,
            hold_pitch_min: -std::f32::consts::FRAC_PI_2,
            place_reach: 0.0,
            reach: 3.0,
            max_mass_kg: 60.0,
            max_speed: 12.0,
            break_distance: 2.0,
            ignore: None,
            request: None,
            held: None,
        }
    }
}

/// How quickly the held body closes the gap: the fraction of the remaining offset removed per
/// step (0.5: halves it every step, ~3 steps to 90 % at 60 Hz, no overshoot).
const GAP_CLOSED_PER_STEP: f32 = 0.5;
/// Fraction of the held body's spin kept per step.
const SPIN_KEPT_PER_STEP: f32 = 0.5;

/// Handles pick/drop requests and drives held bodies for one step of `dt` seconds.
pub(super) fn drive_carriers(rapier: &mut RapierWorld, world: &mut World, dt: f32) {
    let mut carriers: Vec<Entity> = world
        .query::<(Entity, &Carrier)>()
        .iter()
        .map(|(e, _)| e)
        .collect();
    carriers.sort_by_key(|e| e.to_bits());
    for entity in carriers {
        let Some((eye, view, ignore_body)) = carrier_view(world, entity) else {
            continue;
        };
        let Ok(carrier) = world.query_one_mut::<&mut Carrier>(entity) else {
            continue;
        };
        let request = carrier.request.take();
        let (holding, reach, max_mass) =
            (carrier.held.is_some(), carrier.reach, carrier.max_mass_kg);
        match request {
            Some(CarryRequest::Drop) => {
                let place_reach = carrier.place_reach;
                if let Some(handle) = release(rapier, world, entity)
                    && let Some(spot) =
                        super::place::find(rapier, eye, view, place_reach, handle, ignore_body)
                    && let Some(body) = rapier.bodies.get_mut(handle)
                {
                    body.set_position(pose_to_rapier(spot.position, spot.rotation), true);
                    body.set_linvel(vec_to_rapier(Vec3::ZERO), true);
                    body.set_angvel(vec_to_rapier(Vec3::ZERO), true);
                }
            }
            Some(CarryRequest::Throw { speed }) => {
                if let Some(handle) = release(rapier, world, entity)
                    && let Some(body) = rapier.bodies.get_mut(handle)
                    && speed.is_finite()
                {
                    let v = vec_from_rapier(body.linvel()) + view * speed;
                    body.set_linvel(vec_to_rapier(v), true);
                }
            }
            Some(CarryRequest::Pick) if !holding => {
                if let Some((picked, handle)) = pick(rapier, eye, view, reach, ignore_body) {
                    lift(rapier, world, entity, picked, handle, max_mass);
                }
            }
            Some(CarryRequest::Take(picked)) if !holding => {
                if let Ok(handle) = world.get::<&BodyHandle>(picked).map(|h| h.0) {
                    lift(rapier, world, entity, picked, handle, max_mass);
                }
            }
            _ => {}
        }
        let Ok(carrier) = world.query_one_mut::<&Carrier>(entity) else {
            continue;
        };
        let Some(held) = carrier.held else {
            continue;
        };
        let carrier = *carrier;
        let handle = world.get::<&BodyHandle>(held).map(|h| h.0).ok();
        let Some(handle) = handle else {
            let _ = release(rapier, world, entity);
            continue;
        };
        let target = hold_point(&carrier, eye, view);
        let Some(body) = rapier.bodies.get_mut(handle) else {
            let _ = release(rapier, world, entity);
            continue;
        };
        let gap = target - vec_from_rapier(body.translation());
        if gap.length() > carrier.break_distance {
            let _ = release(rapier, world, entity);
            continue;
        }
        let velocity = (gap * (GAP_CLOSED_PER_STEP / dt)).clamp_length_max(carrier.max_speed);
        body.set_linvel(vec_to_rapier(velocity), true);
        let spin = body.angvel() * SPIN_KEPT_PER_STEP;
        body.set_angvel(spin, true);
    }
}

/// Where `carrier` holds its body, for an eye at `eye` looking along unit `view`.
fn hold_point(carrier: &Carrier, eye: Vec3, view: Vec3) -> Vec3 {
    let flat = Vec3::new(view.x, 0.0, view.z);
    let Some(flat) = flat.try_normalize() else {
        return eye + view * carrier.hold_distance;
    };
    let pitch = view.y.clamp(-1.0, 1.0).asin().max(carrier.hold_pitch_min);
    let forward = flat * pitch.cos() + Vec3::Y * pitch.sin();
    let right = flat.cross(Vec3::Y);
    let up = right.cross(forward);
    eye + forward * carrier.hold_distance
        + right * carrier.hold_offset.x
        + up * carrier.hold_offset.y
}

/// Eye position, unit view direction, and the body the pick ray must ignore.
pub(super) fn carrier_view(
    world: &World,
    entity: Entity,
) -> Option<(Vec3, Vec3, Option<rapier3d::prelude::RigidBodyHandle>)> {
    let transform = *world.get::<&Transform>(entity).ok()?;
    let carrier = *world.get::<&Carrier>(entity).ok()?;
    let rotation: Quat = transform.rotation;
    let view = (rotation * Vec3::NEG_Z).normalize_or_zero();
    let ignore = carrier
        .ignore
        .and_then(|e| world.get::<&BodyHandle>(e).ok().map(|h| h.0))
        .or_else(|| world.get::<&BodyHandle>(entity).ok().map(|h| h.0));
    Some((transform.translation, view, ignore))
}

fn pick(
    rapier: &RapierWorld,
    eye: Vec3,
    view: Vec3,
    reach: f32,
    ignore: Option<rapier3d::prelude::RigidBodyHandle>,
) -> Option<(Entity, rapier3d::prelude::RigidBodyHandle)> {
    let mut filter = QueryFilter::default().exclude_sensors();
    if let Some(body) = ignore {
        filter = filter.exclude_rigid_body(body);
    }
    let queries = rapier.query_pipeline_with_filter(filter);
    let ray = Ray::new(vec_to_rapier(eye), vec_to_rapier(view));
    let (collider, _) = queries.cast_ray(&ray, reach, true)?;
    let handle = rapier.colliders.get(collider)?.parent()?;
    let entity = entity_of(rapier.bodies.get(handle)?.user_data)?;
    Some((entity, handle))
}

/// `carrier` takes `picked` (body `handle`) when it is dynamic and at most `max_mass` kg:
/// gravity off, held from now on.
fn lift(
    rapier: &mut RapierWorld,
    world: &mut World,
    carrier: Entity,
    picked: Entity,
    handle: rapier3d::prelude::RigidBodyHandle,
    max_mass: f32,
) {
    if let Some(body) = rapier.bodies.get_mut(handle)
        && body.is_dynamic()
        && body.mass() <= max_mass
    {
        body.set_gravity_scale(0.0, true);
        if let Ok(c) = world.query_one_mut::<&mut Carrier>(carrier) {
            c.held = Some(picked);
        }
    }
}

/// Lets go of the carrier's body: gravity back on, velocity kept. Returns the released body.
fn release(
    rapier: &mut RapierWorld,
    world: &mut World,
    carrier: Entity,
) -> Option<rapier3d::prelude::RigidBodyHandle> {
    let c = world.query_one_mut::<&mut Carrier>(carrier).ok()?;
    let held = c.held.take()?;
    let handle = world.get::<&BodyHandle>(held).ok()?.0;
    let body = rapier.bodies.get_mut(handle)?;
    body.set_gravity_scale(1.0, true);
    Some(handle)
}
