//! Checking a level before it is saved: every problem found, each naming the item it is in
//! (an [`ItemRef`] a UI selects when the problem is clicked).
//!
//! [`check_references`] reads only the `Level`: every name an item uses (models, materials,
//! instances, sounds, clips, volumes, events, light groups) must exist, names must not be
//! used twice where the engine refuses that, transforms must be invertible, volumes must sit
//! on sensors — the same rules as `assets::scene_from_level` and `level::plan_gameplay`, but
//! all problems at once instead of the first. [`check_level`] adds the engine's own full load
//! (`level::playable_from_level`: models, bodies, sounds, clips, `needs`) so that nothing the
//! game would refuse can be saved. Main thread. Must not: modify the level.

use std::collections::{HashMap, HashSet};
use std::path::Path;

use crate::assets::{AssetError, AssetRoot, Level};

use super::item::ItemRef;

/// One reason a level cannot be saved.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// The item to select; `None` when the engine's message names none the editor can find.
    pub item: Option<ItemRef>,
    pub message: String,
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.item {
            Some(item) => write!(f, "{item}: {}", self.message),
            None => write!(f, "{}", self.message),
        }
    }
}

pub(super) struct Checker<'a> {
    problems: Vec<Problem>,
    pub(super) level: &'a Level,
}

impl Checker<'_> {
    pub(super) fn report(&mut self, item: ItemRef, message: String) {
        self.problems.push(Problem {
            item: Some(item),
            message,
        });
    }

    /// Names used twice among `names` (each reported at its second use).
    pub(super) fn unique<'n>(
        &mut self,
        kind: &str,
        names: impl Iterator<Item = (ItemRef, &'n str)>,
    ) -> HashSet<&'n str> {
        let mut seen = HashSet::new();
        for (item, name) in names {
            if !seen.insert(name) {
                self.report(item, format!("the {kind} name {name:?} is used twice"));
            }
        }
        seen
    }
}

/// Every unresolved reference and invalid name of `level`, in the order of its lists.
pub fn check_references(level: &Level) -> Vec<Problem> {
    let mut c = Checker {
        problems: Vec::new(),
        level,
    };
    let models = c.unique(
        "model",
        (level
            .models
            .iter()
            .enumerate()
            .map(|(i, m)| (ItemRef::Model(i), m.name.as_str())))
        .chain(
            level
                .grids
                .iter()
                .enumerate()
                .map(|(i, g)| (ItemRef::Grid(i), g.name.as_str())),
        )
        .chain(
            level
                .boxes
                .iter()
                .enumerate()
                .map(|(i, b)| (ItemRef::Box(i), b.name.as_str())),
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
        level
            .materials
            .iter()
            .enumerate()
            .map(|(i, m)| (ItemRef::Material(i), m.name.as_str())),
    );
    let material = |c: &mut Checker, item, user: &str, name: &str| {
        if !materials.contains(name) {
            c.report(
                item,
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
    let mut names: HashMap<&str, usize> = HashMap::new();
    for (i, e) in level.instances.iter().enumerate() {
        let item = ItemRef::Instance(i);
        if !models.contains(e.model.as_str()) {
            c.report(
                item,
                format!(
                    "instance {i} uses the model {:?}, which the level does not define",
                    e.model
                ),
            );
        }
        if let Some(m) = &e.material {
            material(&mut c, item, &format!("instance {i}"), m);
        }
        let m = e.transform.world_from_model();
        if !m.is_finite() || m.determinant() == 0.0 {
            c.report(
                item,
                format!("instance {i} has a degenerate or non-finite transform"),
            );
        }
        if let Some(name) = &e.name {
            *names.entry(name).or_default() += 1;
        }
    }
    let camera = &level.camera;
    if !(camera.vertical_fov_deg > 0.0 && camera.vertical_fov_deg < 180.0)
        || camera.look_at == camera.position
    {
        let message = "the camera needs a field of view in (0, 180) degrees and a look_at away \
                       from its position";
        c.report(ItemRef::Camera, message.into());
    }
    super::check_gameplay::gameplay(&mut c, &names, &materials);
    c.problems
}

/// [`check_references`], then, when those pass and `root` is given, the engine's full load
/// of the level as if read from `path` (its models and sounds are read from `root`), whose
/// first error becomes a problem (with the item its message names, when it names one).
pub fn check_level(path: &Path, level: &Level, root: Option<&AssetRoot>) -> Vec<Problem> {
    let problems = check_references(level);
    if !problems.is_empty() {
        return problems;
    }
    let Some(root) = root else {
        return problems;
    };
    match crate::level::playable_from_level(path, level, root) {
        Ok(_) => Vec::new(),
        Err(e) => {
            let message = match &e {
                AssetError::Level { message, .. } => message.clone(),
                other => other.to_string(),
            };
            vec![Problem {
                item: item_named(level, &message),
                message,
            }]
        }
    }
}

/// The item an engine message names (`instance 3`, `rule "open"`, `laser 0`, …), if any.
fn item_named(level: &Level, message: &str) -> Option<ItemRef> {
    let g = &level.gameplay;
    let number = |word: &str| -> Option<usize> {
        let at = message.find(&format!("{word} "))? + word.len() + 1;
        message[at..]
            .split(|c: char| !c.is_ascii_digit())
            .next()?
            .parse()
            .ok()
    };
    let named = |word: &str, names: Vec<&str>| -> Option<usize> {
        names
            .iter()
            .position(|n| message.contains(&format!("{word} {n:?}")))
    };
    let rules = g.rules.iter().map(|r| r.name.as_str()).collect();
    let volumes = g.volumes.iter().map(|v| v.name.as_str()).collect();
    let clips = g.animations.iter().map(|a| a.name.as_str()).collect();
    let sounds = g.sounds.iter().map(|s| s.name.as_str()).collect();
    named("rule", rules)
        .map(ItemRef::Rule)
        .or_else(|| named("volume", volumes).map(ItemRef::Volume))
        .or_else(|| named("clip", clips).map(ItemRef::Clip))
        .or_else(|| named("sound", sounds).map(ItemRef::Sound))
        .or_else(|| number("laser").map(ItemRef::Laser))
        .or_else(|| number("emitter").map(ItemRef::Emitter))
        .or_else(|| number("usable").map(ItemRef::Usable))
        .or_else(|| number("instance").map(ItemRef::Instance))
        .or_else(|| message.starts_with("camera").then_some(ItemRef::Camera))
}
