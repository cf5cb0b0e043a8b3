//! Instance rows of the [`Upkeep`]: spawning, moving, re-materialising and removing the
//! instances of entities, and keeping rows in step with their meshes and light groups.
//!
//! Owns: the mapping entity ↔ instance rows (one row per placement of the entity's model) and
//! the writes of `GpuInstance` rows, and their light-group flags (switched off; out of sight of
//! the camera's render area). Rows of removed entities are filled by swapping in the last
//! row, so the table stays dense. Main thread. Must not: touch BLAS data (see `upkeep.rs`).

use std::collections::HashSet;

use glam::Mat4;
use hecs::Entity;

use super::upkeep::Upkeep;
use crate::ecs::ModelHandle;
use crate::layout::{
    GpuInstance, INSTANCE_FLAG_EMISSION_OFF, INSTANCE_FLAG_IDENTITY, INSTANCE_FLAG_UNSAMPLED,
    INVALID,
};
use crate::scene::Aabb;
use crate::scene::SceneWrite;

fn affine_rows(m: Mat4) -> [[f32; 4]; 3] {
    let r = m.transpose().to_cols_array_2d();
    [r[0], r[1], r[2]]
}

impl Upkeep {
    fn instance_row(
        &self,
        slot: usize,
        world_from_object: Mat4,
        material_override: Option<u32>,
        group: Option<u32>,
    ) -> GpuInstance {
        let mesh = &self.meshes[slot];
        let mut flags = 0;
        if group.is_some_and(|g| self.groups_off.contains(&g)) {
            flags |= INSTANCE_FLAG_EMISSION_OFF;
        }
        if group.is_some_and(|g| !self.group_sampled(g)) {
            flags |= INSTANCE_FLAG_UNSAMPLED;
        }
        let row = GpuInstance {
            world_from_object: [[0.0; 4]; 3],
            object_from_world: [[0.0; 4]; 3],
            node_base: mesh.node_base,
            block_base: mesh.block_base,
            triangle_base: mesh.triangle_base,
            vertex_base: mesh.vertex_base,
            material_override: material_override
                .map(|m| self.level_material_base + m)
                .unwrap_or(INVALID),
            flags,
            _padding: [0; 2],
        };
        // Render space = world − origin (see `origin.rs`); exact for nearby translations.
        let render_from_object = Mat4::from_translation(-self.scene.origin) * world_from_object;
        self.placed_row(row, render_from_object)
    }

    /// `row` with its transforms set to `render_from_object` (render space, see `origin.rs`)
    /// and its identity flag kept in step.
    pub(super) fn placed_row(&self, mut row: GpuInstance, render_from_object: Mat4) -> GpuInstance {
        row.flags &= !INSTANCE_FLAG_IDENTITY;
        if render_from_object == Mat4::IDENTITY {
            row.flags |= INSTANCE_FLAG_IDENTITY;
        }
        let inverse = render_from_object.inverse();
        row.world_from_object = affine_rows(render_from_object);
        row.object_from_world = affine_rows(if inverse.is_finite() {
            inverse
        } else {
            Mat4::ZERO
        });
        row
    }

