//! Physics in level files: bodies load, fall and land; bad body data is refused with a message
//! naming the level file and the instance; levels without bodies load as before.

use crate::common;
use crate::physics_common;

use std::path::{Path, PathBuf};

use candela::assets::{AssetError, AssetRoot};
use candela::ecs::Transform;
use candela::level::{PlayableLevel, load_level};
use candela::sim::physics::{BodyKind, PhysicsWorld, SensorContacts};
use glam::Vec3;

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Self {
        let path = std::env::temp_dir().join(format!("candela_phys_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(path.join("root")).expect("temp dir");
        Dir(path)
    }
    fn root(&self) -> AssetRoot {
        AssetRoot::new(self.0.join("root")).expect("root")
    }
    fn level(&self, name: &str, instances: &str) -> PathBuf {
        let text = format!(
            r#"Level(
    materials: [(name: "grey", kind: Diffuse)],
    grids: [(name: "floor", size: (10, 10), divisions: (2, 2), material: "grey")],
    boxes: [(name: "crate", size: (0.6, 0.6, 0.6), material: "grey")],
    instances: [{instances}],
    camera: (position: (0, 2, 6), look_at: (0, 0, 0), vertical_fov_deg: 45),
)"#
        );
        let p = self.0.join(name);
        std::fs::write(&p, text).expect("write level");
        p
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const FLOOR: &str = r#"(model: "floor", body: Static(shape: Trimesh))"#;

/// Spawns the level's bodies as `Engine::spawn_level` does (transform + body + collider).
fn spawn(level: &PlayableLevel, world: &mut hecs::World) -> Vec<hecs::Entity> {
    level
        .scene
        .instances
        .iter()
        .zip(&level.bodies)
        .map(|(i, body)| {
            let e = world.spawn((Transform::from_matrix(i.world_from_model),));
            if let Some(b) = body {
                let _ = world.insert(e, (b.body, b.collider.clone()));
                if b.collider.sensor {
                    let _ = world.insert_one(e, SensorContacts::default());
                }
            }
            e
        })
        .collect()
}

#[test]
fn level_bodies_fall_and_land() -> Result<(), AssetError> {
    let dir = Dir::new("ok");
    let path = dir.level(
        "ok.ron",
        &format!(
            r#"{FLOOR},
            (model: "crate", name: "c", transform: (translation: (0, 2, 0)), body: Dynamic(shape: Box, mass: 20)),
            (model: "crate", transform: (translation: (2, 1, 0), scale: (1, 0.5, 1)), body: Dynamic(shape: ConvexHull)),
            (model: "crate", transform: (translation: (-2, 0.5, 0)), body: Sensor(shape: Cuboid(half_extents: (1, 0.5, 1))))"#
        ),
    );
    let scene = load_level(&path, &dir.root())?;
    let kinds: Vec<Option<BodyKind>> = scene
        .bodies
        .iter()
        .map(|b| b.as_ref().map(|b| b.body.kind))
        .collect();
    assert_eq!(
        kinds,
        [
            Some(BodyKind::Static),
            Some(BodyKind::Dynamic),
            Some(BodyKind::Dynamic),
            Some(BodyKind::Static)
        ]
    );
    assert!(
        scene.scene.instances[1].dynamic,
        "a dynamic body's instance moves"
    );
    assert!(!scene.scene.instances[0].dynamic);
    let mut world = hecs::World::new();
    let mut physics = PhysicsWorld::new();
    let entities = spawn(&scene, &mut world);
    for _ in 0..180 {
        physics.step(&mut world, physics_common::STEP_SECONDS);
    }
    let y = |e| {
        world
            .get::<&Transform>(e)
            .map(|t| t.translation.y)
            .unwrap_or(f32::NAN)
    };
    // The crate (0.6 m, from its bounding box) rests on the floor grid at y = 0; the squashed
    // hull (0.3 m tall) too. 1 cm: contact softness.
    assert!(
        (y(entities[1]) - 0.3).abs() < 0.01,
        "crate at {}",
        y(entities[1])
    );
    assert!(
        (y(entities[2]) - 0.15).abs() < 0.01,
        "hull at {}",
        y(entities[2])
    );
    // The scale stays on the Transform; physics writes translation and rotation only.
    let scale = world
        .get::<&Transform>(entities[2])
        .map(|t| t.scale)
        .unwrap_or(Vec3::ZERO);
    assert!((scale - Vec3::new(1.0, 0.5, 1.0)).length() < 1e-5);
    assert_eq!(
        physics.awake_bodies(),
        0,
        "everything settles and sleeps within 3 s"
    );
    Ok(())
}

fn refused(name: &str, instance: &str, expect: &[&str]) {
    let dir = Dir::new(name);
    let path = dir.level(&format!("{name}.ron"), &format!("{FLOOR}, {instance}"));
    let message = match load_level(&path, &dir.root()) {
        Ok(_) => panic!("{name}: should be refused"),
        Err(e) => e.to_string(),
    };
    println!("{name}: {message}");
    assert!(
        message.contains(&format!("{name}.ron")),
        "does not name the level: {message}"
    );
    for part in expect {
        assert!(message.contains(part), "{name}: {message:?} lacks {part:?}");
    }
}

#[test]
fn negative_mass_is_refused() {
    refused(
        "neg_mass",
        r#"(model: "crate", name: "heavy", body: Dynamic(shape: Box, mass: -2))"#,
        &["instance 1", "\"heavy\"", "mass", "-2"],
    );
}

#[test]
fn dynamic_trimesh_is_refused() {
    refused(
        "dyn_trimesh",
        r#"(model: "crate", body: Dynamic(shape: Trimesh))"#,
        &["instance 1", "\"crate\"", "Trimesh"],
    );
}

#[test]
fn zero_radius_is_refused() {
    refused(
        "zero_radius",
        r#"(model: "crate", name: "ball", body: Dynamic(shape: Sphere(radius: 0)))"#,
        &["instance 1", "\"ball\"", "radius"],
    );
}

#[test]
fn flat_hull_is_refused() {
    refused(
        "flat_hull",
        r#"(model: "floor", name: "sheet", body: Dynamic(shape: ConvexHull))"#,
        &["instance 1", "\"sheet\"", "convex hull"],
    );
}

#[test]
fn unknown_body_field_is_refused() {
    refused(
        "unknown_field",
        r#"(model: "crate", body: Dynamic(shape: Box, mas: 2))"#,
        &["mas"],
    );
}

#[test]
fn unknown_shape_is_refused() {
    refused(
        "unknown_shape",
        r#"(model: "crate", body: Static(shape: Cylinder))"#,
        &["Cylinder"],
    );
}

/// The asset root a repository level is loaded with: the reference scenes and the bench hall
/// name files in `shared/external` (their headers say which folder); the gameplay levels name
/// sounds under `assets/common/`; the third-person courtyard names its hero as
/// `common/hero/hero.glb` under `assets/`; the others are engine-made or name files under
/// `assets/test_scenes/`.
fn root_of(level: &Path, assets: &Path) -> PathBuf {
    let external = assets.join("../../shared/external");
    let relative = level.strip_prefix(assets).unwrap_or(level);
    if relative == Path::new("test_scenes/platform/third_person.ron")
        || relative == Path::new("test_scenes/wading/wading.ron")
    {
        return assets.to_path_buf();
    }
    match relative.parent().and_then(|p| p.to_str()) {
        Some("test_scenes/reference") => external
            .join("reference")
            .join(level.file_stem().unwrap_or_default()),
        Some("test_scenes/bench") => external.join("obj"),
        Some("test_scenes/gameplay") | Some("reflect") | Some("its_about_time") => {
            assets.to_path_buf()
        }
        _ => assets.join("test_scenes"),
    }
}

/// The top-level RON type of a file: the first identifier before `(` outside comments and
/// `#![...]` attributes (`""` for an anonymous struct, as `demo.ron` is written).
fn ron_type(text: &str) -> String {
    let code = text
        .lines()
        .map(str::trim_start)
        .find(|l| !l.is_empty() && !l.starts_with("//") && !l.starts_with("#!"))
        .unwrap_or("");
    code.split('(').next().unwrap_or("").trim().to_string()
}

/// Every level in the repository (every `.ron` under `assets/` that is not a capture script,
/// an authored clip set, a game file, or one of Reflect's chamber files — parts of one world,
/// loaded merged over their base by `games/reflect/tests/world.rs`) loads, and has exactly the bodies its text declares (one per
/// `body:` field): levels without bodies load as before, levels with bodies keep them all.
#[test]
fn existing_levels_load_unchanged() -> Result<(), AssetError> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets");
    let files = common::files_under(&assets, &["ron"]);
    let mut levels = Vec::new();
    for file in &files {
        if file.parent().is_some_and(|p| p.ends_with("reflect/levels")) {
            continue;
        }
        let text = std::fs::read_to_string(file).map_err(|e| AssetError::io(file, e))?;
        match ron_type(&text).as_str() {
            "Script" | "AuthoredClipSet" | "Reflect" => continue,
            "" | "Level" => {}
            other => panic!("{}: unknown RON type {other:?}", file.display()),
        }
        let root = AssetRoot::new(root_of(file, &assets))?;
        let scene = load_level(file, &root)?;
        let declared = text
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .map(|l| l.matches("body:").count())
            .sum::<usize>();
        let bodies = scene.bodies.iter().filter(|b| b.is_some()).count();
        println!(
            "{}: {} instances, {bodies} bodies",
            file.display(),
            scene.scene.instances.len()
        );
        assert!(
            !scene.scene.instances.is_empty(),
            "{}: no instances",
            file.display()
        );
        assert_eq!(
            bodies,
            declared,
            "{}: bodies loaded vs declared",
            file.display()
        );
        levels.push(file.clone());
    }
    // The walk found the levels the other tests name (it would otherwise check nothing).
    for named in [
        "test_scenes/script/small.ron",
        "test_scenes/cornell_box.ron",
        "test_scenes/demo/demo.ron",
        "test_scenes/gameplay/plate_door.ron",
        "test_scenes/reference/cornell_box.ron",
    ] {
        assert!(
            levels.iter().any(|l| l.ends_with(named)),
            "the walk of {} did not find {named}",
            assets.display()
        );
    }
    Ok(())
}
