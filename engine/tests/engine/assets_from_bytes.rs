//! Loading from memory (`load_model_bytes`, `load_animation_bytes`, what the fuzz targets use)
//! runs the same loaders as loading from a file: real assets give identical models either way,
//! and errors still name the model file and the problem.

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, MemoryFiles, Model, load_model_bytes, load_model_file};
use candela::sim::animation::{load_animation_bytes, load_animation_file};

type TestResult = Result<(), Box<dyn std::error::Error>>;

use super::common::external;

/// Every file below `folder`, keyed by its path relative to `folder`.
fn folder_files(folder: &Path) -> Result<MemoryFiles, std::io::Error> {
    let mut files = MemoryFiles::new();
    let mut pending = vec![folder.to_path_buf()];
    while let Some(dir) = pending.pop() {
        for entry in std::fs::read_dir(&dir)? {
            let path = entry?.path();
            if path.is_dir() {
                pending.push(path);
            } else if let Ok(relative) = path.strip_prefix(folder) {
                files.insert(&relative.to_string_lossy(), std::fs::read(&path)?);
            }
        }
    }
    Ok(files)
}

/// Loads `path` from its file and from memory (its folder's files in a [`MemoryFiles`], the
/// model named by its canonical path) and returns both.
fn both_ways(path: &Path) -> Result<(Model, Model), Box<dyn std::error::Error>> {
    let from_file = load_model_file(path)?;
    let canonical = path.canonicalize()?;
    let folder = canonical.parent().ok_or("no folder")?;
    let bytes = std::fs::read(&canonical)?;
    let mut from_bytes = load_model_bytes(&canonical, &bytes, &folder_files(folder)?)?;
    assert_eq!(from_bytes.name, canonical.display().to_string());
    from_bytes.name = from_file.name.clone();
    Ok((from_file, from_bytes))
}

/// `Model` has no `PartialEq` (meshes hold floats that may be NaN in principle): compare
/// everything through `Debug`, which prints every field and texel.
fn assert_same(path: &Path, from_file: &Model, from_bytes: &Model) {
    assert!(
        format!("{from_file:?}") == format!("{from_bytes:?}"),
        "{}: the model loaded from memory differs from the one loaded from its file",
        path.display()
    );
}

#[test]
fn gltf_with_external_buffer_and_texture_loads_the_same_from_bytes() -> TestResult {
    let path = external("gltf/BoxTextured/glTF/BoxTextured.gltf");
    let (from_file, from_bytes) = both_ways(&path)?;
    assert!(!from_file.meshes.is_empty() && !from_file.textures.is_empty());
    assert_same(&path, &from_file, &from_bytes);
    Ok(())
}

#[test]
fn glb_loads_the_same_from_bytes() -> TestResult {
    let path = external("gltf/BoxTextured/glTF-Binary/BoxTextured.glb");
    let (from_file, from_bytes) = both_ways(&path)?;
    assert!(!from_file.textures.is_empty());
    assert_same(&path, &from_file, &from_bytes);
    Ok(())
}

#[test]
fn obj_with_its_mtl_loads_the_same_from_bytes() -> TestResult {
    for path in [
        external("obj/mcguire_cornell_box/CornellBox-Glossy.obj"),
        PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../assets/test_scenes/cornell/candela_cornell.obj"
        )),
    ] {
        let (from_file, from_bytes) = both_ways(&path)?;
        assert!(from_file.materials.len() > 1, "{}", path.display());
        assert_same(&path, &from_file, &from_bytes);
    }
    Ok(())
}

/// An OBJ whose MTL lies in a subfolder and names its texture relative to that subfolder.
#[test]
fn obj_mtl_and_texture_in_folders_load_the_same_from_bytes() -> TestResult {
    let dir = std::env::temp_dir().join(format!("candela_from_bytes_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("mats"))?;
    std::fs::create_dir_all(dir.join("textures"))?;
    std::fs::copy(
        external("gltf/BoxTextured/glTF/CesiumLogoFlat.png"),
        dir.join("textures/logo.png"),
    )?;
    std::fs::write(
        dir.join("mats/box.mtl"),
        "newmtl logo\nKd 1 1 1\nmap_Kd ../textures/logo.png\n",
    )?;
    std::fs::write(
        dir.join("quad.obj"),
        "mtllib mats/box.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
         usemtl logo\nf 1/1 2/2 3/3 4/4\n",
    )?;
    let path = dir.join("quad.obj");
    let (from_file, from_bytes) = both_ways(&path)?;
    assert_eq!(from_file.textures.len(), 1);
    assert_same(&path, &from_file, &from_bytes);
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}

#[test]
fn animation_loads_the_same_from_bytes() -> TestResult {
    for path in [
        external("gltf/SimpleSkin/glTF/SimpleSkin.gltf"),
        external("gltf/CesiumMan/glTF-Binary/CesiumMan.glb"),
    ] {
        let from_file = load_animation_file(&path)?;
        let canonical = path.canonicalize()?;
        let files = folder_files(canonical.parent().ok_or("no folder")?)?;
        let from_bytes = load_animation_bytes(&canonical, &std::fs::read(&canonical)?, &files)?;
        assert!(!from_file.clips.is_empty(), "{}", path.display());
        assert!(from_file == from_bytes, "{}", path.display());
    }
    Ok(())
}

#[test]
fn errors_from_bytes_name_the_model_and_the_problem() {
    let name = Path::new("art/crate.obj");
    let obj = b"mtllib crate.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    match load_model_bytes(name, obj, &MemoryFiles::new()) {
        Err(e @ AssetError::MissingFile { .. }) => {
            let message = e.to_string();
            assert!(
                message.contains("art/crate.obj") && message.contains("art/crate.mtl"),
                "{message}"
            );
        }
        other => panic!("expected MissingFile, got {other:?}"),
    }
    let escaping = b"mtllib ../secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let files = MemoryFiles::new().with("secret.mtl", &b"newmtl m\n"[..]);
    match load_model_bytes(name, escaping, &files) {
        Err(AssetError::OutsideRoot {
            path, requested, ..
        }) => {
            assert_eq!(
                (path.as_path(), requested.as_str()),
                (name, "../secret.mtl")
            );
        }
        other => panic!("expected OutsideRoot, got {other:?}"),
    }
    match load_model_bytes(
        Path::new("art/crate.gltf"),
        b"{ not json",
        &MemoryFiles::new(),
    ) {
        Err(e @ AssetError::Gltf { .. }) => {
            assert!(
                e.to_string().starts_with("art/crate.gltf: malformed glTF"),
                "{e}"
            );
        }
        other => panic!("expected a glTF error, got {other:?}"),
    }
}
