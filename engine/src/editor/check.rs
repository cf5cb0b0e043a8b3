//! Checking a level before it is saved, and what a click on one of its problems selects.
//!
//! The rules are the level layer's (`level::validate_level`, and the full load's
//! `level::level_problems`); a [`Problem`] is its typed [`crate::level::LevelProblem`]: the
//! item (kind and index), the field and a message. [`check_references`] reads only the level;
//! [`check_level`] adds the engine's own full load (models, bodies, sounds, clips, `needs`) so
//! that nothing the game would refuse can be saved. [`instance_to_select`] maps a problem to
//! the instance the selection (which holds instances only) takes, from the typed item alone —
//! never from the message. Main thread. Must not: modify the level.

use std::path::Path;

use crate::assets::{AssetRoot, Level};

use crate::level::ItemRef;

/// One reason a level cannot be saved: the level layer's typed problem.
pub use crate::level::LevelProblem as Problem;

/// Every problem the level's data alone shows, all at once, in the order of its lists.
pub fn check_references(level: &Level) -> Vec<Problem> {
    crate::level::validate_level(level)
}

/// [`check_references`], then, when those pass and `root` is given, the engine's full load
/// of the level as if read from `path` (its models and sounds are read from `root`), whose
/// first problem is returned with the item it is in.
pub fn check_level(path: &Path, level: &Level, root: Option<&AssetRoot>) -> Vec<Problem> {
    match root {
        Some(root) => crate::level::level_problems(path, level, root),
        None => check_references(level),
    }
}

/// The instance of `level` a click on `problem` selects: the instance the problem is in, or
/// the one its item sits on (a volume's sensor, a laser's, an emitter's or a usable's
/// instance, when exactly one instance has that name); `None` for other items. Reads only
/// `problem.item`, never the message.
pub fn instance_to_select(problem: &Problem, level: &Level) -> Option<usize> {
    let g = &level.gameplay;
    let name = match problem.item {
        ItemRef::Instance(i) => return (i < level.instances.len()).then_some(i),
        ItemRef::Volume(i) => &g.volumes.get(i)?.instance,
        ItemRef::Laser(i) => &g.lasers.get(i)?.instance,
        ItemRef::Emitter(i) => &g.emitters.get(i)?.instance,
        ItemRef::Usable(i) => &g.usables.get(i)?.instance,
        _ => return None,
    };
    let mut named = (level.instances.iter().enumerate())
        .filter(|(_, e)| e.name.as_deref() == Some(name.as_str()))
        .map(|(i, _)| i);
    match (named.next(), named.next()) {
        (Some(i), None) => Some(i),
        _ => None,
    }
}
