//! Shared by the `editor_mode*` tests: a small level (floor, two cubes, a wall) open in
//! `EditMode` over a headless engine (CPU tracer), driven by synthetic egui input on a
//! 2560 × 1440 point screen, and the pointer gestures and probes the tests use.

#![allow(dead_code)]

use candela::app::edit::{EditMode, EditTarget, Handles, project};
use candela::app::{Engine, Environment, Step};
use candela::assets::AssetRoot;
use candela::editor::{pick, pixel_ray};
use candela::level::{load_composed, load_level};
use candela::render::RenderConfig;
use glam::{Vec2, Vec3};

use super::input::Painted;
use super::{Scratch, assets, copy_dir, reflect_files};

pub const LEVEL: &str = r#"Level(
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

pub const SIZE: Vec2 = Vec2::new(2560.0, 1440.0);

pub struct Run {
    pub _scratch: Scratch,
    pub engine: Engine,
    pub mode: EditMode,
    pub ctx: egui::Context,
    pub time: f64,
    /// The keyboard's modifiers held during the passes.
    pub modifiers: egui::Modifiers,
}

impl Run {
    /// A run over `engine` and the editor `mode`, before any pass, at time 0 with no modifiers.
    /// The palette's thumbnails are cached in the scratch folder.
    pub fn new(scratch: Scratch, engine: Engine, mode: EditMode) -> Run {
        let cache = scratch.path().join("thumbnails");
        Run {
            _scratch: scratch,
            engine,
            mode: mode.with_thumbnail_cache(Some(cache)),
            ctx: egui::Context::default(),
            time: 0.0,
            modifiers: egui::Modifiers::NONE,
        }
    }
}

pub fn start(name: &str) -> anyhow::Result<Run> {
    start_with(name, |_| Ok(()))
}

