//! Timing a game's replay in real time: [`bench_replay`] plays a recording headless with the
//! given render configuration (the game's: tracer, size, denoising, workload scaling), each
//! frame as long as the last one took, for at most some seconds of wall time, and measures
//! the second half of the frames (once the scaling settled): frame time, the main thread's
//! phases, render and denoise time, the film size and samples per pixel the scaling settles
//! on, the emitters the light sampling holds, the commit's bytes (Brigade's budget is 2 MB a
//! frame) and the memory (the scene both tracers read, and the process's resident set, against
//! Brigade's 737 MB) ([`BenchFigures`]). The game's table of them is the game's.
//!
//! With `CANDELA_PROFILE=1` in the environment the profiler's scopes are on for the run, as
//! with the F5 view shown, and its frames kept (`docs/PERFORMANCE.md` compares the two).
//!
//! Main thread (the render thread renders). Must not: change the game.

use std::path::Path;
use std::time::Instant;

use super::config::{HarnessError, HarnessGame};
use super::replay_run::{Started, start_headless};
use crate::app::runner::Phase;
use crate::render::RenderConfig;

/// What one replay's run measured (medians over the second half of its frames).
#[derive(Clone, Debug, Default)]
pub struct BenchFigures {
    /// Frames run.
    pub frames: usize,
    /// Milliseconds per frame, wall clock.
    pub frame_ms: f64,
    /// Milliseconds per frame of each main-thread phase, in `Phase::ALL` order.
    pub phase_ms: Vec<f64>,
    /// The render thread's milliseconds per frame (tracing).
    pub render_ms: f64,
    /// The denoiser's milliseconds per frame (its guide pass included; 0 when off).
    pub denoise_ms: f64,
    /// The film size the scaling settled on (the median).
    pub film: (u32, u32),
    /// The most samples per pixel a frame took.
    pub spp: u32,
    /// Emissive triangles the light sampling held (the median).
    pub lights: u32,
    /// The largest commit of the run, bytes (the first frame's, which carries the whole scene,
    /// left out: the budget is per frame of play).
    pub commit_max: usize,
    /// The median commit over the second half, bytes.
    pub commit_median: usize,
    /// Bytes of the flattened scene the tracers read at the end (`RenderScene::memory`).
    pub scene_bytes: usize,
    /// The process's resident memory at the end, bytes (both copies of the scene, the game,
    /// the denoiser's planes).
    pub rss_bytes: u64,
}

/// The head of a Markdown table of [`BenchFigures`]: `first` names the rows, `extra` are
/// columns the game adds after the standard ones (cells it appends to [`table_row`]).
pub fn table_head(first: &str, extra: &[&str]) -> String {
    let mut out = format!("| {first} | frames | frame ms (median) | fps |");
    for p in Phase::ALL {
        out += &format!(" {} ms |", p.name());
    }
    out += " render ms | denoise ms | internal res | spp | emitters sampled | commit KiB (median / max) | scene MB | resident MB |";
    for e in extra {
        out += &format!(" {e} |");
    }
    out += "\n|---|";
    out += &"---:|".repeat(3 + Phase::ALL.len() + 8 + extra.len());
    out + "\n"
}

/// One row of [`table_head`]'s table (no line end: a game appends its extra cells and `\n`).
pub fn table_row(name: &str, f: &BenchFigures) -> String {
    let mut out = format!(
        "| {name} | {} | {:.1} | {:.1} |",
        f.frames,
        f.frame_ms,
        1e3 / f.frame_ms
    );
    for ms in &f.phase_ms {
        out += &format!(" {ms:.2} |");
    }
    let mb = |b: f64| b / 1e6;
    out + &format!(
        " {:.1} | {:.1} | {}×{} | {} | {} | {:.0} / {:.0} | {:.1} | {:.0} |",
        f.render_ms,
        f.denoise_ms,
        f.film.0,
        f.film.1,
        f.spp,
        f.lights,
        f.commit_median as f64 / 1024.0,
        f.commit_max as f64 / 1024.0,
        mb(f.scene_bytes as f64),
        mb(f.rss_bytes as f64)
    )
}

/// The median of `v` (NaN when empty).
pub fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Plays the recording at `path` of `config`'s game with `render` for at most `seconds` of
/// wall time (or until it finishes).
pub fn bench_replay<C: HarnessGame>(
    config: &C,
    path: &Path,
    render: RenderConfig,
    seconds: f64,
) -> Result<BenchFigures, HarnessError> {
    let Started {
        mut engine,
        mut game,
        ..
    } = start_headless(config, Some(path), render)?;
    let mut profiler = crate::app::window::ProfileRecorder::default();
    let profiling = std::env::var_os("CANDELA_PROFILE").is_some_and(|v| v == "1");
    if profiling {
        profiler.set_on(true);
    }
    let begun = Instant::now();
    let mut last = Instant::now();
    let mut dt = 1.0 / 30.0;
    let (mut frame_ms, mut phases, mut rendered) = (Vec::new(), Vec::new(), Vec::new());
    let mut commits = Vec::new();
    while !engine.replay_finished() && begun.elapsed().as_secs_f64() < seconds {
        let report = engine.frame(dt, &mut game)?;
        rendered.extend(engine.rendered().into_iter().flatten());
        let now = Instant::now();
        dt = (now - last).as_secs_f64().min(0.1);
        last = now;
        frame_ms.push(dt * 1e3);
        phases.push(report.phases);
        commits.push(report.commit_bytes);
    }
    profiler.set_on(false);
    if profiling {
        let scopes = profiler.frame(None).map_or(0, |f| {
            f.threads.iter().map(|t| t.scopes.len()).sum::<usize>()
        });
        log::info!(
            "profiler: scopes on, {} frames kept, {scopes} scopes in the last",
            profiler.recent(usize::MAX).len()
        );
    }
    let scene_bytes = engine.scene().memory().total();
    let rss_bytes = super::soak::rss_bytes();
    let _ = engine.shutdown();
    let late_commits: Vec<f64> = commits[commits.len() / 2..]
        .iter()
        .map(|&b| b as f64)
        .collect();
    let late = &rendered[rendered.len() / 2..];
    let mut figures = BenchFigures {
        frames: frame_ms.len(),
        frame_ms: median(frame_ms[frame_ms.len() / 2..].to_vec()),
        render_ms: median(late.iter().map(|r| r.render_seconds * 1e3).collect()),
        denoise_ms: median(late.iter().map(|r| r.denoise_seconds * 1e3).collect()),
        spp: late.iter().map(|r| r.spp).max().unwrap_or(0),
        lights: median(late.iter().map(|r| f64::from(r.lights)).collect()) as u32,
        commit_max: commits.iter().skip(1).copied().max().unwrap_or(0),
        commit_median: median(late_commits) as usize,
        scene_bytes,
        rss_bytes,
        ..Default::default()
    };
    let mut films: Vec<(u32, u32)> = late.iter().map(|r| r.film_size).collect();
    films.sort_unstable();
    figures.film = films.get(films.len() / 2).copied().unwrap_or_default();
    let late_phases = &phases[phases.len() / 2..];
    figures.phase_ms = Phase::ALL
        .iter()
        .map(|&p| median(late_phases.iter().map(|t| t.get(p) * 1e3).collect()))
        .collect();
    Ok(figures)
}