    /// Places (or moves) `entity` showing `model` at `world_from_model`, with an optional level
    /// material override and light group. The same model again rewrites the entity's rows; a
    /// different model replaces them.
    pub fn set_instance(
        &mut self,
        entity: Entity,
        model: ModelHandle,
        world_from_model: Mat4,
        material_override: Option<u32>,
        group: Option<u32>,
    ) {
        let Some(record) = self.models.get(model.0 as usize).cloned() else {
            log::warn!("set_instance: unknown model {}", model.0);
            return;
        };
        let (existing, old_group) = match self.entities.get(&entity) {
            Some((rows, g)) => (Some(rows.clone()), Some(*g)),
            None => (None, None),
        };
        let reuse = existing.as_ref().is_some_and(|rows| {
            rows.len() == record.placements.len()
                && rows
                    .iter()
                    .zip(&record.placements)
                    .all(|(&r, &(mesh, _))| self.rows[r as usize].1 == record.meshes[mesh])
        });
        if existing.is_some() && !reuse {
            self.remove_instance(entity);
        }
        let mut rows = Vec::with_capacity(record.placements.len());
        for (i, &(mesh, model_from_mesh)) in record.placements.iter().enumerate() {
            let slot = record.meshes[mesh];
            let row = self.instance_row(
                slot,
                world_from_model * model_from_mesh,
                material_override,
                group,
            );
            let index = if reuse {
                existing.as_ref().map(|r| r[i]).unwrap_or(0)
            } else {
                self.rows.push((entity, slot));
                self.rows.len() as u32 - 1
            };
            // The same emitter moved, in the same group, with the same material and flags: its
            // lights only need placing again (`scene::light_refit`); unmoved, nothing at all.
            let before = reuse
                .then(|| self.scene.instances.get(index as usize))
                .flatten();
            let moved_only = old_group == Some(group)
                && before.is_some_and(|b| {
                    b.material_override == row.material_override
                        && (b.flags ^ row.flags) & !INSTANCE_FLAG_IDENTITY == 0
                });
            let unmoved = moved_only
                && before.is_some_and(|b| bytemuck::bytes_of(b) == bytemuck::bytes_of(&row));
            if self.meshes[slot].emissive && !unmoved {
                match moved_only {
                    true => self.lights_moved.push(index),
                    false => self.lights_dirty = true,
                }
            }
            self.push(SceneWrite::Instances {
                first: index,
                data: vec![row],
            });
            rows.push(index);
        }
        self.stats.instances_written += rows.len() as u32;
        self.entities.insert(entity, (rows, group));
        self.tlas_dirty = true;
    }

    /// Removes `entity`'s instances (nothing if it has none).
    pub fn remove_instance(&mut self, entity: Entity) {
        let Some((mut rows, _)) = self.entities.remove(&entity) else {
            return;
        };
        rows.sort_unstable_by(|a, b| b.cmp(a));
        for index in rows {
            let index = index as usize;
            let last = self.rows.len() - 1;
            if self.meshes[self.rows[index].1].emissive {
                self.lights_dirty = true;
            }
            if index != last {
                let moved = self.scene.instances[last];
                let (owner, slot) = self.rows[last];
                if self.meshes[slot].emissive {
                    // Its lights name it by row: the table (and the tree's lookup) must follow.
                    self.lights_dirty = true;
                }
                self.rows[index] = (owner, slot);
                if let Some((owner_rows, _)) = self.entities.get_mut(&owner) {
                    for r in owner_rows.iter_mut().filter(|r| **r as usize == last) {
                        *r = index as u32;
                    }
                }
                self.push(SceneWrite::Instances {
                    first: index as u32,
                    data: vec![moved],
                });
            }
            self.rows.pop();
            self.push(SceneWrite::TruncateInstances {
                len: self.rows.len() as u32,
            });
        }
        self.tlas_dirty = true;
    }

    /// The level's render areas (none: every group is sampled everywhere); every group is
    /// sampled until the next [`Upkeep::sample_from`].
    pub fn set_render_areas(&mut self, areas: Vec<crate::assets::RenderArea>) {
        self.render_areas = areas;
        self.set_sampled_groups(None);
    }

    /// Samples the light groups the render areas containing `camera` (metres, world space)
    /// name, or every group outside them all (`assets::sampled_groups`).
    pub fn sample_from(&mut self, camera: glam::Vec3) {
        if self.render_areas.is_empty() {
            return;
        }
        let groups = crate::assets::sampled_groups(&self.render_areas, camera.to_array());
        self.set_sampled_groups(groups.as_deref());
    }

    /// Which light groups next-event estimation samples, from the render area the camera is in
    /// (`assets::RenderArea`): `None`, every group (outside every area); `Some(groups)`, only
    /// those. Emitters of the other groups leave the light table but still emit when a path
    /// hits them (`layout::INSTANCE_FLAG_UNSAMPLED`: MIS weight 1 there, so the estimate stays
    /// unbiased); emitters in no group are always sampled. Rewrites only the rows of groups
    /// whose state changed (and then the light table).
    pub fn set_sampled_groups(&mut self, sampled: Option<&[u32]>) {
        let next: Option<HashSet<u32>> = sampled.map(|g| g.iter().copied().collect());
        if next == self.groups_sampled {
            return;
        }
        let before = std::mem::replace(&mut self.groups_sampled, next);
        let mut groups: Vec<u32> = (self.entities.values())
            .filter_map(|(_, g)| *g)
            .collect::<HashSet<u32>>()
            .into_iter()
            .collect();
        groups.sort_unstable();
        for group in groups {
            let was = before.as_ref().is_none_or(|s| s.contains(&group));
            if was != self.group_sampled(group) {
                self.apply_group_flags(group);
            }
        }
    }

