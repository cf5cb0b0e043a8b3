//! [`ScriptError`]: everything that can go wrong with a capture script, each variant naming the
//! script file and the item (`camera[2]`, `motions[0] ("drone_*")`, `screenshots[1]`).
//!
//! Owns: the error type only. Must not: decide anything.

use std::path::PathBuf;

use crate::assets::AssetError;
use crate::render::RenderError;
use crate::render::film::ImageIoError;

/// A capture script failed to read, check, bind or run.
#[derive(Debug, thiserror::Error)]
pub enum ScriptError {
    #[error("cannot read script {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// Not RON, or not a script (unknown or missing field, wrong type).
    #[error("{}: line {line}, column {column}: {message}", path.display())]
    Parse {
        path: PathBuf,
        line: usize,
        column: usize,
        message: String,
    },
    #[error("{}: {item}: frame {frame} is outside the script's frames 0..{frames}", path.display())]
    FrameOutOfRange {
        path: PathBuf,
        item: String,
        frame: u32,
        frames: u32,
    },
    #[error("{}: {item}: {message}", path.display())]
    Invalid {
        path: PathBuf,
        item: String,
        message: String,
    },
    #[error("{}: {item}: the level has no instance named {name:?}", path.display())]
    UnknownInstance {
        path: PathBuf,
        item: String,
        name: String,
    },
    #[error(
        "{}: {item}: instance {name:?} is static in the level (mark it `dynamic: true` to move it)",
        path.display()
    )]
    StaticInstance {
        path: PathBuf,
        item: String,
        name: String,
    },
    #[error("{}: {item}: no instance of the level is in light group {group}", path.display())]
    UnknownLightGroup {
        path: PathBuf,
        item: String,
        group: u32,
    },
    #[error("{}: the script names no level and none was given", path.display())]
    NoLevel { path: PathBuf },
    #[error("{}: level: {source}", path.display())]
    Level {
        path: PathBuf,
        #[source]
        source: AssetError,
    },
    #[error("{}: render: {source}", path.display())]
    Render {
        path: PathBuf,
        #[source]
        source: RenderError,
    },
    #[error("{}: screenshot {}: {source}", path.display(), file.display())]
    Image {
        path: PathBuf,
        file: PathBuf,
        #[source]
        source: ImageIoError,
    },
}
