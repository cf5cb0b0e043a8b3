//! Read-only views of the [`Upkeep`] for reports and tests: what a mesh's BVH costs now against
//! right after its last build, and how many instance rows an entity owns.
//!
//! Owns: [`MeshCost`] and the accessors. Main thread. Must not: change the upkeep.

use hecs::Entity;

use super::refit::{rebuild_bound, sah_cost, triangle_area_ratio};
use super::upkeep::{REBUILD_RATIO, Upkeep};
use crate::ecs::ModelHandle;

/// SAH cost of one mesh's BLAS (see [`crate::accel::sah_cost`]; dimensionless, relative to the
/// root box's surface area).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshCost {
    /// The tree as it is now (after the last refit or rebuild), measured by
    /// [`crate::accel::sah_cost`] like `built`.
    pub current: f32,
    /// Right after its last (re)build; the rebuild policy compares `current` against
    /// [`crate::accel::REBUILD_RATIO`] × this.
    pub built: f32,
    /// The cost above which the next refit is rebuilt ([`crate::accel::rebuild_bound`] for the
    /// current shape).
    pub bound: f32,
    /// Triangles of the mesh.
    pub triangles: usize,
}

impl Upkeep {
    /// The BLAS cost of mesh `mesh` of `model` (`None` for an unknown model or mesh).
    /// O(nodes): the current cost is measured afresh.
    pub fn mesh_cost(&self, model: ModelHandle, mesh: usize) -> Option<MeshCost> {
        let slot = *self.models.get(model.0 as usize)?.meshes.get(mesh)?;
        let slot = self.meshes.get(slot)?;
        Some(MeshCost {
            current: sah_cost(&slot.blas.nodes, &slot.blas.blocks),
            built: slot.built_cost,
            bound: rebuild_bound(
                REBUILD_RATIO,
                slot.built_cost,
                slot.built_area,
                triangle_area_ratio(&slot.blas),
            ),
            triangles: slot.triangles.len(),
        })
    }

    /// Instance rows `entity` owns (one per placement of its model; 0 when it has none).
    pub fn instance_rows(&self, entity: Entity) -> usize {
        self.entities.get(&entity).map_or(0, |(rows, _)| rows.len())
    }

    /// Emissive triangles in the light sampling distribution as of the last
    /// [`Upkeep::finish_frame`] (switched-off light groups are not in it).
    pub fn light_count(&self) -> u32 {
        self.scene.lights.count
    }
}
