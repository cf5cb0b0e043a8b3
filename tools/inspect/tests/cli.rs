//! The `inspect` binary: its listing names what the file holds, and `--dump-vertices` writes
//! the layout of the three.js animation reference, matching it (tolerance `2e-5 · max|coord|
//! + 1e-6`, the reference self-check's bound for float32 data).

use std::path::{Path, PathBuf};
use std::process::Command;

type TestResult = Result<(), Box<dyn std::error::Error>>;

fn shared(relative: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../../shared")).join(relative)
}

fn floats(path: &Path) -> Result<Vec<f32>, std::io::Error> {
    Ok(std::fs::read(path)?
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect())
}

#[test]
fn lists_nodes_meshes_materials_skins_and_clips() -> TestResult {
    let file = shared("external/gltf/InterpolationTest/glTF-Binary/InterpolationTest.glb");
    let output = Command::new(env!("CARGO_BIN_EXE_inspect"))
        .arg(&file)
        .output()?;
    assert!(output.status.success(), "{output:?}");
    let text = String::from_utf8(output.stdout)?;
    for heading in [
        "nodes (",
        "meshes (",
        "materials (",
        "skins (0)",
        "clips (9)",
    ] {
        assert!(text.contains(heading), "no {heading:?} in:\n{text}");
    }
    assert!(text.contains("\"Step Scale\": 1.6667 s"), "{text}");
    assert!(text.contains("CUBICSPLINE rotation"), "{text}");
    Ok(())
}

#[test]
fn dumped_vertices_match_the_reference() -> TestResult {
    let file = shared("external/gltf/CesiumMan/glTF-Binary/CesiumMan.glb");
    let reference = shared("external/animation-reference/CesiumMan/0/t_1.000000.bin");
    let out = std::env::temp_dir().join(format!("candela_inspect_{}.bin", std::process::id()));
    let status = Command::new(env!("CARGO_BIN_EXE_inspect"))
        .arg(&file)
        .args(["--clip", "0", "--time", "1.0", "--dump-vertices"])
        .arg(&out)
        .status()?;
    assert!(status.success());
    let (ours, theirs) = (floats(&out)?, floats(&reference)?);
    let _ = std::fs::remove_file(&out);
    assert_eq!(ours.len(), theirs.len());
    assert!(!theirs.is_empty(), "the reference holds no vertices");
    assert!(
        theirs.iter().all(|v| v.is_finite()),
        "the reference has a non-finite coordinate"
    );
    // Every dumped coordinate must be finite (a NaN would vanish in an `f32::max` fold).
    if let Some(bad) = ours.iter().position(|v| !v.is_finite()) {
        panic!("dumped coordinate {bad} is {}", ours[bad]);
    }
    let size = theirs.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    let error = ours
        .iter()
        .zip(&theirs)
        .fold(0.0f32, |m, (a, b)| m.max((a - b).abs()));
    assert!(error <= 2e-5 * size + 1e-6, "max error {error}");
    Ok(())
}

#[test]
fn unknown_clip_is_an_error_naming_it() -> TestResult {
    let file = shared("external/gltf/CesiumMan/glTF-Binary/CesiumMan.glb");
    let output = Command::new(env!("CARGO_BIN_EXE_inspect"))
        .arg(&file)
        .args([
            "--clip",
            "walk",
            "--time",
            "1",
            "--dump-vertices",
            "/dev/null",
        ])
        .output()?;
    assert!(!output.status.success());
    let stderr = String::from_utf8(output.stderr)?;
    assert!(
        stderr.contains("walk") && stderr.contains("CesiumMan"),
        "{stderr}"
    );
    Ok(())
}
