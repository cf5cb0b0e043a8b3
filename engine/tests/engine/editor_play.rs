//! "Play from here", both directions (issue 33), through the calls the window runner makes on
//! F1 (`EditMode::play_from_here`, `EditMode::enter_with`) with a first-person game and a
//! headless engine, the edits made by synthetic input through the egui context:
//! - leaving the editor, the game starts at the editor camera: the player stands on the floor
//!   below the camera's eye, looking its way, and plays the edited level (the crate where it
//!   was typed to be);
//! - returning to the editor, every play-time change is discarded (the crate, fallen while
//!   playing, is back where the document says), the game holds the new entities, and the undo
//!   history is kept: Ctrl+Z undoes the edit made before playing.

use crate::editor_common;

use candela::app::FirstPersonGame;
use candela::app::edit::{EditHooks, EditMode};
use candela::app::{Engine, Game};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::render::RenderConfig;
use editor_common::Scratch;
use editor_common::input::replace_text;
use editor_common::mode_run::{Run, click, key, pass, pass_painted};
use glam::{Vec2, Vec3};

const LEVEL: &str = r#"Level(
    materials: [(name: "grey", kind: Diffuse)],
    boxes: [
        (name: "floor", size: (20, 0.2, 20), material: "grey"),
        (name: "cube", size: (1, 1, 1), material: "grey"),
    ],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0)), body: Static(shape: Box)),
        (model: "cube", name: "crate", transform: (translation: (2, 2, 0)),
            body: Dynamic(shape: Box, mass: 1)),
    ],
    camera: (position: (0, 1.6, 6), look_at: (0, 1.5, 0), vertical_fov_deg: 50),
    sky: Constant((0.2, 0.2, 0.2)),
)"#;

fn centre(r: egui::Rect) -> Vec2 {
    Vec2::new(r.center().x, r.center().y)
}

/// The crate's entity transform in the world.
fn crate_drawn(run: &Run) -> anyhow::Result<Vec3> {
    let entity = run.mode.world.entities(&run.mode.state.doc.level)[1];
    let t = *run.engine.world().get::<&Transform>(entity)?;
    Ok(t.translation)
}

#[test]
fn play_from_here_starts_at_the_camera_and_coming_back_restores_the_edited_level()
-> anyhow::Result<()> {
    let scratch = Scratch::new("editor_play");
    let path = scratch.path().join("level.ron");
    std::fs::write(&path, LEVEL)?;
    let root = AssetRoot::new(scratch.path())?;
    let mut game = FirstPersonGame::load(&path, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(64, 36), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("setup: {e}"))?;
    let start_feet = game.player().expect("the player").feet(engine.world());
    let (target, spawned) = game.edit_target().expect("a level to edit");
    let mode = EditMode::open(target, spawned)?;
    let mut run = Run::new(scratch, engine, mode);
    // F1: the runner holds the game while editing.
    run.engine.set_paused(true);
    assert!(
        run.mode
            .enter_with(&mut run.engine, game.editor())
            .respawned
    );
    pass(&mut run, Vec::new())?;
    // Select the crate in the outliner, type x = −2, frame it (F).
    let at = pass_painted(&mut run, Vec::new())?.find("crate  (cube)")?;
    click(&mut run, centre(at), egui::Modifiers::NONE)?;
    let painted = pass_painted(&mut run, Vec::new())?;
    let label = painted.find("translation (m)")?;
    let x = painted.numbers_right_of(label)[0];
    click(&mut run, centre(x), egui::Modifiers::NONE)?;
    pass(&mut run, replace_text("-2"))?;
    pass(&mut run, Vec::new())?;
    let edited = Vec3::new(-2.0, 2.0, 0.0);
    assert_eq!(
        run.mode.state.doc.level.instances[1].transform.translation,
        edited.to_array()
    );
    assert!((crate_drawn(&run)? - edited).length() < 1e-4);
    pass(&mut run, vec![key(egui::Key::F, egui::Modifiers::NONE)])?;
    let camera = run.mode.camera.expect("the editor camera");
    let history = run.mode.state.history.undo_len();
    assert_eq!(history, 1);
    // The camera is somewhere else than the player: the test can tell them apart.
    assert!(
        (camera.position - start_feet).with_y(0.0).length() > 1.0,
        "camera {} player {start_feet}",
        camera.position
    );

    // F1 again: play from here.
    run.mode.play_from_here(&mut run.engine, game.editor());
    run.engine.set_paused(false);
    assert!(!run.mode.active());
    for _ in 0..60 {
        run.engine.frame(1.0 / 60.0, &mut game)?;
        let _ = run.engine.rendered();
    }
    let player = game.player().expect("the player");
    let feet = player.feet(run.engine.world());
    let below = camera.position.with_y(0.0);
    assert!(
        (feet - below).length() < 0.05,
        "the player stands on the floor below the camera: feet {feet}, camera {}",
        camera.position
    );
    let flat = camera.forward().with_y(0.0).normalize();
    let view = player.view().with_y(0.0).normalize();
    assert!(
        flat.dot(view) > 0.999,
        "looking the camera's way: {flat} {view}"
    );
    // The game played the edited level: the crate fell from where it was typed to be.
    let fallen = crate_drawn(&run)?;
    assert!((fallen.x - edited.x).abs() < 0.05, "{fallen}");
    assert!(fallen.y < 1.0, "the crate fell while playing: {fallen}");

    // F1: back to the editor. Play-time changes are gone, the history is kept.
    run.engine.set_paused(true);
    assert!(
        run.mode
            .enter_with(&mut run.engine, game.editor())
            .respawned
    );
    assert_eq!(
        game.spawned().entities,
        run.mode.world.spawned().entities,
        "the game holds the new entities"
    );
    pass(&mut run, Vec::new())?;
    assert!(
        (crate_drawn(&run)? - edited).length() < 1e-4,
        "{}",
        crate_drawn(&run)?
    );
    assert_eq!(
        run.mode.state.doc.level.instances[1].transform.translation,
        edited.to_array()
    );
    assert_eq!(
        run.mode.state.history.undo_len(),
        history,
        "the history kept"
    );
    pass(&mut run, vec![key(egui::Key::Z, egui::Modifiers::COMMAND)])?;
    assert_eq!(
        run.mode.state.doc.level.instances[1].transform.translation,
        [2.0, 2.0, 0.0]
    );
    assert!((crate_drawn(&run)? - Vec3::new(2.0, 2.0, 0.0)).length() < 1e-4);
    Ok(())
}
