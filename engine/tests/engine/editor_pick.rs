//! Picking in the editor (issue 12): the ray from the camera through a pixel hits the level
//! instance drawn there, in a small level spawned in a headless engine (CPU tracer): two
//! cubes in front of a wall over a floor. The pixel of each cube's centre picks that cube
//! (at its front face), a pixel of the sky picks nothing, and an entity left out of the
//! instance list is seen through.

use crate::editor_common;

use candela::app::{Engine, Environment, Step};
use candela::assets::{AssetRoot, CameraDesc};
use candela::editor::{SelectMode, Selection, pick, pixel_ray};
use candela::level::load_level;
use candela::render::RenderConfig;
use editor_common::Scratch;
use glam::Vec3;

const LEVEL: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse)],
    boxes: [
        (name: "floor", size: (20, 0.2, 20), material: "grey"),
        (name: "cube", size: (1, 1, 1), material: "grey"),
        (name: "wall", size: (20, 3, 0.2), material: "grey"),
    ],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "cube", name: "left", transform: (translation: (-1.5, 1, 0))),
        (model: "cube", name: "right", transform: (translation: (1.5, 1, 0))),
        (model: "wall", name: "wall", transform: (translation: (0, 1.5, -3))),
    ],
    camera: (position: (0, 1, 5), look_at: (0, 1, 0), vertical_fov_deg: 50),
    sky: Constant((0.2, 0.2, 0.2)),
)"#;

const W: u32 = 64;
const H: u32 = 48;

/// Where world point `p` appears in the `W` × `H` view (pixels, `y` down): the inverse of
/// the camera mapping `pixel_ray` uses.
fn project(camera: &CameraDesc, p: Vec3) -> (f32, f32) {
    let position = Vec3::from(camera.position);
    let forward = (Vec3::from(camera.look_at) - position).normalize();
    let right = forward.cross(Vec3::from(camera.up)).normalize();
    let up = right.cross(forward);
    let tan_half = (camera.vertical_fov_deg.to_radians() * 0.5).tan();
    let d = p - position;
    let sx = d.dot(right) / d.dot(forward) / (tan_half * W as f32 / H as f32);
    let sy = d.dot(up) / d.dot(forward) / tan_half;
    ((sx + 1.0) * 0.5 * W as f32, (1.0 - sy) * 0.5 * H as f32)
}

#[test]
fn a_click_picks_the_instance_under_the_pixel() -> anyhow::Result<()> {
    let scratch = Scratch::new("pick");
    let path = scratch.path().join("pick.ron");
    std::fs::write(&path, LEVEL)?;
    let level = load_level(&path, &AssetRoot::new(scratch.path())?)?;
    let camera = level.scene.camera;
    let mut engine = Engine::new(RenderConfig::cpu(W, H), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = engine.rendered();
    let queries = engine.queries();
    let entities = &spawned.entities;
    let at = |p: Vec3| {
        let (x, y) = project(&camera, p);
        pick(&queries, entities, &pixel_ray(&camera, W, H, x, y))
    };
    let left = at(Vec3::new(-1.5, 1.0, 0.0)).expect("the left cube");
    assert_eq!(left.instance, 1);
    // Its front face is at z = 0.5; the ray's direction is unit, so distance is metres.
    assert!((left.position.z - 0.5).abs() < 1e-3, "{left:?}");
    let expected = (left.position - Vec3::from(camera.position)).length();
    assert!((left.distance - expected).abs() < 1e-3, "{left:?}");
    assert_eq!(at(Vec3::new(1.5, 1.0, 0.0)).map(|p| p.instance), Some(2));
    assert_eq!(at(Vec3::new(0.0, 2.0, -3.0)).map(|p| p.instance), Some(3));
    assert_eq!(at(Vec3::new(0.0, 0.0, 2.0)).map(|p| p.instance), Some(0));
    // Above the wall: the sky.
    assert_eq!(
        pick(&queries, entities, &pixel_ray(&camera, W, H, 32.0, 0.5)),
        None
    );
    // An entity that is not a level instance is seen through: the wall behind the cube.
    let mut without_left = entities.clone();
    without_left[1] = hecs::Entity::DANGLING;
    let (x, y) = project(&camera, Vec3::new(-1.5, 1.0, 0.0));
    let through = pick(&queries, &without_left, &pixel_ray(&camera, W, H, x, y));
    assert_eq!(through.map(|p| p.instance), Some(3));
    // Clicks with Shift add to the selection.
    let mut selection = Selection::default();
    selection.click(Some(left.instance), SelectMode::Replace);
    selection.click(
        at(Vec3::new(1.5, 1.0, 0.0)).map(|p| p.instance),
        SelectMode::Add,
    );
    assert_eq!(selection.instances(), &[1, 2]);
    Ok(())
}

#[test]
fn the_pixel_ray_follows_the_renderers_camera_mapping() {
    let camera = CameraDesc {
        position: [1.0, 2.0, 3.0],
        look_at: [1.0, 2.0, 0.0],
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: 90.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    // The view's centre looks along the camera's forward axis.
    let centre = pixel_ray(&camera, 200, 100, 100.0, 50.0);
    assert!((centre.direction - Vec3::NEG_Z).length() < 1e-6);
    assert_eq!(centre.origin, Vec3::new(1.0, 2.0, 3.0));
    // The top edge's centre is 45° up (vertical FOV 90°), the right edge's centre at
    // atan(tan 45° · aspect 2) to the right.
    let top = pixel_ray(&camera, 200, 100, 100.0, 0.0);
    assert!((top.direction - Vec3::new(0.0, 1.0, -1.0).normalize()).length() < 1e-6);
    let right = pixel_ray(&camera, 200, 100, 200.0, 50.0);
    assert!((right.direction - Vec3::new(2.0, 0.0, -1.0).normalize()).length() < 1e-6);
}
