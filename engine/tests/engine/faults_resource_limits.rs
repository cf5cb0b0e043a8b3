//! Resource limits: small crafted files that *claim* huge sizes — buffers of a terabyte, an
//! image of 65535 × 65535, meshes of tens of millions of triangles, 100,000 nested glTF nodes,
//! JSON nested 100,000 deep, skins with too many joints, cyclic and self-referencing skins —
//! are refused with an error naming the file and the size (or load within the stated bounds
//! of `engine/src/assets/limits.rs`, docs/RELIABILITY.md "Resource limits"), before anything of
//! the claimed size is allocated, and without a stack overflow. The files are written by the
//! test (none over 3 MB); none is kept in the repository.

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, load_model_file};
use candela::sim::animation::load_animation_file;

type TestResult = Result<(), Box<dyn std::error::Error>>;

struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> std::io::Result<Self> {
        let dir = std::env::temp_dir().join(format!(
            "candela_faults_limits_{name}_{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir)?;
        Ok(Self(dir))
    }

    fn write(&self, name: &str, contents: impl AsRef<[u8]>) -> std::io::Result<PathBuf> {
        let path = self.0.join(name);
        std::fs::write(&path, contents)?;
        Ok(path)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn triangle_bytes() -> Vec<u8> {
    [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|f| f.to_le_bytes())
        .collect()
}

/// One triangle (positions from `t.bin`, 36 bytes) with `buffer_length` claimed for its
/// buffer, the node list `nodes` (a JSON array) and `extra` top-level members.
fn gltf(buffer_length: u64, nodes: &str, extra: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":{buffer_length},"uri":"t.bin"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
        "nodes":{nodes},"scenes":[{{"nodes":[0]}}],"scene":0{extra}}}"#
    )
}

/// Expects `path` refused by the model loader with a message naming every string in `names`.
fn refused(path: &Path, names: &[&str]) -> Result<AssetError, String> {
    match load_model_file(path) {
        Ok(_) => Err(format!("{} loaded", path.display())),
        Err(e) => {
            let text = e.to_string();
            for name in names {
                if !text.contains(name) {
                    return Err(format!("message {text:?} does not name {name:?}"));
                }
            }
            Ok(e)
        }
    }
}

