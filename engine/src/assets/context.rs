//! What every loader carries while it reads one model file: the asset root, the file itself,
//! the notes it writes for the user, and helpers that turn failures into [`AssetError`]s that
//! name the model file.
//!
//! Owns: resolving referenced files (MTL, textures, buffers) inside the root relative to a
//! folder, reading files with a size limit, and collecting notes (also sent to `log`). The
//! files come from disk (an [`AssetRoot`]) or from memory (the model's bytes and a
//! [`MemoryFiles`]); the loaders cannot tell which, so both run the same parsing and checks.
//! Must not: know any file format.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use super::error::{AssetError, AssetResult};
use super::limits::MAX_FILE_BYTES;
use super::memory::MemoryFiles;
use super::root::{AssetRoot, lexical_join};

/// Where one load's files come from.
enum Source<'a> {
    /// The model file and everything it references lie on disk inside this root.
    Disk(&'a AssetRoot),
    /// The model's bytes, and the files it references by path relative to `root`, the
    /// model's folder (which nothing may leave).
    Memory {
        model: &'a [u8],
        files: &'a MemoryFiles,
        root: PathBuf,
    },
}

/// The state of one model load. Every error built here names [`LoadContext::file`].
pub(crate) struct LoadContext<'a> {
    source: Source<'a>,
    /// The model file (canonical path, inside the root; for a load from memory, the name it
    /// was given, used only in messages and to resolve references).
    pub file: PathBuf,
    /// The folder of the model file: what relative references start from.
    pub folder: PathBuf,
    /// Notes for [`Model::notes`](super::Model::notes).
    pub notes: Vec<String>,
}

impl<'a> LoadContext<'a> {
    /// A context for `file`, a canonical path inside `root`.
    pub fn new(root: &'a AssetRoot, file: PathBuf) -> Self {
        let folder = file
            .parent()
            .map_or_else(|| root.path().to_path_buf(), Path::to_path_buf);
        Self {
            source: Source::Disk(root),
            file,
            folder,
            notes: Vec::new(),
        }
    }

    /// A context for a model held in memory: `name` names it in messages (its folder is the
    /// root its references resolve in), `model` is its bytes and `files` what it references.
    pub fn in_memory(name: &Path, model: &'a [u8], files: &'a MemoryFiles) -> Self {
        let folder = name.parent().map(Path::to_path_buf).unwrap_or_default();
        Self {
            source: Source::Memory {
                model,
                files,
                root: folder.clone(),
            },
            file: name.to_path_buf(),
            folder,
            notes: Vec::new(),
        }
    }

    /// Records something the user should know (also logged at info level).
    pub fn note(&mut self, message: impl Into<String>) {
        let message = message.into();
        log::info!("{}: {message}", self.file.display());
        self.notes.push(message);
    }

    /// Records a loss the user should know about (also logged at warn level).
    pub fn warn(&mut self, message: impl Into<String>) {
        let message = message.into();
        log::warn!("{}: {message}", self.file.display());
        self.notes.push(message);
    }

    /// Resolves `requested` (relative, `/`-separated, as written in the model or its MTL)
    /// against `base`, a folder inside the root. Leaving the root is
    /// [`AssetError::OutsideRoot`]; a missing target is [`AssetError::MissingFile`]; both
    /// name the model file.
    pub fn resolve(&self, base: &Path, requested: &str) -> AssetResult<PathBuf> {
        // Windows-style separators appear in OBJ/MTL files written on Windows.
        let requested = requested.replace('\\', "/");
        let root = match &self.source {
            Source::Disk(root) => root,
            Source::Memory { files, root, .. } => {
                return self.resolve_in(files, root, base, &requested);
            }
        };
        match root.resolve(&self.file, Some(base), &requested) {
            Ok(path) => Ok(path),
            Err(AssetError::NotFound { path }) => Err(AssetError::MissingFile {
                path: self.file.clone(),
                referenced: path,
            }),
            Err(AssetError::Io { path, source }) => Err(AssetError::ReadFailed {
                path: self.file.clone(),
                referenced: path,
                source,
            }),
            Err(other) => Err(other),
        }
    }

