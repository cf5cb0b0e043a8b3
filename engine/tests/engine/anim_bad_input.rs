//! Bad animation data, one test per case: each asserts the [`AnimError`] variant, that the
//! message names the file and the item at fault, and (by returning at all) that nothing
//! panicked. A good file built the same way loads, so each failure is the one change made.

use std::path::{Path, PathBuf};

use candela::sim::animation::{AnimError, AnimatedModel, load_animation_file};

type TestResult = Result<(), Box<dyn std::error::Error>>;

/// A temporary folder for one test (removed when dropped).
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> Result<Self, std::io::Error> {
        let dir =
            std::env::temp_dir().join(format!("candela_anim_bad_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir)?;
        Ok(Self(dir))
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Builds a glTF file: binary data goes to `data.bin`, one buffer view per accessor.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
}

impl Builder {
    /// Adds an accessor of `kind` (SCALAR, VEC3, …) holding float32 `values`; returns its index.
    fn floats(&mut self, kind: &str, components: usize, values: &[f32]) -> usize {
        let offset = self.bin.len();
        for v in values {
            self.bin.extend_from_slice(&v.to_le_bytes());
        }
        self.push(offset, 5126, kind, values.len() / components)
    }

    /// Adds a VEC4 unsigned-byte accessor (JOINTS_0); returns its index.
    fn joints(&mut self, values: &[u8]) -> usize {
        let offset = self.bin.len();
        self.bin.extend_from_slice(values);
        self.push(offset, 5121, "VEC4", values.len() / 4)
    }

    fn push(&mut self, offset: usize, component: u32, kind: &str, count: usize) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let length = self.bin.len() - offset;
        self.views.push(format!(
            r#"{{"buffer":0,"byteOffset":{offset},"byteLength":{length}}}"#
        ));
        self.accessors.push(format!(
            r#"{{"bufferView":{},"componentType":{component},"type":"{kind}","count":{count}}}"#,
            self.views.len() - 1
        ));
        self.accessors.len() - 1
    }

    /// Writes `model.gltf` (top-level members `members`, JSON without braces) and its buffer.
    fn write(&self, dir: &TempDir, members: &str) -> Result<PathBuf, std::io::Error> {
        std::fs::write(dir.0.join("data.bin"), &self.bin)?;
        let path = dir.0.join("model.gltf");
        let json = format!(
            r#"{{"asset":{{"version":"2.0"}},
            "buffers":[{{"byteLength":{},"uri":"data.bin"}}],
            "bufferViews":[{}],"accessors":[{}],{members}}}"#,
            self.bin.len(),
            self.views.join(","),
            self.accessors.join(",")
        );
        std::fs::write(&path, json)?;
        Ok(path)
    }
}

const TRIANGLE: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];

/// One node with a triangle mesh, animated by one channel of `path` on `node`: key times
/// `times`, outputs `values` (of accessor type `kind`: SCALAR, VEC3 or VEC4).
fn animated(
    dir: &TempDir,
    node: usize,
    path: &str,
    interpolation: &str,
    times: &[f32],
    kind: &str,
    values: &[f32],
) -> Result<PathBuf, std::io::Error> {
    let mut b = Builder::default();
    let position = b.floats("VEC3", 3, &TRIANGLE);
    let input = b.floats("SCALAR", 1, times);
    let components = match kind {
        "SCALAR" => 1,
        "VEC4" => 4,
        _ => 3,
    };
    let output = b.floats(kind, components, values);
    b.write(
        dir,
        &format!(
            r#""scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0,"name":"lift"}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":{position}}}}}]}}],
            "animations":[{{"name":"rise","channels":[{{"sampler":0,"target":{{"node":{node},"path":"{path}"}}}}],
              "samplers":[{{"input":{input},"output":{output},"interpolation":"{interpolation}"}}]}}]"#
        ),
    )
}

/// Loads `path`, expecting an error whose message names every string in `names`.
fn expect_error(path: &Path, names: &[&str]) -> Result<AnimError, String> {
    match load_animation_file(path) {
        Ok(_) => Err(format!("{} loaded", path.display())),
        Err(error) => {
            let message = error.to_string();
            for name in names.iter().chain(&["model.gltf"]) {
                if !message.contains(name) {
                    return Err(format!("message {message:?} does not name {name:?}"));
                }
            }
            Ok(error)
        }
    }
}

fn load(path: &Path) -> Result<AnimatedModel, AnimError> {
    load_animation_file(path)
}

#[test]
fn a_good_channel_loads() -> TestResult {
    let dir = TempDir::new("good")?;
    let path = animated(
        &dir,
        0,
        "translation",
        "LINEAR",
        &[0.0, 1.0],
        "VEC3",
        &[0.0, 0.0, 0.0, 0.0, 2.0, 0.0],
    )?;
    let model = load(&path)?;
    assert_eq!(model.clips.len(), 1);
    assert_eq!(model.clips[0].name, "rise");
    assert_eq!(model.clips[0].duration_seconds, 1.0);
    // Halfway through a linear translation from y = 0 to y = 2.
    let pose = model.pose_at(0, 0.5);
    assert_eq!(pose.translation[0].y, 1.0);
    Ok(())
}

