//! Breakable bodies: a wall or a pillar made of pre-fractured pieces that stand still (static
//! or kinematic bodies) until they break, then fall and scatter as dynamic bodies.
//!
//! Owns: the level's [`Breakable`]s and whether each has broken; the impact test. A breakable
//! with an impact speed breaks, inside the physics step and *before* rapier resolves contacts,
//! when a dynamic body moving at least that fast would touch one of its pieces within the step
//! (its colliders swept along its velocity, `cast_shape`): the pieces are dynamic by the time
//! the body reaches them, so a fast boulder carries on through the wall (it never stalls on
//! pieces that break under it), and CCD on the boulder keeps it from tunnelling through a wall
//! that holds. A `Break` rule action breaks one at any time. Main thread, fixed step.
//! Deterministic: breakables are visited in level order, and whether any fast body would hit a
//! breakable does not depend on the order the bodies are tried in. Must not: touch the ECS
//! beyond the pieces' [`super::RigidBody`] kind (their `Transform`s follow their bodies as any
//! others).

use std::collections::HashMap;

use hecs::{Entity, World};
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::prelude::{
    Collider, ColliderHandle, PhysicsWorld as RapierWorld, QueryFilter, RigidBodyHandle,
    RigidBodyType,
};

/// Pre-fractured pieces that break together.
#[derive(Clone, Debug, PartialEq)]
pub struct Breakable {
    /// The pieces' entities (bodies that stand still until the break).
    pub pieces: Vec<Entity>,
    /// The speed, m/s, of a dynamic body about to hit a piece that breaks it (`None`: only a
    /// `Break` action does).
    pub impact_speed: Option<f32>,
    /// Kilograms of each piece once it is free.
    pub piece_mass: f32,
    /// Metres per second each piece is sent away from the pieces' centre when it breaks, and
    /// tipped outward at that speed over 0.5 m (rad/s), so a wall a rule breaks falls apart
    /// instead of standing as a stack.
    pub scatter_speed: f32,
}

/// The level's breakables and which have broken.
#[derive(Clone, Debug, Default)]
pub(super) struct Breakables {
    list: Vec<(Breakable, bool)>,
}

impl Breakables {
    pub(super) fn set(&mut self, list: Vec<Breakable>) {
        self.list = list.into_iter().map(|b| (b, false)).collect();
    }

    pub(super) fn broken(&self, index: usize) -> Option<bool> {
        self.list.get(index).map(|(_, broken)| *broken)
    }

    /// Broken flags, one word each (empty without breakables: hashes stay as before).
    pub(super) fn state_words(&self, out: &mut Vec<u64>) {
        out.extend(self.list.iter().map(|(_, broken)| u64::from(*broken)));
    }

    /// Breaks breakable `index` now: its pieces become dynamic bodies of their mass, awake,
    /// in rapier and in their ECS [`super::RigidBody`] (so the step writes their poses out
    /// and no longer drives them as platforms). Returns whether it was standing.
    pub(super) fn break_now(
        &mut self,
        index: usize,
        world: &mut World,
        rapier: &mut RapierWorld,
        handles: &HashMap<Entity, RigidBodyHandle>,
    ) -> bool {
        let Some((breakable, broken)) = self.list.get_mut(index) else {
            return false;
        };
        if *broken {
            return false;
        }
        *broken = true;
        let centres: Vec<Option<rapier3d::math::Vec3>> = (breakable.pieces.iter())
            .map(|p| handles.get(p).and_then(|&h| rapier.bodies.get(h)))
            .map(|b| b.map(|b| b.translation()))
            .collect();
        let known: Vec<_> = centres.iter().flatten().copied().collect();
        let centre =
            known.iter().copied().sum::<rapier3d::math::Vec3>() / known.len().max(1) as f32;
        for (piece, at) in breakable.pieces.iter().zip(&centres) {
            if let Ok(mut body) = world.get::<&mut super::RigidBody>(*piece) {
                body.kind = super::BodyKind::Dynamic;
            }
            let Some(body) = handles.get(piece).and_then(|&h| rapier.bodies.get_mut(h)) else {
                continue;
            };
            body.set_body_type(RigidBodyType::Dynamic, true);
            if let Some(at) = at {
                let away = (*at - centre).normalize_or_zero();
                body.set_linvel(away * breakable.scatter_speed, true);
                // And tipped outward, as if turning about a point half a metre below: the
                // pieces of a stack do not ride on one another.
                let tip = rapier3d::math::Vec3::Y.cross(away) * (breakable.scatter_speed / 0.5);
                body.set_angvel(tip, true);
            }
            let colliders: Vec<ColliderHandle> = body.colliders().to_vec();
            let share = breakable.piece_mass / colliders.len().max(1) as f32;
            for c in colliders {
                if let Some(collider) = rapier.colliders.get_mut(c) {
                    collider.set_mass(share);
                }
            }
        }
        true
    }

    /// Breaks every standing breakable with an impact speed that a dynamic body moving at
    /// least that fast would touch within `seconds`. Costs nothing while no standing breakable
    /// has an impact speed; otherwise the awake dynamic bodies are gathered once per step.
    pub(super) fn break_on_impact(
        &mut self,
        world: &mut World,
        rapier: &mut RapierWorld,
        handles: &HashMap<Entity, RigidBodyHandle>,
        seconds: f32,
    ) {
        let standing = |(b, broken): &(Breakable, bool)| b.impact_speed.filter(|_| !broken);
        let Some(slowest) = self.list.iter().filter_map(standing).reduce(f32::min) else {
            return;
        };
        // (body, speed m/s) of the awake dynamic bodies fast enough for some breakable.
        let movers: Vec<(RigidBodyHandle, f32)> = rapier
            .active_bodies()
            .filter(|(_, b)| b.is_dynamic())
            .map(|(h, b)| (h, b.linvel().length()))
            .filter(|&(_, speed)| speed >= slowest)
            .collect();
        if movers.is_empty() {
            return;
        }
        for index in 0..self.list.len() {
            let Some(speed) = standing(&self.list[index]) else {
                continue;
            };
            let fast = movers.iter().filter(|(_, v)| *v >= speed).map(|(h, _)| *h);
            if impact(rapier, handles, &self.list[index].0.pieces, fast, seconds) {
                self.break_now(index, world, rapier, handles);
            }
        }
    }
}

/// Whether one of `movers` (dynamic bodies) would touch one of `pieces`' colliders within
/// `seconds`, its colliders swept along its velocity.
fn impact(
    rapier: &RapierWorld,
    handles: &HashMap<Entity, RigidBodyHandle>,
    pieces: &[Entity],
    mut movers: impl Iterator<Item = RigidBodyHandle>,
    seconds: f32,
) -> bool {
    let targets: Vec<RigidBodyHandle> = pieces
        .iter()
        .filter_map(|p| handles.get(p))
        .copied()
        .collect();
    let is_piece =
        |_: ColliderHandle, c: &Collider| c.parent().is_some_and(|p| targets.contains(&p));
    movers.any(|handle| {
        let Some(body) = rapier.bodies.get(handle) else {
            return false;
        };
        let velocity = body.linvel();
        let filter = QueryFilter::default()
            .exclude_sensors()
            .exclude_rigid_body(handle)
            .predicate(&is_piece);
        let queries = rapier.query_pipeline_with_filter(filter);
        body.colliders().iter().any(|&c| {
            rapier.colliders.get(c).is_some_and(|collider| {
                let options = ShapeCastOptions::with_max_time_of_impact(seconds);
                queries
                    .cast_shape(collider.position(), velocity, collider.shape(), options)
                    .is_some()
            })
        })
    })
}
