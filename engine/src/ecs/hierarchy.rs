//! Transform propagation: local [`Transform`]s and [`Parent`] links → [`GlobalTransform`]s.
//!
//! Owns: resolving the hierarchy once per fixed step, parents before children. A missing
//! parent counts as the world; a cycle is broken (its entities are placed as roots) rather
//! than looping. Main thread. Must not: touch anything but `GlobalTransform`.

use std::collections::HashMap;

use glam::Mat4;
use hecs::{Entity, World};

use super::components::{GlobalTransform, Parent, Transform};

/// Writes every entity's `GlobalTransform` from its `Transform` and its ancestors'. Entities
/// with a `Transform` but no `GlobalTransform` get one.
pub fn propagate_transforms(world: &mut World) {
    let locals: HashMap<Entity, (glam::Mat4, Option<Entity>)> = world
        .query::<(Entity, &Transform, Option<&Parent>)>()
        .iter()
        .map(|(e, t, p)| (e, (t.matrix(), p.map(|p| p.0))))
        .collect();
    let mut resolved: HashMap<Entity, Mat4> = HashMap::with_capacity(locals.len());
    for &start in locals.keys() {
        // Walk up to the first resolved ancestor (or the root), then back down.
        let mut chain = vec![start];
        let mut cursor = start;
        let mut base = Mat4::IDENTITY;
        loop {
            if let Some(m) = resolved.get(&cursor) {
                base = *m;
                chain.pop();
                break;
            }
            match locals.get(&cursor).and_then(|(_, p)| *p) {
                Some(parent) if locals.contains_key(&parent) && !chain.contains(&parent) => {
                    chain.push(parent);
                    cursor = parent;
                }
                _ => break,
            }
        }
        for &e in chain.iter().rev() {
            base *= locals[&e].0;
            resolved.insert(e, base);
        }
    }
    let missing: Vec<Entity> = world
        .query::<(Entity, &Transform)>()
        .without::<&GlobalTransform>()
        .iter()
        .map(|(e, _)| e)
        .collect();
    for e in missing {
        let _ = world.insert_one(e, GlobalTransform::default());
    }
    for (e, global) in world.query_mut::<(Entity, &mut GlobalTransform)>() {
        if let Some(m) = resolved.get(&e) {
            global.0 = *m;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};

    #[test]
    fn children_follow_parents_and_cycles_do_not_hang() {
        let mut world = World::new();
        let root = world.spawn((Transform::from_translation(Vec3::X),));
        let child = world.spawn((
            Transform {
                rotation: Quat::from_rotation_y(std::f32::consts::FRAC_PI_2),
                ..Transform::from_translation(Vec3::Z)
            },
            Parent(root),
        ));
        let grandchild = world.spawn((Transform::from_translation(Vec3::X), Parent(child)));
        let a = world.spawn((Transform::from_translation(Vec3::Y), Parent(root)));
        // A two-entity cycle.
        let c1 = world.spawn((Transform::from_translation(Vec3::X),));
        let c2 = world.spawn((Transform::from_translation(Vec3::X), Parent(c1)));
        world.insert_one(c1, Parent(c2)).expect("c1 exists");
        propagate_transforms(&mut world);
        let at = |e| {
            world
                .get::<&GlobalTransform>(e)
                .expect("global")
                .0
                .transform_point3(Vec3::ZERO)
        };
        assert!((at(root) - Vec3::X).length() < 1e-6);
        assert!((at(child) - Vec3::new(1.0, 0.0, 1.0)).length() < 1e-6);
        // Grandchild: +X in the child's frame, which is rotated 90° about Y: +X → −Z.
        assert!(
            (at(grandchild) - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-5,
            "{}",
            at(grandchild)
        );
        assert!((at(a) - Vec3::new(1.0, 1.0, 0.0)).length() < 1e-6);
        assert!(at(c1).is_finite() && at(c2).is_finite());
    }
}
