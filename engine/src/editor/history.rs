//! [`History`]: the one undo/redo stack of the editor. Every edit is applied through it and
//! kept with its inverse; undo applies the inverse, redo the edit again. Between
//! [`History::begin_drag`] and [`History::end_drag`], consecutive edits with the same merge
//! key (the same field of the same items, `Edit::merge_key`) become one command: the last
//! value is kept with the first one's undo, so a whole drag is undone at once.
//!
//! Owns: the commands, their descriptions for the history panel, a state id for "unsaved
//! changes". Main thread. Must not: touch the world or files.

use super::command::{Edit, EditError};
use super::document::Document;

/// One applied edit with what undoes it.
#[derive(Clone, Debug)]
struct Command {
    description: String,
    edit: Edit,
    undo: Edit,
    /// Identifies the document state after this command (see [`History::state_id`]).
    id: u64,
    /// The drag it was made in, if any.
    drag: Option<u64>,
}

/// A line of the history panel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HistoryEntry {
    pub description: String,
    /// Applied (`true`) or undone and waiting for a redo (`false`).
    pub done: bool,
}

/// The undo and redo stacks.
#[derive(Clone, Debug)]
pub struct History {
    done: Vec<Command>,
    undone: Vec<Command>,
    next_id: u64,
    drag: Option<u64>,
    next_drag: u64,
    /// Most commands kept; the oldest are forgotten beyond it.
    limit: usize,
}

impl Default for History {
    fn default() -> Self {
        Self::new(10_000)
    }
}

impl History {
    /// An empty history keeping at most `limit` commands (at least one).
    pub fn new(limit: usize) -> Self {
        Self {
            done: Vec::new(),
            undone: Vec::new(),
            next_id: 1,
            drag: None,
            next_drag: 0,
            limit: limit.max(1),
        }
    }

    fn fresh_id(&mut self) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        id
    }

    /// Applies `edit` to `doc` and records it (merging it into the last command when both
    /// belong to the current drag and set the same fields). Clears the redo stack. An empty
    /// batch records nothing. On an error nothing changes.
    pub fn apply(&mut self, doc: &mut Document, edit: Edit) -> Result<(), EditError> {
        if matches!(&edit, Edit::Batch(edits) if edits.is_empty()) {
            return Ok(()); // nothing selected: no command
        }
        let description = edit.describe_in(doc);
        let undo = edit.apply(doc)?;
        self.undone.clear();
        let id = self.fresh_id();
        if let Some(drag) = self.drag
            && let Some(top) = self.done.last_mut()
            && top.drag == Some(drag)
            && let Some(key) = edit.merge_key()
            && top.edit.merge_key() == Some(key)
        {
            top.edit = edit;
            top.id = id;
            return Ok(());
        }
        self.done.push(Command {
            description,
            edit,
            undo,
            id,
            drag: self.drag,
        });
        if self.done.len() > self.limit {
            self.done.remove(0);
        }
        Ok(())
    }

    /// Starts a drag: edits until [`History::end_drag`] merge by their merge keys.
    pub fn begin_drag(&mut self) {
        self.drag = Some(self.next_drag);
        self.next_drag += 1;
    }

    /// Ends the drag; the next edit starts a new command.
    pub fn end_drag(&mut self) {
        self.drag = None;
    }

    /// Whether a drag is going on.
    pub fn dragging(&self) -> bool {
        self.drag.is_some()
    }

    /// Undoes the last command; returns the edit that undid it (`None`: nothing to undo).
    pub fn undo(&mut self, doc: &mut Document) -> Result<Option<Edit>, EditError> {
        self.drag = None;
        let Some(command) = self.done.pop() else {
            return Ok(None);
        };
        match command.undo.apply(doc) {
            Ok(_) => {
                let undo = command.undo.clone();
                self.undone.push(command);
                Ok(Some(undo))
            }
            Err(e) => {
                self.done.push(command);
                Err(e)
            }
        }
    }

    /// Redoes the last undone command; returns its edit (`None`: nothing to redo).
    pub fn redo(&mut self, doc: &mut Document) -> Result<Option<Edit>, EditError> {
        self.drag = None;
        let Some(mut command) = self.undone.pop() else {
            return Ok(None);
        };
        match command.edit.apply(doc) {
            Ok(undo) => {
                // The state is the one the command made first: its id again.
                command.undo = undo;
                let edit = command.edit.clone();
                self.done.push(command);
                Ok(Some(edit))
            }
            Err(e) => {
                self.undone.push(command);
                Err(e)
            }
        }
    }

    pub fn can_undo(&self) -> bool {
        !self.done.is_empty()
    }

    pub fn can_redo(&self) -> bool {
        !self.undone.is_empty()
    }

    /// Commands that undo would undo, how many.
    pub fn undo_len(&self) -> usize {
        self.done.len()
    }

    /// Identifies the document's state: equal ids, equal documents (0: as opened). Compare
    /// with the id at the last save to know whether there are unsaved changes.
    pub fn state_id(&self) -> u64 {
        self.done.last().map_or(0, |c| c.id)
    }

    /// The history panel's lines: applied commands oldest first, then undone ones, the next
    /// redo first.
    pub fn entries(&self) -> Vec<HistoryEntry> {
        let line = |c: &Command, done| HistoryEntry {
            description: c.description.clone(),
            done,
        };
        self.done
            .iter()
            .map(|c| line(c, true))
            .chain(self.undone.iter().rev().map(|c| line(c, false)))
            .collect()
    }
}
