//! A walk over every deliberately broken or unusual model we have: every `.gltf`/`.glb` under
//! `shared/external/gltf/_robustness/` (glTF-Validator and tinygltf test data) and every
//! `.obj` under `shared/external/obj/` (tinyobjloader's parser cases and real meshes).
//!
//! Pass/fail, for every file:
//! 1. it loads, or is refused with an `AssetError` whose message names the file;
//! 2. no panic escapes `load_model_file` (checked with `catch_unwind`), and no
//!    `AssetError::LoaderPanic` is returned (that would be a panic the loader caught: a missing
//!    check);
//! 3. it finishes within `TIME_LIMIT` (each load runs on its own thread; a load past the limit
//!    is reported and left behind).
//!
//! Against the glTF-Validator reports (`*.report.json` beside 372 of the inputs):
//! - a report with no error (severity 0) means the file must load, except the files in
//!   `VALID_BUT_REFUSED`, each refused for a stated reason (and each must stay refused, so the
//!   list stays true);
//! - a report with an error code in `FATAL_CODES` (the file cannot be read at all: broken JSON
//!   or GLB container, a node loop, a buffer shorter than declared, an index past its vertices)
//!   means the file must be refused;
//! - any other error code may go either way: most are in data the engine does not read
//!   (animations, skins, cameras, unused accessors or images) or in rules it does not depend on
//!   (alignment, min/max bounds, unit-length vectors).
//!
//! The counts (loaded / refused by variant) are printed; run with `--nocapture` to see them.

use crate::common;

use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use candela::assets::{AssetError, load_model_file};

/// Generous for a debug build: the slowest file here loads in well under a second.
const TIME_LIMIT: Duration = Duration::from_secs(10);

/// Validator codes that make a file unreadable: such files must be refused.
const FATAL_CODES: &[&str] = &[
    "INVALID_JSON",
    "GLB_INVALID_MAGIC",
    "GLB_INVALID_VERSION",
    "GLB_LENGTH_TOO_SMALL",
    "GLB_LENGTH_MISMATCH",
    "GLB_UNEXPECTED_END_OF_HEADER",
    "GLB_UNEXPECTED_END_OF_CHUNK_HEADER",
    "GLB_UNEXPECTED_END_OF_CHUNK_DATA",
    "GLB_CHUNK_TOO_BIG",
    "GLB_UNEXPECTED_FIRST_CHUNK",
    "GLB_DUPLICATE_CHUNK",
    "GLB_EMPTY_CHUNK",
    "UNKNOWN_ASSET_MAJOR_VERSION",
    "NODE_LOOP",
    "BUFFER_BYTE_LENGTH_MISMATCH",
    "ACCESSOR_INDEX_OOB",
];

/// Files the validator finds valid that the engine refuses, with the reason.
const VALID_BUT_REFUSED: &[(&str, &str)] = &[
    (
        "base/data/buffer/non_relative_uri.gltf",
        "an http: buffer URI; assets never come from the network",
    ),
    (
        "base/data/json/integer_written_as_float.gltf",
        "gltf-json reads integer fields as integers only (1.0 is refused)",
    ),
    (
        "base/data/root/named_objects.gltf",
        "gltf-json 1.4 requires an animation channel target node",
    ),
    (
        "base/data/root/unused_objects.gltf",
        "gltf-json 1.4 requires an animation channel target node",
    ),
    (
        "base/data/scene/custom_property.gltf",
        "gltf-json 1.4 requires scene.nodes",
    ),
    (
        "ext/KHR_animation_pointer/data/animation/channel/target/custom_property.gltf",
        "KHR_animation_pointer: no target node",
    ),
    (
        "ext/KHR_animation_pointer/data/animation/channel/target/missing_extension_declaration.gltf",
        "KHR_animation_pointer: no target node",
    ),
    (
        "ext/KHR_animation_pointer/data/animation/channel/target/valid.gltf",
        "KHR_animation_pointer: no target node",
    ),
];

