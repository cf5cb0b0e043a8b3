//! The comments of a level file, anchored to what they describe, so that a save can put them
//! back: serde drops comments, so the editor reads them from the file's text on open
//! (`comment_scan`) and the writer (`write`) emits them again around the same items.
//!
//! Anchors: the file's leading block (before `Level(`), each top-level field of the level and
//! of its `gameplay` section, each item of their lists by index (`instances[3]`), and the end
//! of each of those (comments before a closing bracket). Comments inside an item or a
//! multi-line value are kept as lines before it; a comment at the end of a line stays at the
//! end of the line of the item it was on. Instance comments follow inserted and deleted
//! instances (the edit that deletes one carries its comments, and an undo brings them back).
//!
//! Main thread. Must not: parse the level's values (that is serde's).

use std::collections::BTreeMap;

/// The comments anchored to one item or field, verbatim (`// …` or `/* … */`, without
/// indentation).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Anchored {
    /// Comment lines above it (and those from inside it, in order).
    pub before: Vec<String>,
    /// The comment at the end of its (first) line.
    pub trailing: Option<String>,
}

impl Anchored {
    /// No comment at all.
    pub fn is_empty(&self) -> bool {
        self.before.is_empty() && self.trailing.is_none()
    }

    /// Adds a comment that ended a line of code: the first becomes the trailing comment, any
    /// more become lines before.
    pub(super) fn add_trailing(&mut self, text: String) {
        if self.trailing.is_none() {
            self.trailing = Some(text);
        } else {
            self.before.push(text);
        }
    }

    /// How many comments it holds.
    pub fn count(&self) -> usize {
        self.before.len() + usize::from(self.trailing.is_some())
    }
}

/// Every comment of a level file, by anchor. Keys are paths: `""` is the level itself,
/// `"instances"` a top-level field, `"gameplay.rules"` a field of the gameplay section.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Comments {
    /// Comment lines before `Level(` (the file's leading block).
    pub header: Vec<String>,
    /// `#![enable(…)]` lines before `Level(`, re-emitted as they were.
    pub attributes: Vec<String>,
    /// A comment at the end of the `Level(` line.
    pub opening: Option<String>,
    /// Comments of top-level fields and of gameplay fields, by path.
    pub fields: BTreeMap<String, Anchored>,
    /// Comments of list items, by the list's path and the item's index (trailing entries
    /// without comments are left out).
    pub items: BTreeMap<String, Vec<Anchored>>,
    /// Comments before (and at the end of the line of) the closing bracket of the level
    /// (`""`), of `gameplay` and of each list, by path.
    pub ends: BTreeMap<String, Anchored>,
    /// Comments after the level's closing parenthesis.
    pub footer: Vec<String>,
    /// The fields the file wrote, by path, in its order: a save writes them in this order
    /// (then any others in the level type's order), and writes them even when they hold
    /// their default value.
    pub order: Vec<String>,
}

impl Comments {
    /// The comments of item `index` of the list at `path`.
    pub fn item(&self, path: &str, index: usize) -> Option<&Anchored> {
        self.items.get(path)?.get(index).filter(|a| !a.is_empty())
    }

    /// The comments of the field at `path`.
    pub fn field(&self, path: &str) -> Option<&Anchored> {
        self.fields.get(path).filter(|a| !a.is_empty())
    }

    /// The comments before the closing bracket of `path`.
    pub fn end(&self, path: &str) -> Option<&Anchored> {
        self.ends.get(path).filter(|a| !a.is_empty())
    }

    /// Mutable comments of item `index` of the list at `path` (created empty).
    pub(super) fn item_mut(&mut self, path: &str, index: usize) -> &mut Anchored {
        let list = self.items.entry(path.to_string()).or_default();
        if list.len() <= index {
            list.resize(index + 1, Anchored::default());
        }
        &mut list[index]
    }

    /// An item was inserted at `index` of the list at `path`, with `comments`: later items'
    /// comments move up by one.
    pub fn insert_item(&mut self, path: &str, index: usize, comments: Anchored) {
        let list = self.items.entry(path.to_string()).or_default();
        if index >= list.len() {
            if comments.is_empty() {
                self.tidy(path);
                return;
            }
            list.resize(index, Anchored::default());
        }
        list.insert(index, comments);
        self.tidy(path);
    }

    /// Item `index` of the list at `path` was removed: returns its comments; later items'
    /// comments move down by one.
    pub fn remove_item(&mut self, path: &str, index: usize) -> Anchored {
        let removed = match self.items.get_mut(path) {
            Some(list) if index < list.len() => list.remove(index),
            _ => Anchored::default(),
        };
        self.tidy(path);
        removed
    }

    /// Drops trailing empty entries (and an emptied list), so equal comments compare equal.
    pub(super) fn tidy(&mut self, path: &str) {
        if let Some(list) = self.items.get_mut(path) {
            while list.last().is_some_and(Anchored::is_empty) {
                list.pop();
            }
            if list.is_empty() {
                self.items.remove(path);
            }
        }
    }

    /// Drops every empty entry (after scanning a file).
    pub(super) fn tidy_all(&mut self) {
        self.fields.retain(|_, a| !a.is_empty());
        self.ends.retain(|_, a| !a.is_empty());
        let paths: Vec<String> = self.items.keys().cloned().collect();
        for path in paths {
            self.tidy(&path);
        }
    }

    /// How many comments there are in all (tests and the status line).
    pub fn count(&self) -> usize {
        let anchored = |a: &Anchored| a.count();
        self.header.len()
            + self.footer.len()
            + usize::from(self.opening.is_some())
            + self.fields.values().map(anchored).sum::<usize>()
            + self.ends.values().map(anchored).sum::<usize>()
            + self.items.values().flatten().map(anchored).sum::<usize>()
    }

    /// Every comment's text, in no particular order (tests: none may be lost).
    pub fn texts(&self) -> Vec<&str> {
        let anchored = self
            .fields
            .values()
            .chain(self.ends.values())
            .chain(self.items.values().flatten());
        let mut out: Vec<&str> = Vec::new();
        for a in anchored {
            out.extend(a.before.iter().map(String::as_str));
            out.extend(a.trailing.as_deref());
        }
        out.extend(self.header.iter().map(String::as_str));
        out.extend(self.footer.iter().map(String::as_str));
        out.extend(self.opening.as_deref());
        out
    }
}
