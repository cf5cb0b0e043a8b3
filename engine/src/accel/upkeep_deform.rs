//! Deforming meshes of the [`Upkeep`]: new vertex positions each frame, the BLAS refitted, or
//! rebuilt when refitting has degraded it past the policy's bound (`REBUILD_RATIO` × the
//! estimated cost of a fresh build, see `refit.rs`).
//!
//! Owns: the per-frame deform path (vertex writes, refit or rebuild, the rows of a rebuilt
//! mesh). Main thread. Must not: touch instance placement (see `upkeep_instances.rs`).

use glam::Vec3;

use super::blas::{Blas, build_blas_with_params};
use super::refit::{rebuild_bound, refit_blas_measured, sah_cost, triangle_area_ratio};
use super::upkeep::{MeshSlot, REBUILD_RATIO, Upkeep};
use crate::ecs::ModelHandle;
use crate::scene::{Aabb, SceneWrite};

impl Upkeep {
    /// New object-space positions (and optionally normals) for mesh `mesh` of `model`: refits
    /// its BLAS, or rebuilds it when the refit has degraded past [`REBUILD_RATIO`]. Every
    /// placement of the model shows the new shape. Wrong vertex counts are ignored (logged).
    pub fn deform(
        &mut self,
        model: ModelHandle,
        mesh: usize,
        positions: &[Vec3],
        normals: Option<&[Vec3]>,
    ) {
        let Some(&slot_index) = self
            .models
            .get(model.0 as usize)
            .and_then(|m| m.meshes.get(mesh))
        else {
            log::warn!("deform: model {} has no mesh {mesh}", model.0);
            return;
        };
        let started = std::time::Instant::now();
        let first = self.meshes[slot_index].vertex_base as usize;
        let count = self.meshes[slot_index].vertex_count as usize;
        if positions.len() != count || normals.is_some_and(|n| n.len() != count) {
            log::warn!("deform: mesh has {count} vertices, got {}", positions.len());
            return;
        }
        // Taken out while the upkeep writes (not cloned: a frame of several settled steps
        // deforms the explorer once per step), put back below.
        let mut slot = std::mem::replace(&mut self.meshes[slot_index], MeshSlot::vacant());
        // Written in place in the game-side scene, then copied once for the commit (not copied
        // out, written, and copied back in by `push`: perf 2026-12-07, `docs/PERFORMANCE.md`).
        let Some(vertices) = self.scene.vertices.get_mut(first..first + count) else {
            log::warn!(
                "deform: mesh's vertices {first}..{} out of range",
                first + count
            );
            self.meshes[slot_index] = slot;
            return;
        };
        for (i, v) in vertices.iter_mut().enumerate() {
            v.position = positions[i].to_array();
            if let Some(n) = normals {
                v.normal = n[i].to_array();
            }
        }
        let data = vertices.to_vec();
        self.push_applied(SceneWrite::Vertices {
            first: first as u32,
            data,
        });
        puffin::profile_scope!("BLAS refit/rebuild");
        let refit = refit_blas_measured(&mut slot.blas, positions, &slot.triangles);
        let bound = rebuild_bound(
            REBUILD_RATIO,
            slot.built_cost,
            slot.built_area,
            refit.area_ratio,
        );
        if refit.cost > bound {
            slot.blas = build_blas_with_params(positions, &slot.triangles, self.blas_params);
            slot.built_cost = sah_cost(&slot.blas.nodes, &slot.blas.blocks);
            slot.built_area = triangle_area_ratio(&slot.blas);
            self.stats.blas_rebuilds += 1;
            self.place_blas(&mut slot, false);
            self.rewrite_rows_of_slot(slot_index, &slot);
        } else {
            self.stats.blas_refits += 1;
            self.place_blas(&mut slot, false);
        }
        self.meshes[slot_index] = slot;
        self.refresh_bounds_of_slot(slot_index);
        self.stats.seconds += started.elapsed().as_secs_f64();
    }
}

impl MeshSlot {
    /// An empty stand-in, left in the table while the real slot is taken out to be written
    /// (`upkeep_deform.rs`); never seen outside that call.
    pub(super) fn vacant() -> Self {
        Self {
            blas: Blas {
                nodes: Vec::new(),
                blocks: Vec::new(),
                bounds: Aabb::EMPTY,
                sah_cost: 0.0,
            },
            node_base: 0,
            node_capacity: 0,
            block_base: 0,
            block_capacity: 0,
            triangle_base: 0,
            vertex_base: 0,
            vertex_count: 0,
            triangles: Vec::new(),
            built_cost: 0.0,
            built_area: 0.0,
            emissive: false,
        }
    }
}
