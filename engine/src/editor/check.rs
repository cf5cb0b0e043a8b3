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

use crate::assets::{ActionEntry, AssetError, AssetRoot, BodyEntry, ConditionEntry, Level};

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

struct Checker<'a> {
    problems: Vec<Problem>,
    level: &'a Level,
}

impl Checker<'_> {
    fn report(&mut self, item: ItemRef, message: String) {
        self.problems.push(Problem {
            item: Some(item),
            message,
        });
    }

    /// Names used twice among `names` (each reported at its second use).
    fn unique<'n>(
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
        c.report(ItemRef::Camera, "the camera needs a field of view in (0, 180) degrees and a look_at away from its position".into());
    }
    gameplay(&mut c, &names, &materials);
    c.problems
}

/// The gameplay section's references (`instances`: how many instances have each name).
fn gameplay(c: &mut Checker, instances: &HashMap<&str, usize>, materials: &HashSet<&str>) {
    let level: &Level = c.level;
    let g = &level.gameplay;
    let instance = |c: &mut Checker, item, user: &str, name: &str| match instances.get(name) {
        Some(1) => true,
        Some(_) => {
            c.report(
                item,
                format!("{user} uses the instance {name:?}, but two instances have that name"),
            );
            false
        }
        None => {
            c.report(
                item,
                format!("{user} uses the instance {name:?}, which the level does not define"),
            );
            false
        }
    };
    let sounds = c.unique(
        "sound",
        g.sounds
            .iter()
            .enumerate()
            .map(|(i, s)| (ItemRef::Sound(i), s.name.as_str())),
    );
    let sound = |c: &mut Checker, item, user: &str, name: &str| {
        if !sounds.contains(name) {
            c.report(
                item,
                format!("{user} uses the sound {name:?}, which the level does not define"),
            );
        }
    };
    if let Some(m) = &g.music {
        sound(c, ItemRef::Music, "music", &m.sound);
    }
    for (i, e) in g.emitters.iter().enumerate() {
        let user = format!("emitter {i}");
        instance(c, ItemRef::Emitter(i), &user, &e.instance);
        sound(c, ItemRef::Emitter(i), &user, &e.sound);
    }
    let clips = c.unique(
        "clip",
        g.animations
            .iter()
            .enumerate()
            .map(|(i, a)| (ItemRef::Clip(i), a.name.as_str())),
    );
    for (i, clip) in g.animations.iter().enumerate() {
        let user = format!("clip {:?}", clip.name);
        for track in &clip.tracks {
            if instance(c, ItemRef::Clip(i), &user, &track.target)
                && let Some(e) = level
                    .instances
                    .iter()
                    .find(|e| e.name.as_deref() == Some(&*track.target))
                && matches!(
                    e.body,
                    Some(BodyEntry::Static { .. } | BodyEntry::Dynamic { .. })
                )
            {
                c.report(
                    ItemRef::Clip(i),
                    format!(
                        "{user} moves instance {:?}, whose body is not Kinematic",
                        track.target
                    ),
                );
            }
        }
    }
    let clip = |c: &mut Checker, item, user: &str, name: &str| {
        if !clips.contains(name) {
            c.report(
                item,
                format!("{user} uses the clip {name:?}, which the level does not define"),
            );
        }
    };
    for (i, a) in g.autoplay.iter().enumerate() {
        clip(c, ItemRef::Autoplay(i), "autoplay", &a.clip);
    }
    let groups: HashSet<u32> = level
        .instances
        .iter()
        .filter_map(|i| i.light_group)
        .chain(g.lasers.iter().filter_map(|l| l.beam?.light_group))
        .collect();
    let group = |c: &mut Checker, item, user: &str, group: u32| {
        if !groups.contains(&group) {
            c.report(
                item,
                format!("{user} switches light group {group}, which no instance belongs to"),
            );
        }
    };
    for (i, &gr) in g.lights_off.iter().enumerate() {
        group(c, ItemRef::LightsOff(i), "lights_off", gr);
    }
    for (i, v) in g.volumes.iter().enumerate() {
        let user = format!("volume {:?}", v.name);
        if instance(c, ItemRef::Volume(i), &user, &v.instance)
            && let Some(e) = level
                .instances
                .iter()
                .find(|e| e.name.as_deref() == Some(&*v.instance))
            && !matches!(e.body, Some(BodyEntry::Sensor { .. }))
        {
            c.report(
                ItemRef::Volume(i),
                format!(
                    "{user}: instance {:?} has no `body: Sensor(..)`",
                    v.instance
                ),
            );
        }
    }
    for (i, l) in g.lasers.iter().enumerate() {
        instance(c, ItemRef::Laser(i), &format!("laser {i}"), &l.instance);
        let d = glam::Vec3::from(l.direction);
        if !d.is_finite()
            || d.length_squared() == 0.0
            || !glam::Vec3::from(l.origin).is_finite()
            || !(l.max_length > 0.0)
        {
            c.report(ItemRef::Laser(i), format!("laser {i}: origin and direction must be finite, the direction non-zero and max_length positive"));
        }
    }
    let volumes = c.unique(
        "volume",
        g.volumes
            .iter()
            .enumerate()
            .map(|(i, v)| (ItemRef::Volume(i), v.name.as_str())),
    );
    let events: HashSet<&str> = g
        .animations
        .iter()
        .flat_map(|a| a.events.iter().map(|e| e.name.as_str()))
        .chain(g.events.iter().map(String::as_str))
        .collect();
    for (i, u) in g.usables.iter().enumerate() {
        let user = format!("usable {i}");
        instance(c, ItemRef::Usable(i), &user, &u.instance);
        if !g.events.contains(&u.event) {
            c.report(
                ItemRef::Usable(i),
                format!(
                    "{user} sends the event {:?}, which `events` does not declare",
                    u.event
                ),
            );
        }
    }
    for (i, rule) in g.rules.iter().enumerate() {
        let (item, user) = (ItemRef::Rule(i), format!("rule {:?}", rule.name));
        let mut used = Vec::new();
        condition_names(&rule.when, &mut used);
        for (is_volume, name) in used {
            if is_volume && !volumes.contains(name) {
                c.report(
                    item,
                    format!("{user} uses the volume {name:?}, which the level does not define"),
                );
            } else if !is_volume && !events.contains(name) {
                c.report(item, format!("{user} waits for the event {name:?}, which no clip fires and `events` does not declare"));
            }
        }
        for action in rule.then.iter().chain(&rule.otherwise) {
            match action {
                ActionEntry::Lights { group: gr, .. } | ActionEntry::ToggleLights(gr) => {
                    group(c, item, &user, *gr)
                }
                ActionEntry::Play { clip: name, .. }
                | ActionEntry::Reverse { clip: name }
                | ActionEntry::Pause { clip: name } => clip(c, item, &user, name),
                ActionEntry::Sound { sound: s, at, .. } => {
                    sound(c, item, &user, s);
                    if let Some(at) = at {
                        instance(c, item, &user, at);
                    }
                }
                ActionEntry::Material {
                    instance: name,
                    material,
                } => {
                    instance(c, item, &user, name);
                    if let Some(m) = material
                        && !materials.contains(m.as_str())
                    {
                        c.report(
                            item,
                            format!(
                                "{user} uses the material {m:?}, which the level does not define"
                            ),
                        );
                    }
                }
                ActionEntry::Win | ActionEntry::Lose => {}
            }
        }
    }
}

/// The volume names (`true`) and event names (`false`) a condition uses.
fn condition_names<'a>(c: &'a ConditionEntry, out: &mut Vec<(bool, &'a str)>) {
    match c {
        ConditionEntry::Occupied(v) | ConditionEntry::Entered(v) | ConditionEntry::Exited(v) => {
            out.push((true, v))
        }
        ConditionEntry::Occupants { volume, .. } => out.push((true, volume)),
        ConditionEntry::Event(e) => out.push((false, e)),
        ConditionEntry::All(cs)
        | ConditionEntry::Any(cs)
        | ConditionEntry::AtLeast { of: cs, .. } => cs.iter().for_each(|c| condition_names(c, out)),
        ConditionEntry::Not(c) | ConditionEntry::Times { of: c, .. } => condition_names(c, out),
    }
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
