//! Edits of the level's lists other than instances and the per-field edits of `fields`: a
//! model file added to `models` or removed from it (the palette places a file the level does
//! not use yet), a clip replaced whole (its keys, times and events: the clip inspector edits a
//! copy), the light groups that start switched off, and the clips that play from the start
//! (with their play mode, which is how a clip loops). Each returns its inverse, as every
//! [`super::Edit`] does.
//!
//! Main thread. Must not: touch the world or the history; it edits the level only.

use crate::assets::{AuthoredClip, AutoplayEntry, Level, ModelEntry};

use super::command::EditError;

/// One edit of a level list (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub enum ListEdit {
    /// Insert `entry` so that it becomes `models[index]`.
    InsertModel { index: usize, entry: ModelEntry },
    /// Remove `models[index]`.
    RemoveModel { index: usize },
    /// Replace `gameplay.animations[index]` by `clip`.
    Clip {
        index: usize,
        clip: Box<AuthoredClip>,
    },
    /// Replace `gameplay.lights_off` (light groups that start switched off).
    LightsOff(Vec<u32>),
    /// Replace `gameplay.autoplay` (clips that play from the start, each with its mode).
    Autoplay(Vec<AutoplayEntry>),
}

impl ListEdit {
    /// Applies the edit to `level` and returns its inverse. On an error `level` is unchanged.
    pub fn apply(&self, level: &mut Level) -> Result<ListEdit, EditError> {
        let g = &mut level.gameplay;
        Ok(match self {
            ListEdit::InsertModel { index, entry } => {
                let len = level.models.len();
                if *index > len {
                    return Err(EditError::NoSuchItem {
                        kind: "model slot",
                        index: *index,
                        len,
                    });
                }
                level.models.insert(*index, entry.clone());
                ListEdit::RemoveModel { index: *index }
            }
            ListEdit::RemoveModel { index } => {
                let len = level.models.len();
                if *index >= len {
                    return Err(EditError::NoSuchItem {
                        kind: "model",
                        index: *index,
                        len,
                    });
                }
                ListEdit::InsertModel {
                    index: *index,
                    entry: level.models.remove(*index),
                }
            }
            ListEdit::Clip { index, clip } => {
                let len = g.animations.len();
                let slot = g.animations.get_mut(*index).ok_or(EditError::NoSuchItem {
                    kind: "clip",
                    index: *index,
                    len,
                })?;
                ListEdit::Clip {
                    index: *index,
                    clip: Box::new(std::mem::replace(slot, (**clip).clone())),
                }
            }
            ListEdit::LightsOff(groups) => {
                ListEdit::LightsOff(std::mem::replace(&mut g.lights_off, groups.clone()))
            }
            ListEdit::Autoplay(list) => {
                ListEdit::Autoplay(std::mem::replace(&mut g.autoplay, list.clone()))
            }
        })
    }

    /// What the edit does, for the history panel (names taken from `level` before it applies).
    pub fn describe(&self, level: &Level) -> String {
        match self {
            ListEdit::InsertModel { entry, .. } => {
                format!("Add model {:?} ({})", entry.name, entry.path)
            }
            ListEdit::RemoveModel { index } => match level.models.get(*index) {
                Some(m) => format!("Remove model {:?}", m.name),
                None => format!("Remove model {index}"),
            },
            ListEdit::Clip { clip, .. } => format!("Edit clip {:?}", clip.name),
            ListEdit::LightsOff(_) => "Set the light groups that start off".into(),
            ListEdit::Autoplay(_) => "Set the clips that play from the start".into(),
        }
    }

    /// The part of a merge key this edit sets (`None`: never merges: models come and go whole).
    pub fn merge_part(&self) -> Option<(&'static str, usize, &'static str)> {
        match self {
            ListEdit::InsertModel { .. } | ListEdit::RemoveModel { .. } => None,
            ListEdit::Clip { index, .. } => Some(("clip", *index, "clip")),
            ListEdit::LightsOff(_) => Some(("gameplay", 0, "lights off")),
            ListEdit::Autoplay(_) => Some(("gameplay", 0, "autoplay")),
        }
    }
}
