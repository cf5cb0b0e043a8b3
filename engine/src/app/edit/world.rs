//! [`EditWorld`]: keeping the running world in step with the editor's document (issue 12,
//! `docs/EDITOR.md` "Keeping the world in step"), so that an edit is seen lit at once.
//!
//! After each applied edit, undo or redo the editor hands its [`Touch`] here:
//! - `Touch::Transforms`: each moved instance's entity gets its new `Transform` in place
//!   (static entities are marked `Restyled` so the extractor looks at them again) and its
//!   body, if it has one, is teleported there; a body whose scale changed is rebuilt with the
//!   whole level, since its collider was built at the old scale.
//! - `Touch::Level` (models, materials, gameplay, inserted or deleted instances): the world is
//!   built again from the document ([`EditTarget::build`]) and the level spawned again in place
//!   of the old one — its entities, characters and their children despawned, light groups
//!   back on, the level's logic restarted. Models are registered again only when the
//!   document's model sections changed. A document that does not load keeps the old world and
//!   returns the error (the editor shows it; the save check names it too).
//!
//! Main thread, outside the engine's frame. Must not: touch the renderer (everything reaches it
//! through the next commit) or the document.

use glam::{Vec3, Vec4Swizzles};
use hecs::Entity;

use crate::app::runner::EditTarget;
use crate::app::runner::Engine;
use crate::app::runner::SpawnedLevel;
use crate::assets::{AssetError, Level, SceneDesc, TransformDesc};
use crate::ecs::{Restyled, Static, Transform};
use crate::editor::Touch;
use crate::level::PlayableLevel;
use crate::sim::physics::RigidBody;

/// What following an edit did to the world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Followed {
    /// Entities moved in place (this many).
    Moved(usize),
    /// The level was spawned again: the game's handles of its entities are stale.
    Respawned,
}

/// Model-space bounds (metres, min and max corners).
pub type Bounds = (Vec3, Vec3);

/// The world of a level being edited: the target, what is spawned of it, and the bounds of
/// each document instance's model (for the selection highlight and framing).
pub struct EditWorld {
    pub target: EditTarget,
    spawned: SpawnedLevel,
    /// Model-space bounds of each world instance's model, in world instance order.
    bounds: Vec<Option<Bounds>>,
    /// The model sections the registered models were built from (the edited file's, the
    /// base's).
    sections: Option<(ModelSections, Option<ModelSections>)>,
    /// The light groups the spawned world's level switches off at its start (`lights_off`).
    lights_off: Vec<u32>,
}

/// The parts of a level its models are built from.
#[derive(Clone, PartialEq)]
struct ModelSections {
    models: Vec<crate::assets::ModelEntry>,
    grids: Vec<crate::assets::GridEntry>,
    boxes: Vec<crate::assets::BoxEntry>,
    terrains: Vec<crate::assets::TerrainEntry>,
    cities: Vec<crate::assets::CityEntry>,
}

impl ModelSections {
    fn of(level: &Level) -> Self {
        Self {
            models: level.models.clone(),
            grids: level.grids.clone(),
            boxes: level.boxes.clone(),
            terrains: level.terrains.clone(),
            cities: level.cities.clone(),
        }
    }
}

impl EditWorld {
    /// The world as the game spawned it (`spawned`); nothing is known of its models until the
    /// first [`EditWorld::respawn`].
    pub fn new(target: EditTarget, spawned: SpawnedLevel) -> Self {
        Self {
            target,
            spawned,
            bounds: Vec::new(),
            sections: None,
            lights_off: Vec::new(),
        }
    }

    /// What is spawned now.
    pub fn spawned(&self) -> &SpawnedLevel {
        &self.spawned
    }

    /// The entity of each of the document's instances, in document order (those the world
    /// does not have are left out at the end).
    pub fn entities(&self, level: &Level) -> &[Entity] {
        let all = &self.spawned.entities;
        let first = self.target.first_instance.min(all.len());
        let end = (first + level.instances.len()).min(all.len());
        &all[first..end]
    }

    /// World-space corners of document instance `index`'s model bounds, if known.
    pub fn world_box(&self, level: &Level, index: usize) -> Option<[Vec3; 8]> {
        self.box_at(index, &level.instances.get(index)?.transform)
    }

