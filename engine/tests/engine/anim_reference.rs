//! Candela's glTF animation (node hierarchy, step / linear / cubic-spline sampling, morph
//! targets, skinning) against an independent reference: world-space vertex positions and
//! node world matrices computed by three.js 0.187.0 for Khronos sample models, in
//! `shared/external/animation-reference/` (read from there, never copied into the repo).
//! Every model of its `index.json` is checked, at rest and at every sample time of every clip.
//!
//! Tolerance: positions within `2e-5 · max|coord| + 1e-6` of the reference, the bound the
//! reference's own independent self-check uses. The data is float32 (≈6e-8 relative) and
//! Candela composes matrices in float32 (three in float64): a few float32 roundings per level
//! of hierarchy and per joint, which stays well below 2e-5 of the model size even through
//! RecursiveSkeletons' deep chains. It holds for *every* model and time, including the two
//! cases the reference README warns about, because the sampler follows the same conventions:
//! - SimpleSkin and AnimatedTriangle store rotation keys up to 2.3e-4 off unit length; a time
//!   on a key or between identical keys returns the key as stored, not normalised (normalising
//!   would be off by up to 4.5e-4, beyond this tolerance);
//! - InterpolationTest `0_Step_Scale` samples at 0.25 d (exactly on a STEP key: takes it) and
//!   at 0.75 d (3e-8 s before a key: keeps the previous one), which a float64 clock against
//!   float32 key times reproduces; the test passes the manifest's exact float64 times.
//!
//! Node world matrices are compared too (1e-5 relative to each column's size, or to the model
//! size for the translation column), and the sampled local TRS of animated nodes (1e-5, a few
//! float32 ulps of unit-range values), and morph weights (1e-6).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use candela::sim::animation::{
    AnimatedModel, load_animation_file, scene_primitives, world_positions,
};
use glam::{Mat4, Vec3};
use serde_json::Value;

type TestResult = Result<(), Box<dyn std::error::Error>>;

fn shared() -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared")).to_path_buf()
}

fn reference_dir() -> PathBuf {
    shared().join("external/animation-reference")
}

fn read_json(path: &Path) -> Result<Value, Box<dyn std::error::Error>> {
    Ok(serde_json::from_str(&std::fs::read_to_string(path)?)?)
}

fn read_bin(path: &Path) -> Result<Vec<Vec3>, Box<dyn std::error::Error>> {
    let bytes = std::fs::read(path)?;
    Ok(bytes
        .chunks_exact(12)
        .map(|c| {
            let f = |i: usize| f32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]);
            Vec3::new(f(0), f(4), f(8))
        })
        .collect())
}

fn floats(value: &Value) -> Vec<f32> {
    value
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(Value::as_f64)
                .map(|v| v as f32)
                .collect()
        })
        .unwrap_or_default()
}

/// The largest of `errors`, NaN when any error is NaN (a NaN coordinate must fail the
/// comparison, where `f32::max` would drop it), 0 for none.
fn worst(errors: impl IntoIterator<Item = f32>) -> f32 {
    errors.into_iter().fold(0.0f32, |m, e| {
        if m.is_nan() || e.is_nan() {
            f32::NAN
        } else {
            m.max(e)
        }
    })
}

/// Largest absolute difference per coordinate of two vectors, NaN when either has a NaN.
fn vec_error(a: Vec3, e: Vec3) -> f32 {
    worst((a - e).abs().to_array())
}

/// Largest error of one model over all its poses, and the failures found.
#[derive(Default)]
struct Report {
    max_position_error: f32,
    tolerance: f32,
    max_matrix_error: f32,
    max_trs_error: f32,
    poses: usize,
    /// Node world matrices compared.
    matrices: usize,
    morph_weights: usize,
    failures: Vec<String>,
}

