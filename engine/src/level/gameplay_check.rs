//! Checking a level's `gameplay` section and turning it into a [`GameplayPlan`]: every name it
//! uses (instances, materials, sounds, clips, volumes, clip events, light groups, usables)
//! must exist, and the error names the level and the item that uses the unknown name.
//!
//! Owns: [`plan_gameplay`]. Sound files are resolved through the [`AssetRoot`] and decoded
//! here (`audio::decode_sound`), so a sound that does not decode fails the level load.
//! Main thread (level loading). Must not: spawn entities or run rules.

use std::collections::{HashMap, HashSet};
use std::path::Path;

use glam::Vec3;

use crate::assets::{
    ActionEntry, AssetError, AssetResult, AssetRoot, AuthoredClipSet, BeamEntry, BodyEntry,
    ConditionEntry, Level,
};
use crate::sim::triggers::{
    Action, Condition, GameplayPlan, PlannedBeam, PlannedEmitter, PlannedLaser, PlannedSound,
    PlannedUsable, PlannedVolume, Rule, Usable,
};

/// Name → index of a list of named items; a name used twice is an error.
fn index<'a>(
    kind: &str,
    names: impl Iterator<Item = &'a str>,
    error: &impl Fn(String) -> AssetError,
) -> AssetResult<HashMap<&'a str, usize>> {
    let mut map = HashMap::new();
    for (i, name) in names.enumerate() {
        if map.insert(name, i).is_some() {
            return Err(error(format!("{kind} name {name:?} is used twice")));
        }
    }
    Ok(map)
}

/// Looks `name` up in `map`; the error says which item used it.
fn find(
    map: &HashMap<&str, usize>,
    name: &str,
    kind: &str,
    user: &str,
    error: &impl Fn(String) -> AssetError,
) -> AssetResult<usize> {
    map.get(name).copied().ok_or_else(|| {
        error(format!(
            "{user} uses the {kind} {name:?}, which the level does not define"
        ))
    })
}

