//! One fuzz entry point per input format the engine reads: each takes arbitrary bytes, feeds
//! them to the engine's own parser or loader the way a player's file would reach it, and
//! checks the properties that must hold for every input. A returned `Err` is a clean refusal
//! (the expected outcome for most inputs); a panic is a bug, and so is a loader that had to
//! catch its own panic ([`candela::assets::AssetError::LoaderPanic`]) or an accepted path
//! outside the asset root.
//!
//! Every input stays in memory (afl's persistent mode runs thousands a second): the loaders
//! read it from a byte slice, with the files it references in memory ([`fixed`]). Only
//! `asset_path` and `level` read the per-thread scratch folder on disk ([`scratch`]), made
//! once, never written per input.
//!
//! Owns: the [`Target`] list, [`run`], the fixed in-memory files ([`fixed`]), the scratch
//! folder ([`scratch`]), and a deterministic byte mutator ([`mutate`]) for the corpus tests and
//! `examples/exec_rate.rs` (executions per second). Runs on the
//! calling thread (afl's fork server, or the tests). Must not: keep state between runs, or
//! write files per run.

pub mod fixed;
pub mod mutate;
pub mod scratch;
pub mod seeds;
mod targets;

pub use targets::run;

/// Every input format with a fuzz target. The name is the corpus folder under `fuzz/corpus/`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Target {
    /// A level file (RON, with gameplay), loaded to play.
    Level,
    /// A capture script (RON).
    Script,
    /// A recorded input replay (binary).
    Replay,
    /// The player's settings (RON).
    Settings,
    /// The progress save (RON).
    Save,
    /// Key bindings (RON).
    Bindings,
    /// A glTF JSON file.
    Gltf,
    /// A binary glTF file.
    Glb,
    /// A glTF or GLB file loaded for animation (skins, joints, clips, morph targets).
    Animation,
    /// A Wavefront OBJ file (with an MTL beside it).
    Obj,
    /// A Wavefront MTL file (referenced by a fixed OBJ).
    Mtl,
    /// A texture (PNG, JPEG, HDR, TGA… by content), referenced by a fixed OBJ + MTL.
    Texture,
    /// A sound file (WAV or Ogg Vorbis).
    Sound,
    /// A path a level or model names, resolved against the asset root.
    AssetPath,
}

impl Target {
    pub const ALL: [Target; 14] = [
        Target::Level,
        Target::Script,
        Target::Replay,
        Target::Settings,
        Target::Save,
        Target::Bindings,
        Target::Gltf,
        Target::Glb,
        Target::Animation,
        Target::Obj,
        Target::Mtl,
        Target::Texture,
        Target::Sound,
        Target::AssetPath,
    ];

    /// The target's name: its corpus folder and its `CANDELA_FUZZ_TARGET` value.
    pub fn name(self) -> &'static str {
        match self {
            Target::Level => "level",
            Target::Script => "script",
            Target::Replay => "replay",
            Target::Settings => "settings",
            Target::Save => "save",
            Target::Bindings => "bindings",
            Target::Gltf => "gltf",
            Target::Glb => "glb",
            Target::Animation => "animation",
            Target::Obj => "obj",
            Target::Mtl => "mtl",
            Target::Texture => "texture",
            Target::Sound => "sound",
            Target::AssetPath => "asset_path",
        }
    }

    /// The target named `name`.
    pub fn named(name: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Whether the format is text, so that the mutator also splices in syntax tokens.
    pub fn is_text(self) -> bool {
        matches!(
            self,
            Target::Level
                | Target::Script
                | Target::Settings
                | Target::Save
                | Target::Bindings
                | Target::Gltf
                | Target::Obj
                | Target::Mtl
                | Target::AssetPath
        )
    }
}

/// What one input did: accepted, or refused with the engine's message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    Accepted,
    Refused(String),
}
