//! Recovery files: `<name>.ron.recovery` beside a level, written atomically whenever the UI
//! asks (`app::edit` writes one after every finished command, so a crash or a killed process
//! loses at most a drag in progress), without any check, so that nothing a designer did is
//! lost even while the level has problems. For a part of a composed world whose base file
//! (`common.ron`) was edited and differs from that file, the base as edited goes beside it,
//! `<name>.ron.recovery.base` (kept with the part's, so that each part's recovery holds the
//! base edits made with it). On open, a recovery file newer than its
//! level is reported ([`find_recovery`]) so that the UI can offer to restore it; restoring
//! opens it as a document, with its base when there is one; a successful save removes both.
//!
//! Main thread (the panic hook's thread on a crash). Must not: write the level file itself.

use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::assets::atomic_file::write_atomic;

use super::document::{Document, DocumentError};
use super::save::{SaveError, with_suffix};
use super::write::render_document;

/// `<path>.recovery`: `levels/hall.ron` → `levels/hall.ron.recovery`.
pub fn recovery_path(level: &Path) -> PathBuf {
    with_suffix(level, ".recovery")
}

/// `<path>.recovery.base`: where the edited base of `level`'s composed world is kept.
pub fn base_recovery_path(level: &Path) -> PathBuf {
    with_suffix(level, ".recovery.base")
}

/// Writes `doc` to the recovery file of `level` and returns its path; `base` (the edited base
/// file's document, when it differs from that file) to [`base_recovery_path`], or removes a
/// base recovery file left there when `None`.
pub fn write_recovery(
    level: &Path,
    doc: &Document,
    base: Option<&Document>,
) -> Result<PathBuf, SaveError> {
    let render = |d: &Document| render_document(d).map_err(|e| SaveError::Format(e.to_string()));
    let text = render(doc)?;
    let path = recovery_path(level);
    write_atomic(&path, text.as_bytes())?;
    match base {
        Some(base) => write_atomic(&base_recovery_path(level), render(base)?.as_bytes())?,
        None => {
            let base = base_recovery_path(level);
            remove_if_there(&base).map_err(|source| SaveError::Remove { path: base, source })?;
        }
    }
    Ok(path)
}

/// Removes `path`; whether it was there.
fn remove_if_there(path: &Path) -> std::io::Result<bool> {
    match std::fs::remove_file(path) {
        Ok(()) => Ok(true),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(e),
    }
}

/// A recovery file worth offering.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RecoveryInfo {
    pub path: PathBuf,
    /// When the recovery file was written.
    pub modified: SystemTime,
    /// When the level file was last written (`None`: it does not exist).
    pub level_modified: Option<SystemTime>,
}

/// The recovery file of `level`, if there is one newer than the level (or the level is gone).
pub fn find_recovery(level: &Path) -> Option<RecoveryInfo> {
    let path = recovery_path(level);
    let modified = std::fs::metadata(&path).ok()?.modified().ok()?;
    let level_modified = std::fs::metadata(level)
        .ok()
        .and_then(|m| m.modified().ok());
    match level_modified {
        Some(l) if l >= modified => None,
        _ => Some(RecoveryInfo {
            path,
            modified,
            level_modified,
        }),
    }
}

/// Opens the recovery file of `level` as a document (to edit, then save over the level), with
/// the edited base from [`base_recovery_path`] as its `base` when that file is there.
pub fn restore_recovery(level: &Path) -> Result<Document, DocumentError> {
    let mut doc = Document::open(&recovery_path(level))?;
    let base = base_recovery_path(level);
    if base.is_file() {
        doc.base = Some(Box::new(Document::open(&base)?));
    }
    Ok(doc)
}

/// Removes the recovery file of `level` and its base's; whether the level's was there.
pub fn discard_recovery(level: &Path) -> std::io::Result<bool> {
    remove_if_there(&base_recovery_path(level))?;
    remove_if_there(&recovery_path(level))
}
