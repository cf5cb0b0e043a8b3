//! The body of each fuzz target: the bytes go where a player's file would go, and what comes
//! back is checked. Refusals are fine; panics, loaders that caught their own panic, accepted
//! meshes with non-finite or out-of-range data, replays that do not survive a round trip, and
//! asset paths that resolve outside the root are bugs, reported by panicking (afl records
//! the input as a crash; the corpus tests fail naming it).
//!
//! Every input stays in memory: the model, animation, texture and sound targets go through
//! the engine's loaders from a byte slice (`load_model_bytes`, `load_animation_bytes`,
//! `decode_sound_bytes`) with the files they reference in a [`MemoryFiles`] ([`crate::fixed`]);
//! a level is parsed from its text and loaded against the scratch asset root, which is read,
//! never written, per execution.
//!
//! Runs on the calling thread. Must not: write files.

use std::path::Path;

use candela::app::{ActionSet, Bindings, Progress, Recording, Script, Settings, parse_checked};
use candela::assets::{AssetError, Level, MemoryFiles, Model, load_model_bytes};
use candela::audio::decode_sound_bytes;
use candela::level::playable_from_level;
use candela::sim::animation::{AnimError, load_animation_bytes};

use crate::fixed::{FIXED_OBJ, PLAIN_MTL, TEXTURE_MTL, files};
use crate::scratch;
use crate::{Outcome, Target};

/// Runs `target` on `bytes`. Panics on a bug (see the module doc).
pub fn run(target: Target, bytes: &[u8]) -> Outcome {
    match target {
        Target::Level => level(bytes),
        Target::Script => {
            let text = String::from_utf8_lossy(bytes);
            refused(Script::parse(
                &scratch::root().join("fuzz_script.ron"),
                &text,
            ))
        }
        Target::Replay => replay(bytes),
        Target::Settings => {
            let set = ActionSet::standard();
            let text = String::from_utf8_lossy(bytes);
            refused(parse_checked::<Settings>(&text, |s| s.check(&set)))
        }
        Target::Save => {
            let text = String::from_utf8_lossy(bytes);
            refused(parse_checked::<Progress>(&text, Progress::check))
        }
        Target::Bindings => {
            let set = ActionSet::standard();
            let text = String::from_utf8_lossy(bytes);
            refused(Bindings::parse(Path::new("fuzz_bindings.ron"), &text, &set))
        }
        Target::Gltf => model("fuzz.gltf", bytes, &files(&[])),
        Target::Glb => model("fuzz.glb", bytes, &files(&[])),
        Target::Animation => animation(bytes),
        Target::Obj => model("fuzz.obj", bytes, &files(&[("fuzz.mtl", PLAIN_MTL)])),
        Target::Mtl => model("fuzz.obj", FIXED_OBJ, &files(&[("fuzz.mtl", bytes)])),
        Target::Texture => model(
            "fuzz.obj",
            FIXED_OBJ,
            &files(&[("fuzz.mtl", TEXTURE_MTL), ("fuzz_texture", bytes)]),
        ),
        Target::Sound => refused(decode_sound_bytes("fuzz_sound", bytes)),
        Target::AssetPath => asset_path(bytes),
    }
}

fn refused<T, E: std::fmt::Display>(result: Result<T, E>) -> Outcome {
    match result {
        Ok(_) => Outcome::Accepted,
        Err(e) => Outcome::Refused(e.to_string()),
    }
}

/// What `load_level` does after reading the file: parse, then load against the asset root.
fn level(bytes: &[u8]) -> Outcome {
    let path = scratch::root().join("fuzz_level.ron");
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Outcome::Refused("the level is not UTF-8".to_string());
    };
    let loaded = Level::parse(&path, text)
        .and_then(|level| playable_from_level(&path, &level, &scratch::asset_root()));
    match loaded {
        Ok(_) => Outcome::Accepted,
        Err(e) => asset_refusal(e),
    }
}

fn asset_refusal(e: AssetError) -> Outcome {
    if let AssetError::LoaderPanic { path, message } = &e {
        panic!("a loader panicked on {}: {message}", path.display());
    }
    Outcome::Refused(e.to_string())
}

/// Loads `bytes` as the model `name` (its extension picks the loader), beside `files`.
fn model(name: &str, bytes: &[u8], files: &MemoryFiles) -> Outcome {
    match load_model_bytes(Path::new(name), bytes, files) {
        Ok(model) => {
            check_model(&model);
            Outcome::Accepted
        }
        Err(e) => asset_refusal(e),
    }
}

/// What every accepted model must satisfy: finite positions, indices and material ids in range.
fn check_model(model: &Model) {
    for mesh in &model.meshes {
        assert!(
            mesh.positions.iter().all(|p| p.is_finite()),
            "accepted mesh {:?} has a non-finite position",
            mesh.name
        );
        let vertices = mesh.positions.len() as u64;
        assert!(
            mesh.triangles
                .iter()
                .flatten()
                .all(|&i| u64::from(i) < vertices),
            "accepted mesh {:?} has an index past its {vertices} vertices",
            mesh.name
        );
        assert_eq!(
            mesh.triangle_materials.len(),
            mesh.triangles.len(),
            "accepted mesh {:?}: one material per triangle",
            mesh.name
        );
        assert!(
            mesh.triangle_materials
                .iter()
                .all(|&m| (m as usize) < model.materials.len()),
            "accepted mesh {:?} names a material past the model's {}",
            mesh.name,
            model.materials.len()
        );
    }
}

fn animation(bytes: &[u8]) -> Outcome {
    // The loader knows GLB by its magic; the name only appears in messages.
    let name = if bytes.starts_with(b"glTF") {
        "fuzz_anim.glb"
    } else {
        "fuzz_anim.gltf"
    };
    match load_animation_bytes(Path::new(name), bytes, &files(&[])) {
        Ok(_) => Outcome::Accepted,
        Err(AnimError::LoaderPanic { file, message }) => {
            panic!(
                "the animation loader panicked on {}: {message}",
                file.display()
            )
        }
        Err(AnimError::Asset(e)) => asset_refusal(e),
        Err(e) => Outcome::Refused(e.to_string()),
    }
}

fn replay(bytes: &[u8]) -> Outcome {
    let path = Path::new("fuzz.replay");
    match Recording::decode(path, bytes) {
        Ok(recording) => {
            match Recording::decode(path, &recording.encode()) {
                Ok(again) => assert!(
                    again == recording,
                    "a decoded replay changes in encode → decode"
                ),
                Err(e) => panic!("a decoded replay does not decode once re-encoded: {e}"),
            }
            Outcome::Accepted
        }
        Err(e) => Outcome::Refused(e.to_string()),
    }
}

fn asset_path(bytes: &[u8]) -> Outcome {
    let text = String::from_utf8_lossy(bytes);
    let requested = text.lines().next().unwrap_or_default();
    let root_dir = scratch::root();
    let root = scratch::asset_root();
    match root.resolve(&root_dir.join("level.ron"), None, requested) {
        Ok(resolved) => {
            let inside = match (resolved.canonicalize(), root_dir.canonicalize()) {
                (Ok(file), Ok(root)) => file.starts_with(root),
                // Resolved but gone, or the root gone: nothing was read outside.
                _ => true,
            };
            assert!(
                inside,
                "{requested:?} resolved to {} outside the asset root",
                resolved.display()
            );
            Outcome::Accepted
        }
        Err(e) => Outcome::Refused(e.to_string()),
    }
}