/// A PNG whose header claims `side` × `side` RGBA texels, with empty image data.
fn png_claiming(side: u32) -> Vec<u8> {
    let mut header = side.to_be_bytes().to_vec();
    header.extend(side.to_be_bytes());
    header.extend([8, 6, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    for (kind, data) in [
        (b"IHDR", header),
        (b"IDAT", Vec::new()),
        (b"IEND", Vec::new()),
    ] {
        let mut chunk = kind.to_vec();
        chunk.extend(&data);
        png.extend((data.len() as u32).to_be_bytes());
        png.extend(&chunk);
        png.extend(crc32(&chunk).to_be_bytes());
    }
    png
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = u32::MAX;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// Resident memory of this process, bytes (Linux `/proc/self/statm`).
fn resident_bytes() -> u64 {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| {
            s.split_whitespace()
                .nth(1)
                .and_then(|v| v.parse::<u64>().ok())
        })
        .map_or(0, |pages| pages * 4096)
}

#[test]
fn files_that_claim_huge_buffers_images_and_meshes_are_refused() -> TestResult {
    let dir = TempDir::new("huge")?;
    dir.write("t.bin", triangle_bytes())?;
    let before = resident_bytes();

    // A buffer claiming a terabyte (the file holds 36 bytes).
    let path = dir.write("terabyte.gltf", gltf(1 << 40, r#"[{"mesh":0}]"#, ""))?;
    let e = refused(&path, &["terabyte.gltf", "1099511627776"])?;
    assert!(matches!(e, AssetError::TooLarge { .. }), "{e:?}");

    // A GLB whose binary chunk claims 4 GiB − 4 bytes.
    let json = gltf(16, r#"[{"mesh":0}]"#, "").replace(r#","uri":"t.bin""#, "");
    let mut json = json.into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let mut glb = b"glTF".to_vec();
    glb.extend(2u32.to_le_bytes());
    glb.extend((12 + 8 + json.len() as u32 + 8 + 36).to_le_bytes());
    glb.extend((json.len() as u32).to_le_bytes());
    glb.extend(b"JSON");
    glb.extend(&json);
    glb.extend(0xFFFF_FFFCu32.to_le_bytes());
    glb.extend(b"BIN\0");
    glb.extend(triangle_bytes());
    let path = dir.write("chunk.glb", glb)?;
    let e = refused(&path, &["chunk.glb"])?;
    assert!(
        matches!(e, AssetError::TooLarge { .. } | AssetError::Gltf { .. }),
        "{e:?}"
    );

    // An image of 65535 × 65535 (the largest a PNG header of this kind holds is refused
    // before decoding: the side limit is 16384).
    dir.write("huge.png", png_claiming(65_535))?;
    let path = dir.write(
        "image.gltf",
        gltf(
            36,
            r#"[{"mesh":0}]"#,
            r#","images":[{"uri":"huge.png"}],"textures":[{"source":0}],
            "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}]"#,
        )
        .replace(
            r#""attributes":{"POSITION":0}"#,
            r#""attributes":{"POSITION":0},"material":0"#,
        ),
    )?;
    let e = refused(&path, &["image.gltf", "huge.png", "65535"])?;
    assert!(matches!(e, AssetError::TooLarge { .. }), "{e:?}");

    // Twenty million triangles: an index accessor of 60,000,000 elements over 36 bytes.
    let path = dir.write(
        "triangles.gltf",
        gltf(36, r#"[{"mesh":0}]"#, "")
            .replace(
                r#""max":[1,1,0]}]"#,
                r#""max":[1,1,0]},{"bufferView":0,"componentType":5125,"count":60000000,"type":"SCALAR"}]"#,
            )
            .replace(
                r#""attributes":{"POSITION":0}"#,
                r#""attributes":{"POSITION":0},"indices":1"#,
            ),
    )?;
    let e = refused(&path, &["triangles.gltf", "60000000"])?;
    assert!(
        matches!(e, AssetError::TooLarge { .. } | AssetError::Gltf { .. }),
        "{e:?}"
    );

    // Thirty million vertices from a sparse accessor that needs no buffer bytes.
    let path = dir.write(
        "sparse.gltf",
        gltf(36, r#"[{"mesh":0}]"#, "")
            .replace(
                r#""max":[1,1,0]}]"#,
                r#""max":[1,1,0]},{"componentType":5126,"count":30000000,"type":"VEC3","min":[0,0,0],"max":[0,0,0],
                   "sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}]"#,
            )
            .replace(r#""attributes":{"POSITION":0}"#, r#""attributes":{"POSITION":1}"#),
    )?;
    let e = refused(&path, &["sparse.gltf", "30000000"])?;
    assert!(matches!(e, AssetError::TooLarge { .. }), "{e:?}");

    // None of the refusals allocated what it claimed (the smallest claim, 30 M vertices, is
    // 360 MB of positions): resident memory grew by less than 64 MiB.
    let grown = resident_bytes().saturating_sub(before);
    assert!(grown < 64 << 20, "resident memory grew by {grown} bytes");
    Ok(())
}

#[test]
fn deep_node_chains_and_deep_json_load_or_are_refused_without_overflowing() -> TestResult {
    let dir = TempDir::new("deep")?;
    dir.write("t.bin", triangle_bytes())?;

    // 100,000 nodes, each the only child of the one before, each 1 mm above its parent; the
    // mesh is on the last. Loads (the walks are iterative), placed 100 m up.
    const DEPTH: usize = 100_000;
    let mut nodes = String::from("[");
    for i in 0..DEPTH {
        if i > 0 {
            nodes.push(',');
        }
        if i + 1 < DEPTH {
            nodes.push_str(&format!(
                r#"{{"children":[{}],"translation":[0,0.001,0]}}"#,
                i + 1
            ));
        } else {
            nodes.push_str(r#"{"mesh":0,"translation":[0,0.001,0]}"#);
        }
    }
    nodes.push(']');
    let path = dir.write("chain.gltf", gltf(36, &nodes, ""))?;
    let model = load_model_file(&path).map_err(|e| format!("a deep chain was refused: {e}"))?;
    assert_eq!(model.placements.len(), 1);
    let y = model.placements[0].model_from_mesh.w_axis.y;
    assert!((y - 100.0).abs() < 0.05, "placed at y = {y} m");
    // The animation loader walks the same chain.
    load_animation_file(&path).map_err(|e| format!("the animation loader refused it: {e}"))?;

    // JSON nested 100,000 arrays deep in a member the loaders do not read: skipped without
    // recursion (no stack overflow), so the file loads, empty; or is refused naming the file.
    let deep = format!(
        r#"{{"asset":{{"version":"2.0"}},"extras":{}{}}}"#,
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    let path = dir.write("nested.gltf", deep)?;
    match load_model_file(&path) {
        Ok(model) => assert!(model.meshes.is_empty(), "meshes from nothing"),
        Err(e) => assert!(e.to_string().contains("nested.gltf"), "{e}"),
    }
    if let Err(e) = load_animation_file(&path) {
        assert!(e.to_string().contains("nested.gltf"), "{e}");
    }
    // The same depth where the loader must read it (a node's `extras` is not read either, so
    // a node's translation): refused, naming the file.
    let deep_node = format!(
        r#"{{"asset":{{"version":"2.0"}},"nodes":[{{"translation":{}0{}}}]}}"#,
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    let path = dir.write("nested_node.gltf", deep_node)?;
    let e = refused(&path, &["nested_node.gltf"])?;
    assert!(matches!(e, AssetError::Gltf { .. }), "{e:?}");
    assert!(load_animation_file(&path).is_err());
    Ok(())
}

#[test]
fn cyclic_recursive_and_oversized_skins_are_refused() -> TestResult {
    let dir = TempDir::new("skins")?;
    dir.write("t.bin", triangle_bytes())?;
    let expect_refused = |name: &str, contents: String, words: &[&str]| -> TestResult {
        let path = dir.write(name, contents)?;
        match load_animation_file(&path) {
            Ok(_) => Err(format!("{name}: loaded").into()),
            Err(e) => {
                let text = e.to_string();
                for word in std::iter::once(&name).chain(words) {
                    if !text.contains(word) {
                        return Err(format!("{name}: {text:?} does not name {word:?}").into());
                    }
                }
                Ok(())
            }
        }
    };
    // Joints whose parents form a cycle (0 → 1 → 2 → 1).
    expect_refused(
        "cycle.gltf",
        gltf(
            36,
            r#"[{"mesh":0,"children":[1]},{"children":[2]},{"children":[1]}]"#,
            r#","skins":[{"joints":[1,2]}]"#,
        ),
        &["cycle"],
    )?;
    // A joint that is its own parent.
    expect_refused(
        "self_parent.gltf",
        gltf(
            36,
            r#"[{"mesh":0,"children":[1]},{"children":[1]}]"#,
            r#","skins":[{"joints":[1]}]"#,
        ),
        &[],
    )?;
    // 70,000 joints (the limit is 65535: joint indices are 16-bit).
    let joints = vec!["1"; 70_000].join(",");
    expect_refused(
        "many_joints.gltf",
        gltf(
            36,
            r#"[{"mesh":0,"children":[1]},{}]"#,
            &format!(r#","skins":[{{"joints":[{joints}]}}]"#),
        ),
        &["70000", "65535"],
    )?;
    // A joint index past the nodes.
    expect_refused(
        "far_joint.gltf",
        gltf(
            36,
            r#"[{"mesh":0}]"#,
            r#","skins":[{"joints":[4000000000]}]"#,
        ),
        &[],
    )?;
    // The control: the same skin over a valid tree loads.
    let path = dir.write(
        "ok.gltf",
        gltf(
            36,
            r#"[{"mesh":0,"children":[1]},{"children":[2]},{}]"#,
            r#","skins":[{"joints":[1,2]}]"#,
        ),
    )?;
    load_animation_file(&path).map_err(|e| format!("a valid skin was refused: {e}"))?;
    Ok(())
}