    /// Whether next-event estimation samples light group `group` now (see
    /// [`Upkeep::set_sampled_groups`]; a group switched off is in no table either way).
    pub fn group_sampled(&self, group: u32) -> bool {
        self.groups_sampled
            .as_ref()
            .is_none_or(|s| s.contains(&group))
    }

    /// Rewrites the emission and sampling flags of every row of the entities in `group`.
    pub(super) fn apply_group_flags(&mut self, group: u32) {
        let off = self.groups_off.contains(&group);
        let sampled = self.group_sampled(group);
        let rows: Vec<u32> = self
            .entities
            .values()
            .filter(|(_, g)| *g == Some(group))
            .flat_map(|(rows, _)| rows.iter().copied())
            .collect();
        for r in rows {
            let mut row = self.scene.instances[r as usize];
            row.flags &= !(INSTANCE_FLAG_EMISSION_OFF | INSTANCE_FLAG_UNSAMPLED);
            if off {
                row.flags |= INSTANCE_FLAG_EMISSION_OFF;
            }
            if !sampled {
                row.flags |= INSTANCE_FLAG_UNSAMPLED;
            }
            self.push(SceneWrite::Instances {
                first: r,
                data: vec![row],
            });
            self.stats.instances_written += 1;
        }
        self.lights_dirty = true;
    }

    /// After a mesh's BLAS moved in the buffers: point its rows at the new place.
    pub(super) fn rewrite_rows_of_slot(
        &mut self,
        slot_index: usize,
        slot: &super::upkeep::MeshSlot,
    ) {
        for r in 0..self.rows.len() {
            if self.rows[r].1 != slot_index {
                continue;
            }
            let mut row = self.scene.instances[r];
            row.node_base = slot.node_base;
            row.block_base = slot.block_base;
            self.push(SceneWrite::Instances {
                first: r as u32,
                data: vec![row],
            });
            self.stats.instances_written += 1;
        }
    }

    /// After a mesh changed shape: the TLAS (and, for emitters, the light table) must follow.
    pub(super) fn refresh_bounds_of_slot(&mut self, slot_index: usize) {
        if self.rows.iter().any(|&(_, s)| s == slot_index) {
            self.tlas_dirty = true;
            if self.meshes[slot_index].emissive {
                self.lights_dirty = true;
            }
        }
    }

    /// Render-space bounds of row `i`.
    pub(super) fn row_bounds(&self, i: usize) -> Aabb {
        let slot = self.rows[i].1;
        let r = &self.scene.instances[i].world_from_object;
        let m = Mat4::from_cols_array_2d(&[r[0], r[1], r[2], [0.0, 0.0, 0.0, 1.0]]).transpose();
        self.meshes[slot].blas.bounds.transformed(&m)
    }

    /// Applies one frame's extracted changes.
    pub fn apply_changes(&mut self, changes: Vec<crate::extract::SceneChange>) {
        use crate::extract::SceneChange;
        for change in changes {
            match change {
                SceneChange::Place {
                    entity,
                    model,
                    world_from_model,
                    material_override,
                    light_group,
                } => self.set_instance(
                    entity,
                    model,
                    world_from_model,
                    material_override,
                    light_group,
                ),
                SceneChange::Remove { entity } => self.remove_instance(entity),
                SceneChange::Deform {
                    model,
                    mesh,
                    positions,
                    normals,
                } => self.deform(model, mesh, &positions, normals.as_deref()),
            }
        }
    }

    /// The entity that owns instance row `row` (for ray queries).
    pub fn entity_of_instance(&self, row: u32) -> Option<Entity> {
        self.rows.get(row as usize).map(|&(e, _)| e)
    }
}
