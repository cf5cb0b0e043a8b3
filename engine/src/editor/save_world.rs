//! Saving a part of a composed world together with its base file (a Reflect chamber and
//! `common.ron`, edited as one world: `Document::base`): each file is compared, as a level, with
//! what its file on disk holds, and only the files that differ are written, each by
//! [`write_document`] (only the edited items changed, read back, backed up, replaced
//! atomically). The part is also written when neither differs, as a save of one file is.
//!
//! The check (the parts merged) is the caller's. Main thread. Must not: touch the world or the
//! renderer. Each file is replaced atomically, the base first: a failure writing the part
//! leaves the base saved and the part's file as it was, and the error names the part.

use std::path::Path;

use crate::assets::Level;

use super::document::Document;
use super::save::{SaveError, SaveReport, write_document};

/// Writes `doc` to `path` and its base to `base_path`, each when its level differs from its
/// file (see the module doc); returns the reports of the files written, base first.
pub(super) fn save_changed(
    path: &Path,
    doc: &Document,
    base_path: Option<&Path>,
) -> Result<Vec<SaveReport>, SaveError> {
    let mut reports = Vec::new();
    if let (Some(base), Some(base_path)) = (doc.base.as_deref(), base_path)
        && !on_disk_is(base_path, &base.level)
    {
        reports.push(write_document(base_path, base)?);
    }
    if reports.is_empty() || !on_disk_is(path, &doc.level) {
        reports.push(write_document(path, doc)?);
    }
    Ok(reports)
}

/// Whether the file at `path` reads as `level` (a file that does not read is not).
pub(super) fn on_disk_is(path: &Path, level: &Level) -> bool {
    Level::read(path).is_ok_and(|on_disk| on_disk == *level)
}
