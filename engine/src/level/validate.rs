//! The one validator of a level's rules: [`validate_level`] reads only the [`Level`] and
//! returns every problem at once, each typed ([`LevelProblem`]: item, field, message). Every
//! name an item uses (models, materials, instances, sounds, clips, volumes, events, light
//! groups) must exist, names must not be used twice where the engine refuses that, transforms
//! must be invertible, the camera must see something; the gameplay half is
//! `validate_gameplay`.
//!
//! The loader (`load::playable_from_level`) stops at the first problem; the editor lists them
//! all. What needs files (models, sounds, clip keys, bodies against their meshes, `needs`) is
//! the full load's (`load::level_problems`).
//!
//! Owns: [`validate_level`] and the problem list both halves fill. Any thread (reads the level
//! only). Must not: read files or modify the level.

use std::collections::{HashMap, HashSet};

use crate::assets::Level;

use super::item::ItemRef;
use super::problem::LevelProblem;

/// The problems found so far, in the order of the level's lists.
pub(super) struct Problems<'a> {
    pub(super) list: Vec<LevelProblem>,
    pub(super) level: &'a Level,
}

impl Problems<'_> {
    pub(super) fn report(&mut self, item: ItemRef, field: &'static str, message: String) {
        self.list.push(LevelProblem::new(item, field, message));
    }

    /// The names among `names`; each name used twice is reported at its second use.
    pub(super) fn unique<'n>(
        &mut self,
        kind: &str,
        names: impl Iterator<Item = (ItemRef, &'n str)>,
    ) -> HashSet<&'n str> {
        let mut seen = HashSet::new();
        for (item, name) in names {
            if !seen.insert(name) {
                self.report(item, "name", format!("{kind} name {name:?} is used twice"));
            }
        }
        seen
    }
}

/// Every problem of `level` that its data alone shows, in the order of its lists (the scene's
/// items first, then the gameplay section's). Empty: the level's references all resolve.
pub fn validate_level(level: &Level) -> Vec<LevelProblem> {
    let mut c = Problems {
        list: Vec::new(),
        level,
    };
    let models = c.unique(
        "model",
        (level.models.iter().enumerate())
            .map(|(i, m)| (ItemRef::Model(i), m.name.as_str()))
            .chain(
                (level.grids.iter().enumerate()).map(|(i, g)| (ItemRef::Grid(i), g.name.as_str())),
            )
            .chain(
                (level.boxes.iter().enumerate()).map(|(i, b)| (ItemRef::Box(i), b.name.as_str())),
            )
            .chain(
                level
                    .terrains
                    .iter()
                    .map(|t| (ItemRef::Level, t.name.as_str())),
            )
            .chain(
                level
                    .cities
                    .iter()
                    .map(|t| (ItemRef::Level, t.name.as_str())),
            ),
    );
    let materials = c.unique(
        "material",
        (level.materials.iter().enumerate()).map(|(i, m)| (ItemRef::Material(i), m.name.as_str())),
    );
    let material = |c: &mut Problems, item, user: &str, name: &str| {
        if !materials.contains(name) {
            c.report(
                item,
                "material",
                format!("{user} uses the material {name:?}, which the level does not define"),
            );
        }
    };
    for (i, g) in level.grids.iter().enumerate() {
        material(
            &mut c,
            ItemRef::Grid(i),
            &format!("grid {:?}", g.name),
            &g.material,
        );
    }
    for (i, b) in level.boxes.iter().enumerate() {
        material(
            &mut c,
            ItemRef::Box(i),
            &format!("box {:?}", b.name),
            &b.material,
        );
    }
    // How many instances carry each name (gameplay may only use names carried once).
    let mut names: HashMap<&str, usize> = HashMap::new();
    for (i, e) in level.instances.iter().enumerate() {
        let item = ItemRef::Instance(i);
        if !models.contains(e.model.as_str()) {
            let message = format!(
                "instance {i} uses the model {:?}, which the level does not define",
                e.model
            );
            c.report(item, "model", message);
        }
        if let Some(m) = &e.material {
            material(&mut c, item, &format!("instance {i}"), m);
        }
        let m = e.transform.world_from_model();
        if !m.is_finite() || m.determinant() == 0.0 {
            let message = format!(
                "instance {i} ({:?}) has a degenerate or non-finite transform",
                e.model
            );
            c.report(item, "transform", message);
        }
        if let Some(name) = &e.name {
            *names.entry(name).or_default() += 1;
        }
    }
    let camera = &level.camera;
    if !(camera.vertical_fov_deg > 0.0 && camera.vertical_fov_deg < 180.0) {
        let message = format!(
            "camera.vertical_fov_deg must be in (0, 180), not {}",
            camera.vertical_fov_deg
        );
        c.report(ItemRef::Camera, "vertical_fov_deg", message);
    }
    if glam::Vec3::from(camera.look_at) == glam::Vec3::from(camera.position) {
        let message = "camera.look_at equals camera.position".to_string();
        c.report(ItemRef::Camera, "look_at", message);
    }
    super::validate_gameplay::gameplay(&mut c, &names, &materials);
    c.list
}
