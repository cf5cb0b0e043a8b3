//! The editor over a running level, headless (issue 12): `EditMode` in a headless engine (CPU
//! tracer) driven by synthetic egui input on a 2560 × 1440 point screen. A click picks the
//! cube under the pointer (Shift adds, Ctrl toggles, the sky clears); dragging the translate
//! gizmo's X handle moves the cube so that it stays under the pointer, as one command, and
//! the world follows (picked where it went); with grid snapping the move is whole steps;
//! the rotate tool (E) turns it by the snapped angle; a typed value moves it; Ctrl+Z and
//! Ctrl+Shift+Z go back and forth, the world with them.

use crate::editor_common;

use candela::app::edit::{EditMode, EditTarget, Gizmo, Handles, project};
use candela::app::{Engine, Environment, Step};
use candela::assets::{AssetRoot, TransformDesc};
use candela::editor::{Edit, InstanceField, pick, pixel_ray};
use candela::level::load_level;
use candela::render::RenderConfig;
use editor_common::Scratch;
use glam::{Vec2, Vec3};

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

const SIZE: Vec2 = Vec2::new(2560.0, 1440.0);

struct Run {
    _scratch: Scratch,
    engine: Engine,
    mode: EditMode,
    ctx: egui::Context,
    time: f64,
    /// The keyboard's modifiers held during the passes.
    modifiers: egui::Modifiers,
}

fn start(name: &str) -> anyhow::Result<Run> {
    let scratch = Scratch::new(name);
    let path = scratch.path().join("level.ron");
    std::fs::write(&path, LEVEL)?;
    let root = AssetRoot::new(scratch.path())?;
    let level = load_level(&path, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(64, 36), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let mut mode = EditMode::open(EditTarget::single_file(&path, root), spawned)?;
    assert!(
        mode.enter(&mut engine).respawned,
        "entering spawns the document"
    );
    let mut run = Run {
        _scratch: scratch,
        engine,
        mode,
        ctx: egui::Context::default(),
        time: 0.0,
        modifiers: egui::Modifiers::NONE,
    };
    pass(&mut run, Vec::new())?;
    pass(&mut run, Vec::new())?;
    Ok(run)
}

/// One egui pass of the editor with `events`, then one engine frame.
fn pass(run: &mut Run, events: Vec<egui::Event>) -> anyhow::Result<()> {
    run.time += 1.0 / 30.0;
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(SIZE.x, SIZE.y),
        )),
        time: Some(run.time),
        events: std::iter::once(egui::Event::ModifiersChanged(run.modifiers))
            .chain(events)
            .collect(),
        ..Default::default()
    };
    let (mode, engine) = (&mut run.mode, &mut run.engine);
    let _ = run.ctx.run_pass(input, |ctx| {
        mode.ui(ctx, engine);
    });
    run.engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = run.engine.rendered();
    Ok(())
}

fn moved_to(p: Vec2) -> egui::Event {
    egui::Event::PointerMoved(egui::pos2(p.x, p.y))
}

fn button(p: Vec2, pressed: bool, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::PointerButton {
        pos: egui::pos2(p.x, p.y),
        button: egui::PointerButton::Primary,
        pressed,
        modifiers,
    }
}

