//! `bench pipeline --only overlap`: does the game update of frame N+1 really run while frame N
//! renders? Frame time against max(update, render) (perfect overlap) and against their sum
//! (no overlap), with both sides loaded by known amounts.
//!
//! Scene: the demo level, its pool waving every frame (so the upkeep refits and rebuilds the
//! TLAS), CPU tracer at 96 × 54 with the spp that makes a render take `RENDER_MS` (calibrated
//! first). Game update: the game closure sleeps (or, with `--busy`, spins) for a known time each
//! frame; one fixed step per frame (frame time = the clock's step, so the clock takes exactly one
//! step). Main side = update + upkeep (the engine's own figures), render side = apply + render
//! (the render thread's), frame = wall time per frame over 30 frames after 5 warm-up frames.
//! With `--busy`, run with `--threads 1` so the main thread's spinning and the renderer each
//! have one of the two cores.

use std::time::{Duration, Instant};

use candela::app::{Engine, Environment, FixedClock, Step, waves_system};
use candela::level::PlayableLevel;
use candela::render::film::ConvergePolicy;
use candela::render::{RenderConfig, TracerChoice};

use super::pipeline::{PipelineArgs, write_csv};
use crate::machine::median;

/// Target render time per frame, milliseconds.
const RENDER_MS: f64 = 40.0;
const WARM_UP: usize = 5;
const FRAMES: usize = 30;

struct Outcome {
    frame: f64,
    main: f64,
    render: f64,
    /// Main thread waiting for the render thread to take the commit.
    handoff: f64,
}

fn engine(desc: &PlayableLevel, spp: u32) -> anyhow::Result<Engine> {
    let config = RenderConfig {
        tracer: TracerChoice::Cpu,
        width: 96,
        height: 54,
        spp,
        seed: 1,
        converge: ConvergePolicy::default(),
        scaling: None,
        denoise: false,
        light_sampling: None,
        indirect_every: None,
        first_hit_guides: false,
        atrous_kernel: Default::default(),
        sky_rebuild: candela::scene::SkyRebuild::Blocking,
        temporal_upscale: None,
    };
    let mut engine = Engine::new(config, Environment::of(&desc.scene))?;
    engine.spawn_level(desc);
    *engine.clock_mut() = FixedClock::new(60.0);
    Ok(engine)
}

/// Runs `frames` frames with `load` of update per frame; returns per-frame means.
fn measure(desc: &PlayableLevel, spp: u32, load: Duration, busy: bool) -> anyhow::Result<Outcome> {
    let mut engine = engine(desc, spp)?;
    let step = engine.clock().step_seconds;
    let mut time = 0.0;
    let mut main = Vec::new();
    let mut handoff = Vec::new();
    let mut render = Vec::new();
    let mut started = Instant::now();
    for frame in 0..WARM_UP + FRAMES {
        if frame == WARM_UP {
            started = Instant::now();
        }
        let report = engine.frame(step, &mut |step: &mut Step<'_>| {
            let world = &mut *step.world;
            let dt = step.step_seconds;
            time += dt;
            waves_system(world, time);
            if busy {
                let until = Instant::now() + load;
                while Instant::now() < until {
                    std::hint::spin_loop();
                }
            } else {
                std::thread::sleep(load);
            }
        })?;
        anyhow::ensure!(
            report.steps == 1,
            "frame {frame} took {} steps",
            report.steps
        );
        if frame >= WARM_UP {
            main.push(report.update_seconds() + report.upkeep_seconds());
            handoff.push(report.handoff_seconds());
        }
        for r in engine.rendered() {
            let r = r?;
            if r.frame as usize >= WARM_UP {
                render.push(r.apply_seconds + r.render_seconds);
            }
        }
    }
    // The last frame is done when its render is back.
    while render.len() < FRAMES {
        let Some(r) = engine.wait_rendered() else {
            break;
        };
        let r = r?;
        if r.frame as usize >= WARM_UP {
            render.push(r.apply_seconds + r.render_seconds);
        }
    }
    let wall = started.elapsed().as_secs_f64();
    engine.shutdown();
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    Ok(Outcome {
        frame: wall / FRAMES as f64,
        main: mean(&main),
        render: mean(&render),
        handoff: mean(&handoff),
    })
}

/// Samples per pixel for a render of about `RENDER_MS`.
fn calibrate(desc: &PlayableLevel) -> anyhow::Result<u32> {
    let mut engine = engine(desc, 1)?;
    let mut times = Vec::new();
    for _ in 0..6 {
        engine.frame(engine.clock().step_seconds, &mut |_: &mut Step<'_>| {})?;
        if let Some(r) = engine.wait_rendered() {
            times.push(r?.render_seconds);
        }
    }
    engine.shutdown();
    let one = median(&times[1..]).max(1e-5);
    Ok(((RENDER_MS * 1e-3 / one).round() as u32).max(1))
}

pub fn run(desc: &PlayableLevel, args: &PipelineArgs) -> anyhow::Result<()> {
    let kind = if args.busy { "busy work" } else { "sleep" };
    println!(
        "## Overlap of game update and render (update loaded by {kind}, {} rayon threads)\n",
        rayon::current_num_threads()
    );
    let spp = calibrate(desc)?;
    println!("render: 96 × 54, {spp} spp (calibrated to ≈ {RENDER_MS} ms)\n");
    println!(
        "| update load ms | main (update + upkeep) ms | hand-off wait ms | render (apply + trace) ms | frame ms | frame / max | frame / sum |\n|---:|---:|---:|---:|---:|---:|---:|"
    );
    let mut csv = String::from(
        "load,update_load_ms,main_ms,handoff_ms,render_ms,frame_ms,over_max,over_sum\n",
    );
    for factor in [0.5, 1.0, 1.5] {
        let load = Duration::from_secs_f64(RENDER_MS * 1e-3 * factor);
        let runs: Vec<Outcome> = (0..args.reps.min(3))
            .map(|_| measure(desc, spp, load, args.busy))
            .collect::<anyhow::Result<_>>()?;
        // The run with the median frame time, reported whole (its own main and render).
        let mut order: Vec<usize> = (0..runs.len()).collect();
        order.sort_by(|&a, &b| runs[a].frame.total_cmp(&runs[b].frame));
        let o = &runs[order[order.len() / 2]];
        let (over_max, over_sum) = (
            o.frame / o.main.max(o.render),
            o.frame / (o.main + o.render),
        );
        println!(
            "| {:.0} | {:.1} | {:.1} | {:.1} | {:.1} | **{over_max:.3}** | {over_sum:.3} |",
            load.as_secs_f64() * 1e3,
            o.main * 1e3,
            o.handoff * 1e3,
            o.render * 1e3,
            o.frame * 1e3
        );
        csv += &format!(
            "{kind},{:.1},{:.3},{:.3},{:.3},{:.3},{over_max:.4},{over_sum:.4}\n",
            load.as_secs_f64() * 1e3,
            o.main * 1e3,
            o.handoff * 1e3,
            o.render * 1e3,
            o.frame * 1e3
        );
    }
    println!();
    let name = if args.busy {
        "overlap_busy.csv"
    } else {
        "overlap_sleep.csv"
    };
    write_csv(&args.out_dir, name, &csv)
}
