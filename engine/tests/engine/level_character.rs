//! Skinned characters declared in level files: the committed third-person courtyard loads
//! its hero (`assets/common/hero/hero.glb`) with the states' clips resolved, and `Engine::spawn_level` makes a capsule body
//! with the controller and the state machine plus a child entity drawing the skinned model,
//! which stands idle on the ground; bad data — a missing model file, a clip the model does not
//! have, bad numbers, a model that is not a single skinned mesh — fails at load time with a
//! message naming the level file, the character and the model file.

use std::path::{Path, PathBuf};

use candela::app::{Engine, Environment, Step};
use candela::assets::{AssetError, AssetRoot};
use candela::ecs::{GlobalTransform, Parent, Renderable};
use candela::level::{PlayableLevel, load_level};
use candela::render::RenderConfig;
use candela::sim::animation::{CharacterAnimation, SkinnedAnimator};
use candela::sim::physics::{CharacterController, CharacterState};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The folder holding the repository and `shared/` (the bad-data cases below read the glTF
/// samples from ../shared/external).
fn workspace_parent() -> PathBuf {
    repo().join("..")
}

/// The courtyard, with the repository's `assets/` folder as its asset root.
fn courtyard() -> anyhow::Result<PlayableLevel> {
    let level = repo().join("assets/test_scenes/platform/third_person.ron");
    Ok(load_level(&level, &AssetRoot::new(repo().join("assets"))?)?)
}

#[test]
fn the_courtyard_loads_its_hero_with_resolved_states() -> anyhow::Result<()> {
    let level = courtyard()?;
    assert_eq!(level.characters.len(), 1);
    let hero = &level.characters[0];
    assert_eq!(hero.name, "hero");
    let names: Vec<&str> = hero
        .machine
        .states()
        .iter()
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(names, ["jump", "fall", "idle", "walk", "run"]);
    let clip_of = |state: &str| {
        let s = hero.machine.states().iter().find(|s| s.name == state);
        s.map(|s| hero.animated.clips[s.clip].name.as_str())
    };
    for state in ["jump", "fall", "idle", "walk", "run"] {
        assert_eq!(
            clip_of(state),
            Some(state),
            "the hero's clips are named as the states"
        );
    }
    assert_eq!(hero.model_path, "common/hero/hero.glb");
    assert_eq!((hero.scale, hero.height, hero.radius), (1.0, 1.8, 0.3));
    assert_eq!(hero.animated.skins[0].joints.len(), 21);
    assert_eq!(hero.controller.walk_speed, 2.0);
    assert_eq!(hero.controller.run_speed, 5.0);
    assert_eq!(
        hero.controller.gravity,
        CharacterController::default().gravity,
        "an absent field keeps the default"
    );
    Ok(())
}

#[test]
fn spawning_makes_a_body_and_a_drawn_child_that_stand_idle() -> anyhow::Result<()> {
    let level = courtyard()?;
    let mut engine = Engine::new(RenderConfig::cpu(8, 8), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let hero = spawned.characters.get("hero").copied();
    let hero = hero.ok_or_else(|| anyhow::anyhow!("no hero spawned"))?;
    for _ in 0..30 {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let _ = engine.rendered();
    }
    let world = engine.world();
    assert_eq!(world.get::<&Parent>(hero.visual)?.0, hero.body);
    assert!(world.get::<&Renderable>(hero.visual).is_ok());
    assert!(world.get::<&SkinnedAnimator>(hero.visual).is_ok());
    let state = *world.get::<&CharacterState>(hero.body)?;
    assert!(state.grounded, "{state:?}");
    let anim = world.get::<&CharacterAnimation>(hero.body)?;
    assert_eq!(anim.state_name(), Some("idle"));
    // The body's centre is half the capsule above the spawn point; the model's feet are on
    // the ground (the child's origin), within the controller's skin and snapping.
    let (centre, _) = engine
        .physics()
        .pose(hero.body)
        .ok_or_else(|| anyhow::anyhow!("no body"))?;
    assert!(
        (centre - glam::Vec3::new(0.0, 0.9, 6.0)).length() < 0.05,
        "{centre}"
    );
    let feet = world
        .get::<&GlobalTransform>(hero.visual)?
        .0
        .w_axis
        .truncate();
    assert!(feet.y.abs() < 0.05 && (feet.z - 6.0).abs() < 0.05, "{feet}");
    drop(anim);
    let _ = engine.shutdown();
    Ok(())
}

/// A level in a temporary folder whose character is `character` (RON), with the glTF
/// samples as its asset root; returns the load result and the level's path.
fn load_with(name: &str, character: &str) -> (Result<PlayableLevel, AssetError>, PathBuf) {
    let dir =
        std::env::temp_dir().join(format!("candela_level_char_{name}_{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join("level.ron");
    let text = format!(
        "Level(camera: (position: (0, 1, 3), look_at: (0, 0, 0), vertical_fov_deg: 50),
         characters: [{character}])"
    );
    let written = std::fs::write(&path, text);
    assert!(written.is_ok(), "{written:?}");
    let gltf = workspace_parent().join("shared/external/gltf");
    let root = AssetRoot::new(&gltf).expect("the glTF samples");
    let result = load_level(&path, &root);
    let _ = std::fs::remove_dir_all(&dir);
    (result, path)
}

const FOX: &str = "Fox/glTF-Binary/Fox.glb";

fn fox(fields: &str, states: &str) -> String {
    format!("(name: \"hero\", model: \"{FOX}\", spawn: (0, 0, 0), {fields} states: [{states}])")
}

const IDLE: &str = "(name: \"idle\", clip: \"Survey\")";

fn error_of(name: &str, character: &str) -> (String, PathBuf) {
    match load_with(name, character) {
        (Err(e), path) => (e.to_string(), path),
        (Ok(_), _) => panic!("{name}: the level loaded"),
    }
}

#[test]
fn a_missing_model_is_an_error_naming_the_file() {
    let character = "(name: \"hero\", model: \"nowhere/Ghost.glb\", spawn: (0, 0, 0), states: [])";
    let (message, path) = error_of("missing", character);
    assert!(message.contains("nowhere/Ghost.glb"), "{message}");
    assert!(message.contains(&path.display().to_string()), "{message}");
    assert!(message.contains("\"hero\""), "{message}");
}

#[test]
fn a_clip_the_model_lacks_is_an_error_listing_its_clips() {
    let (message, _) = error_of("clip", &fox("", "(name: \"dance\", clip: \"Dance\")"));
    for part in ["\"dance\"", "\"Dance\"", FOX, "Survey", "Walk", "Run"] {
        assert!(message.contains(part), "{part} missing: {message}");
    }
}

#[test]
fn bad_numbers_are_errors_naming_the_field() {
    let cases = [
        ("scale", fox("scale: -1,", IDLE), "scale"),
        (
            "capsule",
            fox("capsule: (height: 0.5, radius: 0.4),", IDLE),
            "capsule.radius",
        ),
        (
            "walk",
            fox("controller: (walk_speed: 0),", IDLE),
            "controller.walk_speed",
        ),
        (
            "speeds",
            fox(
                "",
                "(name: \"idle\", clip: \"Survey\", min_speed_mps: 2, max_speed_mps: 1)",
            ),
            "max_speed_mps",
        ),
        ("states", fox("", ""), "at least one animation state"),
        (
            "hysteresis",
            fox("hysteresis_mps: -1,", IDLE),
            "hysteresis_mps",
        ),
    ];
    for (name, character, field) in cases {
        let (message, _) = error_of(name, &character);
        assert!(message.contains(field), "{name}: {message}");
        assert!(message.contains("\"hero\""), "{name}: {message}");
    }
}

#[test]
fn a_model_without_a_single_skinned_mesh_is_refused() {
    let character = "(name: \"hero\", model: \"SimpleMeshes/glTF/SimpleMeshes.gltf\",
        spawn: (0, 0, 0), states: [(name: \"idle\", clip: \"0\")])";
    let (message, _) = error_of("meshes", character);
    assert!(message.contains("SimpleMeshes.gltf"), "{message}");
}
