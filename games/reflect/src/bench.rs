//! `reflect --bench`: each chamber played from its committed replay in real time, headless,
//! on the CPU tracer at 640×360 with workload scaling holding what the chamber's level declares
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

use candela::app::Phase;
use candela::app::harness::{BenchFigures, HarnessGame, bench_replay};
use candela::assets::AssetRoot;
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};

use crate::world::ReflectWorld;

/// Plays a chamber's replay on `world` for at most `seconds` of wall time, as the game plays:
/// the CPU tracer at 640×360 with workload scaling holding the level's target.
fn run(
    world: &ReflectWorld,
    replay: &Path,
    seconds: f64,
    denoise: bool,
) -> anyhow::Result<BenchFigures> {
    let (_, start) = world.open_replay(replay)?;
    let level = world.environment(&world.new_game(start)).render;
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        denoise,
        scaling: Some(ScalingTarget::of_level(&level)),
        ..RenderConfig::cpu(640, 360)
    };
    Ok(bench_replay(world, replay, config, seconds)?)
}

/// Runs every chamber with and without room switching (denoising each frame when `denoise`,
/// as the game does by default); returns the Markdown table.
pub fn bench(
    world: &ReflectWorld,
    root: &AssetRoot,
    replays: &Path,
    seconds: f64,
    denoise: bool,
) -> anyhow::Result<String> {
    let all_on = world.without_room_switching(root)?;
    let mut out = String::from("| chamber | frames | frame ms (median) | fps |");
    for p in Phase::ALL {
        out += &format!(" {} ms |", p.name());
    }
    out += " render ms | denoise ms | internal res | spp | emitters sampled (switching) | emitters (all on) |\n|---|";
    out += &"---:|".repeat(3 + Phase::ALL.len() + 6);
    out += "\n";
    for chamber in &world.chambers {
        let replay = replays.join(format!("{}.replay", chamber.id));
        let f = run(world, &replay, seconds, denoise)?;
        let on = run(&all_on, &replay, seconds.min(8.0), denoise)?;
        out += &format!(
            "| {} | {} | {:.1} | {:.1} |",
            chamber.id,
            f.frames,
            f.frame_ms,
            1e3 / f.frame_ms
        );
        for ms in &f.phase_ms {
            out += &format!(" {ms:.2} |");
        }
        out += &format!(
            " {:.1} | {:.1} | {}×{} | {} | {} | {} |\n",
            f.render_ms, f.denoise_ms, f.film.0, f.film.1, f.spp, f.lights, on.lights
        );
        eprintln!("{}: done", chamber.id);
    }
    Ok(out)
}
