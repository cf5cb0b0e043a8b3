//! `reflect --bench`: each chamber played from its committed replay in real time, headless,
//! on the CPU tracer at 640×360 (`--bench-output`) with workload scaling holding what the chamber's level declares
//! (`render: (target_fps, min_scale)`, 30 fps and ¼ when it declares nothing) — the frame time split by
//! phase, the internal resolution and samples per pixel the scaling settles on, and how many
//! emissive triangles the light sampling holds with the chambers switching their lights and
//! with every light on. Printed as a Markdown table (`docs/PERFORMANCE.md`).
//!
//! Each run is the engine harness's (`candela::app::harness::bench_replay`); Reflect chooses
//! the render configuration and lays out the table.
//!
//! Owns: [`bench`]. Main thread (the render thread renders). Must not: change the game.

use std::path::Path;

use candela::app::harness::{BenchFigures, HarnessGame, bench_replay, table_head, table_row};
use candela::assets::AssetRoot;
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};

use crate::world::ReflectWorld;

/// How `reflect --bench` runs.
#[derive(Clone, Copy, Debug)]
pub struct BenchOptions {
    /// Most seconds of wall time per chamber.
    pub seconds: f64,
    /// Denoise each frame, as the game does by default.
    pub denoise: bool,
    /// The output size in pixels (640×360 by default; the real-time issue's figure is 1280×720).
    pub output: (u32, u32),
    /// Overrides the levels' `render.indirect_every` (`None`: the level's).
    pub indirect_every: Option<u32>,
    /// Take the denoiser's guides from the tracer's first hits, samples through the pixel
    /// frame's jitter (`RenderConfig::first_hit_guides`), instead of a guide pass.
    pub first_hit_guides: bool,
}

/// Plays a chamber's replay on `world` for at most `options.seconds` of wall time, as the game
/// plays: the CPU tracer at the output size with workload scaling holding the level's target.
fn run(
    world: &ReflectWorld,
    replay: &Path,
    options: &BenchOptions,
) -> anyhow::Result<BenchFigures> {
    let (_, start) = world.open_replay(replay)?;
    let level = world.environment(&world.new_game(start)).render;
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        denoise: options.denoise,
        scaling: Some(ScalingTarget {
            // The steady state is measured: start at the level's floor, not at frames of the
            // full output size (seconds each at 1280×720 on two cores).
            start_resolution: level.min_resolution(),
            ..ScalingTarget::of_level(&level)
        }),
        indirect_every: options.indirect_every,
        first_hit_guides: options.first_hit_guides,
        ..RenderConfig::cpu(options.output.0, options.output.1)
    };
    Ok(bench_replay(world, replay, config, options.seconds)?)
}

/// Runs every chamber with and without room switching (denoising each frame when `denoise`,
/// as the game does by default); returns the Markdown table.
pub fn bench(
    world: &ReflectWorld,
    root: &AssetRoot,
    replays: &Path,
    options: &BenchOptions,
) -> anyhow::Result<String> {
    let all_on = world.without_room_switching(root)?;
    // "emitters sampled" is with the chambers switching their lights.
    let mut out = table_head("chamber", &["emitters (all on)"]);
    for chamber in &world.chambers {
        let replay = replays.join(format!("{}.replay", chamber.id));
        let f = run(world, &replay, options)?;
        let short = BenchOptions {
            seconds: options.seconds.min(8.0),
            ..*options
        };
        let on = run(&all_on, &replay, &short)?;
        out += &format!("{} {} |\n", table_row(&chamber.id, &f), on.lights);
        eprintln!("{}: done", chamber.id);
    }
    Ok(out)
}