/// tinyobjloader cases with a known right answer.
const OBJ_MUST_REFUSE: &[&str] = &[
    "test-nan.obj",
    "invalid-relative-vertex-index.obj",
    "invalid-relative-texture-index.obj",
    "issue-140-zero-face-idx.obj",
];
const OBJ_MUST_LOAD: &[&str] = &[
    "cube.obj",
    "cornell_box.obj",
    "issue-295-trianguation-failure.obj",
    "mtl filename with whitespace issue46.obj",
    "catmark_torus_creases0.obj",
    "leading-decimal-dot-issue-201.obj",
];

enum Outcome {
    Loaded,
    Refused(AssetError),
    Panicked(String),
    TimedOut,
}

fn external() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external"
    ))
}

/// Loads `path` on its own thread, catching panics, within [`TIME_LIMIT`].
fn load(path: &Path) -> (Outcome, Duration) {
    let (sender, receiver) = mpsc::channel();
    let owned = path.to_path_buf();
    let start = Instant::now();
    std::thread::spawn(move || {
        let result = catch_unwind(AssertUnwindSafe(|| load_model_file(&owned)));
        let outcome = match result {
            Ok(Ok(_)) => Outcome::Loaded,
            Ok(Err(error)) => Outcome::Refused(error),
            Err(payload) => Outcome::Panicked(
                payload
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_string())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_default(),
            ),
        };
        let _ = sender.send(outcome);
    });
    match receiver.recv_timeout(TIME_LIMIT) {
        Ok(outcome) => (outcome, start.elapsed()),
        Err(_) => (Outcome::TimedOut, start.elapsed()),
    }
}

fn variant(error: &AssetError) -> &'static str {
    match error {
        AssetError::NotFound { .. } => "NotFound",
        AssetError::Io { .. } => "Io",
        AssetError::OutsideRoot { .. } => "OutsideRoot",
        AssetError::MissingFile { .. } => "MissingFile",
        AssetError::ReadFailed { .. } => "ReadFailed",
        AssetError::TooLarge { .. } => "TooLarge",
        AssetError::Gltf { .. } => "Gltf",
        AssetError::Obj { .. } => "Obj",
        AssetError::Texture { .. } => "Texture",
        AssetError::BadMesh { .. } => "BadMesh",
        AssetError::Unsupported { .. } => "Unsupported",
        AssetError::Level { .. } => "Level",
        AssetError::LoaderPanic { .. } => "LoaderPanic",
        AssetError::InLevel { .. } => "InLevel",
    }
}

/// The error codes (severity 0) of the validator report beside `path`, if there is one.
fn report_errors(path: &Path) -> Option<Vec<String>> {
    let mut report = path.as_os_str().to_owned();
    report.push(".report.json");
    let text = std::fs::read_to_string(report).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    let messages = json.get("issues")?.get("messages")?.as_array()?;
    Some(
        messages
            .iter()
            .filter(|m| m.get("severity").and_then(|s| s.as_u64()) == Some(0))
            .filter_map(|m| m.get("code")?.as_str().map(str::to_string))
            .collect(),
    )
}

