//! The gameplay half of [`super::validate_level`]: sounds, music, emitters, clips and their
//! targets, autoplay, light groups, volumes on sensors, lasers and their beams, usables and
//! events, rules' conditions and actions — every problem reported with its item and field.
//! The rules here are the loader's: `gameplay_plan` resolves names only after they pass.
//!
//! Any thread (reads the level only). Must not: read files or modify the level.

use std::collections::{HashMap, HashSet};

use glam::Vec3;

use crate::assets::{ActionEntry, BeamEntry, BodyEntry, ConditionEntry, Level};

use super::item::ItemRef;
use super::validate::Problems;

/// The level's instances by name: the first index and how many carry the name.
struct Instances<'a>(HashMap<&'a str, (usize, usize)>);

impl Instances<'_> {
    /// The instance `user` (in `item`, `field`) names; reports a name no instance or two carry.
    fn find(
        &self,
        c: &mut Problems,
        (item, field): (ItemRef, &'static str),
        user: &str,
        name: &str,
    ) -> Option<usize> {
        let message = match self.0.get(name) {
            Some(&(i, 1)) => return Some(i),
            Some(_) => {
                format!("{user} uses the instance {name:?}, but two instances have that name")
            }
            None => format!("{user} uses the instance {name:?}, which the level does not define"),
        };
        c.report(item, field, message);
        None
    }
}

