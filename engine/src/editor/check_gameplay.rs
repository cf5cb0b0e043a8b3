//! The gameplay half of the editor's reference check (`check`): sounds, emitters, clips and
//! their targets, autoplay, light groups, volumes on sensors, lasers, usables and events,
//! rules' conditions and actions — every problem reported with its item.
//!
//! Main thread. Must not: modify the level.

use std::collections::{HashMap, HashSet};

use crate::assets::{ActionEntry, BodyEntry, ConditionEntry, Level};

use super::check::Checker;
use super::item::ItemRef;

/// The gameplay section's references (`instances`: how many instances have each name).
pub(super) fn gameplay(
    c: &mut Checker,
    instances: &HashMap<&str, usize>,
    materials: &HashSet<&str>,
) {
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
            || l.max_length.is_nan()
            || l.max_length <= 0.0
        {
            let message = format!(
                "laser {i}: origin and direction must be finite, the direction non-zero and \
                 max_length positive"
            );
            c.report(ItemRef::Laser(i), message);
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
                let message = format!(
                    "{user} waits for the event {name:?}, which no clip fires and `events` \
                     does not declare"
                );
                c.report(item, message);
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