#[test]
fn every_robustness_file_loads_or_is_refused_cleanly() {
    let validator_root = external().join("gltf/_robustness/glTF-Validator-testdata");
    let mut files = common::files_under(&external().join("gltf/_robustness"), &["gltf", "glb"]);
    let gltf_count = files.len();
    files.extend(common::files_under(&external().join("obj"), &["obj"]));
    assert!(
        gltf_count > 300,
        "only {gltf_count} glTF files found under _robustness"
    );
    assert!(
        files.len() - gltf_count > 50,
        "only {} OBJ files found",
        files.len() - gltf_count
    );

    let mut failures = Vec::new();
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    let mut slowest = (Duration::ZERO, PathBuf::new());
    let (mut with_report, mut valid_reports) = (0usize, 0usize);
    // Every entry of the named lists must name a file of the walk (a renamed or moved file
    // would otherwise leave its entry checking nothing).
    let mut named_seen: BTreeMap<&str, usize> = OBJ_MUST_REFUSE
        .iter()
        .chain(OBJ_MUST_LOAD)
        .copied()
        .chain(VALID_BUT_REFUSED.iter().map(|(file, _)| *file))
        .map(|n| (n, 0))
        .collect();
    for path in &files {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if let Some(seen) = named_seen.get_mut(name.as_str()) {
            *seen += 1;
        }
        if let Ok(relative) = path.strip_prefix(&validator_root)
            && let Some(seen) =
                named_seen.get_mut(relative.to_string_lossy().replace('\\', "/").as_str())
        {
            *seen += 1;
        }
        let shown = path
            .strip_prefix(external())
            .unwrap_or(path)
            .display()
            .to_string();
        let (outcome, elapsed) = load(path);
        if elapsed > slowest.0 {
            slowest = (elapsed, path.clone());
        }
        let kind = if shown.starts_with("obj") {
            "obj"
        } else {
            "gltf"
        };
        let loaded = match &outcome {
            Outcome::Loaded => {
                *counts.entry(format!("{kind} loaded")).or_default() += 1;
                true
            }
            Outcome::Refused(error) => {
                *counts
                    .entry(format!("{kind} refused: {}", variant(error)))
                    .or_default() += 1;
                let message = error.to_string();
                if matches!(error, AssetError::LoaderPanic { .. }) {
                    failures.push(format!("{shown}: the loader caught a panic: {message}"));
                } else if !message.contains(&name) {
                    failures.push(format!(
                        "{shown}: the message does not name the file: {message}"
                    ));
                }
                false
            }
            Outcome::Panicked(message) => {
                failures.push(format!("{shown}: PANICKED: {message}"));
                continue;
            }
            Outcome::TimedOut => {
                failures.push(format!("{shown}: took longer than {TIME_LIMIT:?}"));
                continue;
            }
        };
        if let Ok(relative) = path.strip_prefix(&validator_root) {
            let relative = relative.to_string_lossy().replace('\\', "/");
            let exception = VALID_BUT_REFUSED.iter().find(|(file, _)| *file == relative);
            if let Some(errors) = report_errors(path) {
                with_report += 1;
                valid_reports += usize::from(errors.is_empty());
                if errors.is_empty() && !loaded && exception.is_none() {
                    failures.push(format!(
                        "{shown}: valid per its report but refused: {outcome_message}",
                        outcome_message = refused_message(&outcome)
                    ));
                }
                if let Some(code) = errors.iter().find(|c| FATAL_CODES.contains(&c.as_str()))
                    && loaded
                {
                    failures.push(format!("{shown}: its report has {code} but it loaded"));
                }
            }
            if let Some((_, reason)) = exception
                && loaded
            {
                failures.push(format!("{shown}: listed as refused ({reason}) but it loads now: update VALID_BUT_REFUSED"));
            }
        }
        if OBJ_MUST_REFUSE.contains(&name.as_str()) && loaded {
            failures.push(format!("{shown}: must be refused"));
        }
        if OBJ_MUST_LOAD.contains(&name.as_str()) && !loaded {
            failures.push(format!("{shown}: must load: {}", refused_message(&outcome)));
        }
    }
    println!(
        "robustness walk over {} files (slowest {:?}: {}):",
        files.len(),
        slowest.0,
        slowest.1.display()
    );
    for (what, count) in &counts {
        println!("  {count:4}  {what}");
    }
    println!(
        "  {with_report} files had a validator report, {valid_reports} of them without errors"
    );
    assert!(
        with_report > 300,
        "only {with_report} validator reports read"
    );
    let unmatched: Vec<&str> = named_seen
        .iter()
        .filter(|(_, seen)| **seen == 0)
        .map(|(name, _)| *name)
        .collect();
    assert!(
        unmatched.is_empty(),
        "named in OBJ_MUST_REFUSE / OBJ_MUST_LOAD / VALID_BUT_REFUSED but no such file in the walk: {unmatched:?}"
    );
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

fn refused_message(outcome: &Outcome) -> String {
    match outcome {
        Outcome::Refused(error) => error.to_string(),
        _ => String::new(),
    }
}
