//! Errors of input recordings: every one names the file, and says what did not match (another
//! level, another game, a different step rate, an action this game does not have) or where the
//! file is broken (truncated, corrupt, a format version this build cannot read).
//! Data only. Must not: decide what the runner does about them.

use std::path::PathBuf;

use crate::assets::atomic_file::AtomicFileError;

/// A recording that cannot be read, written or replayed here.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError {
    #[error("{path}: cannot read: {source}")]
    Read {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error(transparent)]
    Write(#[from] AtomicFileError),
    #[error("{path}: not a Candela input recording (no `CDLAREC` signature)")]
    NotARecording { path: PathBuf },
    #[error("{path}: recording format version {found}; this build reads version {supported}")]
    Version {
        path: PathBuf,
        found: u32,
        supported: u32,
    },
    /// The file ends early (`at` says where: in the header, in step k of n, before the checksum).
    #[error("{path}: truncated: the file ends {at}")]
    Truncated { path: PathBuf, at: String },
    #[error("{path}: corrupt: {message}")]
    Corrupt { path: PathBuf, message: String },
    #[error("{path}: recorded for game `{recorded}`, not `{expected}`")]
    OtherGame {
        path: PathBuf,
        recorded: String,
        expected: String,
    },
    #[error(
        "{path}: recorded on another level: level `{recorded_id}` with content hash \
         {recorded_hash:016x}, but this is level `{level_id}` with hash {level_hash:016x} \
         (the level file changed, or this replay is for another level)"
    )]
    OtherLevel {
        path: PathBuf,
        recorded_id: String,
        recorded_hash: u64,
        level_id: String,
        level_hash: u64,
    },
    #[error("{path}: recorded at {recorded} steps per second; this game steps at {expected}")]
    StepRate {
        path: PathBuf,
        recorded: f64,
        expected: f64,
    },
    #[error("{path}: unknown action `{name}` (this game has no action of that name)")]
    UnknownAction { path: PathBuf, name: String },
    #[error(
        "{path}: action `{name}` was recorded taking {recorded} input; this game's takes {expected}"
    )]
    ActionKind {
        path: PathBuf,
        name: String,
        recorded: &'static str,
        expected: &'static str,
    },
    /// A frame pushed to a recorder does not fit its action set.
    #[error(
        "recording for `{game}`: step {step} has {found} values, the action set has {expected}"
    )]
    FrameShape {
        game: String,
        step: u64,
        found: usize,
        expected: usize,
    },
}
