//! [`Selection`]: the instances the editor's tools act on, by index into the level's
//! instance list, in the order they were selected (the last is the primary one, whose fields
//! the inspector shows), and the one other item in focus — a material, volume, laser, clip,
//! rule or light group chosen in the outliner or the problems panel, which the inspector
//! shows instead ([`Selection::item`]; a click on an instance drops it). In a composed world
//! the item in focus may be one of the base file's instead (`common.ron`'s materials,
//! [`Selection::base_item`]). Follows inserted and removed instances ([`Shift`]).
//!
//! Main thread. Must not: read the level (indices are checked by whoever uses them).

use super::command::Shift;
use crate::level::ItemRef;

/// How a click changes the selection (plain click, Shift, Ctrl).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SelectMode {
    /// The clicked instance alone (a click on nothing clears the selection).
    Replace,
    /// The clicked instance joins the selection.
    Add,
    /// The clicked instance joins or leaves the selection.
    Toggle,
}

/// Selected instances, each once, in selection order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Selection {
    instances: Vec<usize>,
    item: Option<ItemRef>,
    /// `item` indexes the base file's lists, not the edited file's.
    in_base: bool,
}

impl Selection {
    /// Applies a click on `instance` (`None`: on nothing) with `mode`.
    pub fn click(&mut self, instance: Option<usize>, mode: SelectMode) {
        self.item = None;
        match (mode, instance) {
            (SelectMode::Replace, None) => self.instances.clear(),
            (SelectMode::Replace, Some(i)) => self.instances = vec![i],
            (_, None) => {}
            (SelectMode::Add, Some(i)) => {
                self.instances.retain(|&k| k != i);
                self.instances.push(i);
            }
            (SelectMode::Toggle, Some(i)) => {
                if self.contains(i) {
                    self.instances.retain(|&k| k != i);
                } else {
                    self.instances.push(i);
                }
            }
        }
    }

    /// Applies a box select of `instances` with `mode`: `Replace` selects exactly them (an
    /// empty box clears), `Add` adds them, `Toggle` flips each.
    pub fn boxed(&mut self, instances: &[usize], mode: SelectMode) {
        self.item = None;
        if mode == SelectMode::Replace {
            self.instances.clear();
        }
        for &i in instances {
            let mode = if mode == SelectMode::Toggle {
                SelectMode::Toggle
            } else {
                SelectMode::Add
            };
            self.click(Some(i), mode);
        }
    }

    /// Selects exactly `instances` (duplicates dropped, order kept).
    pub fn set(&mut self, instances: impl IntoIterator<Item = usize>) {
        self.instances.clear();
        for i in instances {
            if !self.contains(i) {
                self.instances.push(i);
            }
        }
    }

    pub fn clear(&mut self) {
        self.instances.clear();
        self.item = None;
    }

    /// Puts `item` in focus (the inspector shows it); the instances stay selected.
    pub fn focus(&mut self, item: Option<ItemRef>) {
        self.item = item;
        self.in_base = false;
    }

    /// Puts `item` of the base file (indices into the base's lists) in focus.
    pub fn focus_base(&mut self, item: ItemRef) {
        self.item = Some(item);
        self.in_base = true;
    }

    /// The item of the edited file in focus other than the selected instances, if any (see
    /// the module doc).
    pub fn item(&self) -> Option<ItemRef> {
        self.item.filter(|_| !self.in_base)
    }

    /// The base file's item in focus, if any.
    pub fn base_item(&self) -> Option<ItemRef> {
        self.item.filter(|_| self.in_base)
    }

    pub fn contains(&self, instance: usize) -> bool {
        self.instances.contains(&instance)
    }

    /// The selected instances in selection order.
    pub fn instances(&self) -> &[usize] {
        &self.instances
    }

    /// The last selected instance.
    pub fn primary(&self) -> Option<usize> {
        self.instances.last().copied()
    }

    pub fn is_empty(&self) -> bool {
        self.instances.is_empty()
    }

    /// Follows an edit that inserted or removed an instance.
    pub fn shift(&mut self, shift: Shift) {
        match shift {
            Shift::Inserted(at) => {
                for i in &mut self.instances {
                    if *i >= at {
                        *i += 1;
                    }
                }
            }
            Shift::Removed(at) => {
                self.instances.retain(|&i| i != at);
                for i in &mut self.instances {
                    if *i > at {
                        *i -= 1;
                    }
                }
            }
        }
    }

    /// Drops indices at or past `len` (after a level was replaced).
    pub fn retain_below(&mut self, len: usize) {
        self.instances.retain(|&i| i < len);
    }
}
