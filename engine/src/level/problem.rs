//! [`LevelProblem`]: one reason a level cannot be loaded, typed — the item it is in
//! ([`ItemRef`]: kind and index), the field of that item, and a message for people. Code that
//! reacts to a problem (the editor selecting the item) reads `item` and `field`, never the
//! message.
//!
//! Owns: [`LevelProblem`] and how the loader turns one into an [`AssetError`]. Any thread
//! (plain data). Must not: read files or the level.

use std::path::Path;

use crate::assets::AssetError;

use super::item::ItemRef;

/// One problem of a level, found by [`super::validate_level`] or by the full load
/// ([`super::level_problems`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", self.describe())]
pub struct LevelProblem {
    /// The item the problem is in ([`ItemRef::Level`]: the level as a whole).
    pub item: ItemRef,
    /// The field of `item` that is wrong, as the level file spells it (`"instance"`, `"when"`,
    /// `"then"`, `"body"`, `"transform"`…); empty when the item as a whole is wrong.
    pub field: &'static str,
    /// What is wrong, for people: it names the item and the value (wording may change).
    pub message: String,
}

impl LevelProblem {
    pub fn new(item: ItemRef, field: &'static str, message: impl Into<String>) -> Self {
        Self {
            item,
            field,
            message: message.into(),
        }
    }

    /// A problem of the level as a whole (or of no item the level's lists hold).
    pub fn of_level(message: impl Into<String>) -> Self {
        Self::new(ItemRef::Level, "", message)
    }

    /// `"{item}: {message}"`, or the message alone for the level as a whole.
    fn describe(&self) -> String {
        match self.item {
            ItemRef::Level => self.message.clone(),
            item => format!("{item}: {}", self.message),
        }
    }

    /// The loader's error for this problem of the level read from `level_path`: the file and
    /// the message (gameplay problems prefixed `gameplay:`).
    pub fn into_error(self, level_path: &Path) -> AssetError {
        let message = if self.item.is_gameplay() {
            format!("gameplay: {}", self.message)
        } else {
            self.message
        };
        AssetError::Level {
            path: level_path.to_path_buf(),
            message,
        }
    }
}