/// Checks `level.gameplay` (read from `level_path`) and resolves its names.
pub fn plan_gameplay(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> AssetResult<GameplayPlan> {
    let error = |message: String| AssetError::Level {
        path: level_path.to_path_buf(),
        message: format!("gameplay: {message}"),
    };
    let g = &level.gameplay;
    let mut plan = GameplayPlan::default();
    // Instance names: only duplicated names that gameplay actually uses are an error.
    let mut instances: HashMap<&str, usize> = HashMap::new();
    let mut twice: HashSet<&str> = HashSet::new();
    for (i, entry) in level.instances.iter().enumerate() {
        if let Some(name) = entry.name.as_deref()
            && instances.insert(name, i).is_some()
        {
            twice.insert(name);
        }
    }
    let instance = |name: &str, user: &str| {
        if twice.contains(name) {
            return Err(error(format!(
                "{user} uses the instance {name:?}, but two instances have that name"
            )));
        }
        find(&instances, name, "instance", user, &error)
    };
    let materials = index(
        "material",
        level.materials.iter().map(|m| m.name.as_str()),
        &error,
    )?;
    let sounds = index("sound", g.sounds.iter().map(|s| s.name.as_str()), &error)?;
    for s in &g.sounds {
        let path = root
            .resolve(level_path, None, &s.path)
            .map_err(|e| error(format!("sound {:?}: {e}", s.name)))?;
        let sound = crate::audio::decode_sound(&path)
            .map_err(|e| error(format!("sound {:?}: {e}", s.name)))?;
        plan.sounds.push(PlannedSound {
            name: s.name.clone(),
            path,
            sound,
        });
    }
    if let Some(music) = &g.music {
        let sound = find(&sounds, &music.sound, "sound", "music", &error)?;
        plan.music = Some((sound, volume(music.volume, "music", &error)?));
    }
    for (i, e) in g.emitters.iter().enumerate() {
        let user = format!("emitter {i}");
        plan.emitters.push(PlannedEmitter {
            instance: instance(&e.instance, &user)?,
            sound: find(&sounds, &e.sound, "sound", &user, &error)?,
            volume: volume(e.volume, &user, &error)?,
        });
    }
    plan_clips(level_path, level, &instance, &mut plan, &error)?;
    let clips = index("clip", g.animations.iter().map(|c| c.name.as_str()), &error)?;
    for a in &g.autoplay {
        plan.autoplay
            .push((find(&clips, &a.clip, "clip", "autoplay", &error)?, a.mode));
    }
    // A beam's own group counts: rules may switch a laser's light alone.
    let groups: HashSet<u32> = level
        .instances
        .iter()
        .filter_map(|i| i.light_group)
        .chain(g.lasers.iter().filter_map(|l| l.beam?.light_group))
        .collect();
    let group = |group: u32, user: &str| {
        if groups.contains(&group) {
            Ok(group)
        } else {
            Err(error(format!(
                "{user} switches light group {group}, which no instance belongs to"
            )))
        }
    };
    for &g in &g.lights_off {
        plan.lights_off.push(group(g, "lights_off")?);
    }
    for v in &g.volumes {
        let user = format!("volume {:?}", v.name);
        let i = instance(&v.instance, &user)?;
        if !matches!(level.instances[i].body, Some(BodyEntry::Sensor { .. })) {
            return Err(error(format!(
                "{user}: instance {:?} has no `body: Sensor(..)`, so nothing can be detected in it",
                v.instance
            )));
        }
        plan.volumes.push(PlannedVolume {
            name: v.name.clone(),
            instance: i,
            detects: v.detects.clone(),
        });
    }
    for (i, l) in g.lasers.iter().enumerate() {
        let user = format!("laser {i}");
        let direction = Vec3::from(l.direction);
        let finite = Vec3::from(l.origin).is_finite() && direction.is_finite();
        if !finite
            || direction.length_squared() == 0.0
            || l.max_length.is_nan()
            || l.max_length <= 0.0
        {
            return Err(error(format!(
                "{user}: origin and direction must be finite, the direction non-zero and max_length positive"
            )));
        }
        let at = instance(&l.instance, &user)?;
        let beam = match l.beam {
            Some(b) => {
                let planned = planned_beam(&b, level.instances[at].light_group, &user, &error)?;
                if level.needs.is_some_and(|n| !n.emitters) && planned.radiance.max_element() > 0.0
                {
                    return Err(error(format!(
                        "{user}: its visible beam emits, but the level's `needs` leaves out \
                         emitters (add `emitters: true`, or `beam: None`)"
                    )));
                }
                Some(planned)
            }
            None => None,
        };
        plan.lasers.push(PlannedLaser {
            instance: at,
            origin: Vec3::from(l.origin),
            direction,
            max_reflections: l.max_reflections,
            max_length: l.max_length.min(1e6),
            beam,
        });
    }
    let volumes = index("volume", g.volumes.iter().map(|v| v.name.as_str()), &error)?;
    let events: HashSet<&str> = g
        .animations
        .iter()
        .flat_map(|c| c.events.iter().map(|e| e.name.as_str()))
        .chain(g.events.iter().map(String::as_str))
        .collect();
    for (i, u) in g.usables.iter().enumerate() {
        let user = format!("usable {i} ({:?})", u.instance);
        let instance = instance(&u.instance, &user)?;
        if !g.events.contains(&u.event) {
            return Err(error(format!(
                "{user} sends the event {:?}, which `events` does not declare",
                u.event
            )));
        }
        if u.prompt.trim().is_empty() {
            return Err(error(format!("{user} has an empty prompt")));
        }
        plan.usables.push(PlannedUsable {
            instance,
            usable: Usable {
                prompt: u.prompt.clone(),
                event: u.event.clone(),
            },
        });
    }
    let refs = Refs {
        volumes: &volumes,
        events: &events,
        clips: &clips,
        sounds: &sounds,
        materials: &materials,
    };
    for rule in &g.rules {
        let user = format!("rule {:?}", rule.name);
        let actions = |list: &[ActionEntry]| {
            list.iter()
                .map(|a| refs.action(a, &user, &instance, &group, &error))
                .collect::<AssetResult<Vec<_>>>()
        };
        plan.rules.push(Rule {
            name: rule.name.clone(),
            when: refs.condition(&rule.when, &user, &error)?,
            then: actions(&rule.then)?,
            otherwise: actions(&rule.otherwise)?,
            once: rule.once,
        });
    }
    Ok(plan)
}

fn volume(v: f32, user: &str, error: &impl Fn(String) -> AssetError) -> AssetResult<f32> {
    if (0.0..=16.0).contains(&v) {
        Ok(v)
    } else {
        Err(error(format!("{user}: volume {v} is not in 0..=16")))
    }
}

/// The clips: targets must be named instances that may move under a clip.
fn plan_clips(
    level_path: &Path,
    level: &Level,
    instance: &impl Fn(&str, &str) -> AssetResult<usize>,
    plan: &mut GameplayPlan,
    error: &impl Fn(String) -> AssetError,
) -> AssetResult<()> {
    let mut targets: Vec<String> = Vec::new();
    for clip in &level.gameplay.animations {
        for track in &clip.tracks {
            let user = format!("clip {:?}", clip.name);
            let i = instance(&track.target, &user)?;
            if !targets.contains(&track.target) {
                match &level.instances[i].body {
                    None | Some(BodyEntry::Kinematic { .. }) | Some(BodyEntry::Sensor { .. }) => {}
                    Some(_) => {
                        return Err(error(format!(
                            "{user} moves instance {:?}, whose body is not Kinematic (physics would fight the clip)",
                            track.target
                        )));
                    }
                }
                targets.push(track.target.clone());
                plan.clip_targets.push(i);
            }
        }
    }
    let set = AuthoredClipSet {
        targets,
        clips: level.gameplay.animations.clone(),
    };
    plan.clips = set
        .to_clips(level_path)
        .map_err(|e| error(format!("animations: {e}")))?;
    Ok(())
}

/// The name tables rules refer to.
struct Refs<'a> {
    volumes: &'a HashMap<&'a str, usize>,
    events: &'a HashSet<&'a str>,
    clips: &'a HashMap<&'a str, usize>,
    sounds: &'a HashMap<&'a str, usize>,
    materials: &'a HashMap<&'a str, usize>,
}

