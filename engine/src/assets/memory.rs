//! The files a model loaded from memory refers to: a map from a path relative to the model's
//! folder to the file's bytes. [`load_model_bytes`](super::load_model_bytes) and
//! `sim::animation::load_animation_bytes` resolve the model's references (MTL libraries,
//! textures, glTF buffers and images) in it instead of on disk, through the same loader code.
//!
//! Owns: [`MemoryFiles`]. Runs on whichever thread loads assets (the fuzz targets' thread).
//! Must not: touch the file system.

use std::collections::HashMap;
use std::path::{Component, Path};

/// Files by path relative to the model's folder, `/`-separated (`"fuzz.mtl"`,
/// `"textures/wood.png"`). The model's folder is the root of a load from memory: a reference
/// that leaves it is [`AssetError::OutsideRoot`](super::AssetError::OutsideRoot), one that
/// names no file here is [`AssetError::MissingFile`](super::AssetError::MissingFile).
#[derive(Clone, Debug, Default)]
pub struct MemoryFiles {
    files: HashMap<String, Vec<u8>>,
}

impl MemoryFiles {
    /// No files: every reference is missing.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds (or replaces) the file at `path` (relative to the model's folder; `.` components
    /// and backslashes are accepted and normalised, `..` components are dropped).
    pub fn insert(&mut self, path: &str, bytes: impl Into<Vec<u8>>) -> &mut Self {
        self.files
            .insert(key(Path::new(&path.replace('\\', "/"))), bytes.into());
        self
    }

    /// [`MemoryFiles::insert`], by value.
    pub fn with(mut self, path: &str, bytes: impl Into<Vec<u8>>) -> Self {
        self.insert(path, bytes);
        self
    }

    /// The bytes of the file at `relative` (a path below the model's folder), if there is one.
    pub fn get(&self, relative: &Path) -> Option<&[u8]> {
        self.files.get(&key(relative)).map(Vec::as_slice)
    }

    /// How many files there are.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }
}

/// The map key of `relative`: its normal components joined with `/`.
fn key(relative: &Path) -> String {
    let parts: Vec<_> = relative
        .components()
        .filter_map(|component| match component {
            Component::Normal(part) => Some(part.to_string_lossy()),
            _ => None,
        })
        .collect();
    parts.join("/")
}
