//! Errors of animation data: one enum, each variant naming the file (or level entry) and the
//! item at fault (clip, channel, node, mesh, primitive, vertex).
//!
//! Owns: [`AnimError`]. Must not: print or log (callers decide what to show).

use std::path::PathBuf;

use crate::assets::AssetError;

/// Anything wrong with a clip, a skin or morph targets, from a glTF file or a level file.
/// `file` is the glTF file, or the level file for authored clips.
#[derive(Debug, thiserror::Error)]
pub enum AnimError {
    /// The file itself could not be read or parsed (not an animation problem as such).
    #[error(transparent)]
    Asset(#[from] AssetError),
    /// A channel targets a node that does not exist.
    #[error(
        "{file}: clip {clip:?}, channel {channel}: targets node {node}, but the file has {node_count} nodes"
    )]
    MissingNode {
        file: PathBuf,
        clip: String,
        channel: usize,
        node: usize,
        node_count: usize,
    },
    /// A sampler whose output count does not match its input count (×3 for CUBICSPLINE,
    /// ×target count for morph weights).
    #[error(
        "{file}: clip {clip:?}, channel {channel}: {inputs} key times but {outputs} output values (expected {expected})"
    )]
    KeyCountMismatch {
        file: PathBuf,
        clip: String,
        channel: usize,
        inputs: usize,
        outputs: usize,
        expected: usize,
    },
    /// A key time or value that is NaN or infinite.
    #[error("{file}: clip {clip:?}, channel {channel}: key {key} has a non-finite {what}")]
    NonFiniteKey {
        file: PathBuf,
        clip: String,
        channel: usize,
        key: usize,
        what: &'static str,
    },
    /// Key times that decrease (glTF requires strictly increasing times).
    #[error(
        "{file}: clip {clip:?}, channel {channel}: key time {key} ({time} s) is not after the previous one"
    )]
    TimesNotIncreasing {
        file: PathBuf,
        clip: String,
        channel: usize,
        key: usize,
        time: f32,
    },
    /// Anything else wrong with a channel (no keys, unknown path or interpolation, bad accessor type).
    #[error("{file}: clip {clip:?}, channel {channel}: {message}")]
    BadChannel {
        file: PathBuf,
        clip: String,
        channel: usize,
        message: String,
    },
    /// A vertex names a joint the skin does not have.
    #[error(
        "{file}: mesh {mesh:?} primitive {primitive}: vertex {vertex} uses joint {joint}, but skin {skin} has {joint_count} joints"
    )]
    JointOutOfRange {
        file: PathBuf,
        mesh: String,
        primitive: usize,
        vertex: usize,
        joint: u32,
        skin: usize,
        joint_count: usize,
    },
    /// A node that cannot be evaluated (non-finite transform, several parents, a cycle).
    #[error("{file}: node {node}: {message}")]
    BadNode {
        file: PathBuf,
        node: usize,
        message: String,
    },
    /// A skin that is malformed (no joints, wrong inverse-bind count, non-finite matrices).
    #[error("{file}: skin {skin}: {message}")]
    BadSkin {
        file: PathBuf,
        skin: usize,
        message: String,
    },
    /// A primitive whose skinning or morph data is malformed.
    #[error("{file}: mesh {mesh:?} primitive {primitive}: {message}")]
    BadPrimitive {
        file: PathBuf,
        mesh: String,
        primitive: usize,
        message: String,
    },
    /// An authored clip file that is not valid RON for [`AuthoredClipSet`](super::AuthoredClipSet).
    #[error("{file}: invalid authored clips: {message}")]
    BadRon { file: PathBuf, message: String },
    /// An authored track names a target the clip set does not declare.
    #[error("{file}: clip {clip:?}, track {track}: unknown target {target:?}")]
    UnknownTarget {
        file: PathBuf,
        clip: String,
        track: usize,
        target: String,
    },
    /// A clip asked for by name or index that the model does not have.
    #[error("{file}: no clip {clip:?} (the file has {count} clips)")]
    NoSuchClip {
        file: PathBuf,
        clip: String,
        count: usize,
    },
    /// A joint asked for by name that no skin of the model has.
    #[error("{file}: no joint {joint:?} in the model's skins (its joints: {})", joints.join(", "))]
    NoSuchJoint {
        file: PathBuf,
        joint: String,
        joints: Vec<String>,
    },
    /// The loader, or a library it calls, panicked: a bug in Candela (a check is missing).
    #[error(
        "{file}: the animation loader panicked ({message}); this is a bug, please report it with the file"
    )]
    LoaderPanic { file: PathBuf, message: String },
}

/// Result of animation functions.
pub type AnimResult<T> = Result<T, AnimError>;
