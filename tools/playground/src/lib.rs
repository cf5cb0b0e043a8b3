//! The `playground` tool as a library: play a platform test level in first person
//! (`candela::app::FirstPersonGame`) in a window inside the shell (title menu, HUD, pause,
//! settings: `candela::app::run_game`), soak it with random input, or headless — replaying a
//! recording step by step and summing it up in one line, or timing the replay (`--bench`:
//! fixed steps per second with the least rendering, eight steps per rendered 16×9 frame on the
//! CPU tracer). Every mode is the engine harness's (`candela::app::harness`: `soak_levels`,
//! `run_fixed_steps`, `play_windowed`) with `FirstPersonLevel` as the configuration.
//!
//! Owns: the arguments, loading (a bad level or replay fails before anything runs) and the
//! summary line. Must not: contain game logic (the engine's `FirstPersonGame` has it) or loops
//! of its own (the harness has them). `--record`
//! records a windowed run (the window runner writes the file when the window closes); the
//! committed replays are recorded by a bot, `engine/examples/record_platform_replays.rs`.

use std::path::{Path, PathBuf};

use anyhow::{Context, bail};
use candela::app::StepInput;
use candela::app::harness::{
    FirstPersonLevel, FixedSteps, WindowedPlay, play_shots, play_windowed, run_fixed_steps,
    soak_levels,
};
use candela::assets::AssetRoot;
use candela::sim::triggers::Outcome;
use clap::Parser;

/// Play a level in first person: WASD to walk, mouse to look (click to capture it), E to use
/// or to pick up and drop, left button to throw, Space to jump, Shift to run.
#[derive(Clone, Debug, Parser)]
#[command(name = "playground", version)]
pub struct Args {
    /// The level file (RON).
    pub level: PathBuf,
    /// Folder every path of the level must stay in (default: the level file's folder).
    #[arg(long)]
    pub asset_root: Option<PathBuf>,
    /// Play this recording instead of the devices.
    #[arg(long)]
    pub replay: Option<PathBuf>,
    /// Windowed: record every fixed step played into this file (written atomically when the
    /// window closes). Play one run from the level's start: a restart is recorded as more
    /// steps of the same run.
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// No window: run fixed steps on the CPU tracer at 16×9 and print a summary.
    #[arg(long)]
    pub headless: bool,
    /// Headless: fixed steps to run (default: the replay's length, else 600).
    #[arg(long)]
    pub steps: Option<u64>,
    /// Headless: time the run (eight steps per rendered frame) and print steps per second.
    #[arg(long)]
    pub bench: bool,
    /// Headless: soak the level for this many frames with random input (see `candela::app::soak`).
    #[arg(long)]
    pub soak: Option<u64>,
    /// Windowed: take screenshots of the title menu and of play (title.png, play.png in this
    /// folder), walking forward a little, then quit (a look at the game under Xvfb).
    #[arg(long)]
    pub screenshots: Option<PathBuf>,
    /// Windowed: show the stats overlay from the start (F3 toggles it).
    #[arg(long)]
    pub stats: bool,
    /// The soak's random seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

fn asset_root(level: &Path, root: Option<&Path>) -> anyhow::Result<AssetRoot> {
    let dir = match root {
        Some(r) => r.to_path_buf(),
        // A bare file name's parent is "": the current folder.
        None => match level.parent().context("the level has no folder")? {
            p if p.as_os_str().is_empty() => PathBuf::from("."),
            p => p.to_path_buf(),
        },
    };
    Ok(AssetRoot::new(dir)?)
}

/// Runs what `args` asks; returns the summary line.
pub fn run(args: &Args) -> anyhow::Result<String> {
    if args.record.is_some() && (args.replay.is_some() || args.headless || args.bench) {
        bail!("--record records the devices in a window: not with --replay, --headless or --bench");
    }
    let root = asset_root(&args.level, args.asset_root.as_deref())?;
    let level = FirstPersonLevel::load(&args.level, &root)?;
    if let Some(frames) = args.soak {
        let soaks = soak_levels(&level, &[0], frames, args.seed, |_| ())?;
        let r = &soaks[0].report;
        let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
        return Ok(format!(
            "{}: soak of {} frames (seed {}): no NaN, nothing fell out, {} film checks finite; \
             resident memory {:.1} MiB after warm-up, {:.1} MiB at the end",
            args.level.display(),
            r.frames,
            args.seed,
            r.film_checks,
            mib(r.rss_warm),
            mib(r.rss_end)
        ));
    }
    if args.headless || args.bench {
        return headless(args, &level);
    }
    let mut game = level.game();
    if let Some(path) = &args.replay {
        game.start_with(StepInput::Replay(game.open_replay(path)?));
    }
    if let Some(path) = &args.record {
        game.start_with(StepInput::record(game.recorder()?, path));
    }
    // The shell around the game: title menu, HUD, pause (Escape), settings saved in the
    // player's config folder; `run_game` sets the input map from the actions and settings.
    game.use_shell_hud();
    let play = WindowedPlay {
        title: format!("Candela playground — {}", args.level.display()),
        app: "playground".into(),
        cues: args
            .screenshots
            .as_deref()
            .map(|dir| play_shots(dir, &game.level_id(), 30, 60))
            .unwrap_or_default(),
        stats: args.stats,
        // Denoised as Reflect is: the row kernels take 5–10 ms a frame at 320×180 on two cores
        // (docs/PERFORMANCE.md, "Denoiser time per frame"), and a 1-spp film in motion is noise.
        denoise: true,
        max_exposure_ev: None,
    };
    // The shell's window with the render configuration game binaries share (the tracer
    // `auto` picks, 640×360 at 1 spp, holding 30 fps by workload scaling).
    let report = play_windowed(&level, &mut game, play)?;
    Ok(format!("{} frames", report.frames))
}

/// Headless: the engine harness's fixed-step run (`candela::app::harness::run_fixed_steps`,
/// eight steps a frame for `--bench`) summed up in the one line the tool prints.
fn headless(args: &Args, level: &FirstPersonLevel) -> anyhow::Result<String> {
    let per_frame = if args.bench { 8 } else { 1 };
    let run = FixedSteps {
        steps: args.steps,
        without_recording: 600,
        per_frame,
    };
    let end = run_fixed_steps(level, args.replay.as_deref(), run, |end| Summary {
        steps: end.steps,
        seconds: end.seconds,
        hash: end.engine.state_hash(),
        outcome: end.engine.logic().outcome().cloned(),
        recorded: end.recorded,
        finished: end.replay_finished,
    })?;
    let done = end.steps;
    let mut line = format!(
        "{}: {done} steps, outcome {:?}, state hash {:016x}",
        args.level.display(),
        end.outcome,
        end.hash
    );
    if let (Some(path), Some(recorded)) = (&args.replay, end.recorded) {
        line += &format!(", replay {} ({recorded} steps)", path.display());
        if !end.finished {
            bail!("{line}: the replay did not finish in {done} steps");
        }
    }
    if args.bench {
        let rate = done as f64 / end.seconds;
        line += &format!(
            ", {rate:.0} steps/s = {:.1}× real time at 60 Hz ({per_frame} steps per 16×9 CPU frame)",
            rate / 60.0
        );
    }
    Ok(line)
}

/// What the tool reads of a finished headless run.
struct Summary {
    steps: u64,
    seconds: f64,
    hash: u64,
    outcome: Option<Outcome>,
    recorded: Option<u64>,
    finished: bool,
}
