//! Bad levels: every problem is a typed `AssetError` whose message names the level file (and the
//! item at fault); nothing panics. One test per case.

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, AssetRoot};
use candela::level::load_level;

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Self {
        let path =
            std::env::temp_dir().join(format!("candela_level_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(path.join("root/models")).expect("temp dir");
        Dir(path)
    }
    fn root(&self) -> AssetRoot {
        AssetRoot::new(self.0.join("root")).expect("root")
    }
    fn write(&self, rel: &str, text: &str) -> PathBuf {
        let p = self.0.join(rel);
        std::fs::write(&p, text).expect("write");
        p
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

fn level(models: &str, instances: &str, extra: &str) -> String {
    format!(
        "Level(models: [{models}], instances: [{instances}], \
         camera: (position: (0, 0, 3), look_at: (0, 0, 0), vertical_fov_deg: 40), {extra})"
    )
}

fn error_of(level_path: &Path, root: &AssetRoot) -> AssetError {
    match load_level(level_path, root) {
        Ok(_) => panic!("{} should be refused", level_path.display()),
        Err(e) => {
            let text = e.to_string();
            let name = level_path
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or_default();
            assert!(
                text.contains(name),
                "message does not name the level: {text}"
            );
            e
        }
    }
}

#[test]
fn model_path_that_leaves_the_asset_root() {
    let d = Dir::new("outside");
    d.write("outside.obj", TRIANGLE_OBJ);
    let path = d.write(
        "root/escape.ron",
        &level(
            r#"(name: "m", path: "../outside.obj")"#,
            r#"(model: "m")"#,
            "",
        ),
    );
    match error_of(&path, &d.root()) {
        AssetError::InLevel { source, .. } => match *source {
            AssetError::OutsideRoot { requested, .. } => assert_eq!(requested, "../outside.obj"),
            other => panic!("expected OutsideRoot, got {other}"),
        },
        other => panic!("expected InLevel(OutsideRoot), got {other}"),
    }
}

#[test]
fn unknown_ron_field() {
    let d = Dir::new("unknown_field");
    let path = d.write(
        "root/typo.ron",
        &level("", "", "sky: Constant((0, 0, 0)), bounces: 3"),
    );
    match error_of(&path, &d.root()) {
        AssetError::Level { message, .. } => assert!(message.contains("bounces"), "{message}"),
        other => panic!("expected a level error, got {other}"),
    }
}

#[test]
fn malformed_ron() {
    let d = Dir::new("malformed");
    let path = d.write("root/broken.ron", "Level(models: [(name: \"m\", path: ");
    assert!(matches!(
        error_of(&path, &d.root()),
        AssetError::Level { .. }
    ));
}

#[test]
fn missing_level_file() {
    let d = Dir::new("missing");
    let path = d.0.join("root/nothing.ron");
    assert!(matches!(
        error_of(&path, &d.root()),
        AssetError::NotFound { .. }
    ));
}

#[test]
fn missing_model_file_names_the_model() {
    let d = Dir::new("missing_model");
    let path = d.write(
        "root/level.ron",
        &level(
            r#"(name: "m", path: "models/gone.obj")"#,
            r#"(model: "m")"#,
            "",
        ),
    );
    let text = error_of(&path, &d.root()).to_string();
    assert!(text.contains("gone.obj"), "{text}");
}

#[test]
fn instance_of_an_undefined_model() {
    let d = Dir::new("undefined_model");
    d.write("root/models/t.obj", TRIANGLE_OBJ);
    let path = d.write(
        "root/level.ron",
        &level(
            r#"(name: "t", path: "models/t.obj")"#,
            r#"(model: "teapot")"#,
            "",
        ),
    );
    let text = error_of(&path, &d.root()).to_string();
    assert!(text.contains("teapot"), "{text}");
}

#[test]
fn instance_with_an_undefined_material() {
    let d = Dir::new("undefined_material");
    d.write("root/models/t.obj", TRIANGLE_OBJ);
    let path = d.write(
        "root/level.ron",
        &level(
            r#"(name: "t", path: "models/t.obj")"#,
            r#"(model: "t", material: Some("gold"))"#,
            "",
        ),
    );
    let text = error_of(&path, &d.root()).to_string();
    assert!(text.contains("gold"), "{text}");
}

#[test]
fn degenerate_transform_and_camera() {
    let d = Dir::new("degenerate");
    d.write("root/models/t.obj", TRIANGLE_OBJ);
    let flat = d.write(
        "root/flat.ron",
        &level(
            r#"(name: "t", path: "models/t.obj")"#,
            r#"(model: "t", transform: (scale: (1, 0, 1)))"#,
            "",
        ),
    );
    assert!(error_of(&flat, &d.root()).to_string().contains("transform"));
    let fov = d.write(
        "root/fov.ron",
        "Level(camera: (position: (0, 0, 3), look_at: (0, 0, 0), vertical_fov_deg: 0))",
    );
    assert!(
        error_of(&fov, &d.root())
            .to_string()
            .contains("vertical_fov_deg")
    );
}

#[test]
fn a_valid_level_loads() {
    let d = Dir::new("valid");
    d.write("root/models/t.obj", TRIANGLE_OBJ);
    let path = d.write(
        "root/ok.ron",
        &level(
            r#"(name: "t", path: "models/t.obj")"#,
            r#"(model: "t"), (model: "t", transform: (translation: (2, 0, 0)))"#,
            "",
        ),
    );
    let desc = load_level(&path, &d.root()).expect("loads").scene;
    assert_eq!(desc.instances.len(), 2);
    assert_eq!(desc.models[0].meshes[0].triangles.len(), 1);
}
