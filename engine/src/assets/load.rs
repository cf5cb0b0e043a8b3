//! The entry points of model loading: resolve the file inside the asset root, pick the loader
//! by extension (`.obj`, `.gltf`, `.glb`), and make sure nothing escapes but a [`Model`] or an
//! [`AssetError`] naming the file.
//!
//! Inputs: an [`AssetRoot`] and a path relative to it (or a plain file path for tools and
//! tests), or the model's bytes with a name and the [`MemoryFiles`] it references (the fuzz
//! targets). Output: a checked [`Model`] (every mesh went through `mesh_check`). The three
//! entry points differ only in the [`LoadContext`] they build: the same loaders parse and
//! check the bytes.
//! Runs on whichever thread loads assets (the main thread or a loader thread).
//! Must not: know any file format (the `obj` and `gltf` modules do), or touch the GPU.
//!
//! A panic inside a loader or a library it calls is caught and returned as
//! [`AssetError::LoaderPanic`]: the engine keeps running on bad art. Such a panic is a bug
//! (a check is missing before the call that panicked); the robustness tests fail on it.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use super::context::LoadContext;
use super::error::{AssetError, AssetResult};
use super::memory::MemoryFiles;
use super::model::Model;
use super::root::AssetRoot;
use super::{gltf, obj};

/// Loads the model at `path` (relative to `root`, `/`-separated), dispatching by extension:
/// `.obj` (with its MTL files), `.gltf` or `.glb`. Everything the model references must lie
/// inside `root` as well, relative to the model file's folder. `referrer` is the file that
/// names `path` (a level, say), for messages.
pub fn load_model(root: &AssetRoot, referrer: &Path, path: &str) -> AssetResult<Model> {
    let file = root.resolve(referrer, None, path)?;
    let mut model = load_caught(LoadContext::new(root, file))?;
    model.name = path.to_string();
    Ok(model)
}

/// Loads a model held in memory: `bytes` is the model file, `name` its file name or path
/// (the extension picks the loader as in [`load_model`]; every error names it; its folder is
/// the root references resolve in) and `files` holds what it references (MTL libraries,
/// textures, glTF buffers and images) by path relative to that folder. The same loaders and
/// checks run as for a file on disk.
pub fn load_model_bytes(name: &Path, bytes: &[u8], files: &MemoryFiles) -> AssetResult<Model> {
    let mut model = load_caught(LoadContext::in_memory(name, bytes, files))?;
    model.name = name.display().to_string();
    Ok(model)
}

/// Runs the loader of `context`'s file, turning a panic into [`AssetError::LoaderPanic`].
fn load_caught(mut context: LoadContext) -> AssetResult<Model> {
    let loaded = catch_unwind(AssertUnwindSafe(|| dispatch(&mut context)));
    let file = context.file.clone();
    let mut model = match loaded {
        Ok(result) => result?,
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|text| (*text).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".to_string());
            return Err(AssetError::LoaderPanic {
                path: file,
                message,
            });
        }
    };
    model.notes = std::mem::take(&mut context.notes);
    Ok(model)
}

/// Loads the model file at `path` with its own folder as the asset root (for tools and tests).
pub fn load_model_file(path: &Path) -> AssetResult<Model> {
    let file = path
        .canonicalize()
        .map_err(|source| AssetError::io(path, source))?;
    let (Some(folder), Some(name)) = (file.parent(), file.file_name()) else {
        return Err(AssetError::Unsupported {
            path: path.to_path_buf(),
            message: "not a model file".to_string(),
        });
    };
    let Some(name) = name.to_str() else {
        return Err(AssetError::Unsupported {
            path: path.to_path_buf(),
            message: "the file name is not valid UTF-8".to_string(),
        });
    };
    let root = AssetRoot::new(folder)?;
    load_model(&root, path, name)
}

/// Picks the loader by the file's extension (case-insensitive).
fn dispatch(context: &mut LoadContext) -> AssetResult<Model> {
    let extension = context
        .file
        .extension()
        .and_then(|extension| extension.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("obj") => obj::load(context),
        Some("gltf") | Some("glb") => gltf::load(context),

        _ => Err(context.unsupported("unknown model format (expected .obj, .gltf or .glb)")),
    }
}
