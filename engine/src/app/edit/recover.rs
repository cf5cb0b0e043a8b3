//! The recovery file of the level being edited (`editor::recovery`), kept by [`EditMode`]:
//! written after every finished command (a drag when it is released), so that a crash or a
//! killed process loses at most the drag in progress; removed when undo or a save brings the
//! document back to its file; offered on opening when it is newer than the level, and then
//! restored or discarded from the toolbar. In a composed world the recovery holds the base
//! file's edits too (`editor::base_recovery_path`), and restoring brings both back. An offered
//! file is never overwritten: the first command before a choice moves it aside to
//! `<level>.recovery.old` (its base's to `<level>.recovery.base.old`).
//!
//! Main thread, inside the editor's pass or its public operations. Must not: write the level
//! file (only saves do) or touch the world except through the mode's `follow`.

use std::path::{Path, PathBuf};

use super::mode::EditMode;
use crate::app::runner::Engine;
use crate::editor::{
    EditorState, Touch, base_recovery_path, discard_recovery, recovery_path, restore_recovery,
};

/// `<level>.recovery.old`: where an offered recovery file goes when new edits are made before
/// it was restored or discarded.
pub fn older_recovery_path(level: &Path) -> PathBuf {
    let mut name = recovery_path(level).into_os_string();
    name.push(".old");
    PathBuf::from(name)
}

impl EditMode {
    /// Brings the recovery file up to date with the document (nothing during a drag, or when
    /// it already is).
    pub(super) fn keep_recovery(&mut self) {
        let id = self.state.history.state_id();
        if !self.recovery_files || self.state.history.dragging() || id == self.recovered_state {
            return;
        }
        self.recovered_state = id;
        if !self.state.dirty() {
            // Back at the file's state: nothing to recover (an offered file stays offered).
            if self.recovery.is_none()
                && let Err(e) = discard_recovery(&self.state.path)
            {
                self.say(format!("cannot remove the recovery file: {e}"));
            }
            return;
        }
        if let Some(offered) = self.recovery.take() {
            let base = base_recovery_path(&self.state.path);
            if base.is_file() {
                let mut older = base.clone().into_os_string();
                older.push(".old");
                if let Err(e) = std::fs::rename(&base, &older) {
                    self.say(format!("the older base recovery file is lost: {e}"));
                }
            }
            let older = older_recovery_path(&self.state.path);
            match std::fs::rename(&offered.path, &older) {
                Ok(()) => self.say(format!(
                    "the older recovery file is kept as {}",
                    older.display()
                )),
                Err(e) => {
                    self.say(format!("the older recovery file stays unused: {e}"));
                    self.recovery = Some(offered);
                    return;
                }
            }
        }
        self.autosave();
    }

    /// Writes the recovery file; says why not when it cannot.
    pub fn autosave(&mut self) {
        match self.state.write_recovery() {
            Ok(path) => log::debug!("editor: recovery file {}", path.display()),
            Err(e) => self.say(format!("no recovery file: {e}")),
        }
    }

    /// Replaces the document by the recovery file offered on opening (unsaved: a restored
    /// document differs from its file until it is saved).
    pub(super) fn restore(&mut self, engine: &mut Engine) -> bool {
        let path = self.state.path.clone();
        self.recovery = None;
        match restore_recovery(&path) {
            Ok(mut doc) => {
                let selection = std::mem::take(&mut self.state.selection);
                let palette = std::mem::take(&mut self.state.palette);
                let thumbs = self.state.thumbs.take();
                let base_path = self.state.base_path.take();
                let with_base = doc.base.is_some();
                if !with_base {
                    doc.base = self.state.doc.base.take();
                }
                self.state = EditorState::restored(&path, doc);
                self.state.palette = palette;
                self.state.thumbs = thumbs;
                self.state.base_path = base_path;
                self.recovered_state = self.state.history.state_id();
                self.state.selection = selection;
                self.state
                    .selection
                    .retain_below(self.state.doc.level.instances.len());
                self.say(if with_base {
                    "restored the recovery file with the base file's edits (not saved yet)"
                } else {
                    "restored the recovery file (not saved yet)"
                });
                self.follow(engine, vec![Touch::Level])
            }
            Err(e) => {
                self.say(format!("cannot restore: {e}"));
                false
            }
        }
    }

    /// Drops the offered recovery file.
    pub(super) fn discard_offer(&mut self) {
        self.recovery = None;
        if let Err(e) = discard_recovery(&self.state.path) {
            self.say(format!("cannot remove the recovery file: {e}"));
        }
    }
}