    /// [`LoadContext::resolve`] in memory: the same confinement, lexically (memory has no
    /// symbolic links), and the same errors.
    fn resolve_in(
        &self,
        files: &MemoryFiles,
        root: &Path,
        base: &Path,
        requested: &str,
    ) -> AssetResult<PathBuf> {
        let Some(path) = lexical_join(base, root, Path::new(requested)) else {
            return Err(AssetError::OutsideRoot {
                path: self.file.clone(),
                requested: requested.to_string(),
                root: root.to_path_buf(),
            });
        };
        match path.strip_prefix(root).ok().and_then(|key| files.get(key)) {
            Some(_) => Ok(path),
            None => Err(AssetError::MissingFile {
                path: self.file.clone(),
                referenced: path,
            }),
        }
    }

    /// Reads the model file itself, refusing files over [`MAX_FILE_BYTES`].
    pub fn read_model_file(&self) -> AssetResult<Cow<'a, [u8]>> {
        match &self.source {
            Source::Disk(_) => read_limited(&self.file, &self.file).map(Cow::Owned),
            Source::Memory { model, .. } => {
                self.check_size(&self.file, model.len())?;
                Ok(Cow::Borrowed(*model))
            }
        }
    }

    /// Reads a referenced file (already resolved), refusing files over [`MAX_FILE_BYTES`].
    pub fn read_referenced(&self, referenced: &Path) -> AssetResult<Vec<u8>> {
        let (files, root) = match &self.source {
            Source::Disk(_) => return read_limited(&self.file, referenced),
            Source::Memory { files, root, .. } => (files, root),
        };
        let bytes = referenced
            .strip_prefix(root)
            .ok()
            .and_then(|key| files.get(key))
            .ok_or_else(|| AssetError::MissingFile {
                path: self.file.clone(),
                referenced: referenced.to_path_buf(),
            })?;
        self.check_size(referenced, bytes.len())?;
        Ok(bytes.to_vec())
    }

    /// Refuses a file of `size` bytes over [`MAX_FILE_BYTES`], as [`read_limited`] does.
    fn check_size(&self, file: &Path, size: usize) -> AssetResult<()> {
        let size = size as u64;
        if size > MAX_FILE_BYTES {
            return Err(AssetError::TooLarge {
                path: self.file.clone(),
                what: format!("file {}", file.display()),
                size,
                limit: MAX_FILE_BYTES,
            });
        }
        Ok(())
    }

    /// A [`AssetError::Gltf`] naming the model file.
    pub fn gltf_error(&self, message: impl Into<String>) -> AssetError {
        AssetError::Gltf {
            path: self.file.clone(),
            message: message.into(),
        }
    }

    /// A [`AssetError::Obj`] naming the model file.
    pub fn obj_error(&self, message: impl Into<String>) -> AssetError {
        AssetError::Obj {
            path: self.file.clone(),
            message: message.into(),
        }
    }

    /// A [`AssetError::TooLarge`] naming the model file.
    pub fn too_large(&self, what: impl Into<String>, size: u64, limit: u64) -> AssetError {
        AssetError::TooLarge {
            path: self.file.clone(),
            what: what.into(),
            size,
            limit,
        }
    }

    /// A [`AssetError::Unsupported`] naming the model file.
    pub fn unsupported(&self, message: impl Into<String>) -> AssetError {
        AssetError::Unsupported {
            path: self.file.clone(),
            message: message.into(),
        }
    }
}

/// Reads `file` (named in errors through `model`, the file being loaded).
fn read_limited(model: &Path, file: &Path) -> AssetResult<Vec<u8>> {
    let io_error = |source: std::io::Error| {
        if source.kind() == std::io::ErrorKind::NotFound {
            if model == file {
                AssetError::NotFound {
                    path: model.to_path_buf(),
                }
            } else {
                AssetError::MissingFile {
                    path: model.to_path_buf(),
                    referenced: file.to_path_buf(),
                }
            }
        } else if model == file {
            AssetError::Io {
                path: model.to_path_buf(),
                source,
            }
        } else {
            AssetError::ReadFailed {
                path: model.to_path_buf(),
                referenced: file.to_path_buf(),
                source,
            }
        }
    };
    let size = std::fs::metadata(file).map_err(io_error)?.len();
    if size > MAX_FILE_BYTES {
        return Err(AssetError::TooLarge {
            path: model.to_path_buf(),
            what: format!("file {}", file.display()),
            size,
            limit: MAX_FILE_BYTES,
        });
    }
    std::fs::read(file).map_err(io_error)
}