/// Compares one pose (rest, or `clip` at `time`) with its reference `sample` entry.
fn check_pose(
    model: &AnimatedModel,
    dir: &Path,
    label: &str,
    pose: &candela::sim::animation::Pose,
    sample: &Value,
    report: &mut Report,
) -> TestResult {
    let file = sample["file"].as_str().ok_or("sample without file")?;
    let expected = read_bin(&dir.join(file))?;
    let actual = world_positions(model, pose);
    if actual.len() != expected.len() {
        report.failures.push(format!(
            "{label}: {} vertices, reference has {}",
            actual.len(),
            expected.len()
        ));
        return Ok(());
    }
    if expected.is_empty() {
        report
            .failures
            .push(format!("{label}: the reference has no vertices"));
        return Ok(());
    }
    let scale = worst(expected.iter().map(|p| p.abs().max_element()));
    if !scale.is_finite() || expected.iter().any(|p| !p.is_finite()) {
        report
            .failures
            .push(format!("{label}: the reference has a non-finite vertex"));
        return Ok(());
    }
    let tolerance = 2e-5 * scale + 1e-6;
    report.tolerance = report.tolerance.max(tolerance);
    // The first vertex that is off (a NaN coordinate counts as off), and the largest error.
    let errors: Vec<f32> = actual
        .iter()
        .zip(&expected)
        .map(|(a, e)| vec_error(*a, *e))
        .collect();
    let error = worst(errors.iter().copied());
    report.max_position_error = worst([report.max_position_error, error]);
    if let Some(bad) = errors.iter().position(|e| !(*e <= tolerance)) {
        report.failures.push(format!(
            "{label}: vertex {bad} off by {:.3e} (tolerance {tolerance:.3e}): {} vs {}",
            errors[bad], actual[bad], expected[bad]
        ));
    }
    let primitives = scene_primitives(model);
    let world = model.world_matrices(pose);
    // Every pose of the reference carries every node's world matrix: a missing list, a
    // malformed matrix or a node we do not have is a failure, never a skipped comparison.
    let matrices = sample["node_world_matrices"]
        .as_array()
        .ok_or("sample without node_world_matrices")?;
    if matrices.len() != world.len() {
        report.failures.push(format!(
            "{label}: {} node world matrices, reference has {}",
            world.len(),
            matrices.len()
        ));
    }
    {
        for (node, m) in matrices.iter().enumerate() {
            let m = floats(m);
            if m.len() != 16 {
                report.failures.push(format!(
                    "{label}: node {node}: reference matrix of {} floats",
                    m.len()
                ));
                continue;
            }
            let reference = Mat4::from_cols_slice(&m);
            let Some(mine) = world.get(node).copied() else {
                continue;
            };
            let mut error = 0.0f32;
            for c in 0..4 {
                let d = (mine.col(c) - reference.col(c)).abs().max_element();
                // Relative to the column's size: a node scaled by 100 (AnimatedMorphCube)
                // has float32 rounding of ~1e-5 in absolute terms.
                let size = if c == 3 {
                    scale
                } else {
                    reference.col(c).abs().max_element()
                };
                error = worst([error, d / size.max(1.0)]);
            }
            if !mine.is_finite() {
                error = f32::NAN;
            }
            report.max_matrix_error = worst([report.max_matrix_error, error]);
            report.matrices += 1;
            if !(error <= 1e-5) {
                report.failures.push(format!(
                    "{label}: node {node} world matrix off by {error:.3e}"
                ));
            }
        }
    }
    // Clip samples carry the local TRS of every animated node (the rest pose has none).
    let locals = sample["animated_node_local_trs"].as_object();
    if label != "rest" && locals.is_none_or(|l| l.is_empty()) {
        report
            .failures
            .push(format!("{label}: sample without animated_node_local_trs"));
    }
    if let Some(locals) = locals {
        for (node, trs) in locals {
            let node: usize = node.parse()?;
            let parts = [
                (
                    floats(&trs["translation"]),
                    pose.translation[node].to_array().to_vec(),
                ),
                (
                    floats(&trs["rotation"]),
                    pose.rotation[node].to_array().to_vec(),
                ),
                (floats(&trs["scale"]), pose.scale[node].to_array().to_vec()),
            ];
            for (reference, mine) in parts {
                let error = worst(
                    reference
                        .iter()
                        .zip(&mine)
                        .map(|(r, m)| (r - m).abs() / r.abs().max(1.0)),
                );
                report.max_trs_error = worst([report.max_trs_error, error]);
                if reference.len() != mine.len() || !(error <= 1e-5) {
                    report.failures.push(format!(
                        "{label}: node {node} local TRS {mine:?} vs {reference:?}"
                    ));
                }
            }
        }
    }
    // three's morph influences per primitive; ours are per node (all primitives of a mesh
    // share them). Weights are unit-range: 1e-6 is a few float32 ulps.
    for entry in sample["morph_weights"].as_array().into_iter().flatten() {
        let prim = entry["prim"].as_u64().ok_or("morph entry without prim")? as usize;
        let node = primitives
            .get(prim)
            .map(|p| p.node)
            .ok_or("morph entry names no primitive")?;
        let reference = floats(&entry["weights"]);
        let mine = &pose.weights[node];
        let error = worst(reference.iter().zip(mine).map(|(r, m)| (r - m).abs()));
        if reference.len() != mine.len() || !(error <= 1e-6) {
            report.failures.push(format!(
                "{label}: node {node} morph weights {mine:?} vs {reference:?}"
            ));
        }
        report.morph_weights += 1;
    }
    report.poses += 1;
    Ok(())
}

