//! The level's own materials in the upkeep's material table (what instance overrides index,
//! the mirror gun's mirror among them). A level spawned again — the editor respawns after most
//! edits — writes its materials over the rows the last one reserved when they fit, so the
//! table does not grow with every edit; only a level with more materials than reserved
//! appends a new range.
//!
//! Main thread. Must not: touch model materials (they belong to their models' rows).

use super::upkeep::Upkeep;
use crate::assets::Material;
use crate::scene::SceneWrite;
use crate::scene::materials::to_gpu_material;

impl Upkeep {
    /// Registers the materials the level defines (instance overrides index them); returns the
    /// first one's index in the material table. Call before any instance uses an override;
    /// calling it again (a level spawned again) reuses the reserved rows when they suffice.
    pub fn add_level_materials(&mut self, materials: &[Material]) -> u32 {
        let count = materials.len() as u32;
        let base = match self.level_material_slots {
            Some(slots) if count <= slots => self.level_material_base,
            _ => {
                self.level_material_slots = Some(count);
                self.scene.materials.len() as u32
            }
        };
        let gpu: Vec<_> = materials
            .iter()
            .map(|m| to_gpu_material(m, 0, &[]))
            .collect();
        self.push(SceneWrite::Materials {
            first: base,
            data: gpu,
        });
        self.level_material_base = base;
        // Emission may have changed under instances that keep their rows.
        self.lights_dirty = true;
        base
    }
}