/// Reports `name` (of a `kind`) that `names` lacks.
fn known(
    c: &mut Problems,
    names: &HashSet<&str>,
    (item, field): (ItemRef, &'static str),
    user: &str,
    kind: &str,
    name: &str,
) {
    if !names.contains(name) {
        let message = format!("{user} uses the {kind} {name:?}, which the level does not define");
        c.report(item, field, message);
    }
}

/// Reports a sound volume outside `0..=16`.
fn volume(c: &mut Problems, at: (ItemRef, &'static str), user: &str, v: f32) {
    if !(0.0..=16.0).contains(&v) {
        c.report(at.0, at.1, format!("{user}: volume {v} is not in 0..=16"));
    }
}

/// The gameplay section's problems (`names`: how many instances carry each name; `materials`:
/// the level's material names).
pub(super) fn gameplay(c: &mut Problems, names: &HashMap<&str, usize>, materials: &HashSet<&str>) {
    let level: &Level = c.level;
    let g = &level.gameplay;
    let mut first = HashMap::new();
    for (i, e) in level.instances.iter().enumerate() {
        if let Some(name) = e.name.as_deref() {
            first.entry(name).or_insert(i);
        }
    }
    let instances = Instances(
        first
            .into_iter()
            .map(|(name, i)| (name, (i, names.get(name).copied().unwrap_or(1))))
            .collect(),
    );
    let body = |i: usize| level.instances.get(i).and_then(|e| e.body.as_ref());
    let sounds = c.unique(
        "sound",
        (g.sounds.iter().enumerate()).map(|(i, s)| (ItemRef::Sound(i), s.name.as_str())),
    );
    if let Some(m) = &g.music {
        known(
            c,
            &sounds,
            (ItemRef::Music, "sound"),
            "music",
            "sound",
            &m.sound,
        );
        volume(c, (ItemRef::Music, "volume"), "music", m.volume);
    }
    for (i, e) in g.emitters.iter().enumerate() {
        let (item, user) = (ItemRef::Emitter(i), format!("emitter {i}"));
        instances.find(c, (item, "instance"), &user, &e.instance);
        known(c, &sounds, (item, "sound"), &user, "sound", &e.sound);
        volume(c, (item, "volume"), &user, e.volume);
    }
    for (i, clip) in g.animations.iter().enumerate() {
        let (item, user) = (ItemRef::Clip(i), format!("clip {:?}", clip.name));
        let mut seen = HashSet::new();
        for track in &clip.tracks {
            if !seen.insert(track.target.as_str()) {
                continue;
            }
            let Some(t) = instances.find(c, (item, "tracks"), &user, &track.target) else {
                continue;
            };
            if matches!(
                body(t),
                Some(BodyEntry::Static { .. } | BodyEntry::Dynamic { .. })
            ) {
                let message = format!(
                    "{user} moves instance {:?}, whose body is not Kinematic (physics would \
                     fight the clip)",
                    track.target
                );
                c.report(item, "tracks", message);
            }
        }
    }
    let clips = c.unique(
        "clip",
        (g.animations.iter().enumerate()).map(|(i, a)| (ItemRef::Clip(i), a.name.as_str())),
    );
    for (i, a) in g.autoplay.iter().enumerate() {
        known(
            c,
            &clips,
            (ItemRef::Autoplay(i), "clip"),
            "autoplay",
            "clip",
            &a.clip,
        );
    }
    // A beam's own group counts: rules may switch a laser's light alone.
    let groups: HashSet<u32> = (level.instances.iter().filter_map(|i| i.light_group))
        .chain(g.lasers.iter().filter_map(|l| l.beam?.light_group))
        .collect();
    super::validate_memory::memory(c, level, &groups);
    super::validate_breakables::breakables(c, level);
    let group = |c: &mut Problems, (item, field), user: &str, group: u32| {
        if !groups.contains(&group) {
            let message =
                format!("{user} switches light group {group}, which no instance belongs to");
            c.report(item, field, message);
        }
    };
    for (i, &gr) in g.lights_off.iter().enumerate() {
        group(c, (ItemRef::LightsOff(i), ""), "lights_off", gr);
    }
    for (i, v) in g.volumes.iter().enumerate() {
        let (item, user) = (ItemRef::Volume(i), format!("volume {:?}", v.name));
        if let Some(at) = instances.find(c, (item, "instance"), &user, &v.instance)
            && !matches!(body(at), Some(BodyEntry::Sensor { .. }))
        {
            let message = format!(
                "{user}: instance {:?} has no `body: Sensor(..)`, so nothing can be detected in it",
                v.instance
            );
            c.report(item, "instance", message);
        }
    }
    for (i, l) in g.lasers.iter().enumerate() {
        let (item, user) = (ItemRef::Laser(i), format!("laser {i}"));
        let direction = Vec3::from(l.direction);
        let wrong = if !Vec3::from(l.origin).is_finite() {
            Some("origin")
        } else if !direction.is_finite() || direction.length_squared() == 0.0 {
            Some("direction")
        } else if l.max_length.is_nan() || l.max_length <= 0.0 {
            Some("max_length")
        } else {
            None
        };
        if let Some(field) = wrong {
            let message = format!(
                "{user}: origin and direction must be finite, the direction non-zero and \
                 max_length positive"
            );
            c.report(item, field, message);
        }
        instances.find(c, (item, "instance"), &user, &l.instance);
        if let Some(b) = &l.beam {
            beam(c, item, &user, b, level.needs.is_some_and(|n| !n.emitters));
        }
    }
    let volumes = c.unique(
        "volume",
        (g.volumes.iter().enumerate()).map(|(i, v)| (ItemRef::Volume(i), v.name.as_str())),
    );
    let events: HashSet<&str> = (g.animations.iter())
        .flat_map(|a| a.events.iter().map(|e| e.name.as_str()))
        .chain(g.events.iter().map(String::as_str))
        .collect();
    for (i, u) in g.usables.iter().enumerate() {
        let (item, user) = (ItemRef::Usable(i), format!("usable {i} ({:?})", u.instance));
        instances.find(c, (item, "instance"), &user, &u.instance);
        if !g.events.contains(&u.event) {
            let message = format!(
                "{user} sends the event {:?}, which `events` does not declare",
                u.event
            );
            c.report(item, "event", message);
        }
        if u.prompt.trim().is_empty() {
            c.report(item, "prompt", format!("{user} has an empty prompt"));
        }
    }
    for (i, rule) in g.rules.iter().enumerate() {
        let (item, user) = (ItemRef::Rule(i), format!("rule {:?}", rule.name));
        let mut used = Vec::new();
        condition_names(&rule.when, &mut used);
        for (is_volume, name) in used {
            if is_volume {
                known(c, &volumes, (item, "when"), &user, "volume", name);
            } else if !events.contains(name) {
                let message = format!(
                    "{user} waits for the event {name:?}, which no clip fires and `events` \
                     does not declare"
                );
                c.report(item, "when", message);
            }
        }
        let actions = (rule.then.iter().map(|a| ("then", a)))
            .chain(rule.otherwise.iter().map(|a| ("otherwise", a)));
        for (field, action) in actions {
            let at = (item, field);
            match action {
                ActionEntry::Lights { group: gr, .. } | ActionEntry::ToggleLights(gr) => {
                    group(c, at, &user, *gr)
                }
                ActionEntry::Play { clip: name, .. }
                | ActionEntry::Reverse { clip: name }
                | ActionEntry::Pause { clip: name } => known(c, &clips, at, &user, "clip", name),
                ActionEntry::Sound {
                    sound: s,
                    at: on,
                    volume: v,
                } => {
                    known(c, &sounds, at, &user, "sound", s);
                    if let Some(on) = on {
                        instances.find(c, at, &user, on);
                    }
                    volume(c, at, &user, *v);
                }
                ActionEntry::Material {
                    instance: name,
                    material,
                } => {
                    instances.find(c, at, &user, name);
                    if let Some(m) = material {
                        known(c, materials, at, &user, "material", m);
                    }
                }
                // Counters are checked with the rules' memory (`validate_memory.rs`).
                // Breakables are checked in `validate_breakables.rs`.
                ActionEntry::Count { .. }
                | ActionEntry::SetCounter { .. }
                | ActionEntry::Break(_)
                | ActionEntry::Win
                | ActionEntry::Lose => {}
            }
        }
    }
}

/// A laser's visible beam: a finite non-negative colour and strength, a positive finite
/// radius; an emitting beam needs `needs.emitters` when the level declares `needs`.
fn beam(c: &mut Problems, item: ItemRef, user: &str, b: &BeamEntry, no_emitters: bool) {
    let color = Vec3::from(b.color);
    let valid = color.is_finite()
        && color.min_element() >= 0.0
        && b.strength.is_finite()
        && b.strength >= 0.0
        && b.radius.is_finite()
        && b.radius > 0.0;
    if !valid {
        let message = format!(
            "{user}: beam colour and strength must be finite and non-negative, its radius \
             positive (got colour {:?}, strength {}, radius {})",
            b.color, b.strength, b.radius
        );
        c.report(item, "beam", message);
    } else if no_emitters && (color * b.strength).max_element() > 0.0 {
        let message = format!(
            "{user}: its visible beam emits, but the level's `needs` leaves out emitters (add \
             `emitters: true`, or `beam: None`)"
        );
        c.report(item, "beam", message);
    }
}

/// The volume names (`true`) and event names (`false`) a condition uses, in order.
fn condition_names<'a>(c: &'a ConditionEntry, out: &mut Vec<(bool, &'a str)>) {
    match c {
        ConditionEntry::Occupied(v) | ConditionEntry::Entered(v) | ConditionEntry::Exited(v) => {
            out.push((true, v))
        }
        ConditionEntry::Occupants { volume, .. } | ConditionEntry::SunLit(volume) => {
            out.push((true, volume))
        }
        ConditionEntry::Event(e) => out.push((false, e)),
        ConditionEntry::All(cs)
        | ConditionEntry::Any(cs)
        | ConditionEntry::AtLeast { of: cs, .. }
        | ConditionEntry::Sequence(cs) => cs.iter().for_each(|c| condition_names(c, out)),
        ConditionEntry::Not(c) | ConditionEntry::Times { of: c, .. } => condition_names(c, out),
        // Checked with the rules' memory (`validate_memory.rs`).
        ConditionEntry::LightsOn(_)
        | ConditionEntry::Fired(_)
        | ConditionEntry::Counter { .. }
        | ConditionEntry::SunElevation { .. } => {}
    }
}
