//! `its_about_time --bench`: each area of the ruins played from its puzzle's committed replay
//! (`assets/its_about_time/replays/<puzzle>.replay`) in real time, headless, as the game plays
//! it — the CPU tracer at 640×360 output (`--bench-output`) with workload scaling holding the level's frame rate
//! down to its `min_scale` (`render: (target_fps: 30, min_scale: 0.5)`), the denoiser on,
//! the sky following turned time on a worker thread — measuring the frame time split by phase
//! (scene upkeep is the per-frame BVH upkeep with the explorer, the water and every mover), the
//! internal resolution and samples per pixel the scaling settles on, and the emitters the light
//! sampling holds. Printed as a Markdown table (`docs/PERFORMANCE.md`).
//!
//! Each run is the engine harness's (`candela::app::harness::bench_replay`); the game chooses
//! the render configuration and lays out the table.
//!
//! Owns: [`bench`]. Main thread (the render thread renders). Must not: change the game.

use candela::app::harness::{bench_replay, table_head, table_row};
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};

use crate::replays::named;
use crate::routes::NAMES;
use crate::world::RuinsWorld;

/// Plays every puzzle's replay on `world` for at most `seconds` of wall time each at `output`
/// (pixels; the game's bench: 640×360); returns the Markdown table.
pub fn bench(
    world: &RuinsWorld,
    seconds: f64,
    denoise: bool,
    output: (u32, u32),
) -> anyhow::Result<String> {
    let mut out = table_head("area (replay)", &[]);
    let level = &world.level.scene.render;
    for name in NAMES.iter().filter(|n| **n != "full_game") {
        let config = RenderConfig {
            tracer: TracerChoice::Cpu,
            denoise,
            // What the level declares (`render: (target_fps, min_scale)`), started at its floor
            // as Reflect's bench does: the steady state is measured.
            scaling: Some(ScalingTarget {
                start_resolution: level.min_resolution(),
                ..ScalingTarget::of_level(level)
            }),
            sky_rebuild: candela::scene::SkyRebuild::Background,
            // As in play (`windowed_render`): guides from the tracer's first hits.
            first_hit_guides: true,
            ..RenderConfig::cpu(output.0, output.1)
        };
        let replay = named(world.root.path(), name);
        let f = bench_replay(world, &replay, config, seconds)?;
        out += &(table_row(name, &f) + "\n");
        eprintln!("{name}: done");
    }
    Ok(out)
}
