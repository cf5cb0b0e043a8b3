//! Physics in level files: bodies load, fall and land; bad body data is refused with a message
//! naming the level file and the instance; levels without bodies load as before.

mod physics_common;

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

/// Every level in the repository still loads (none has bodies yet).
#[test]
fn existing_levels_load_unchanged() -> Result<(), AssetError> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes");
    let root = AssetRoot::new(&assets)?;
    let mut loaded = 0;
    for level in ["script/small.ron", "cornell_box.ron", "demo/demo.ron"] {
        let scene = load_level(&assets.join(level), &root)?;
        assert!(scene.bodies.iter().all(Option::is_none));
        loaded += 1;
    }
    assert_eq!(loaded, 3);
    Ok(())
}
