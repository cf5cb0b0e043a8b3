//! The light table of the [`Upkeep`] at the end of a frame: rebuilt (emissive instances added,
//! removed, restyled, switched or scaled) or refitted (emissive instances only moved rigidly,
//! `scene::light_refit`), and the writes that carry it to the render side.
//!
//! Owns: [`Upkeep::finish_lights`]. Main thread. Must not: decide what dirtied the table
//! (`upkeep_instances.rs`, `upkeep_materials.rs`, `origin.rs` do) or touch BVH data.

use super::upkeep::Upkeep;
use crate::scene::SceneWrite;
use crate::scene::light_refit::{LightRefit, refit_lights};
use crate::scene::lights::{LightTable, build_lights};

impl Upkeep {
    /// Refits the light table to this frame's moved emitters, or rebuilds it when anything
    /// else dirtied it (or a move was not rigid).
    pub(super) fn finish_lights(&mut self) {
        if !self.lights_dirty && !self.lights_moved.is_empty() {
            self.refit_lights();
        }
        self.lights_moved.clear();
        if self.lights_dirty {
            self.rebuild_lights();
        }
    }

    /// Refits the light table and tree to the emissive rows moved this frame; marks the table
    /// dirty (a rebuild follows) when a move was not rigid.
    fn refit_lights(&mut self) {
        puffin::profile_scope!("light refit");
        let refit = refit_lights(
            &self.scene.lights,
            &self.lights_moved,
            &self.scene.instances,
            &self.scene.triangles,
            &self.scene.vertices,
        );
        let Some(refit) = refit else {
            self.lights_dirty = true;
            return;
        };
        for (first, data) in LightRefit::runs(&refit.lights) {
            self.push(SceneWrite::Lights { first, data });
        }
        for (first, data) in LightRefit::runs(&refit.nodes) {
            self.push(SceneWrite::LightNodes { first, data });
        }
        self.stats.light_refits += 1;
    }

    /// Builds the light table and its tree again from every instance.
    fn rebuild_lights(&mut self) {
        puffin::profile_scope!("light table");
        let counts: Vec<u32> = self
            .rows
            .iter()
            .map(|&(_, s)| self.meshes[s].triangles.len() as u32)
            .collect();
        let table = build_lights(
            &self.scene.instances,
            &counts,
            &self.scene.triangles,
            &self.scene.vertices,
            &self.scene.materials,
        );
        self.push(SceneWrite::Lights {
            first: 0,
            data: table.lights.clone(),
        });
        self.push(SceneWrite::LightNodes {
            first: 0,
            data: table.tree.nodes.clone(),
        });
        self.push(SceneWrite::LightLookup {
            first: 0,
            data: table.tree.lookup.clone(),
        });
        self.scene.lights = LightTable {
            lights: std::mem::take(&mut self.scene.lights.lights),
            tree: std::mem::take(&mut self.scene.lights.tree),
            ..table
        };
        self.stats.light_table_builds += 1;
        self.lights_dirty = false;
    }
}
