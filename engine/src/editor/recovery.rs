//! Recovery files: `<name>.ron.recovery` beside a level, written atomically whenever the UI
//! asks (`app::edit` writes one after every finished command, so a crash or a killed process
//! loses at most a drag in progress), without any check, so that nothing a designer did is
//! lost even while the level has problems. On open, a recovery file newer than its
//! level is reported ([`find_recovery`]) so that the UI can offer to restore it; restoring
//! opens it as a document; a successful save removes it.
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

/// Writes `doc` to the recovery file of `level` and returns its path.
pub fn write_recovery(level: &Path, doc: &Document) -> Result<PathBuf, SaveError> {
    let text = render_document(doc).map_err(|e| SaveError::Format(e.to_string()))?;
    let path = recovery_path(level);
    write_atomic(&path, text.as_bytes())?;
    Ok(path)
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

/// Opens the recovery file of `level` as a document (to edit, then save over the level).
pub fn restore_recovery(level: &Path) -> Result<Document, DocumentError> {
    Document::open(&recovery_path(level))
}

/// Removes the recovery file of `level`; whether there was one.
pub fn discard_recovery(level: &Path) -> std::io::Result<bool> {
    match std::fs::remove_file(recovery_path(level)) {
        Ok(()) => Ok(true),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(false),
        Err(e) => Err(e),
    }
}
