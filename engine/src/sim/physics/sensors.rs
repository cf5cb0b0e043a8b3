//! Sensors: colliders that detect bodies without blocking them (trigger volumes, pressure
//! plates, goal zones).
//!
//! Owns: [`SensorContacts`] (on an entity whose [`super::Collider`] is a sensor) and updating
//! it after every fixed step from rapier's intersection graph: which bodies' entities are
//! inside, which entered and which left during that step. Lists are sorted by entity, so the
//! outcome does not depend on hash order. Main thread, after the pipeline step.
//! Must not: decide what a trigger does (triggers are built on top of this later).

use hecs::{Entity, World};
use rapier3d::prelude::PhysicsWorld as RapierWorld;

use super::bodies::{BodyHandle, entity_of};

/// Who overlaps a sensor. Read by game rules; written by physics after each step.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SensorContacts {
    /// Entities whose bodies overlap the sensor now.
    pub inside: Vec<Entity>,
    /// Entities that started overlapping during the last step.
    pub entered: Vec<Entity>,
    /// Entities that stopped overlapping (or were despawned) during the last step.
    pub exited: Vec<Entity>,
}

/// Refreshes every [`SensorContacts`] from the narrow phase.
pub(super) fn update_sensors(rapier: &RapierWorld, world: &mut World) {
    for (entity, handle, contacts) in world
        .query_mut::<(Entity, &BodyHandle, &mut SensorContacts)>()
        .into_iter()
    {
        let mut now: Vec<Entity> = Vec::new();
        let Some(body) = rapier.bodies.get(handle.0) else {
            continue;
        };
        for &sensor in body.colliders() {
            for (a, b, intersecting) in rapier.narrow_phase.intersection_pairs_with(sensor) {
                if !intersecting {
                    continue;
                }
                let other = if a == sensor { b } else { a };
                let Some(other_entity) = rapier
                    .colliders
                    .get(other)
                    .and_then(|c| c.parent())
                    .and_then(|h| rapier.bodies.get(h))
                    .and_then(|b| entity_of(b.user_data))
                else {
                    continue;
                };
                if other_entity != entity {
                    now.push(other_entity);
                }
            }
        }
        now.sort_by_key(|e| e.to_bits());
        now.dedup();
        let contains = |list: &[Entity], e: &Entity| {
            list.binary_search_by_key(&e.to_bits(), |x| x.to_bits())
                .is_ok()
        };
        contacts.entered = now
            .iter()
            .filter(|e| !contains(&contacts.inside, e))
            .copied()
            .collect();
        contacts.exited = contacts
            .inside
            .iter()
            .filter(|e| !contains(&now, e))
            .copied()
            .collect();
        contacts.inside = now;
    }
}
