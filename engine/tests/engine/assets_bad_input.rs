//! Bad input, one test per case: each asserts the [`AssetError`] variant and that the message
//! names the model file (and, where there is one, the file or element at fault).

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, AssetRoot, load_model, load_model_file};

type TestResult = Result<(), Box<dyn std::error::Error>>;

/// A fresh temporary folder for one test (removed when dropped).
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> Result<Self, std::io::Error> {
        let dir =
            std::env::temp_dir().join(format!("candela_assets_bad_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir)?;
        Ok(Self(dir))
    }

    fn write(&self, name: &str, contents: impl AsRef<[u8]>) -> Result<PathBuf, std::io::Error> {
        let path = self.0.join(name);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, contents)?;
        Ok(path)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Loads `path`, expecting an error whose message names every string in `names`.
fn expect_error(path: &Path, names: &[&str]) -> Result<AssetError, String> {
    match load_model_file(path) {
        Ok(_) => Err(format!("{} loaded", path.display())),
        Err(error) => {
            let message = error.to_string();
            for name in names {
                if !message.contains(name) {
                    return Err(format!("message {message:?} does not name {name:?}"));
                }
            }
            Ok(error)
        }
    }
}

const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";

/// A minimal glTF: one triangle (positions in `buffer_uri`), plus `extra` top-level members.
fn triangle_gltf(buffer_uri: &str, byte_length: usize, extra: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":{byte_length},"uri":"{buffer_uri}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],"scene":0{extra}}}"#
    )
}

fn triangle_bytes(first: f32) -> Vec<u8> {
    [first, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|f| f.to_le_bytes())
        .collect()
}

#[test]
fn missing_model_file() -> TestResult {
    let dir = TempDir::new("missing")?;
    let path = dir.0.join("nope.obj");
    assert!(matches!(
        expect_error(&path, &["nope.obj"])?,
        AssetError::NotFound { .. }
    ));
    let root = AssetRoot::new(&dir.0)?;
    match load_model(&root, Path::new("level.ron"), "models/nope.glb") {
        Err(error @ AssetError::NotFound { .. }) => assert!(error.to_string().contains("nope.glb")),
        other => panic!("expected NotFound, got {other:?}"),
    }
    Ok(())
}

#[test]
fn truncated_gltf_json() -> TestResult {
    let dir = TempDir::new("truncated")?;
    let full = triangle_gltf("t.bin", 36, "");
    let path = dir.write("truncated.gltf", &full[..full.len() / 2])?;
    dir.write("t.bin", triangle_bytes(0.0))?;
    let error = expect_error(&path, &["truncated.gltf", "JSON"])?;
    assert!(matches!(error, AssetError::Gltf { .. }), "{error:?}");
    Ok(())
}

#[test]
fn gltf_buffer_shorter_than_its_byte_length() -> TestResult {
    let dir = TempDir::new("buffer_length")?;
    let path = dir.write("short.gltf", triangle_gltf("short.bin", 100, ""))?;
    dir.write("short.bin", triangle_bytes(0.0))?;
    let error = expect_error(&path, &["short.gltf", "byteLength 100", "36 bytes"])?;
    assert!(matches!(error, AssetError::Gltf { .. }), "{error:?}");
    Ok(())
}

#[test]
fn glb_whose_length_field_is_below_its_header() -> TestResult {
    let dir = TempDir::new("glb_length")?;
    let mut bytes = b"glTF".to_vec();
    bytes.extend(2u32.to_le_bytes());
    bytes.extend(4u32.to_le_bytes());
    let path = dir.write("tiny.glb", bytes)?;
    assert!(matches!(
        expect_error(&path, &["tiny.glb", "length"])?,
        AssetError::Gltf { .. }
    ));
    Ok(())
}

