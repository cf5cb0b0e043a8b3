//! Edit commands: every change the editor makes to a level [`Document`] is an [`Edit`], and
//! applying an edit returns its inverse (the edit that puts back exactly what it replaced), so
//! undo needs no snapshot of the level.
//!
//! Owns: [`Edit`] and its fields, applying them, their descriptions for the history panel,
//! their merge keys (consecutive edits of the same field of the same item merge within a
//! drag, see `history`), what of the world they touch, and how they shift instance indices.
//! Main thread. Must not: touch the world or the renderer; it edits the document only.

use crate::assets::{ConditionEntry, InstanceEntry, Level};

use super::comments::Anchored;
use super::document::Document;
pub use super::fields::{InstanceField, LaserField, MaterialField, VolumeField};
pub use super::list_edit::ListEdit;

/// The instance list's key in [`super::Comments`] (comments follow inserted and deleted
/// instances).
const INSTANCES: &str = "instances";

/// One edit of a level document. Indices are positions in the level's lists.
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    /// Set one field of `instances[index]`.
    Instance { index: usize, field: InstanceField },
    /// Insert `entry` (with its file comments) so that it becomes `instances[index]`.
    InsertInstance {
        index: usize,
        entry: Box<InstanceEntry>,
        comments: Anchored,
    },
    /// A copy of `instances[index]` right after it; a named original gives the copy a fresh
    /// name (`door` → `door_2`), so that gameplay references stay unambiguous.
    DuplicateInstance { index: usize },
    /// Remove `instances[index]` (its comments go with it, and come back with an undo).
    DeleteInstance { index: usize },
    /// Set one field of `materials[index]`.
    Material { index: usize, field: MaterialField },
    /// Set one field of `gameplay.lasers[index]`.
    Laser { index: usize, field: LaserField },
    /// Set one field of `gameplay.volumes[index]`.
    Volume { index: usize, field: VolumeField },
    /// Replace the condition of `gameplay.rules[index]`.
    RuleCondition { index: usize, when: ConditionEntry },
    /// In the condition of `gameplay.rules[index]`, every use of the volume `from` becomes a
    /// use of `to` (a door wired from one plate to another).
    RewireRule {
        index: usize,
        from: String,
        to: String,
    },
    /// An edit of another list of the level (models, a clip, lights off, autoplay).
    List(ListEdit),
    /// Several edits as one (a group of instances moved together); applied in order.
    Batch(Vec<Edit>),
    /// An edit of the base file of a composed world (`Document::base`: a common material
    /// edited from a Reflect chamber); saved to that file.
    Base(Box<Edit>),
}

/// Why an edit could not be applied; the document is unchanged.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EditError {
    #[error("the level has no {kind} {index} (it has {len})")]
    NoSuchItem {
        kind: &'static str,
        index: usize,
        len: usize,
    },
    #[error("rule {rule:?} does not use the volume {volume:?}")]
    NotWired { rule: String, volume: String },
    #[error("the level is not composed over a base file")]
    NoBase,
}

/// Identifies what an edit sets: edits with equal keys set the same fields of the same items
/// and may merge into one command (the last value wins, the first one's undo is kept).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeKey(Vec<(&'static str, usize, &'static str)>);

/// What of the world an edit changes, for the runner: transforms it may update in place,
/// anything else by spawning the level again.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Touch {
    /// Only the transforms of these instances.
    Transforms(Vec<usize>),
    /// Anything else: re-spawn the level.
    Level,
}

/// How an edit moves instance indices (the selection follows).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shift {
    /// An instance was inserted at this index; those at and after it moved up by one.
    Inserted(usize),
    /// The instance at this index was removed; those after it moved down by one.
    Removed(usize),
}

fn get<'a, T>(list: &'a mut [T], kind: &'static str, index: usize) -> Result<&'a mut T, EditError> {
    let len = list.len();
    list.get_mut(index)
        .ok_or(EditError::NoSuchItem { kind, index, len })
}

