//! Fault: a path that leaves the asset root, by every way a file can write one. Each case is
//! a model inside the root naming a target that exists *outside* it (so only the confinement
//! can refuse it): `..`, an absolute path, a symbolic link (to a file and to a folder), and
//! the same through a glTF buffer URI, a glTF image URI (plain and percent-encoded), an OBJ's
//! `mtllib` and an MTL's `map_Kd`. Every refusal must name the file that wrote the path and
//! the path; none may read the outside file. A negative control loads the same files with the
//! targets moved inside, so a confinement that refused everything would fail too.

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, AssetRoot, load_model};

type TestResult = Result<(), Box<dyn std::error::Error>>;

/// A fresh folder `<tmp>/candela_faults_root_<name>_<pid>` holding `root/` and `outside/`.
struct Place(PathBuf);

impl Place {
    fn new(name: &str) -> std::io::Result<Self> {
        let dir =
            std::env::temp_dir().join(format!("candela_faults_root_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("root"))?;
        std::fs::create_dir_all(dir.join("outside"))?;
        Ok(Self(dir))
    }

    fn write(&self, name: &str, contents: impl AsRef<[u8]>) -> std::io::Result<PathBuf> {
        let path = self.0.join(name);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, contents)?;
        Ok(path)
    }

    fn root(&self) -> Result<AssetRoot, AssetError> {
        AssetRoot::new(self.0.join("root"))
    }
}

impl Drop for Place {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

fn triangle_bytes() -> Vec<u8> {
    [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|f| f.to_le_bytes())
        .collect()
}

/// One triangle whose positions come from `buffer_uri`, with an emissive texture from
/// `image_uri` when given.
fn gltf(buffer_uri: &str, image_uri: Option<&str>) -> String {
    let image = image_uri
        .map(|uri| {
            format!(
                r#","images":[{{"uri":"{uri}"}}],"textures":[{{"source":0}}],
                "materials":[{{"emissiveTexture":{{"index":0}}}}]"#
            )
        })
        .unwrap_or_default();
    let material = if image_uri.is_some() {
        r#","material":0"#
    } else {
        ""
    };
    format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":36,"uri":"{buffer_uri}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}{material}}}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],"scene":0{image}}}"#
    )
}

/// A 1 × 1 RGBA PNG.
fn tiny_png() -> Vec<u8> {
    let mut bytes = Vec::new();
    let encoder = image::codecs::png::PngEncoder::new(&mut bytes);
    image::ImageEncoder::write_image(
        encoder,
        &[255, 0, 0, 255],
        1,
        1,
        image::ColorType::Rgba8.into(),
    )
    .map(|()| bytes)
    .unwrap_or_default()
}

/// Loads `model` (relative to the root) and expects a refusal whose message names
/// `referrer_name` (the file that wrote the path) and every string in `names`.
fn refused(
    root: &AssetRoot,
    model: &str,
    referrer_name: &str,
    names: &[&str],
) -> Result<AssetError, String> {
    match load_model(root, Path::new("level.ron"), model) {
        Ok(_) => Err(format!(
            "{model}: loaded, but it reaches outside the asset root"
        )),
        Err(e) => {
            let text = e.to_string();
            for name in std::iter::once(&referrer_name).chain(names) {
                if !text.contains(name) {
                    return Err(format!("{model}: message {text:?} does not name {name:?}"));
                }
            }
            Ok(e)
        }
    }
}

fn is_outside(e: &AssetError) -> bool {
    matches!(e, AssetError::OutsideRoot { .. })
}

