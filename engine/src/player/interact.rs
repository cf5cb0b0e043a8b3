//! What is under the crosshair: one ray query along the view on the scene of the last commit.
//!
//! Owns: [`focus`] and [`Focus`]: the nearest surface along the view within reach, whether its
//! entity is usable (a level `usables` entry: prompt and event) or a dynamic body that can be
//! picked up. Units: metres. Main thread, fixed step. Must not: change the world (the player
//! acts on the focus).

use glam::Vec3;
use hecs::{Entity, World};

use crate::query::Queries;
use crate::sim::physics::{BodyKind, RigidBody};
use crate::sim::triggers::Usable;
use crate::trace::Ray;

/// What the thing under the crosshair is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FocusKind {
    /// A usable instance: its prompt and the event using it sends.
    Usable(Usable),
    /// A dynamic body (it can be picked up if light enough).
    Body,
    /// Anything else.
    Surface,
}

/// The surface under the crosshair.
#[derive(Clone, Debug, PartialEq)]
pub struct Focus {
    pub entity: Entity,
    /// Metres from the eye.
    pub distance: f32,
    pub kind: FocusKind,
}

/// The first surface along the ray from `eye` along `view` (unit) within `reach` metres,
/// if it belongs to an entity.
pub fn focus(
    world: &World,
    queries: &Queries<'_>,
    eye: Vec3,
    view: Vec3,
    reach: f32,
) -> Option<Focus> {
    let ray = Ray::with_range(eye, view, 0.0, reach);
    let hit = queries.closest(&ray)?;
    let entity = hit.entity?;
    let kind = if let Ok(u) = world.get::<&Usable>(entity) {
        FocusKind::Usable((*u).clone())
    } else if world
        .get::<&RigidBody>(entity)
        .is_ok_and(|b| b.kind == BodyKind::Dynamic)
    {
        FocusKind::Body
    } else {
        FocusKind::Surface
    };
    Some(Focus {
        entity,
        distance: hit.t,
        kind,
    })
}