impl Edit {
    /// Applies the edit to `doc` and returns its inverse. On an error `doc` is unchanged.
    pub fn apply(&self, doc: &mut Document) -> Result<Edit, EditError> {
        let level = &mut doc.level;
        Ok(match self {
            Edit::Instance { index, field } => {
                let entry = get(&mut level.instances, "instance", *index)?;
                Edit::Instance {
                    index: *index,
                    field: field.clone().swap(entry),
                }
            }
            Edit::InsertInstance {
                index,
                entry,
                comments,
            } => {
                let len = level.instances.len();
                if *index > len {
                    return Err(EditError::NoSuchItem {
                        kind: "instance slot",
                        index: *index,
                        len,
                    });
                }
                level.instances.insert(*index, (**entry).clone());
                doc.comments
                    .insert_item(INSTANCES, *index, comments.clone());
                Edit::DeleteInstance { index: *index }
            }
            Edit::DuplicateInstance { index } => {
                let mut copy = get(&mut level.instances, "instance", *index)?.clone();
                copy.name = copy.name.map(|name| fresh_name(level, &name));
                level.instances.insert(index + 1, copy);
                doc.comments
                    .insert_item(INSTANCES, index + 1, Anchored::default());
                Edit::DeleteInstance { index: index + 1 }
            }
            Edit::DeleteInstance { index } => {
                get(&mut level.instances, "instance", *index)?;
                let entry = level.instances.remove(*index);
                let comments = doc.comments.remove_item(INSTANCES, *index);
                Edit::InsertInstance {
                    index: *index,
                    entry: Box::new(entry),
                    comments,
                }
            }
            Edit::Material { index, field } => {
                let material = get(&mut level.materials, "material", *index)?;
                Edit::Material {
                    index: *index,
                    field: field.clone().swap(material),
                }
            }
            Edit::Laser { index, field } => {
                let laser = get(&mut level.gameplay.lasers, "laser", *index)?;
                let field = field.clone().swap(laser);
                Edit::Laser {
                    index: *index,
                    field,
                }
            }
            Edit::Volume { index, field } => {
                let volume = get(&mut level.gameplay.volumes, "volume", *index)?;
                let field = field.clone().swap(volume);
                Edit::Volume {
                    index: *index,
                    field,
                }
            }
            Edit::RuleCondition { index, when } => {
                let rule = get(&mut level.gameplay.rules, "rule", *index)?;
                Edit::RuleCondition {
                    index: *index,
                    when: std::mem::replace(&mut rule.when, when.clone()),
                }
            }
            Edit::RewireRule { index, from, to } => {
                let rule = get(&mut level.gameplay.rules, "rule", *index)?;
                let mut when = rule.when.clone();
                if rewire(&mut when, from, to) == 0 {
                    return Err(EditError::NotWired {
                        rule: rule.name.clone(),
                        volume: from.clone(),
                    });
                }
                Edit::RuleCondition {
                    index: *index,
                    when: std::mem::replace(&mut rule.when, when),
                }
            }
            Edit::List(edit) => Edit::List(edit.apply(level)?),
            Edit::Base(edit) => {
                let base = doc.base.as_deref_mut().ok_or(EditError::NoBase)?;
                Edit::Base(Box::new(edit.apply(base)?))
            }
            Edit::Batch(edits) => {
                let mut inverses = Vec::with_capacity(edits.len());
                for edit in edits {
                    match edit.apply(doc) {
                        Ok(inverse) => inverses.push(inverse),
                        Err(e) => {
                            // Put back what was applied; inverses of applied edits apply.
                            for inverse in inverses.iter().rev() {
                                let _ = inverse.apply(doc);
                            }
                            return Err(e);
                        }
                    }
                }
                inverses.reverse();
                Edit::Batch(inverses)
            }
        })
    }

    /// What the edit does, for the history panel (names taken from `doc` before it applies;
    /// an edit of the base file names its items from the base).
    pub fn describe_in(&self, doc: &Document) -> String {
        match (self, doc.base.as_deref()) {
            (Edit::Base(edit), Some(base)) => format!("{} (base file)", edit.describe(&base.level)),
            _ => self.describe(&doc.level),
        }
    }

    /// What the edit does, for the history panel (names taken from `level` before it applies).
    pub fn describe(&self, level: &Level) -> String {
        let instance = |i: usize| match level.instances.get(i) {
            Some(InstanceEntry {
                name: Some(name), ..
            }) => format!("instance {i} ({name:?})"),
            Some(entry) => format!("instance {i} ({:?})", entry.model),
            None => format!("instance {i}"),
        };
        let named = |names: Vec<&str>, kind: &str, i: usize| match names.get(i) {
            Some(name) => format!("{kind} {name:?}"),
            None => format!("{kind} {i}"),
        };
        let material = |i| {
            named(
                level.materials.iter().map(|m| &*m.name).collect(),
                "material",
                i,
            )
        };
        let g = &level.gameplay;
        let volume = |i| named(g.volumes.iter().map(|v| &*v.name).collect(), "volume", i);
        let rule = |i| named(g.rules.iter().map(|r| &*r.name).collect(), "rule", i);
        match self {
            Edit::Instance { index, field } => {
                format!("Set {} of {}", field.name(), instance(*index))
            }
            Edit::InsertInstance { index, entry, .. } => {
                format!("Add instance {index} ({:?})", entry.model)
            }
            Edit::DuplicateInstance { index } => format!("Duplicate {}", instance(*index)),
            Edit::DeleteInstance { index } => format!("Delete {}", instance(*index)),
            Edit::Material { index, field } => {
                format!("Set {} of {}", field.name(), material(*index))
            }
            Edit::Laser { index, field } => format!("Set {} of laser {index}", field.name()),
            Edit::Volume { index, field } => format!("Set {} of {}", field.name(), volume(*index)),
            Edit::RuleCondition { index, .. } => format!("Set the condition of {}", rule(*index)),
            Edit::RewireRule { index, from, to } => {
                format!("Rewire {} from {from:?} to {to:?}", rule(*index))
            }
            Edit::List(edit) => edit.describe(level),
            Edit::Base(_) => "Edit the base file".into(),
            Edit::Batch(edits) => match edits.first() {
                Some(first) if edits.len() == 1 => first.describe(level),
                Some(first) => format!("{} (and {} more)", first.describe(level), edits.len() - 1),
                None => "Nothing".into(),
            },
        }
    }

