//! `reflect --bench-editor`: what the level editor (F1) costs over Reflect, headless on the
//! CPU tracer — the pick ray query alone, click to selection (the egui pass in which the
//! button is released: the pick, the selection and its highlight are all in that pass, so the
//! highlight shows in the very next frame), the editor's egui pass and its tessellation with a
//! selection and the gizmo shown, against an empty egui pass. The view is 1280 × 720 points;
//! the chamber being edited is the first, over the whole composed world. Printed as a
//! Markdown table (`docs/PERFORMANCE.md`).
//!
//! Owns: [`bench_editor`]. Main thread (the render thread renders). Must not: change the game
//! or write the level (nothing is saved).

use std::time::Instant;

use anyhow::Context;
use candela::app::edit::{EditHooks, EditMode};
use candela::app::{Engine, Game, Step};
use candela::editor::{pick, pixel_ray};
use candela::render::{RenderConfig, TracerChoice};
use glam::Vec2;

use crate::game::ReflectGame;
use crate::world::ReflectWorld;

/// The view the editor is measured in, points.
const VIEW: Vec2 = Vec2::new(1280.0, 720.0);
/// Clicks measured (a 20 × 10 grid over the part of the view no editor window covers).
const GRID: (u32, u32) = (20, 10);
/// That part: between the outliner and the inspector, above the toolbar (points).
const FREE: (Vec2, Vec2) = (Vec2::new(290.0, 20.0), Vec2::new(820.0, 560.0));
/// Passes measured for the per-frame costs.
const PASSES: usize = 200;

fn percentile(mut v: Vec<f64>, p: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * p).round() as usize]
}

struct Bench {
    engine: Engine,
    mode: EditMode,
    ctx: egui::Context,
    time: f64,
}

impl Bench {
    /// One egui pass of the editor with `events`; its wall time in seconds and the number of
    /// vertices its shapes tessellate to (that time is the second figure).
    fn pass(&mut self, events: Vec<egui::Event>) -> (f64, f64, usize) {
        self.time += 1.0 / 30.0;
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(VIEW.x, VIEW.y),
            )),
            time: Some(self.time),
            events,
            ..Default::default()
        };
        let (mode, engine) = (&mut self.mode, &mut self.engine);
        let begun = Instant::now();
        let output = self.ctx.run_pass(input, |ctx| {
            mode.ui(ctx, engine);
        });
        let ui = begun.elapsed().as_secs_f64();
        let begun = Instant::now();
        let meshes = self.ctx.tessellate(output.shapes, output.pixels_per_point);
        let tessellate = begun.elapsed().as_secs_f64();
        let vertices = meshes
            .iter()
            .map(|m| match &m.primitive {
                egui::epaint::Primitive::Mesh(mesh) => mesh.vertices.len(),
                egui::epaint::Primitive::Callback(_) => 0,
            })
            .sum();
        (ui, tessellate, vertices)
    }

    fn frame(&mut self) -> anyhow::Result<()> {
        self.engine.frame(1.0 / 30.0, &mut |_: &mut Step<'_>| {})?;
        let _ = self.engine.rendered();
        Ok(())
    }
}

fn at(p: Vec2, pressed: Option<bool>) -> egui::Event {
    let pos = egui::pos2(p.x, p.y);
    match pressed {
        None => egui::Event::PointerMoved(pos),
        Some(pressed) => egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        },
    }
}

/// Runs the measurement; returns the Markdown table.
pub fn bench_editor(world: &ReflectWorld) -> anyhow::Result<String> {
    let mut game = ReflectGame::new(world.clone(), 0);
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        ..RenderConfig::cpu(160, 90)
    };
    let mut engine = Engine::new(config, game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let (target, spawned) = game.edit_target().context("the editor opens chamber 1")?;
    let mut mode = EditMode::open(target, spawned)?.without_recovery_files();
    let entered = mode.enter(&mut engine);
    anyhow::ensure!(entered.respawned, "entering the editor spawns the chamber");
    let mut b = Bench {
        engine,
        mode,
        ctx: egui::Context::default(),
        time: 0.0,
    };
    for _ in 0..3 {
        b.pass(Vec::new());
        b.frame()?;
    }
    let triangles = b.engine.scene().triangles.len();
    // Picks: the ray query alone, then a click through egui.
    let camera = b.mode.camera.context("the editor camera")?.desc();
    let (mut query, mut click, mut selected) = (Vec::new(), Vec::new(), 0);
    for j in 0..GRID.1 {
        for i in 0..GRID.0 {
            let f = Vec2::new(
                (i as f32 + 0.5) / GRID.0 as f32,
                (j as f32 + 0.5) / GRID.1 as f32,
            );
            let p = FREE.0 + (FREE.1 - FREE.0) * f;
            let ray = pixel_ray(&camera, VIEW.x as u32, VIEW.y as u32, p.x, p.y);
            let entities = b.mode.world.entities(&b.mode.state.doc.level);
            let begun = Instant::now();
            let expected = pick(&b.engine.queries(), entities, &ray).map(|p| p.instance);
            query.push(begun.elapsed().as_secs_f64());
            // Nothing selected before each click: no gizmo handle under the pointer.
            b.mode.state.selection.clear();
            b.pass(vec![at(p, None)]);
            b.pass(vec![at(p, Some(true))]);
            let (seconds, _, _) = b.pass(vec![at(p, Some(false))]);
            click.push(seconds);
            let now = b.mode.state.selection.primary();
            anyhow::ensure!(
                now == expected,
                "a click at {p} selected {now:?}, the ray query hits {expected:?}"
            );
            selected += usize::from(now.is_some());
        }
    }
    // Per-frame cost with the centre's instance selected and its gizmo shown.
    let centre = VIEW * 0.5;
    b.pass(vec![at(centre, None)]);
    b.pass(vec![at(centre, Some(true))]);
    b.pass(vec![at(centre, Some(false))]);
    let (mut ui, mut tess, mut vertices) = (Vec::new(), Vec::new(), 0);
    for k in 0..PASSES {
        let wiggle = Vec2::new((k % 7) as f32, 0.0);
        let (u, t, v) = b.pass(vec![at(centre + Vec2::splat(40.0) + wiggle, None)]);
        ui.push(u);
        tess.push(t);
        vertices = v;
    }
    let empty_ctx = egui::Context::default();
    let mut empty = Vec::new();
    for k in 0..PASSES {
        let input = egui::RawInput {
            time: Some(k as f64 / 30.0),
            ..Default::default()
        };
        let begun = Instant::now();
        let _ = empty_ctx.run_pass(input, |_| {});
        empty.push(begun.elapsed().as_secs_f64());
    }
    let _ = b.engine.shutdown();
    let row = |name: &str, v: &[f64]| {
        format!(
            "| {name} | {:.1} | {:.1} |\n",
            percentile(v.to_vec(), 0.5) * 1e6,
            percentile(v.to_vec(), 0.99) * 1e6
        )
    };
    let mut out = format!(
        "Reflect, chamber 1 edited over the whole world ({triangles} unique triangles), a {}×{} view; \
         {selected} of {} clicks selected an instance (each the one the ray query hits).\n\n\
         | measured | median µs | p99 µs |\n|---|---:|---:|\n",
        VIEW.x,
        VIEW.y,
        GRID.0 * GRID.1
    );
    out += &row("pick ray query", &query);
    out += &row("click to selection (the release's egui pass)", &click);
    out += &row("editor egui pass, selection + gizmo shown", &ui);
    out += &row(&format!("its tessellation ({vertices} vertices)"), &tess);
    out += &row("an empty egui pass (baseline)", &empty);
    Ok(out)
}
