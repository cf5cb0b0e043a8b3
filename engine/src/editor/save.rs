//! Saving a level document: refused while the level has problems (`check`), written as the
//! file on disk with only the edited items changed (`save_diff`), or, when that cannot be
//! done (a new file, an old file it cannot follow), as RON with its comments (`write`), and
//! the report says why; checked to read back as the very same level, the previous
//! file kept as `<name>.bak` beside it, then replaced atomically (a temporary file renamed
//! over it, `assets::atomic_file`), and the recovery file, now stale, removed.
//!
//! Until the final rename the old level file is untouched: any failure (problems, a folder
//! that refuses writes, a full disk) returns an error and leaves it as it was. Main thread.
//! Must not: touch the world or the renderer.

use std::path::{Path, PathBuf};

use crate::assets::atomic_file::{AtomicFileError, write_atomic};
use crate::assets::{AssetRoot, Level};

use super::check::{Problem, check_level};
use super::document::Document;
use super::layout::options;
use super::recovery::discard_recovery;
use super::save_diff::splice_level;
use super::write::render_document;

/// Why a save did not happen; the level file on disk is unchanged.
#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    /// The level has problems (each names its item); nothing was written.
    #[error("the level has {} problem(s), the first: {}", .0.len(), first(.0))]
    Problems(Vec<Problem>),
    /// The level could not be serialised.
    #[error("cannot write the level as RON: {0}")]
    Format(String),
    /// The text made would not read back as the same level (a bug of the writer).
    #[error("the written level would not read back the same ({0}); nothing was written")]
    RoundTrip(String),
    /// The previous version could not be read to back it up.
    #[error("{path}: cannot read the previous version to back it up: {source}")]
    Backup {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// A file could not be written (the error names it and the stage).
    #[error(transparent)]
    Write(#[from] AtomicFileError),
    /// A stale file beside the level (a recovery file of a base no longer edited) could not be
    /// removed.
    #[error("{path}: cannot remove: {source}")]
    Remove {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}

/// The first problem, for the error's message.
fn first(problems: &[Problem]) -> String {
    problems
        .first()
        .map(ToString::to_string)
        .unwrap_or_default()
}

/// What a save did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SaveReport {
    /// The level file written.
    pub path: PathBuf,
    /// Where the previous version was kept, if there was one.
    pub backup: Option<PathBuf>,
    /// Bytes written.
    pub bytes: usize,
    /// `None` when only the edited items changed in the file; otherwise why the whole file
    /// was written anew (`a new file`, or the reason the old text could not be kept).
    pub rewritten: Option<String>,
}

/// `<path>.bak`: `levels/hall.ron` → `levels/hall.ron.bak`.
pub fn backup_path(path: &Path) -> PathBuf {
    with_suffix(path, ".bak")
}

/// `path` with `suffix` appended to its file name.
pub(super) fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut name = path
        .file_name()
        .map(|n| n.to_os_string())
        .unwrap_or_else(|| "level.ron".into());
    name.push(suffix);
    path.with_file_name(name)
}

/// `doc` as level RON that reads back as `doc.level` (checked by parsing it again): `old`
/// (the file's text on disk) with only the edited items changed when it can be done (the
/// second value is `None`), else written whole (the second value says why).
pub(super) fn text_of(
    doc: &Document,
    old: Option<&str>,
) -> Result<(String, Option<String>), SaveError> {
    let why = match old.map(|old| splice_level(old, doc)) {
        Some(Ok(text)) => return Ok((text, None)),
        Some(Err(e)) => e.to_string(),
        None => "a new file".to_string(),
    };
    Ok((full_text(doc)?, Some(why)))
}

/// `doc` written whole by `write`, checked to read back as `doc.level`.
pub(super) fn full_text(doc: &Document) -> Result<String, SaveError> {
    let text = render_document(doc).map_err(|e| SaveError::Format(e.to_string()))?;
    let back = options()
        .from_str::<Level>(&text)
        .map_err(|e| SaveError::RoundTrip(e.to_string()))?;
    if back != doc.level {
        return Err(SaveError::RoundTrip("a value changed".into()));
    }
    Ok(text)
}

/// Saves `doc` to `path` (see the module doc). With `root`, the engine's full load checks the
/// level too (models and sounds read from `root`); without it, only references are checked.
pub fn save_document(
    path: &Path,
    doc: &Document,
    root: Option<&AssetRoot>,
) -> Result<SaveReport, SaveError> {
    let problems = check_level(path, &doc.level, root);
    if !problems.is_empty() {
        return Err(SaveError::Problems(problems));
    }
    write_document(path, doc)
}

/// Steps 2 to 5 of [`save_document`] (write, read back, back up, replace, drop the recovery
/// file) for a document its caller has checked: a part of a composed world, which only checks
/// merged with the other parts.
pub fn write_document(path: &Path, doc: &Document) -> Result<SaveReport, SaveError> {
    let old = if path.exists() {
        Some(std::fs::read(path).map_err(|source| SaveError::Backup {
            path: path.to_path_buf(),
            source,
        })?)
    } else {
        None
    };
    let old_text = old.as_deref().map(String::from_utf8_lossy);
    let (text, rewritten) = text_of(doc, old_text.as_deref())?;
    if let Some(why) = &rewritten {
        log::info!("{}: the whole file is written: {why}", path.display());
    }
    let backup = match &old {
        Some(old) => {
            let backup = backup_path(path);
            write_atomic(&backup, old)?;
            Some(backup)
        }
        None => None,
    };
    write_atomic(path, text.as_bytes())?;
    if let Err(e) = discard_recovery(path) {
        log::warn!(
            "{}: saved, but its recovery file stays: {e}",
            path.display()
        );
    }
    Ok(SaveReport {
        path: path.to_path_buf(),
        backup,
        bytes: text.len(),
        rewritten,
    })
}