#[test]
fn corrupt_png_in_gltf_and_obj() -> TestResult {
    let dir = TempDir::new("corrupt_png")?;
    dir.write("bad.png", b"\x89PNG\r\n\x1a\nthis is not a png at all")?;
    let gltf = triangle_gltf(
        "t.bin",
        36,
        r#","images":[{"uri":"bad.png"}],"textures":[{"source":0}],
        "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}]"#,
    );
    let gltf = gltf.replace(
        r#""attributes":{"POSITION":0}"#,
        r#""attributes":{"POSITION":0},"material":0"#,
    );
    dir.write("t.bin", triangle_bytes(0.0))?;
    let path = dir.write("textured.gltf", gltf)?;
    let error = expect_error(&path, &["textured.gltf", "bad.png"])?;
    assert!(matches!(error, AssetError::Texture { .. }), "{error:?}");

    dir.write("m.mtl", "newmtl m\nmap_Kd bad.png\n")?;
    let path = dir.write(
        "textured.obj",
        format!("mtllib m.mtl\n{TRIANGLE_OBJ}usemtl m\nf 1/1 2/2 3/3\n"),
    )?;
    let error = expect_error(&path, &["textured.obj", "bad.png"])?;
    assert!(matches!(error, AssetError::Texture { .. }), "{error:?}");
    Ok(())
}

#[test]
fn absurd_texture_size_is_refused_before_decoding() -> TestResult {
    let dir = TempDir::new("huge_png")?;
    // A PNG whose header claims 20000 × 20000 RGBA texels, with an empty image data chunk.
    let mut header = 20_000u32.to_be_bytes().to_vec();
    header.extend(20_000u32.to_be_bytes());
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
    dir.write("huge.png", png)?;
    dir.write("m.mtl", "newmtl m\nmap_Kd huge.png\n")?;
    let path = dir.write(
        "huge.obj",
        format!("mtllib m.mtl\n{TRIANGLE_OBJ}usemtl m\nf 1 2 3\n"),
    )?;
    let error = expect_error(&path, &["huge.obj", "huge.png", "20000"])?;
    assert!(matches!(error, AssetError::TooLarge { .. }), "{error:?}");
    Ok(())
}

#[test]
fn nan_positions_in_obj_and_gltf() -> TestResult {
    let dir = TempDir::new("nan")?;
    let path = dir.write("nan.obj", "o thing\nv 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")?;
    let error = expect_error(&path, &["nan.obj", "thing", "vertex 1", "non-finite"])?;
    assert!(matches!(error, AssetError::BadMesh { .. }), "{error:?}");

    dir.write("nan.bin", triangle_bytes(f32::NAN))?;
    let path = dir.write("nan.gltf", triangle_gltf("nan.bin", 36, ""))?;
    let error = expect_error(&path, &["nan.gltf", "vertex 0", "non-finite"])?;
    assert!(matches!(error, AssetError::BadMesh { .. }), "{error:?}");
    Ok(())
}

