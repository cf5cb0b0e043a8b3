//! A level made of parts: a base file (models, materials, camera, sun, sky, render settings
//! that every part shares) and area files (a game's chambers, a world's regions), each a level
//! file of its own in world coordinates, merged into one level before it is loaded — so that a
//! designer edits one chamber in one file and the game still plays them as one world (light
//! groups of rooms that cannot be seen switch off; doors open between files).
//!
//! Owns: [`compose_levels`] (merging parsed files) and [`load_composed`] (reading, merging,
//! loading, and naming the part a problem comes from). Main thread or a loader thread.
//! Must not: spawn anything.
//!
//! Merging: shared definitions (models, materials, boxes, grids, terrains, cities, sounds) are
//! merged by name and must agree where two files define the same name; instances, lasers,
//! emitters, usables and autoplay entries are appended in file order; names that must be unique
//! (named instances, clips, volumes, rules, characters) must not repeat across files. The
//! base file's camera, sun, sky, render settings and render areas win (an area's camera is its
//! own preview view, unused by the merge).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use super::load::{PlayableLevel, playable_from_level};
use crate::assets::{AssetError, AssetResult, AssetRoot, Level};

/// Merges `parts` (each with the file it was read from) into `base`. Errors name the part file
/// and the item that clashes.
pub fn compose_levels(base: &Level, parts: &[(PathBuf, Level)]) -> AssetResult<Level> {
    let mut out = base.clone();
    out.needs = None;
    for (path, part) in parts {
        merge(&mut out, part).map_err(|message| AssetError::Level {
            path: path.clone(),
            message,
        })?;
    }
    Ok(out)
}

/// Reads `base_path` and `part_paths`, merges them and loads the result. A problem that one
/// file causes (a rule wired to a volume that does not exist, a missing model file) names that
/// file: on failure the base is loaded alone, then with the parts up to each one in turn, and
/// the first that fails is reported. So a part may name items of the parts before it, not after.
///
/// Returns the merged level file too (names of its materials and instances, for the game).
pub fn load_composed(
    base_path: &Path,
    part_paths: &[PathBuf],
    root: &AssetRoot,
) -> AssetResult<(Level, PlayableLevel)> {
    let base = Level::read(base_path)?;
    let mut parts = Vec::with_capacity(part_paths.len());
    for path in part_paths {
        parts.push((path.clone(), Level::read(path)?));
    }
    let composed = compose_levels(&base, &parts)?;
    match playable_from_level(base_path, &composed, root) {
        Ok(level) => Ok((composed, level)),
        Err(merged_error) => {
            // Find the first file whose items break it: the base alone, then the base with
            // the parts up to each one (a part may name items of the parts before it).
            playable_from_level(base_path, &compose_levels(&base, &[])?, root)?;
            for i in 0..parts.len() {
                let prefix = compose_levels(&base, &parts[..=i])?;
                playable_from_level(&parts[i].0, &prefix, root)?;
            }
            Err(merged_error)
        }
    }
}

/// Appends `part` to `out`.
fn merge(out: &mut Level, part: &Level) -> Result<(), String> {
    union_by(&mut out.models, &part.models, |m| &m.name, "model")?;
    union_by(&mut out.materials, &part.materials, |m| &m.name, "material")?;
    union_by(&mut out.grids, &part.grids, |m| &m.name, "grid")?;
    union_by(&mut out.boxes, &part.boxes, |m| &m.name, "box")?;
    union_by(&mut out.terrains, &part.terrains, |m| &m.name, "terrain")?;
    union_by(&mut out.cities, &part.cities, |m| &m.name, "city")?;
    let named: HashMap<&str, ()> = out
        .instances
        .iter()
        .filter_map(|i| i.name.as_deref())
        .map(|n| (n, ()))
        .collect();
    if let Some(clash) = part
        .instances
        .iter()
        .filter_map(|i| i.name.as_deref())
        .find(|n| named.contains_key(n))
    {
        return Err(format!(
            "the instance name {clash:?} is already used by an earlier file"
        ));
    }
    out.instances.extend(part.instances.iter().cloned());
    unique_by(
        &mut out.characters,
        &part.characters,
        |c| &c.name,
        "character",
    )?;

    let (g, p) = (&mut out.gameplay, &part.gameplay);
    union_by(&mut g.sounds, &p.sounds, |s| &s.name, "sound")?;
    if g.music.is_none() {
        g.music.clone_from(&p.music);
    }
    g.emitters.extend(p.emitters.iter().cloned());
    unique_by(&mut g.animations, &p.animations, |a| &a.name, "clip")?;
    g.autoplay.extend(p.autoplay.iter().cloned());
    for group in &p.lights_off {
        if !g.lights_off.contains(group) {
            g.lights_off.push(*group);
        }
    }
    unique_by(&mut g.volumes, &p.volumes, |v| &v.name, "volume")?;
    g.lasers.extend(p.lasers.iter().cloned());
    unique_by(&mut g.rules, &p.rules, |r| &r.name, "rule")?;
    for event in &p.events {
        if !g.events.contains(event) {
            g.events.push(event.clone());
        }
    }
    g.usables.extend(p.usables.iter().cloned());
    Ok(())
}

/// Adds the items of `new` whose name `out` lacks; an item whose name `out` has must be equal.
fn union_by<T: Clone + PartialEq>(
    out: &mut Vec<T>,
    new: &[T],
    name: impl Fn(&T) -> &String,
    what: &str,
) -> Result<(), String> {
    for item in new {
        match out.iter().find(|o| name(o) == name(item)) {
            Some(existing) if existing == item => {}
            Some(_) => {
                return Err(format!(
                    "the {what} {:?} differs from the one an earlier file defines",
                    name(item)
                ));
            }
            None => out.push(item.clone()),
        }
    }
    Ok(())
}

/// Appends `new`, whose names must not be in `out` already.
fn unique_by<T: Clone>(
    out: &mut Vec<T>,
    new: &[T],
    name: impl Fn(&T) -> &String,
    what: &str,
) -> Result<(), String> {
    for item in new {
        if out.iter().any(|o| name(o) == name(item)) {
            return Err(format!(
                "the {what} name {:?} is already used by an earlier file",
                name(item)
            ));
        }
        out.push(item.clone());
    }
    Ok(())
}