fn key(key: egui::Key, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

fn click(run: &mut Run, p: Vec2, modifiers: egui::Modifiers) -> anyhow::Result<()> {
    run.modifiers = modifiers;
    pass(run, vec![moved_to(p)])?;
    pass(run, vec![button(p, true, modifiers)])?;
    pass(run, vec![button(p, false, modifiers)])?;
    run.modifiers = egui::Modifiers::NONE;
    Ok(())
}

/// Presses at `from`, moves to `to` in `steps` passes, releases.
fn drag(run: &mut Run, from: Vec2, to: Vec2, steps: u32) -> anyhow::Result<()> {
    pass(run, vec![moved_to(from)])?;
    pass(run, vec![button(from, true, egui::Modifiers::NONE)])?;
    for k in 1..=steps {
        let p = from.lerp(to, k as f32 / steps as f32);
        pass(run, vec![moved_to(p)])?;
    }
    pass(run, vec![button(to, false, egui::Modifiers::NONE)])?;
    pass(run, Vec::new())
}

/// Where world point `p` is on the screen, through the editor's camera.
fn screen(run: &Run, p: Vec3) -> Vec2 {
    let camera = run.mode.camera.expect("the editor camera").desc();
    project(&camera, SIZE, p).expect("in front of the camera")
}

/// The instance the world draws at world point `p` (a ray query on the last commit).
fn drawn_at(run: &Run, p: Vec3) -> Option<usize> {
    let camera = run.mode.camera.expect("the editor camera").desc();
    let px = project(&camera, SIZE, p)?;
    let ray = pixel_ray(&camera, SIZE.x as u32, SIZE.y as u32, px.x, px.y);
    let entities = run.mode.world.entities(&run.mode.state.doc.level);
    pick(&run.engine.queries(), entities, &ray).map(|p| p.instance)
}

fn translation(run: &Run, index: usize) -> Vec3 {
    Vec3::from(
        run.mode.state.doc.level.instances[index]
            .transform
            .translation,
    )
}

fn handles(run: &Run, index: usize) -> Handles {
    let camera = run.mode.camera.expect("the editor camera").desc();
    let entry = &run.mode.state.doc.level.instances[index];
    run.mode
        .gizmo
        .handles(&camera, SIZE, entry)
        .expect("the gizmo is in view")
}

#[test]
fn clicks_select_with_shift_adding_ctrl_toggling_and_the_sky_clearing() -> anyhow::Result<()> {
    let mut run = start("mode_select")?;
    let right = screen(&run, Vec3::new(1.5, 1.0, 0.5));
    let left = screen(&run, Vec3::new(-1.5, 1.0, 0.5));
    click(&mut run, right, egui::Modifiers::NONE)?;
    assert_eq!(run.mode.state.selection.instances(), &[2]);
    click(&mut run, left, egui::Modifiers::SHIFT)?;
    assert_eq!(run.mode.state.selection.instances(), &[2, 1]);
    click(&mut run, right, egui::Modifiers::CTRL)?;
    assert_eq!(run.mode.state.selection.instances(), &[1]);
    // High above the wall, right of every panel: the sky.
    click(&mut run, Vec2::new(2400.0, 40.0), egui::Modifiers::NONE)?;
    assert!(run.mode.state.selection.is_empty());
    assert!(run.mode.last_pick.is_none());
    assert!(!run.mode.state.history.can_undo(), "selecting is no edit");
    Ok(())
}

#[test]
fn the_gizmo_moves_and_turns_the_selection_in_one_command_and_undo_redo_follow()
-> anyhow::Result<()> {
    let mut run = start("mode_gizmo")?;
    let start_at = translation(&run, 2);
    let cube = screen(&run, Vec3::new(1.5, 1.0, 0.5));
    click(&mut run, cube, egui::Modifiers::NONE)?;
    assert_eq!(run.mode.state.selection.primary(), Some(2));
    let h = handles(&run, 2);
    let x_end = h.ends_px[0].expect("the X handle");
    assert_eq!(Gizmo::hit(&h, h.centre_px.lerp(x_end, 0.7)), Some(0));
    let grab = h.centre_px.lerp(x_end, 0.7);
    let to = grab + Vec2::new(240.0, 0.0);
    drag(&mut run, grab, to, 6)?;
    let now = translation(&run, 2);
    assert!(now.x > start_at.x + 0.5, "moved along +X: {now}");
    assert!((now.y - start_at.y).abs() < 1e-4 && (now.z - start_at.z).abs() < 1e-4);
    // The grabbed point stayed under the pointer.
    let centre_now = screen(&run, now);
    let expected = to - (grab - h.centre_px);
    assert!(
        centre_now.distance(expected) < 1.0,
        "{centre_now} vs {expected}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 1, "one command");
    assert_eq!(
        drawn_at(&run, now + Vec3::Z * 0.5),
        Some(2),
        "drawn where it went"
    );
    // Grid snapping: the drag's amount is whole steps.
    run.mode.state.snap.grid = Some(0.5);
    let before = translation(&run, 2);
    let h = handles(&run, 2);
    let grab = h.centre_px.lerp(h.ends_px[0].expect("X"), 0.7);
    drag(&mut run, grab, grab + Vec2::new(173.0, 0.0), 5)?;
    let amount = translation(&run, 2).x - before.x;
    assert!(amount > 0.4, "{amount}");
    assert!(
        (amount / 0.5 - (amount / 0.5).round()).abs() < 1e-3,
        "{amount}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 2);
    // Rotate (E) about Y: 90 points of pointer at 0.5°/point, snapped to 15°, is 45°.
    run.mode.state.snap.angle_deg = Some(15.0);
    pass(&mut run, vec![key(egui::Key::E, egui::Modifiers::NONE)])?;
    let h = handles(&run, 2);
    let grab = h.centre_px.lerp(h.ends_px[1].expect("Y"), 0.7);
    drag(&mut run, grab, grab + Vec2::new(92.0, 0.0), 4)?;
    let r = run.mode.state.doc.level.instances[2].transform.rotation_deg;
    assert!(
        (r[1] - 45.0).abs() < 1e-3 && r[0].abs() < 1e-3 && r[2].abs() < 1e-3,
        "{r:?}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 3);
    // A typed value moves it as well, and the world follows.
    let mut typed: TransformDesc = run.mode.state.doc.level.instances[2].transform;
    typed.translation = [0.0, 1.0, 1.0];
    run.mode.apply(
        &mut run.engine,
        Edit::Instance {
            index: 2,
            field: InstanceField::Transform(typed),
        },
    )?;
    pass(&mut run, Vec::new())?;
    assert_eq!(drawn_at(&run, Vec3::new(0.0, 1.0, 1.6)), Some(2));
    // Ctrl+Z four times: back where it started, drawn there; Ctrl+Shift+Z redoes.
    let command = egui::Modifiers::COMMAND;
    for _ in 0..4 {
        pass(&mut run, vec![key(egui::Key::Z, command)])?;
    }
    pass(&mut run, Vec::new())?;
    assert_eq!(translation(&run, 2), start_at);
    assert_eq!(
        run.mode.state.doc.level.instances[2].transform.rotation_deg,
        [0.0; 3]
    );
    assert_eq!(drawn_at(&run, Vec3::new(1.5, 1.0, 0.5)), Some(2));
    assert_eq!(
        drawn_at(&run, Vec3::new(0.0, 1.0, 1.6)),
        Some(3),
        "the wall behind"
    );
    pass(
        &mut run,
        vec![key(egui::Key::Z, command | egui::Modifiers::SHIFT)],
    )?;
    assert!(translation(&run, 2).x > start_at.x + 0.5, "redone");
    Ok(())
}
