//! Atomic file replacement for what the player's machine keeps (settings, progress saves,
//! input recordings) and for the levels the editor saves: the new bytes go to a temporary
//! file in the target's own folder, are flushed to disk (`fsync`), then renamed over the
//! target, and the folder is synced so the rename itself survives a power cut. Until the
//! rename, the previous file is untouched; a failure at any stage removes the temporary file
//! and returns an error naming the target.
//!
//! Also: [`keep_aside`], which renames a file that could not be read (corrupt settings, a
//! broken save) out of the way so that the player's data is not lost when defaults replace it.
//!
//! Lives in `assets` (re-exported by `app`) so that every layer from `assets` up — the level
//! editor's save and recovery files among them — can use it. Image writing (`render::film`)
//! does the same without the `fsync`. Main thread (any thread: no shared state). Must not:
//! know what the bytes mean.

use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// A file that could not be written or moved aside; the target's previous content is intact.
#[derive(Debug, thiserror::Error)]
#[error("{path}: cannot {stage}: {source}")]
pub struct AtomicFileError {
    /// The file that was to be written (or moved aside).
    pub path: PathBuf,
    /// What failed: "create its folder", "create a temporary file", "write", "sync", "replace".
    pub stage: &'static str,
    #[source]
    pub source: std::io::Error,
}

/// Distinguishes temporary files of writes from one process (two threads, or a write retried
/// after a failure, never share a name).
static WRITE_SERIAL: AtomicU64 = AtomicU64::new(0);

/// Replaces `path` with `bytes`, atomically: afterwards the file holds either its old content
/// or all of `bytes`, never a mixture or a truncation. Creates the parent folder if needed.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), AtomicFileError> {
    let fail = |stage: &'static str| {
        move |source: std::io::Error| AtomicFileError {
            path: path.to_path_buf(),
            stage,
            source,
        }
    };
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&folder).map_err(fail("create its folder"))?;
    // The temporary name is kept short, so any name the file system takes for the target,
    // up to its 255-byte limit, also leaves room for the temporary one.
    let name: String = path
        .file_name()
        .map(|n| n.to_string_lossy().chars().take(64).collect())
        .unwrap_or_else(|| "file".into());
    let serial = WRITE_SERIAL.fetch_add(1, Ordering::Relaxed);
    let temp = folder.join(format!(".{name}.{}.{serial}.tmp", std::process::id()));
    let mut file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&temp)
        .map_err(fail("create a temporary file"))?;
    let written = file
        .write_all(bytes)
        .map_err(fail("write"))
        .and_then(|()| file.sync_all().map_err(fail("sync")));
    drop(file);
    let replaced = written.and_then(|()| std::fs::rename(&temp, path).map_err(fail("replace")));
    if replaced.is_err() {
        // Best effort: the error that matters is the one returned.
        let _ = std::fs::remove_file(&temp);
        return replaced;
    }
    sync_folder(&folder);
    Ok(())
}

/// Makes a rename in `folder` durable. Best effort: some file systems refuse to open or sync a
/// directory, and the data itself is already on disk.
fn sync_folder(folder: &Path) {
    if let Ok(dir) = File::open(folder) {
        let _ = dir.sync_all();
    }
}

/// Moves `path` out of the way as `<name>.corrupt` beside it (or `<name>.corrupt.1`, `.2`, …
/// if that exists, so an earlier kept-aside file is never overwritten) and returns the new path.
///
/// The move is a hard link to the new name (which fails rather than replace a file that
/// appeared there meanwhile) and then the removal of the old name; on a file system without
/// hard links it falls back to a rename after checking the new name is free.
pub fn keep_aside(path: &Path) -> Result<PathBuf, AtomicFileError> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "file".into());
    let fail = |source| AtomicFileError {
        path: path.to_path_buf(),
        stage: "move aside",
        source,
    };
    for n in 0..MAX_KEPT_ASIDE {
        let aside = if n == 0 {
            path.with_file_name(format!("{name}.corrupt"))
        } else {
            path.with_file_name(format!("{name}.corrupt.{n}"))
        };
        match std::fs::hard_link(path, &aside) {
            Ok(()) => {
                std::fs::remove_file(path).map_err(fail)?;
                return Ok(aside);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(fail(e)),
            Err(_) if !aside.exists() => {
                // No hard links here (FAT, some network shares): a plain rename.
                std::fs::rename(path, &aside).map_err(fail)?;
                return Ok(aside);
            }
            Err(_) => continue,
        }
    }
    Err(fail(std::io::Error::other(format!(
        "{MAX_KEPT_ASIDE} earlier copies are already kept aside"
    ))))
}

/// Most kept-aside copies of one file (`<name>.corrupt` to `<name>.corrupt.9999`); past
/// that the bad file is left where it is and the error says so.
pub const MAX_KEPT_ASIDE: u32 = 10_000;