    /// The key consecutive edits of one drag merge by; `None`: never merges (structural
    /// edits, rewiring).
    pub fn merge_key(&self) -> Option<MergeKey> {
        let one = |kind, index: &usize, field| Some(MergeKey(vec![(kind, *index, field)]));
        match self {
            Edit::Instance { index, field } => one("instance", index, field.name()),
            Edit::Material { index, field } => one("material", index, field.name()),
            Edit::Laser { index, field } => one("laser", index, field.name()),
            Edit::Volume { index, field } => one("volume", index, field.name()),
            Edit::RuleCondition { index, .. } => one("rule", index, "condition"),
            Edit::List(edit) => edit.merge_part().map(|part| MergeKey(vec![part])),
            Edit::Base(edit) => {
                let mut keys = vec![("base", 0, "")];
                keys.extend(edit.merge_key()?.0);
                Some(MergeKey(keys))
            }
            Edit::Batch(edits) if !edits.is_empty() => {
                let mut keys = Vec::new();
                for edit in edits {
                    keys.extend(edit.merge_key()?.0);
                }
                Some(MergeKey(keys))
            }
            _ => None,
        }
    }

    /// What of the world the edit changes.
    pub fn touches(&self) -> Touch {
        let mut moved = Vec::new();
        if self.transforms_only(&mut moved) {
            Touch::Transforms(moved)
        } else {
            Touch::Level
        }
    }

    fn transforms_only(&self, moved: &mut Vec<usize>) -> bool {
        match self {
            Edit::Instance {
                index,
                field: InstanceField::Transform(_),
            } => {
                moved.push(*index);
                true
            }
            Edit::Batch(edits) => edits.iter().all(|e| e.transforms_only(moved)),
            _ => false,
        }
    }

    /// How the edit moves instance indices, in the order it applies them.
    pub fn shifts(&self) -> Vec<Shift> {
        match self {
            Edit::InsertInstance { index, .. } => vec![Shift::Inserted(*index)],
            Edit::DuplicateInstance { index } => vec![Shift::Inserted(index + 1)],
            Edit::DeleteInstance { index } => vec![Shift::Removed(*index)],
            Edit::Batch(edits) => edits.iter().flat_map(Edit::shifts).collect(),
            _ => Vec::new(),
        }
    }
}

/// `name_2`, `name_3`, … : the first that no instance of `level` is named.
fn fresh_name(level: &Level, name: &str) -> String {
    let taken = |n: &str| level.instances.iter().any(|i| i.name.as_deref() == Some(n));
    (2u32..)
        .map(|k| format!("{name}_{k}"))
        .find(|n| !taken(n))
        .unwrap_or_else(|| format!("{name}_copy"))
}

/// Replaces every use of the volume `from` in `c` by `to`; returns how many there were.
fn rewire(c: &mut ConditionEntry, from: &str, to: &str) -> usize {
    let swap = |v: &mut String| {
        if v == from {
            *v = to.to_string();
            1
        } else {
            0
        }
    };
    match c {
        ConditionEntry::Occupied(v) | ConditionEntry::Entered(v) | ConditionEntry::Exited(v) => {
            swap(v)
        }
        ConditionEntry::Occupants { volume, .. } | ConditionEntry::SunLit(volume) => swap(volume),
        ConditionEntry::Event(_)
        | ConditionEntry::LightsOn(_)
        | ConditionEntry::Fired(_)
        | ConditionEntry::Counter { .. }
        | ConditionEntry::SunElevation { .. } => 0,
        ConditionEntry::All(cs)
        | ConditionEntry::Any(cs)
        | ConditionEntry::AtLeast { of: cs, .. }
        | ConditionEntry::Sequence(cs) => cs.iter_mut().map(|c| rewire(c, from, to)).sum(),
        ConditionEntry::Not(c) | ConditionEntry::Times { of: c, .. } => rewire(c, from, to),
    }
}