/// [`start`], with `before_open` run on the level's path before the editor opens it.
pub fn start_with(
    name: &str,
    before_open: impl FnOnce(&std::path::Path) -> anyhow::Result<()>,
) -> anyhow::Result<Run> {
    let scratch = Scratch::new(name);
    let path = scratch.path().join("level.ron");
    std::fs::write(&path, LEVEL)?;
    before_open(&path)?;
    let root = AssetRoot::new(scratch.path())?;
    let level = load_level(&path, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(64, 36), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let mut mode = EditMode::open(EditTarget::single_file(&path, root), spawned)?;
    assert!(
        mode.enter(&mut engine).respawned,
        "entering spawns the document"
    );
    settled(scratch, engine, mode)
}

/// The editor over chamber `chamber` (0-based) of Reflect's world, composed over
/// `common.ron` as the game composes it, in a scratch copy of Reflect's and the common assets
/// (saves write there).
pub fn start_chamber(name: &str, chamber: usize) -> anyhow::Result<Run> {
    let scratch = Scratch::new(name);
    for folder in ["reflect/levels", "reflect/kit", "common"] {
        copy_dir(&assets().join(folder), &scratch.path().join(folder))?;
    }
    let root = AssetRoot::new(scratch.path())?;
    let (base, parts) = reflect_files(scratch.path());
    let (_, level) = load_composed(&base, &parts, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(64, 36), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let target = EditTarget::composed_part(&base, &parts, chamber, root)?;
    let mut mode = EditMode::open(target, spawned)?;
    assert!(mode.enter(&mut engine).respawned);
    settled(scratch, engine, mode)
}

/// The run over `engine` with the editor `mode` entered, after two empty passes (the first lays
/// egui's windows out).
fn settled(scratch: Scratch, engine: Engine, mode: EditMode) -> anyhow::Result<Run> {
    let mut run = Run::new(scratch, engine, mode);
    pass(&mut run, Vec::new())?;
    pass(&mut run, Vec::new())?;
    Ok(run)
}

/// One egui pass of the editor with `events`, then one engine frame.
pub fn pass(run: &mut Run, events: Vec<egui::Event>) -> anyhow::Result<()> {
    pass_painted(run, events).map(|_| ())
}

/// [`pass`], returning the text the pass painted (`input::Painted`).
pub fn pass_painted(run: &mut Run, events: Vec<egui::Event>) -> anyhow::Result<Painted> {
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
    let out = run.ctx.run_pass(input, |ctx| {
        mode.ui(ctx, engine);
    });
    run.engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = run.engine.rendered();
    Ok(Painted::of(&out))
}

pub fn moved_to(p: Vec2) -> egui::Event {
    egui::Event::PointerMoved(egui::pos2(p.x, p.y))
}

pub fn button(p: Vec2, pressed: bool, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::PointerButton {
        pos: egui::pos2(p.x, p.y),
        button: egui::PointerButton::Primary,
        pressed,
        modifiers,
    }
}

pub fn key(key: egui::Key, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

pub fn click(run: &mut Run, p: Vec2, modifiers: egui::Modifiers) -> anyhow::Result<()> {
    run.modifiers = modifiers;
    pass(run, vec![moved_to(p)])?;
    pass(run, vec![button(p, true, modifiers)])?;
    pass(run, vec![button(p, false, modifiers)])?;
    run.modifiers = egui::Modifiers::NONE;
    Ok(())
}

/// Presses at `from`, moves to `to` in `steps` passes, releases.
pub fn drag(run: &mut Run, from: Vec2, to: Vec2, steps: u32) -> anyhow::Result<()> {
    drag_with(run, from, to, steps, egui::Modifiers::NONE)
}

/// [`drag`] with `modifiers` held.
pub fn drag_with(
    run: &mut Run,
    from: Vec2,
    to: Vec2,
    steps: u32,
    modifiers: egui::Modifiers,
) -> anyhow::Result<()> {
    run.modifiers = modifiers;
    pass(run, vec![moved_to(from)])?;
    pass(run, vec![button(from, true, modifiers)])?;
    for k in 1..=steps {
        let p = from.lerp(to, k as f32 / steps as f32);
        pass(run, vec![moved_to(p)])?;
    }
    pass(run, vec![button(to, false, modifiers)])?;
    run.modifiers = egui::Modifiers::NONE;
    pass(run, Vec::new())
}

/// The screen rectangle (lowest, highest corner) of a unit cube at `centre`, grown by `margin`
/// points.
pub fn cube_band(run: &Run, centre: Vec3, margin: f32) -> (Vec2, Vec2) {
    let (mut lo, mut hi) = (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY));
    for k in 0..8 {
        let s = |bit: usize| if k & bit == 0 { -0.5 } else { 0.5 };
        let p = screen(run, centre + Vec3::new(s(1), s(2), s(4)));
        lo = lo.min(p);
        hi = hi.max(p);
    }
    (lo - Vec2::splat(margin), hi + Vec2::splat(margin))
}

/// Where world point `p` is on the screen, through the editor's camera.
pub fn screen(run: &Run, p: Vec3) -> Vec2 {
    let camera = run.mode.camera.expect("the editor camera").desc();
    project(&camera, SIZE, p).expect("in front of the camera")
}

/// The instance the world draws at world point `p` (a ray query on the last commit).
pub fn drawn_at(run: &Run, p: Vec3) -> Option<usize> {
    let camera = run.mode.camera.expect("the editor camera").desc();
    let px = project(&camera, SIZE, p)?;
    let ray = pixel_ray(&camera, SIZE.x as u32, SIZE.y as u32, px.x, px.y);
    let entities = run.mode.world.entities(&run.mode.state.doc.level);
    pick(&run.engine.queries(), entities, &ray).map(|p| p.instance)
}

pub fn translation(run: &Run, index: usize) -> Vec3 {
    Vec3::from(
        run.mode.state.doc.level.instances[index]
            .transform
            .translation,
    )
}

pub fn handles(run: &Run, index: usize) -> Handles {
    let camera = run.mode.camera.expect("the editor camera").desc();
    let entry = &run.mode.state.doc.level.instances[index];
    run.mode
        .gizmo
        .handles(&camera, SIZE, entry)
        .expect("the gizmo is in view")
}
