//! The `reflect` binary's arguments and what each mode does: play in a window inside the
//! engine's shell (title, HUD, pause, settings, chamber select, ending), or replay a recording
//! headless and print one summary line; the headless modes (replay, bench, soak, capture) and
//! recording run through the engine's harness with Reflect's configuration (`harness.rs`).
//!
//! Owns: [`Args`] and [`run`]. Main thread. Must not: contain game rules (`game` has them).

use std::path::{Path, PathBuf};

use anyhow::{Context, bail};
use candela::app::StepInput;
use candela::app::harness::{
    HarnessGame, WindowedPlay, play_shots, play_windowed, start_cue, tour_shots,
};
use candela::app::shell::Cue;
use candela::assets::AssetRoot;
use clap::Parser;

use crate::headless::play_replay;
use crate::replays::{FULL_GAME, open_replay};
use crate::world::ReflectWorld;

/// Reflect: WASD walk, mouse look (click to capture), E pick up / drop / use, left mouse make a
/// mirror, right mouse revert it, Space jump, Shift run, Esc pause.
#[derive(Clone, Debug, Parser)]
#[command(name = "reflect", version)]
pub struct Args {
    /// The game file (default: `assets/reflect/reflect.ron` under the current folder, else
    /// next to the source).
    #[arg(long)]
    pub game: Option<PathBuf>,
    /// Play this recording (a chamber's or the whole game's).
    #[arg(long)]
    pub replay: Option<PathBuf>,
    /// No window: replay the recording on the CPU tracer at 16×9, print a summary line, exit
    /// 0 only if the recording solved what it was recorded for.
    #[arg(long)]
    pub headless: bool,
    /// Windowed: take screenshots (title.png, then play.png in each chamber) into this folder,
    /// then quit.
    #[arg(long)]
    pub screenshots: Option<PathBuf>,
    /// Windowed: show the stats overlay from the start (F3 toggles it).
    #[arg(long)]
    pub stats: bool,
    /// Headless: play every chamber's replay in real time on the CPU tracer with workload
    /// scaling holding the frame rate its level declares and print the frame figures as a Markdown table.
    #[arg(long)]
    pub bench: bool,
    /// Headless: write a converged picture of every chamber into this folder (see
    /// `reflect::capture`).
    #[arg(long)]
    pub capture: Option<PathBuf>,
    /// With --capture: frames to converge (one sample per pixel each).
    #[arg(long, default_value_t = 256)]
    pub capture_frames: u32,
    /// With --capture: the picture's width in pixels.
    #[arg(long, default_value_t = 640)]
    pub capture_width: u32,
    /// With --capture: the picture's height in pixels.
    #[arg(long, default_value_t = 360)]
    pub capture_height: u32,
    /// Windowed: record every fixed step played into this file (written atomically when the
    /// window closes); play starts at once in `--record-chamber`, skipping the title.
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// With --record: the chamber id to record (`chamber_1` …), or `full_game` (from the first
    /// chamber to the ending).
    #[arg(long, default_value = FULL_GAME)]
    pub record_chamber: String,
    /// Headless: measure the level editor over the first chamber (pick latency, the
    /// overlay's cost per frame) and print a Markdown table (see `reflect::bench_editor`).
    #[arg(long)]
    pub bench_editor: bool,
    /// With --bench: most seconds per chamber.
    #[arg(long, default_value_t = 20.0)]
    pub bench_seconds: f64,
    /// With --bench: the output size in pixels, `WIDTHxHEIGHT` (workload scaling traces a
    /// fraction of it, down to the level's `min_scale`).
    #[arg(long, default_value = "640x360", value_parser = parse_size)]
    pub bench_output: (u32, u32),
    /// With --bench: one pixel in this many (1, 2 or 4) traces indirect light, overriding the
    /// levels' `render.indirect_every`.
    #[arg(long, value_parser = parse_every)]
    pub indirect_every: Option<u32>,
    /// With --bench: take the denoiser's guides from the tracer's first hits at the frame's
    /// jitter (the default, as in play), or with `--first-hit-guides false` from a guide pass of
    /// their own (one centre ray per pixel).
    #[arg(long, default_value_t = true, num_args = 0..=1, default_missing_value = "true",
          action = clap::ArgAction::Set)]
    pub first_hit_guides: bool,
    /// Headless: play each chamber this many frames with random input and check every frame
    /// (see `reflect::soak`); prints a Markdown table.
    #[arg(long)]
    pub soak: Option<u64>,
    /// With --soak: the monkey's seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Headless: play the whole game this many frames inside its shell with random input
    /// and random menus, settings, editor, saves and chamber changes, checking every frame
    /// (see `reflect::soak::soak_shell`); prints Markdown tables. Uses --seed.
    #[arg(long)]
    pub soak_shell: Option<u64>,
    /// With --soak: only this chamber (`chamber_1` …); every chamber when absent.
    #[arg(long)]
    pub soak_chamber: Option<String>,
    /// Windowed play and --bench: denoise each frame (SVGF with per-pixel reprojection) before
    /// it is shown. `--denoise false` shows the raw traced film.
    #[arg(long, default_value_t = true, action = clap::ArgAction::Set)]
    pub denoise: bool,
}

/// One pixel in 1, 2 or 4 (`render.indirect_every`).
fn parse_every(text: &str) -> Result<u32, String> {
    match text.trim().parse::<u32>() {
        Ok(n @ (1 | 2 | 4)) => Ok(n),
        _ => Err(format!(
            "{text:?}: one pixel in 1, 2 or 4 traces indirect light"
        )),
    }
}

