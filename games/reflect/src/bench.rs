//! `reflect --bench`: each chamber played from its committed replay in real time, headless,
//! on the CPU tracer at 640×360 with workload scaling holding 30 fps — the frame time split by
//! phase, the internal resolution and samples per pixel the scaling settles on, and how many
//! emissive triangles the light sampling holds with the chambers switching their lights and
//! with every light on. Printed as a Markdown table (`docs/PERFORMANCE.md`).
//!
//! Owns: [`bench`]. Main thread (the render thread renders). Must not: change the game.

use std::path::Path;
use std::time::Instant;

use candela::app::{Engine, Game, Phase, StepInput};
use candela::assets::AssetRoot;
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};

use crate::game::ReflectGame;
use crate::replays::open_replay;
use crate::world::ReflectWorld;

/// What one chamber's run measured (medians over the second half of its frames, once the
/// scaling settled).
#[derive(Clone, Debug, Default)]
pub struct ChamberFigures {
    pub frames: usize,
    pub frame_ms: f64,
    /// Milliseconds per frame of each main-thread phase, in `Phase::ALL` order.
    pub phase_ms: Vec<f64>,
    pub render_ms: f64,
    /// The denoiser's milliseconds per frame (its guide pass included; 0 when off).
    pub denoise_ms: f64,
    pub film: (u32, u32),
    pub spp: u32,
    pub lights: u32,
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Plays chamber `index`'s replay on `world` for at most `seconds` of wall time.
fn run(
    world: &ReflectWorld,
    index: usize,
    replay: &Path,
    seconds: f64,
    denoise: bool,
) -> anyhow::Result<ChamberFigures> {
    let (replay, start) = open_replay(world, replay)?;
    debug_assert_eq!(start, index);
    let mut game = ReflectGame::new(world.clone(), start);
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        denoise,
        scaling: Some(ScalingTarget::new(1.0 / 30.0)),
        ..RenderConfig::cpu(640, 360)
    };
    let mut engine = Engine::new(config, game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    engine.set_step_input(StepInput::Replay(replay));
    let begun = Instant::now();
    let mut last = Instant::now();
    let mut dt = 1.0 / 30.0;
    let (mut frame_ms, mut phases, mut rendered) = (Vec::new(), Vec::new(), Vec::new());
    while !engine.replay_finished() && begun.elapsed().as_secs_f64() < seconds {
        let report = engine.frame(dt, &mut game)?;
        rendered.extend(engine.rendered().into_iter().flatten());
        let now = Instant::now();
        dt = (now - last).as_secs_f64().min(0.1);
        last = now;
        frame_ms.push(dt * 1e3);
        phases.push(report.phases);
    }
    let _ = engine.shutdown();
    let half = |n: usize| n / 2;
    let late = &rendered[half(rendered.len())..];
    let mut figures = ChamberFigures {
        frames: frame_ms.len(),
        frame_ms: median(frame_ms[half(frame_ms.len())..].to_vec()),
        render_ms: median(late.iter().map(|r| r.render_seconds * 1e3).collect()),
        denoise_ms: median(late.iter().map(|r| r.denoise_seconds * 1e3).collect()),
        spp: late.iter().map(|r| r.spp).max().unwrap_or(0),
        lights: median(late.iter().map(|r| f64::from(r.lights)).collect()) as u32,
        ..Default::default()
    };
    let mut films: Vec<(u32, u32)> = late.iter().map(|r| r.film_size).collect();
    films.sort_unstable();
    figures.film = films.get(films.len() / 2).copied().unwrap_or_default();
    let late_phases = &phases[half(phases.len())..];
    figures.phase_ms = Phase::ALL
        .iter()
        .map(|&p| median(late_phases.iter().map(|t| t.get(p) * 1e3).collect()))
        .collect();
    Ok(figures)
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
    for (i, chamber) in world.chambers.iter().enumerate() {
        let replay = replays.join(format!("{}.replay", chamber.id));
        let f = run(world, i, &replay, seconds, denoise)?;
        let on = run(&all_on, i, &replay, seconds.min(8.0), denoise)?;
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
