//! [`EditorState`]: one level being edited — its file, its document, the history, the
//! selection, the snapping in effect, the palette, whether there are unsaved changes and the
//! problems of the last save that was refused — and the operations the UI's keys and panels call
//! (apply, undo, redo, drags, duplicate, delete and move the selection, save, autosave).
//!
//! Main thread. Must not: touch the world (the runner follows the returned [`Touch`]) or the
//! renderer.

use std::path::{Path, PathBuf};

use glam::Vec3;

use crate::assets::{AssetRoot, Level};

use super::check::Problem;
use super::command::{Edit, EditError, InstanceField, Touch};
use super::document::{Document, DocumentError};
use super::history::History;
use super::place::Palette;
use super::recovery::write_recovery;
use super::save::{SaveError, SaveReport, save_document, write_document};
use super::save_world::{on_disk_is, save_changed};
use super::selection::Selection;
use super::snap::Snap;

/// A level open in the editor.
#[derive(Clone, Debug)]
pub struct EditorState {
    /// The level file it saves to.
    pub path: PathBuf,
    pub doc: Document,
    pub history: History,
    pub selection: Selection,
    pub snap: Snap,
    /// The palette's model files and its current piece (`place`).
    pub palette: Palette,
    /// The palette's thumbnails (`thumbs`), shared by copies of the state; `None`: the palette
    /// draws none (set by the runner when it opens the editor).
    pub thumbs: Option<std::sync::Arc<std::sync::Mutex<super::thumbs::Thumbnails>>>,
    /// The file of the document's base (`Document::base`, Reflect's `common.ron`): a save
    /// writes the base's changes there. `None`: the file is a level on its own.
    pub base_path: Option<PathBuf>,
    /// The selection's world box (metres, min and max corners, world axes) from the world's
    /// models, which the runner fills each pass for the inspector (`None`: unknown).
    pub bounds: Option<(Vec3, Vec3)>,
    /// Problems that refused the last save (empty after a save succeeds).
    pub problems: Vec<Problem>,
    /// `History::state_id` when the document last matched its file.
    saved_state: u64,
}

impl EditorState {
    /// Opens the level file at `path`.
    pub fn open(path: &Path) -> Result<Self, DocumentError> {
        Ok(Self::new(path, Document::open(path)?))
    }

    /// Edits `doc`, which saves to `path` as it is.
    pub fn new(path: &Path, doc: Document) -> Self {
        Self {
            path: path.to_path_buf(),
            doc,
            history: History::default(),
            selection: Selection::default(),
            snap: Snap::default(),
            palette: Palette::default(),
            thumbs: None,
            base_path: None,
            bounds: None,
            problems: Vec::new(),
            saved_state: 0,
        }
    }

    /// Edits `doc` restored from a recovery file of `path`: unsaved until it is saved, even
    /// after undoing back to where it was restored.
    pub fn restored(path: &Path, doc: Document) -> Self {
        Self {
            saved_state: u64::MAX,
            ..Self::new(path, doc)
        }
    }

    /// Edits `base`, read from `path`, with the document as one world: its models and
    /// materials are offered to the part, its materials are edited through `Edit::Base`, and a
    /// save writes its changes to `path` ([`EditorState::save_world`]).
    pub fn set_base(&mut self, path: &Path, base: Document) {
        self.base_path = Some(path.to_path_buf());
        self.doc.base = Some(Box::new(base));
    }

    /// The base level of a composed world, as edited.
    pub fn base(&self) -> Option<&Level> {
        self.doc.base.as_deref().map(|b| &b.level)
    }

    /// Applies `edit` through the history; the selection follows inserted and removed
    /// instances. Returns what of the world changed.
    pub fn apply(&mut self, edit: Edit) -> Result<Touch, EditError> {
        let touch = edit.touches();
        let shifts = edit.shifts();
        self.history.apply(&mut self.doc, edit)?;
        for shift in shifts {
            self.selection.shift(shift);
        }
        Ok(touch)
    }

    /// Undoes the last command (`None`: nothing to undo).
    pub fn undo(&mut self) -> Result<Option<Touch>, EditError> {
        let undone = self.history.undo(&mut self.doc)?;
        Ok(undone.map(|edit| self.follow(&edit)))
    }

    /// Redoes the last undone command (`None`: nothing to redo).
    pub fn redo(&mut self) -> Result<Option<Touch>, EditError> {
        let redone = self.history.redo(&mut self.doc)?;
        Ok(redone.map(|edit| self.follow(&edit)))
    }