#[test]
fn animation_of_a_missing_node() -> TestResult {
    let dir = TempDir::new("missing_node")?;
    let values = [0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
    let path = animated(
        &dir,
        7,
        "translation",
        "LINEAR",
        &[0.0, 1.0],
        "VEC3",
        &values,
    )?;
    let error = expect_error(&path, &["rise", "node 7", "channel 0"])?;
    assert!(
        matches!(
            error,
            AnimError::MissingNode {
                node: 7,
                node_count: 1,
                ..
            }
        ),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn mismatched_input_and_output_counts() -> TestResult {
    let dir = TempDir::new("counts")?;
    // Three key times, two translations.
    let values = [0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
    let path = animated(
        &dir,
        0,
        "translation",
        "LINEAR",
        &[0.0, 1.0, 2.0],
        "VEC3",
        &values,
    )?;
    let error = expect_error(&path, &["rise", "3 key times", "2 output values"])?;
    assert!(
        matches!(
            error,
            AnimError::KeyCountMismatch {
                inputs: 3,
                outputs: 2,
                expected: 3,
                ..
            }
        ),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn cubic_spline_needs_three_outputs_per_key() -> TestResult {
    let dir = TempDir::new("cubic_counts")?;
    // Two keys need six elements (in-tangent, value, out-tangent each); two are given.
    let values = [0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
    let path = animated(
        &dir,
        0,
        "scale",
        "CUBICSPLINE",
        &[0.0, 1.0],
        "VEC3",
        &values,
    )?;
    let error = expect_error(&path, &["rise", "expected 6"])?;
    assert!(
        matches!(error, AnimError::KeyCountMismatch { expected: 6, .. }),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn nan_key_value() -> TestResult {
    let dir = TempDir::new("nan_value")?;
    let values = [0.0, 0.0, 0.0, 1.0, 0.0, f32::NAN, 0.0, 1.0];
    let path = animated(&dir, 0, "rotation", "LINEAR", &[0.0, 1.0], "VEC4", &values)?;
    let error = expect_error(&path, &["rise", "key 1", "value"])?;
    assert!(
        matches!(
            error,
            AnimError::NonFiniteKey {
                key: 1,
                what: "value",
                ..
            }
        ),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn nan_key_time() -> TestResult {
    let dir = TempDir::new("nan_time")?;
    let values = [0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
    let path = animated(
        &dir,
        0,
        "translation",
        "STEP",
        &[f32::NAN, 1.0],
        "VEC3",
        &values,
    )?;
    let error = expect_error(&path, &["rise", "key 0", "time"])?;
    assert!(
        matches!(
            error,
            AnimError::NonFiniteKey {
                key: 0,
                what: "time",
                ..
            }
        ),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn decreasing_key_times() -> TestResult {
    let dir = TempDir::new("decreasing")?;
    let values = [0.0, 0.0, 0.0, 0.0, 2.0, 0.0];
    let path = animated(
        &dir,
        0,
        "translation",
        "LINEAR",
        &[1.0, 0.5],
        "VEC3",
        &values,
    )?;
    let error = expect_error(&path, &["rise", "key time 1"])?;
    assert!(
        matches!(error, AnimError::TimesNotIncreasing { key: 1, .. }),
        "{error:?}"
    );
    Ok(())
}

#[test]
fn weights_of_a_mesh_without_morph_targets() -> TestResult {
    let dir = TempDir::new("weights")?;
    let path = animated(
        &dir,
        0,
        "weights",
        "LINEAR",
        &[0.0, 1.0],
        "SCALAR",
        &[0.0, 1.0],
    )?;
    let error = expect_error(&path, &["rise", "morph targets"])?;
    assert!(matches!(error, AnimError::BadChannel { .. }), "{error:?}");
    Ok(())
}

/// A triangle skinned by a skin of two joints (nodes 1 and 2), its vertices naming `joints`.
fn skinned(dir: &TempDir, joints: &[u8]) -> Result<PathBuf, std::io::Error> {
    let mut b = Builder::default();
    let position = b.floats("VEC3", 3, &TRIANGLE);
    let joint = b.joints(joints);
    let weight = b.floats("VEC4", 4, &[1.0, 0.0, 0.0, 0.0].repeat(3));
    b.write(
        dir,
        &format!(
            r#""scene":0,"scenes":[{{"nodes":[0,1]}}],
            "nodes":[{{"mesh":0,"skin":0}},{{"children":[2]}},{{"translation":[0,1,0]}}],
            "skins":[{{"joints":[1,2]}}],
            "meshes":[{{"name":"arm","primitives":[{{"attributes":{{"POSITION":{position},"JOINTS_0":{joint},"WEIGHTS_0":{weight}}}}}]}}]"#
        ),
    )
}

#[test]
fn in_range_joints_load_and_skin() -> TestResult {
    let dir = TempDir::new("joints_ok")?;
    let path = skinned(&dir, &[0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0])?;
    let model = load(&path)?;
    let positions = candela::sim::animation::world_positions(&model, &model.rest_pose());
    // Vertex 0 follows joint node 1 (identity); vertices 1 and 2 follow node 2 (up by 1 m).
    assert_eq!(positions[0], glam::Vec3::ZERO);
    assert_eq!(positions[1], glam::Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(positions[2], glam::Vec3::new(0.0, 2.0, 0.0));
    Ok(())
}

#[test]
fn out_of_range_joint_index() -> TestResult {
    let dir = TempDir::new("joints_bad")?;
    // Vertex 2 puts its whole weight on joint 5; the skin has 2 joints.
    let path = skinned(&dir, &[0, 0, 0, 0, 1, 0, 0, 0, 5, 0, 0, 0])?;
    let error = expect_error(&path, &["arm", "vertex 2", "joint 5", "2 joints"])?;
    assert!(
        matches!(
            error,
            AnimError::JointOutOfRange {
                vertex: 2,
                joint: 5,
                joint_count: 2,
                ..
            }
        ),
        "{error:?}"
    );
    Ok(())
}
