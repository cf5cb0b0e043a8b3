//! A walk over every glTF file we have (the Khronos sample models and the deliberately broken
//! glTF-Validator and tinygltf test data under `shared/external/gltf/`), through the
//! animation loader and, for each file that loads, through evaluation: the rest pose and
//! every clip at its start, middle, end and past its end, deformed into world-space vertices.
//!
//! Pass/fail, for every file: no panic escapes (each file runs on its own thread under
//! `catch_unwind`) and no `AnimError::LoaderPanic` comes back; a refusal's message names the
//! file; evaluation finishes within `TIME_LIMIT`; and every evaluated position is finite
//! (the loader refuses non-finite inputs, so a non-finite output would be a bug in the
//! arithmetic). Counts by outcome are printed (`--nocapture`).

use crate::common;

use std::collections::BTreeMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use candela::sim::animation::{AnimError, load_animation_file, world_positions};

/// A load plus evaluation longer than this is a failure (the largest sample model takes well
/// under a second in release builds).
const TIME_LIMIT: Duration = Duration::from_secs(30);

enum Outcome {
    /// Loaded and evaluated: (clips, poses evaluated, non-finite positions).
    Evaluated(usize, usize, usize),
    Refused(AnimError),
    Panicked(String),
}

fn run(path: &Path) -> Outcome {
    let result = catch_unwind(AssertUnwindSafe(|| {
        let model = load_animation_file(path)?;
        let mut poses = vec![model.rest_pose()];
        for (index, clip) in model.clips.iter().enumerate() {
            let d = clip.duration_seconds;
            for time in [0.0, 0.5 * d, d, d + 1.0] {
                poses.push(model.pose_at(index, time));
            }
        }
        let non_finite: usize = poses
            .iter()
            .map(|pose| {
                world_positions(&model, pose)
                    .iter()
                    .filter(|p| !p.is_finite())
                    .count()
            })
            .sum();
        Ok::<_, AnimError>(Outcome::Evaluated(
            model.clips.len(),
            poses.len(),
            non_finite,
        ))
    }));
    match result {
        Ok(Ok(outcome)) => outcome,
        Ok(Err(error)) => Outcome::Refused(error),
        Err(payload) => Outcome::Panicked(
            payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default(),
        ),
    }
}

fn variant(error: &AnimError) -> String {
    let debug = format!("{error:?}");
    match error {
        AnimError::Asset(inner) => {
            let inner = format!("{inner:?}");
            format!(
                "Asset::{}",
                inner.split([' ', '{', '(']).next().unwrap_or("")
            )
        }
        _ => debug
            .split([' ', '{', '('])
            .next()
            .unwrap_or("")
            .to_string(),
    }
}

#[test]
fn every_gltf_file_loads_and_evaluates_or_is_refused_cleanly() {
    let root = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external/gltf"
    ));
    let files = common::files_under(&root, &["gltf", "glb"]);
    assert!(!files.is_empty(), "no glTF files under {}", root.display());
    let mut failures = Vec::new();
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    let (mut clips, mut poses) = (0, 0);
    for path in &files {
        let (sender, receiver) = mpsc::channel();
        let owned = path.clone();
        std::thread::spawn(move || {
            let _ = sender.send(run(&owned));
        });
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        match receiver.recv_timeout(TIME_LIMIT) {
            Err(_) => failures.push(format!("{}: timed out", path.display())),
            Ok(Outcome::Panicked(message)) => {
                failures.push(format!("{}: panicked: {message}", path.display()))
            }
            Ok(Outcome::Refused(error)) => {
                if matches!(error, AnimError::LoaderPanic { .. })
                    || !error.to_string().contains(name)
                {
                    failures.push(format!("{}: {error}", path.display()));
                }
                *counts
                    .entry(format!("refused: {}", variant(&error)))
                    .or_default() += 1;
            }
            Ok(Outcome::Evaluated(c, p, non_finite)) => {
                if non_finite > 0 {
                    failures.push(format!(
                        "{}: {non_finite} non-finite positions",
                        path.display()
                    ));
                }
                clips += c;
                poses += p;
                *counts.entry("evaluated".to_string()).or_default() += 1;
            }
        }
    }
    println!(
        "{} files, {clips} clips, {poses} poses evaluated",
        files.len()
    );
    for (outcome, count) in &counts {
        println!("{count:>5}  {outcome}");
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