fn check_model(name: &str) -> Result<Report, Box<dyn std::error::Error>> {
    let dir = reference_dir().join(name);
    let manifest = read_json(&dir.join("manifest.json"))?;
    let source = manifest["source_file"].as_str().ok_or("no source_file")?;
    let model = load_animation_file(&shared().join("..").join(source))?;
    let mut report = Report::default();
    // The primitive order of the reference (mesh, node, primitive) must be ours.
    let ours: Vec<(u64, u64, u64)> = scene_primitives(&model)
        .iter()
        .map(|p| (p.mesh as u64, p.node as u64, p.primitive as u64))
        .collect();
    let theirs: Vec<(u64, u64, u64)> = manifest["primitives"]
        .as_array()
        .ok_or("no primitives")?
        .iter()
        .map(|p| {
            let field = |k: &str| p[k].as_u64().unwrap_or(u64::MAX);
            (field("mesh"), field("node"), field("primitive"))
        })
        .collect();
    if ours != theirs {
        report
            .failures
            .push(format!("primitive order {ours:?}, reference {theirs:?}"));
        return Ok(report);
    }
    check_pose(
        &model,
        &dir,
        "rest",
        &model.rest_pose(),
        &manifest["rest"],
        &mut report,
    )?;
    for clip in manifest["clips"].as_array().ok_or("no clips")? {
        let index = clip["index"].as_u64().ok_or("clip without index")? as usize;
        let duration = clip["duration"].as_f64().ok_or("clip without duration")?;
        let ours = model.clips.get(index).ok_or("clip missing")?;
        // Durations are float32 key times widened to float64 on both sides.
        if (ours.duration_seconds - duration).abs() > 1e-9 {
            report.failures.push(format!(
                "clip {index}: duration {} vs {duration}",
                ours.duration_seconds
            ));
        }
        for sample in clip["samples"].as_array().ok_or("no samples")? {
            let time = sample["time"].as_f64().ok_or("sample without time")?;
            let pose = model.pose_at(index, time);
            let label = format!("clip {index} t={time}");
            check_pose(&model, &dir, &label, &pose, sample, &mut report)?;
        }
    }
    Ok(report)
}

#[test]
fn every_model_and_time_matches_three_js() -> TestResult {
    let index = read_json(&reference_dir().join("index.json"))?;
    let models: BTreeMap<String, Value> = serde_json::from_value(index["models"].clone())?;
    assert!(!models.is_empty(), "the reference index lists no models");
    let mut failures = Vec::new();
    let mut morph_weight_checks = 0;
    println!(
        "{:<22} {:>6} {:>12} {:>12} {:>12} {:>12}",
        "model", "poses", "max pos err", "tolerance", "max mat err", "max TRS err"
    );
    for name in models.keys() {
        let report = check_model(name)?;
        println!(
            "{name:<22} {:>6} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e}",
            report.poses,
            report.max_position_error,
            report.tolerance,
            report.max_matrix_error,
            report.max_trs_error
        );
        morph_weight_checks += report.morph_weights;
        if report.poses == 0 || report.matrices == 0 {
            failures.push(format!(
                "{name}: {} poses and {} node matrices compared",
                report.poses, report.matrices
            ));
        }
        failures.extend(report.failures.into_iter().map(|f| format!("{name}: {f}")));
    }
    assert!(
        morph_weight_checks > 0,
        "no morph weights compared (the reference has morphed models)"
    );
    assert!(
        failures.is_empty(),
        "{} mismatches:\n{}",
        failures.len(),
        failures
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
    Ok(())
}
