//! TGA textures, which carry no magic number: the loader knows them by the file's extension
//! (content sniffing alone refused every TGA). A 2 × 2 uncompressed TGA named by an MTL loads
//! with its texels; the same bytes under a name without a known extension are still refused,
//! naming the file.

use candela::assets::{AssetError, load_model_file};
use half::f16;

/// A 2 × 2 uncompressed true-colour TGA (BGR, rows bottom-up): red, green / blue, white.
fn tga() -> Vec<u8> {
    let mut bytes = vec![0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0];
    // Bottom row first: blue, white; then the top row: red, green.
    for bgr in [[255, 0, 0], [255, 255, 255], [0, 0, 255], [0, 255, 0]] {
        bytes.extend_from_slice(&bgr);
    }
    bytes
}

const OBJ: &str =
    "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n";

fn dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("candela_tga_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp folder");
    dir
}

#[test]
fn a_tga_named_by_an_mtl_loads_with_its_texels() -> anyhow::Result<()> {
    let dir = dir("ok");
    std::fs::write(dir.join("tex.tga"), tga())?;
    std::fs::write(dir.join("m.mtl"), "newmtl m\nKd 1 1 1\nmap_Kd tex.tga\n")?;
    std::fs::write(dir.join("t.obj"), OBJ)?;
    let model = load_model_file(&dir.join("t.obj"))?;
    assert_eq!(model.textures.len(), 1);
    let t = &model.textures[0];
    assert_eq!((t.width, t.height), (2, 2));
    // Top-left texel red, top-right green (sRGB 255 → linear 1), alpha 1.
    let one = f16::from_f32(1.0);
    let zero = f16::from_f32(0.0);
    assert_eq!(t.texels[0], [one, zero, zero, one], "top-left");
    assert_eq!(t.texels[1], [zero, one, zero, one], "top-right");
    assert_eq!(t.texels[2], [zero, zero, one, one], "bottom-left");
    Ok(())
}

#[test]
fn the_same_bytes_without_a_known_extension_are_refused_naming_the_file() -> anyhow::Result<()> {
    let dir = dir("bad");
    std::fs::write(dir.join("tex.bin"), tga())?;
    std::fs::write(dir.join("m.mtl"), "newmtl m\nKd 1 1 1\nmap_Kd tex.bin\n")?;
    std::fs::write(dir.join("t.obj"), OBJ)?;
    match load_model_file(&dir.join("t.obj")) {
        Err(e @ AssetError::Texture { .. }) => {
            let message = e.to_string();
            assert!(message.contains("tex.bin"), "{message}");
            Ok(())
        }
        other => panic!("expected a texture error, got {other:?}"),
    }
}
