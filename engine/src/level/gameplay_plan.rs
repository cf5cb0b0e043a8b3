//! Turning a level's `gameplay` section into a [`GameplayPlan`]: names resolved to indices,
//! sound files decoded, clips built. The rules a level must follow are checked before, by
//! [`super::validate_level`]; this only resolves, and what needs files (a sound that does not
//! decode, a clip key of the wrong width) is a typed [`LevelProblem`] too.
//!
//! Owns: [`plan_gameplay`]. Sound files are resolved through the [`AssetRoot`] and decoded
//! here (`audio::decode_sound`). Main thread (level loading). Must not: spawn entities or run
//! rules.

use std::collections::HashMap;
use std::path::Path;

use glam::Vec3;

use crate::assets::{ActionEntry, AssetRoot, AuthoredClipSet, ConditionEntry, Level};
use crate::sim::triggers::{
    Action, Condition, GameplayPlan, PlannedBeam, PlannedBreakable, PlannedEmitter, PlannedLaser,
    PlannedSound, PlannedUsable, PlannedVolume, Rule, Usable,
};

use super::item::ItemRef;
use super::problem::LevelProblem;

/// The names gameplay uses, each to its index (the first item of that name).
struct Names<'a> {
    instances: HashMap<&'a str, usize>,
    materials: HashMap<&'a str, usize>,
    sounds: HashMap<&'a str, usize>,
    clips: HashMap<&'a str, usize>,
    volumes: HashMap<&'a str, usize>,
    rules: HashMap<&'a str, usize>,
    counters: HashMap<&'a str, usize>,
    breakables: HashMap<&'a str, usize>,
}

/// Name → index of the first item of each name (`None`: an item without a name).
fn first<'a>(names: impl Iterator<Item = Option<&'a str>>) -> HashMap<&'a str, usize> {
    let mut map = HashMap::new();
    for (i, name) in names.enumerate() {
        if let Some(name) = name {
            map.entry(name).or_insert(i);
        }
    }
    map
}