#[test]
fn every_way_out_of_the_asset_root_is_refused_and_named() -> TestResult {
    let p = Place::new("escape")?;
    let outside = p.0.join("outside");
    let outside_abs = outside.canonicalize()?;
    p.write("outside/t.bin", triangle_bytes())?;
    p.write("outside/t.png", tiny_png())?;
    p.write("outside/m.mtl", "newmtl m\nKd 1 1 1\n")?;
    p.write("outside/o.obj", TRIANGLE_OBJ)?;
    std::os::unix::fs::symlink(outside_abs.join("t.bin"), p.0.join("root/link.bin"))?;
    std::os::unix::fs::symlink(outside_abs.join("o.obj"), p.0.join("root/link.obj"))?;
    std::os::unix::fs::symlink(&outside_abs, p.0.join("root/linkdir"))?;
    let root = p.root()?;

    // The model itself, as a level names it.
    for (model, what) in [
        ("../outside/o.obj", "../outside/o.obj"),
        ("sub/../../outside/o.obj", "../outside/o.obj"),
        ("link.obj", "link.obj"),
        ("linkdir/o.obj", "linkdir/o.obj"),
    ] {
        let e = refused(&root, model, "level.ron", &[what, "leaves the asset root"])?;
        assert!(is_outside(&e), "{model}: {e:?}");
    }
    let absolute = outside_abs.join("o.obj").display().to_string();
    let e = refused(
        &root,
        &absolute,
        "level.ron",
        &[&absolute, "leaves the asset root"],
    )?;
    assert!(is_outside(&e), "{e:?}");

    // glTF buffer URIs: `..`, percent-encoded `..`, absolute, a symlink, a file: URI.
    let abs_bin = outside_abs.join("t.bin").display().to_string();
    let cases: Vec<(&str, String, &str)> = vec![
        ("dotdot.gltf", "../outside/t.bin".into(), "../outside/t.bin"),
        (
            "encoded.gltf",
            "%2E%2E/outside/t.bin".into(),
            "../outside/t.bin",
        ),
        ("absolute.gltf", abs_bin.clone(), &abs_bin),
        ("symlink.gltf", "link.bin".into(), "link.bin"),
        ("symlinkdir.gltf", "linkdir/t.bin".into(), "linkdir/t.bin"),
    ];
    for (name, uri, what) in &cases {
        p.write(&format!("root/{name}"), gltf(uri, None))?;
        let e = refused(&root, name, name, &[what, "leaves the asset root"])?;
        assert!(is_outside(&e), "{name}: {e:?}");
    }
    p.write("root/scheme.gltf", gltf(&format!("file://{abs_bin}"), None))?;
    let e = refused(
        &root,
        "scheme.gltf",
        "scheme.gltf",
        &["\"file\"", "not supported"],
    )?;
    assert!(matches!(e, AssetError::Gltf { .. }), "{e:?}");

    // glTF image URIs (the buffer itself is inside).
    p.write("root/t.bin", triangle_bytes())?;
    let abs_png = outside_abs.join("t.png").display().to_string();
    for (name, uri, what) in [
        ("image_dotdot.gltf", "../outside/t.png", "../outside/t.png"),
        (
            "image_encoded.gltf",
            "..%2Foutside%2Ft.png",
            "../outside/t.png",
        ),
        ("image_absolute.gltf", abs_png.as_str(), abs_png.as_str()),
        ("image_symlinkdir.gltf", "linkdir/t.png", "linkdir/t.png"),
    ] {
        p.write(&format!("root/{name}"), gltf("t.bin", Some(uri)))?;
        let e = refused(&root, name, name, &[what, "leaves the asset root"])?;
        assert!(is_outside(&e), "{name}: {e:?}");
    }

    // OBJ: mtllib by `..` and through a symlinked folder; MTL: an absolute texture path.
    p.write(
        "root/mtl_dotdot.obj",
        format!("mtllib ../outside/m.mtl\n{TRIANGLE_OBJ}"),
    )?;
    let e = refused(
        &root,
        "mtl_dotdot.obj",
        "mtl_dotdot.obj",
        &["../outside/m.mtl", "leaves the asset root"],
    )?;
    assert!(is_outside(&e), "{e:?}");
    p.write(
        "root/mtl_link.obj",
        format!("mtllib linkdir/m.mtl\n{TRIANGLE_OBJ}"),
    )?;
    let e = refused(
        &root,
        "mtl_link.obj",
        "mtl_link.obj",
        &["linkdir/m.mtl", "leaves the asset root"],
    )?;
    assert!(is_outside(&e), "{e:?}");
    p.write("root/abs_tex.mtl", format!("newmtl m\nmap_Kd {abs_png}\n"))?;
    p.write(
        "root/abs_tex.obj",
        "mtllib abs_tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n",
    )?;
    let e = refused(
        &root,
        "abs_tex.obj",
        "abs_tex.obj",
        &[&abs_png, "leaves the asset root"],
    )?;
    assert!(is_outside(&e), "{e:?}");

    // Negative control: the same references to files inside the root load.
    p.write("root/inner/t.bin", triangle_bytes())?;
    p.write("root/inner/t.png", tiny_png())?;
    p.write("root/inner/m.mtl", "newmtl m\nKd 1 1 1\n")?;
    p.write("root/inner/o.obj", TRIANGLE_OBJ)?;
    p.write("root/ok_buffer.gltf", gltf("inner/%74.bin", None))?;
    p.write(
        "root/ok_image.gltf",
        gltf("inner/../t.bin", Some("inner/t.png")),
    )?;
    p.write("root/ok.obj", format!("mtllib inner/m.mtl\n{TRIANGLE_OBJ}"))?;
    for model in [
        "inner/o.obj",
        "sub/../inner/o.obj",
        "ok_buffer.gltf",
        "ok_image.gltf",
        "ok.obj",
    ] {
        load_model(&root, Path::new("level.ron"), model)
            .map_err(|e| format!("{model}: a path inside the root was refused: {e}"))?;
    }
    Ok(())
}