    /// [`EditWorld::world_box`] of instance `index` were it at `transform`.
    pub fn box_at(&self, index: usize, transform: &TransformDesc) -> Option<[Vec3; 8]> {
        let (lo, hi) = (*self.bounds.get(self.target.first_instance + index)?)?;
        let m = transform.world_from_model();
        let mut out = [Vec3::ZERO; 8];
        for (k, corner) in out.iter_mut().enumerate() {
            let p = Vec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            );
            *corner = m.transform_point3(p);
        }
        Some(out)
    }

    /// Brings the world up to date after an edit of `level` (the edited document) that
    /// changed `touch`.
    pub fn follow(
        &mut self,
        engine: &mut Engine,
        level: &Level,
        touch: &Touch,
    ) -> Result<Followed, AssetError> {
        self.follow_in(engine, level, None, touch)
    }

    /// [`EditWorld::follow`] in a composed world whose base file is edited too (`base`, as
    /// edited; `None`: as the target read it).
    pub fn follow_in(
        &mut self,
        engine: &mut Engine,
        level: &Level,
        base: Option<&Level>,
        touch: &Touch,
    ) -> Result<Followed, AssetError> {
        match touch {
            Touch::Transforms(indices) => match self.move_in_place(engine, level, indices) {
                Some(moved) => Ok(Followed::Moved(moved)),
                None => (self.respawn_in(engine, level, base)).map(|()| Followed::Respawned),
            },
            Touch::Level => (self.respawn_in(engine, level, base)).map(|()| Followed::Respawned),
        }
    }

    /// Moves the entities of `indices` to their document transforms; `None` when one of them
    /// cannot be moved in place (a body whose scale changed, an instance the world lacks).
    fn move_in_place(
        &mut self,
        engine: &mut Engine,
        level: &Level,
        indices: &[usize],
    ) -> Option<usize> {
        let mut moves = Vec::with_capacity(indices.len());
        for &index in indices {
            let entry = level.instances.get(index)?;
            let entity = *self.entities(level).get(index)?;
            let transform = Transform::from_matrix(entry.transform.world_from_model());
            let world = &engine.world;
            let old_scale = world.get::<&Transform>(entity).ok()?.scale;
            let has_body = world.satisfies::<&RigidBody>(entity);
            if has_body && !old_scale.abs_diff_eq(transform.scale, 1e-6) {
                return None;
            }
            moves.push((entity, transform, has_body));
        }
        for &(entity, transform, has_body) in &moves {
            let is_static = engine.world.satisfies::<&Static>(entity);
            let _ = engine.world.insert_one(entity, transform);
            if is_static {
                let _ = engine.world.insert_one(entity, Restyled);
            }
            if has_body {
                engine
                    .physics
                    .set_pose(entity, transform.translation, transform.rotation);
            }
        }
        Some(moves.len())
    }

    /// Builds the world from `level` and spawns it in place of the old one (also what the
    /// editor does when it opens, so that what was played is discarded).
    pub fn respawn(&mut self, engine: &mut Engine, level: &Level) -> Result<(), AssetError> {
        self.respawn_in(engine, level, None)
    }

    /// [`EditWorld::respawn`] in a composed world whose base file is edited too (`base`, as
    /// edited; `None`: as the target read it).
    pub fn respawn_in(
        &mut self,
        engine: &mut Engine,
        level: &Level,
        base: Option<&Level>,
    ) -> Result<(), AssetError> {
        let playable = (self.target.build)(level, base)?;
        let sections = (ModelSections::of(level), base.map(ModelSections::of));
        let reuse = (self.sections.as_ref() == Some(&sections)
            && self.spawned.models.len() == playable.scene.models.len())
        .then(|| self.spawned.models.clone());
        engine.despawn_level(&self.spawned, &playable);
        self.spawned = engine.spawn_level_with(&playable, reuse);
        // Everything lit while editing: a room that the game darkens until the player walks
        // in is edited as it will be played, lit (`leave_lights` darkens them again).
        self.lights_off = playable.gameplay.lights_off.clone();
        for &group in &self.lights_off {
            engine.set_light_group(group, true);
        }
        self.bounds = model_bounds(&playable);
        self.sections = Some(sections);
        engine.cut();
        Ok(())
    }
}

impl EditWorld {
    /// Switches off again the light groups the level starts with off (leaving edit mode: the
    /// level's rules light the rooms the player is in, as at the level's start).
    pub fn leave_lights(&self, engine: &mut Engine) {
        for &group in &self.lights_off {
            engine.set_light_group(group, false);
        }
    }
}

/// The bounds of each instance's model (model space, over its placed meshes).
fn model_bounds(level: &PlayableLevel) -> Vec<Option<Bounds>> {
    let desc: &SceneDesc = &level.scene;
    let per_model: Vec<Option<Bounds>> = desc
        .models
        .iter()
        .map(|model| {
            let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
            for placement in &model.placements {
                let Some(mesh) = model.meshes.get(placement.mesh) else {
                    continue;
                };
                for p in &mesh.positions {
                    let w = (placement.model_from_mesh * p.extend(1.0)).xyz();
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
            }
            (lo.x <= hi.x).then_some((lo, hi))
        })
        .collect();
    desc.instances
        .iter()
        .map(|i| per_model.get(i.model).copied().flatten())
        .collect()
}