/// `name` (a `kind`, used by `at`) in `map`; a problem when the level was not validated.
fn find(
    map: &HashMap<&str, usize>,
    name: &str,
    kind: &str,
    (item, field): (ItemRef, &'static str),
) -> Result<usize, LevelProblem> {
    map.get(name).copied().ok_or_else(|| {
        let message = format!("the {kind} {name:?} is not defined (the level was not validated)");
        LevelProblem::new(item, field, message)
    })
}

/// Resolves `level.gameplay` (read from `level_path`, which [`super::validate_level`] found no
/// problem in), decoding its sounds from `root`.
pub(super) fn plan_gameplay(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> Result<GameplayPlan, LevelProblem> {
    let g = &level.gameplay;
    let n = Names {
        instances: first(level.instances.iter().map(|e| e.name.as_deref())),
        materials: first(level.materials.iter().map(|m| Some(m.name.as_str()))),
        sounds: first(g.sounds.iter().map(|s| Some(s.name.as_str()))),
        clips: first(g.animations.iter().map(|c| Some(c.name.as_str()))),
        volumes: first(g.volumes.iter().map(|v| Some(v.name.as_str()))),
        rules: first(g.rules.iter().map(|r| Some(r.name.as_str()))),
        counters: first(g.counters.iter().map(|c| Some(c.name.as_str()))),
        breakables: first(g.breakables.iter().map(|b| Some(b.name.as_str()))),
    };
    let instance = |name: &str, at| find(&n.instances, name, "instance", at);
    let mut plan = GameplayPlan::default();
    for (i, s) in g.sounds.iter().enumerate() {
        let bad = |e: String| {
            LevelProblem::new(
                ItemRef::Sound(i),
                "path",
                format!("sound {:?}: {e}", s.name),
            )
        };
        let path = root
            .resolve(level_path, None, &s.path)
            .map_err(|e| bad(e.to_string()))?;
        let sound = crate::audio::decode_sound(&path).map_err(|e| bad(e.to_string()))?;
        plan.sounds.push(PlannedSound {
            name: s.name.clone(),
            path,
            sound,
        });
    }
    if let Some(m) = &g.music {
        let sound = find(&n.sounds, &m.sound, "sound", (ItemRef::Music, "sound"))?;
        plan.music = Some((sound, m.volume));
    }
    for (i, e) in g.emitters.iter().enumerate() {
        let item = ItemRef::Emitter(i);
        plan.emitters.push(PlannedEmitter {
            instance: instance(&e.instance, (item, "instance"))?,
            sound: find(&n.sounds, &e.sound, "sound", (item, "sound"))?,
            volume: e.volume,
        });
    }
    let mut targets: Vec<String> = Vec::new();
    for (i, clip) in g.animations.iter().enumerate() {
        for track in &clip.tracks {
            let at = instance(&track.target, (ItemRef::Clip(i), "tracks"))?;
            if !targets.contains(&track.target) {
                targets.push(track.target.clone());
                plan.clip_targets.push(at);
            }
        }
    }
    for (i, clip) in g.animations.iter().enumerate() {
        let set = AuthoredClipSet {
            targets: targets.clone(),
            clips: vec![clip.clone()],
        };
        let built = set.to_clips(level_path).map_err(|e| {
            LevelProblem::new(ItemRef::Clip(i), "tracks", format!("animations: {e}"))
        })?;
        plan.clips.extend(built);
    }
    for (i, a) in g.autoplay.iter().enumerate() {
        let clip = find(&n.clips, &a.clip, "clip", (ItemRef::Autoplay(i), "clip"))?;
        plan.autoplay.push((clip, a.mode));
    }
    plan.lights_off = g.lights_off.clone();
    plan.counters = (g.counters.iter())
        .map(|c| (c.name.clone(), c.start))
        .collect();
    for (i, v) in g.volumes.iter().enumerate() {
        plan.volumes.push(PlannedVolume {
            name: v.name.clone(),
            instance: instance(&v.instance, (ItemRef::Volume(i), "instance"))?,
            detects: v.detects.clone(),
        });
    }
    for (i, l) in g.lasers.iter().enumerate() {
        let at = instance(&l.instance, (ItemRef::Laser(i), "instance"))?;
        let instance_group = level.instances.get(at).and_then(|e| e.light_group);
        plan.lasers.push(PlannedLaser {
            instance: at,
            origin: Vec3::from(l.origin),
            direction: Vec3::from(l.direction),
            max_reflections: l.max_reflections,
            max_length: l.max_length.min(1e6),
            beam: l.beam.map(|b| PlannedBeam {
                radiance: Vec3::from(b.color) * b.strength,
                radius: b.radius,
                light_group: b.light_group.or(instance_group),
            }),
        });
    }
    for (i, u) in g.usables.iter().enumerate() {
        plan.usables.push(PlannedUsable {
            instance: instance(&u.instance, (ItemRef::Usable(i), "instance"))?,
            usable: Usable {
                prompt: u.prompt.clone(),
                event: u.event.clone(),
            },
        });
    }
    for (i, b) in g.breakables.iter().enumerate() {
        let at = (ItemRef::Breakable(i), "pieces");
        plan.breakables.push(PlannedBreakable {
            name: b.name.clone(),
            pieces: (b.pieces.iter())
                .map(|p| instance(p, at))
                .collect::<Result<_, _>>()?,
            impact_speed: b.impact_speed,
            piece_mass: b.piece_mass,
            scatter_speed: b.scatter_speed,
        });
    }
    for (i, rule) in g.rules.iter().enumerate() {
        let item = ItemRef::Rule(i);
        let actions = |list: &[ActionEntry], field| {
            list.iter()
                .map(|a| action(&n, &instance, a, (item, field)))
                .collect::<Result<Vec<_>, _>>()
        };
        plan.rules.push(Rule {
            name: rule.name.clone(),
            when: condition(&n, &rule.when, item)?,
            then: actions(&rule.then, "then")?,
            otherwise: actions(&rule.otherwise, "otherwise")?,
            once: rule.once,
        });
    }
    Ok(plan)
}

/// A rule's condition with its volumes resolved.
fn condition(n: &Names, c: &ConditionEntry, item: ItemRef) -> Result<Condition, LevelProblem> {
    let volume = |name: &str| find(&n.volumes, name, "volume", (item, "when"));
    let list = |cs: &[ConditionEntry]| {
        cs.iter()
            .map(|c| condition(n, c, item))
            .collect::<Result<Vec<_>, _>>()
    };
    Ok(match c {
        ConditionEntry::Occupied(v) => Condition::Occupied(volume(v)?),
        ConditionEntry::Entered(v) => Condition::Entered(volume(v)?),
        ConditionEntry::Exited(v) => Condition::Exited(volume(v)?),
        ConditionEntry::Occupants {
            volume: v,
            at_least,
        } => Condition::Occupants {
            volume: volume(v)?,
            at_least: *at_least,
        },
        ConditionEntry::Event(name) => Condition::Event(name.clone()),
        ConditionEntry::All(cs) => Condition::All(list(cs)?),
        ConditionEntry::Any(cs) => Condition::Any(list(cs)?),
        ConditionEntry::Not(c) => Condition::Not(Box::new(condition(n, c, item)?)),
        ConditionEntry::AtLeast { at_least, of } => Condition::AtLeast {
            at_least: *at_least,
            of: list(of)?,
        },
        ConditionEntry::Times { at_least, of } => Condition::Times {
            at_least: *at_least,
            of: Box::new(condition(n, of, item)?),
        },
        ConditionEntry::LightsOn(group) => Condition::LightsOn(*group),
        ConditionEntry::SunLit(v) => Condition::SunLit(volume(v)?),
        ConditionEntry::SunElevation { at_least, at_most } => Condition::SunElevation {
            at_least: at_least.unwrap_or(f32::NEG_INFINITY),
            at_most: at_most.unwrap_or(f32::INFINITY),
        },
        ConditionEntry::Fired(rule) => {
            Condition::Fired(find(&n.rules, rule, "rule", (item, "when"))?)
        }
        ConditionEntry::Counter {
            counter,
            at_least,
            at_most,
        } => Condition::Counter {
            counter: find(&n.counters, counter, "counter", (item, "when"))?,
            at_least: at_least.unwrap_or(i32::MIN),
            at_most: at_most.unwrap_or(i32::MAX),
        },
        ConditionEntry::Sequence(steps) => Condition::Sequence(list(steps)?),
    })
}

/// A rule's action with its clips, sounds, instances and materials resolved.
fn action(
    n: &Names,
    instance: &impl Fn(&str, (ItemRef, &'static str)) -> Result<usize, LevelProblem>,
    a: &ActionEntry,
    at: (ItemRef, &'static str),
) -> Result<Action, LevelProblem> {
    let clip = |name: &str| find(&n.clips, name, "clip", at);
    Ok(match a {
        ActionEntry::Lights { group, on } => Action::Lights {
            group: *group,
            on: *on,
        },
        ActionEntry::ToggleLights(group) => Action::ToggleLights(*group),
        ActionEntry::Play { clip: c, mode } => Action::Play {
            clip: clip(c)?,
            mode: *mode,
        },
        ActionEntry::Reverse { clip: c } => Action::Reverse { clip: clip(c)? },
        ActionEntry::Pause { clip: c } => Action::Pause { clip: clip(c)? },
        ActionEntry::Sound {
            sound,
            at: on,
            volume,
        } => Action::Sound {
            sound: find(&n.sounds, sound, "sound", at)?,
            at: on.as_deref().map(|name| instance(name, at)).transpose()?,
            volume: *volume,
        },
        ActionEntry::Material {
            instance: name,
            material,
        } => Action::Material {
            instance: instance(name, at)?,
            material: (material.as_deref())
                .map(|m| find(&n.materials, m, "material", at).map(|m| m as u32))
                .transpose()?,
        },
        ActionEntry::Count { counter, add } => Action::Count {
            counter: find(&n.counters, counter, "counter", at)?,
            add: *add,
        },
        ActionEntry::SetCounter { counter, value } => Action::SetCounter {
            counter: find(&n.counters, counter, "counter", at)?,
            value: *value,
        },
        ActionEntry::Break(name) => Action::Break(find(&n.breakables, name, "breakable", at)?),
        ActionEntry::Win => Action::Win,
        ActionEntry::Lose => Action::Lose,
    })
}