impl Refs<'_> {
    fn condition(
        &self,
        c: &ConditionEntry,
        user: &str,
        error: &impl Fn(String) -> AssetError,
    ) -> AssetResult<Condition> {
        let volume = |name: &str| find(self.volumes, name, "volume", user, error);
        let list = |cs: &[ConditionEntry]| {
            cs.iter()
                .map(|c| self.condition(c, user, error))
                .collect::<AssetResult<Vec<_>>>()
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
            ConditionEntry::Event(name) => {
                if !self.events.contains(name.as_str()) {
                    return Err(error(format!(
                        "{user} waits for the event {name:?}, which no clip fires and `events` does not declare"
                    )));
                }
                Condition::Event(name.clone())
            }
            ConditionEntry::All(cs) => Condition::All(list(cs)?),
            ConditionEntry::Any(cs) => Condition::Any(list(cs)?),
            ConditionEntry::Not(c) => Condition::Not(Box::new(self.condition(c, user, error)?)),
            ConditionEntry::AtLeast { at_least, of } => Condition::AtLeast {
                at_least: *at_least,
                of: list(of)?,
            },
            ConditionEntry::Times { at_least, of } => Condition::Times {
                at_least: *at_least,
                of: Box::new(self.condition(of, user, error)?),
            },
        })
    }

    fn action(
        &self,
        a: &ActionEntry,
        user: &str,
        instance: &impl Fn(&str, &str) -> AssetResult<usize>,
        group: &impl Fn(u32, &str) -> AssetResult<u32>,
        error: &impl Fn(String) -> AssetError,
    ) -> AssetResult<Action> {
        let clip = |name: &str| find(self.clips, name, "clip", user, error);
        Ok(match a {
            ActionEntry::Lights { group: g, on } => Action::Lights {
                group: group(*g, user)?,
                on: *on,
            },
            ActionEntry::ToggleLights(g) => Action::ToggleLights(group(*g, user)?),
            ActionEntry::Play { clip: c, mode } => Action::Play {
                clip: clip(c)?,
                mode: *mode,
            },
            ActionEntry::Reverse { clip: c } => Action::Reverse { clip: clip(c)? },
            ActionEntry::Pause { clip: c } => Action::Pause { clip: clip(c)? },
            ActionEntry::Sound {
                sound,
                at,
                volume: v,
            } => Action::Sound {
                sound: find(self.sounds, sound, "sound", user, error)?,
                at: at.as_deref().map(|name| instance(name, user)).transpose()?,
                volume: volume(*v, user, error)?,
            },
            ActionEntry::Material {
                instance: name,
                material,
            } => Action::Material {
                instance: instance(name, user)?,
                material: material
                    .as_deref()
                    .map(|m| find(self.materials, m, "material", user, error).map(|m| m as u32))
                    .transpose()?,
            },
            ActionEntry::Win => Action::Win,
            ActionEntry::Lose => Action::Lose,
        })
    }
}

/// A laser's visible beam, checked: a finite non-negative colour and strength, a positive
/// finite radius; the light group defaults to the laser instance's (`instance_group`).
fn planned_beam(
    b: &BeamEntry,
    instance_group: Option<u32>,
    user: &str,
    error: &impl Fn(String) -> AssetError,
) -> AssetResult<PlannedBeam> {
    let color = Vec3::from(b.color);
    let valid = color.is_finite()
        && color.min_element() >= 0.0
        && b.strength.is_finite()
        && b.strength >= 0.0
        && b.radius.is_finite()
        && b.radius > 0.0;
    if !valid {
        return Err(error(format!(
            "{user}: beam colour and strength must be finite and non-negative, its radius \
             positive (got colour {:?}, strength {}, radius {})",
            b.color, b.strength, b.radius
        )));
    }
    Ok(PlannedBeam {
        radiance: color * b.strength,
        radius: b.radius,
        light_group: b.light_group.or(instance_group),
    })
}