/// `WIDTHxHEIGHT` in pixels, both above 0.
fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("{text:?}: expected WIDTHxHEIGHT in pixels, e.g. 1280x720");
    let (w, h) = text.split_once(['x', '×']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if w == 0 || h == 0 {
        return Err(bad());
    }
    Ok((w, h))
}

/// The game file and the asset root it lives in (`…/assets`, two folders above it).
pub fn locate(game: Option<&Path>) -> anyhow::Result<(PathBuf, AssetRoot)> {
    let path = match game {
        Some(p) => p.to_path_buf(),
        None => {
            let here = PathBuf::from("assets/reflect/reflect.ron");
            if here.is_file() {
                here
            } else {
                PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/reflect/reflect.ron")
            }
        }
    };
    let root = path
        .parent()
        .and_then(Path::parent)
        .context("the game file must sit in <asset root>/reflect/")?;
    let root = if root.as_os_str().is_empty() {
        Path::new(".")
    } else {
        root
    };
    Ok((path.clone(), AssetRoot::new(root)?))
}

/// Runs what `args` asks; returns the line to print.
pub fn run(args: &Args) -> anyhow::Result<String> {
    let (path, root) = locate(args.game.as_deref())?;
    let world = ReflectWorld::load(&path, &root)?;
    if let Some(dir) = &args.capture {
        let (width, height) = (args.capture_width, args.capture_height);
        anyhow::ensure!(
            width > 0 && height > 0,
            "--capture-width and --capture-height must be above 0"
        );
        let files =
            crate::capture::capture_chambers(&world, dir, width, height, args.capture_frames)?;
        return Ok(format!("wrote {}", files.join(", ")));
    }
    if let Some(frames) = args.soak {
        let chambers = match &args.soak_chamber {
            Some(id) => vec![
                world
                    .level_index(id)
                    .with_context(|| format!("--soak-chamber {id:?}"))?,
            ],
            None => (0..world.chambers.len()).collect(),
        };
        let results = crate::soak::soak_chambers(&world, &chambers, frames, args.seed)?;
        return Ok(crate::soak::table(&results, args.seed));
    }
    if let Some(frames) = args.soak_shell {
        let report = crate::soak::soak_shell(
            &world,
            frames,
            args.seed,
            crate::soak::SHELL_EVERY,
            Vec::new(),
        )?;
        return Ok(crate::soak::shell_table(&report, args.seed));
    }
    if args.bench_editor {
        return crate::bench_editor::bench_editor(&world);
    }
    if args.bench {
        let replays = root.path().join("reflect/replays");
        let options = crate::bench::BenchOptions {
            seconds: args.bench_seconds,
            denoise: args.denoise,
            output: args.bench_output,
            indirect_every: args.indirect_every,
            first_hit_guides: args.first_hit_guides,
        };
        return crate::bench::bench(&world, &root, &replays, &options);
    }
    if args.headless {
        let Some(replay) = &args.replay else {
            bail!("--headless plays a recording: give --replay FILE");
        };
        let whole = candela::app::Recording::read(replay)?.header.level_id == FULL_GAME;
        let summary = play_replay(&world, replay)?;
        let line = summary.line(&world);
        if !summary.solved(whole) {
            bail!(
                "{line}: the recording {} did not solve what it was recorded for",
                replay.display()
            );
        }
        return Ok(line);
    }
    let mut start_input = None;
    let mut start = 0;
    if let Some(path) = &args.replay {
        if args.record.is_some() {
            bail!("--record records the devices: it cannot be given with --replay");
        }
        let (replay, at) = open_replay(&world, path)?;
        start_input = Some(StepInput::Replay(replay));
        start = at;
    }
    if let Some(path) = &args.record {
        start = record_start(&world, &args.record_chamber)?;
        let recorder = world.recorder(&args.record_chamber)?;
        start_input = Some(StepInput::record(recorder, path));
    }
    let playing_at_once = args.replay.is_some() || args.record.is_some();
    let cues = match (&args.screenshots, playing_at_once) {
        // A recording's shot comes sooner: it only shows that play began.
        (Some(dir), true) => {
            let frames = if args.record.is_some() { 120 } else { 400 };
            play_shots(dir, &world.chambers[start].id, 20, frames)
        }
        (Some(dir), false) => tour_shots(dir, &world.level_ids(), 30, 90),
        // A recording starts with its chamber, not with the title menu's steps.
        (None, true) if args.record.is_some() => vec![start_cue(&world.chambers[start].id)],
        (None, _) => Vec::new(),
    };
    let mut game = world.new_game(start);
    if let Some(input) = start_input {
        game.inner_mut().start_with(input);
    }
    game.inner_mut().use_shell_hud();
    // The shell's window with the render configuration game binaries share (the tracer
    // `auto` picks, 1 spp, workload scaling holding the frame rate the level declares).
    let play = WindowedPlay {
        title: "Reflect".into(),
        app: "reflect".into(),
        cues,
        stats: args.stats,
        denoise: args.denoise,
        max_exposure_ev: None,
    };
    let report = play_windowed(&world, &mut game, play)?;
    Ok(format!("{} frames", report.frames))
}

/// The chamber a recording of `id` starts in (`full_game`: the first).
fn record_start(world: &ReflectWorld, id: &str) -> anyhow::Result<usize> {
    if id == FULL_GAME {
        return Ok(0);
    }
    world.chamber_index(id).with_context(|| {
        let ids: Vec<&str> = world.chambers.iter().map(|c| c.id.as_str()).collect();
        format!("--record-chamber {id:?}: the game has {FULL_GAME} and {ids:?}")
    })
}

/// With a replay: the title, then the replay's chamber played for 400 frames, shot, quit.
pub fn replay_cues(dir: &Path, chamber: &str) -> Vec<Cue> {
    play_shots(dir, chamber, 20, 400)
}