#[test]
fn out_of_range_indices_in_obj_and_gltf() -> TestResult {
    let dir = TempDir::new("indices")?;
    let path = dir.write("far.obj", format!("{TRIANGLE_OBJ}f 1 2 9\n"))?;
    let error = expect_error(&path, &["far.obj", "line 7", "index 9"])?;
    assert!(matches!(error, AssetError::Obj { .. }), "{error:?}");

    let mut bytes = triangle_bytes(0.0);
    bytes.extend([0u16, 1, 99, 0].iter().flat_map(|i| i.to_le_bytes()));
    dir.write("far.bin", bytes)?;
    let gltf = triangle_gltf("far.bin", 44, "")
        .replace(r#""bufferViews":[{"buffer":0,"byteLength":36}]"#, r#""bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}]"#)
        .replace(r#""max":[1,1,0]}]"#, r#""max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]"#)
        .replace(r#""attributes":{"POSITION":0}"#, r#""attributes":{"POSITION":0},"indices":1"#);
    let path = dir.write("far.gltf", gltf)?;
    let error = expect_error(&path, &["far.gltf", "index 99"])?;
    assert!(matches!(error, AssetError::BadMesh { .. }), "{error:?}");
    Ok(())
}

#[test]
fn paths_that_leave_the_asset_root() -> TestResult {
    let dir = TempDir::new("outside")?;
    // The targets exist, so only the root confinement can refuse them.
    dir.write("outside.png", b"\x89PNG")?;
    dir.write("x.mtl", "newmtl m\nKd 1 1 1\n")?;
    dir.write("inner/t.bin", triangle_bytes(0.0))?;
    let gltf = triangle_gltf(
        "t.bin",
        36,
        r#","images":[{"uri":"../outside.png"}],"textures":[{"source":0}],
        "materials":[{"emissiveTexture":{"index":0}}]"#,
    );
    let path = dir.write("inner/image.gltf", gltf)?;
    let error = expect_error(&path, &["image.gltf", "../outside.png"])?;
    assert!(matches!(error, AssetError::OutsideRoot { .. }), "{error:?}");

    let path = dir.write(
        "inner/mtllib.obj",
        format!("mtllib ../x.mtl\n{TRIANGLE_OBJ}f 1 2 3\n"),
    )?;
    let error = expect_error(&path, &["mtllib.obj", "../x.mtl"])?;
    assert!(matches!(error, AssetError::OutsideRoot { .. }), "{error:?}");

    let path = dir.write(
        "inner/buffer.gltf",
        triangle_gltf("../inner/../../x.bin", 36, ""),
    )?;
    let error = expect_error(&path, &["buffer.gltf", "x.bin"])?;
    assert!(matches!(error, AssetError::OutsideRoot { .. }), "{error:?}");

    // Through an asset root: the model may not leave it either.
    let root = AssetRoot::new(dir.0.join("inner"))?;
    match load_model(&root, Path::new("level.ron"), "../x.mtl") {
        Err(AssetError::OutsideRoot { requested, .. }) => assert_eq!(requested, "../x.mtl"),
        other => panic!("expected OutsideRoot, got {other:?}"),
    }
    Ok(())
}

#[test]
fn missing_mtl_and_missing_texture() -> TestResult {
    let dir = TempDir::new("missing_refs")?;
    let path = dir.write(
        "no_mtl.obj",
        format!("mtllib gone.mtl\n{TRIANGLE_OBJ}f 1 2 3\n"),
    )?;
    let error = expect_error(&path, &["no_mtl.obj", "gone.mtl"])?;
    assert!(matches!(error, AssetError::MissingFile { .. }), "{error:?}");

    dir.write("m.mtl", "newmtl m\nmap_Kd gone.png\n")?;
    let path = dir.write(
        "no_texture.obj",
        format!("mtllib m.mtl\n{TRIANGLE_OBJ}usemtl m\nf 1 2 3\n"),
    )?;
    let error = expect_error(&path, &["no_texture.obj", "gone.png"])?;
    assert!(matches!(error, AssetError::MissingFile { .. }), "{error:?}");

    let path = dir.write("no_bin.gltf", triangle_gltf("gone.bin", 36, ""))?;
    let error = expect_error(&path, &["no_bin.gltf", "gone.bin"])?;
    assert!(matches!(error, AssetError::MissingFile { .. }), "{error:?}");
    Ok(())
}

#[test]
fn node_loops_huge_counts_and_unsupported_extensions() -> TestResult {
    let dir = TempDir::new("structure")?;
    dir.write("t.bin", triangle_bytes(0.0))?;
    let looped = triangle_gltf("t.bin", 36, "").replace(
        r#""nodes":[{"mesh":0}]"#,
        r#""nodes":[{"mesh":0,"children":[1]},{"children":[0]}]"#,
    );
    let path = dir.write("loop.gltf", looped)?;
    let error = expect_error(&path, &["loop.gltf", "own ancestor"])?;
    assert!(matches!(error, AssetError::Gltf { .. }), "{error:?}");

    // A sparse accessor without a buffer view declaring a billion zeros.
    let huge = triangle_gltf("t.bin", 36, "").replace(
        r#""max":[1,1,0]}]"#,
        r#""max":[1,1,0]},{"componentType":5126,"count":1000000000,"type":"VEC3","min":[0,0,0],"max":[0,0,0],
           "sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}]"#,
    )
    .replace(r#""attributes":{"POSITION":0}"#, r#""attributes":{"POSITION":1}"#);
    let path = dir.write("huge.gltf", huge)?;
    let error = expect_error(&path, &["huge.gltf", "1000000000"])?;
    assert!(matches!(error, AssetError::TooLarge { .. }), "{error:?}");

    let draco = triangle_gltf(
        "t.bin",
        36,
        r#","extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"]"#,
    );
    let path = dir.write("draco.gltf", draco)?;
    let error = expect_error(&path, &["draco.gltf", "KHR_draco_mesh_compression"])?;
    assert!(matches!(error, AssetError::Unsupported { .. }), "{error:?}");

    let path = dir.write("model.fbx", "Kaydara FBX Binary")?;
    assert!(matches!(
        expect_error(&path, &["model.fbx"])?,
        AssetError::Unsupported { .. }
    ));
    Ok(())
}

/// CRC-32 (IEEE), as PNG chunks use.
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