    fn follow(&mut self, edit: &Edit) -> Touch {
        for shift in edit.shifts() {
            self.selection.shift(shift);
        }
        self.selection.retain_below(self.doc.level.instances.len());
        edit.touches()
    }

    pub fn begin_drag(&mut self) {
        self.history.begin_drag();
    }

    pub fn end_drag(&mut self) {
        self.history.end_drag();
    }

    /// Whether the document differs from its file (as far as the history knows).
    pub fn dirty(&self) -> bool {
        self.history.state_id() != self.saved_state
    }

    /// Deletes the selected instances (one command).
    pub fn delete_selected(&mut self) -> Result<Touch, EditError> {
        let mut indices = self.selection.instances().to_vec();
        indices.sort_unstable_by(|a, b| b.cmp(a));
        let edits = indices
            .into_iter()
            .map(|index| Edit::DeleteInstance { index })
            .collect();
        self.apply(Edit::Batch(edits))
    }

    /// Duplicates the selected instances (one command) and selects the copies.
    pub fn duplicate_selected(&mut self) -> Result<Touch, EditError> {
        let mut indices = self.selection.instances().to_vec();
        indices.sort_unstable();
        let edits = indices
            .iter()
            .rev()
            .map(|&index| Edit::DuplicateInstance { index })
            .collect();
        let touch = self.apply(Edit::Batch(edits))?;
        // Copy j (in index order) lands after its original and the j copies before it.
        self.selection
            .set(indices.iter().enumerate().map(|(j, &i)| i + j + 1));
        Ok(touch)
    }

    /// Moves every selected instance by `delta` metres (world axes) from where it is, the
    /// result snapped to the grid when grid snapping is on (one command; merges within a drag).
    pub fn translate_selected(&mut self, delta: Vec3) -> Result<Touch, EditError> {
        let instances = &self.doc.level.instances;
        let mut edits = Vec::new();
        for &index in self.selection.instances() {
            let Some(entry) = instances.get(index) else {
                continue;
            };
            let mut t = entry.transform;
            t.translation = (Vec3::from(t.translation) + delta).to_array();
            let snapped = Snap {
                grid: self.snap.grid,
                ..Snap::default()
            }
            .transform(t);
            edits.push(Edit::Instance {
                index,
                field: InstanceField::Transform(snapped),
            });
        }
        self.apply(Edit::Batch(edits))
    }

    /// Saves to the level file (see `save`); a refusal's problems are kept in `problems`.
    pub fn save(&mut self, root: Option<&AssetRoot>) -> Result<SaveReport, SaveError> {
        match save_document(&self.path, &self.doc, root) {
            Ok(report) => {
                self.problems.clear();
                self.saved_state = self.history.state_id();
                Ok(report)
            }
            Err(SaveError::Problems(problems)) => {
                self.problems = problems.clone();
                Err(SaveError::Problems(problems))
            }
            Err(e) => Err(e),
        }
    }

    /// Saves a document whose check its caller ran (`problems`, empty when it passed; a part
    /// of a composed world checks merged with the other parts): refused with them, else
    /// written as [`EditorState::save`] writes.
    pub fn save_checked(&mut self, problems: Vec<Problem>) -> Result<SaveReport, SaveError> {
        if !problems.is_empty() {
            self.problems = problems.clone();
            return Err(SaveError::Problems(problems));
        }
        let report = write_document(&self.path, &self.doc)?;
        self.problems.clear();
        self.saved_state = self.history.state_id();
        Ok(report)
    }

    /// Saves a part of a composed world and its base (`save_world`), checked by its caller as
    /// [`EditorState::save_checked`] is: each file whose level changed is written (the part
    /// also when nothing changed, as a save of one file is). Returns what was written.
    pub fn save_world(&mut self, problems: Vec<Problem>) -> Result<Vec<SaveReport>, SaveError> {
        if !problems.is_empty() {
            self.problems = problems.clone();
            return Err(SaveError::Problems(problems));
        }
        let reports = save_changed(&self.path, &self.doc, self.base_path.as_deref())?;
        self.problems.clear();
        self.saved_state = self.history.state_id();
        Ok(reports)
    }

    /// Writes the recovery file (after each command; see `recovery` and `app::edit`), with the
    /// base's when the base file was edited (it differs from what its file holds).
    pub fn write_recovery(&self) -> Result<PathBuf, SaveError> {
        let base = (self.doc.base.as_deref())
            .zip(self.base_path.as_deref())
            .filter(|(base, path)| !on_disk_is(path, &base.level))
            .map(|(base, _)| base);
        write_recovery(&self.path, &self.doc, base)
    }
}
