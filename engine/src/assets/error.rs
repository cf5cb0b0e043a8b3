//! Errors of asset loading: one enum, each variant naming the file and the problem.
//!
//! Owns: [`AssetError`]. Must not: print or log (callers decide what to show).

use std::path::PathBuf;

/// Anything that can go wrong while reading art or a level. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum AssetError {
    #[error("{path}: file not found")]
    NotFound { path: PathBuf },
    #[error("{path}: cannot read: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: the path {requested:?} leaves the asset root {root}")]
    OutsideRoot {
        path: PathBuf,
        requested: String,
        root: PathBuf,
    },
    #[error("{path}: references {referenced}, which does not exist")]
    MissingFile { path: PathBuf, referenced: PathBuf },
    #[error("{path}: cannot read {referenced}: {source}")]
    ReadFailed {
        path: PathBuf,
        referenced: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {what} is too large: {size} > limit {limit}")]
    TooLarge {
        path: PathBuf,
        what: String,
        size: u64,
        limit: u64,
    },
    #[error("{path}: malformed glTF: {message}")]
    Gltf { path: PathBuf, message: String },
    #[error("{path}: malformed OBJ/MTL: {message}")]
    Obj { path: PathBuf, message: String },
    #[error("{path}: texture {texture:?} cannot be decoded: {message}")]
    Texture {
        path: PathBuf,
        texture: String,
        message: String,
    },
    #[error("{path}: mesh {mesh:?}: {message}")]
    BadMesh {
        path: PathBuf,
        mesh: String,
        message: String,
    },
    #[error("{path}: {message}")]
    Unsupported { path: PathBuf, message: String },
    #[error("{path}: level: {message}")]
    Level { path: PathBuf, message: String },
    /// A model a level names failed to load: the level, the model's name in it, and why.
    #[error("{level}: model {model:?}: {source}")]
    InLevel {
        level: PathBuf,
        model: String,
        #[source]
        source: Box<AssetError>,
    },
    /// A loader or a library it calls panicked on this input: a bug in Candela (a check is
    /// missing). The panic was caught so that the engine keeps running.
    #[error(
        "{path}: the loader panicked ({message}); this is a bug, please report it with the file"
    )]
    LoaderPanic { path: PathBuf, message: String },
}

/// Result of asset functions.
pub type AssetResult<T> = Result<T, AssetError>;

impl AssetError {
    /// An I/O failure on `path`: [`AssetError::NotFound`] when it does not exist, otherwise
    /// [`AssetError::Io`].
    pub fn io(path: &std::path::Path, source: std::io::Error) -> Self {
        if source.kind() == std::io::ErrorKind::NotFound {
            AssetError::NotFound {
                path: path.to_path_buf(),
            }
        } else {
            AssetError::Io {
                path: path.to_path_buf(),
                source,
            }
        }
    }
}
