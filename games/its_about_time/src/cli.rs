//! The `its_about_time` binary's arguments and what each mode does: play in a window inside
//! the engine's shell (title, HUD, pause, settings, the ending), or replay a recording headless
//! and print one summary line (exit 0 only when it reached the ending with every artifact), or
//! time each area's replay (`--bench`).
//!
//! Owns: [`Args`] and [`run`]. Main thread. Must not: contain game rules (`game` has them).

use std::path::PathBuf;

use anyhow::{Context, bail};
use candela::app::StepInput;
use candela::app::harness::{WindowedPlay, play_shots, play_windowed, tour_shots};
use clap::Parser;

use crate::game::TimeGame;
use crate::headless::play_replay;
use crate::replays::{open_replay, recorder};
use crate::world::{LEVEL_ID, RuinsWorld};

/// It's About Time: WASD walk (Shift walks slowly… runs by default), mouse turns the camera
/// (click to capture it), E uses, hold Q / R at a sun altar to turn time back / forward,
/// Space jump, Esc pause, F1 editor.
#[derive(Clone, Debug, Parser)]
#[command(name = "its_about_time", version)]
pub struct Args {
    /// The level file (default: `assets/its_about_time/ruins.ron`).
    #[arg(long)]
    pub level: Option<PathBuf>,
    /// Play this recording.
    #[arg(long)]
    pub replay: Option<PathBuf>,
    /// No window: replay the recording on the CPU tracer at 16×9, print a summary line, exit
    /// 0 only if it reached the ending with every artifact.
    #[arg(long)]
    pub headless: bool,
    /// No window: play each puzzle's committed replay in real time on the CPU tracer
    /// (`--bench-output`, workload scaling holding 30 fps) and print the frame figures as a Markdown table.
    #[arg(long)]
    pub bench: bool,
    /// With --bench: seconds of wall time per replay.
    #[arg(long, default_value_t = 12.0)]
    pub bench_seconds: f64,
    /// With --bench: the output size in pixels, `WIDTHxHEIGHT` (workload scaling traces a
    /// fraction of it, down to the level's `min_scale`: 160×90 of 640×360, 320×180 of 1280×720).
    #[arg(long, default_value = "640x360", value_parser = parse_size)]
    pub bench_output: (u32, u32),
    /// Windowed: take screenshots (title.png, then play.png) into this folder, then quit.
    #[arg(long)]
    pub screenshots: Option<PathBuf>,
    /// With --replay and --screenshots: the frames (counted from the start of play, ascending)
    /// to take `play_<frame>.png` at, instead of one `play.png` at frame 400.
    #[arg(long, value_delimiter = ',')]
    pub shots_at: Vec<u32>,
    /// Windowed: show the stats overlay from the start (F3 toggles it).
    #[arg(long)]
    pub stats: bool,
    /// Windowed: record every fixed step played into this file (written atomically when the
    /// window closes); play starts at once, skipping the title.
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// Windowed: denoise each frame before it is shown (`--denoise false`: the raw film).
    #[arg(long, default_value_t = true, action = clap::ArgAction::Set)]
    pub denoise: bool,
    /// Sample every light group everywhere, as if the level declared no `render_areas` (the
    /// level file, and so the replays' level hash, stay as they are): to compare with areas.
    #[arg(long)]
    pub no_render_areas: bool,
    /// With --headless: write the camera's position after each frame, and the render areas
    /// holding it, to this CSV file (`frame,x,y,z,areas`).
    #[arg(long)]
    pub camera_path: Option<PathBuf>,
}

/// `1280x720` → (1280, 720).
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

/// The title, then play from the start with a shot `play_<frame>.png` at each of `frames`
/// (ascending, counted from the start of play), then quit.
fn replay_shots(dir: &std::path::Path, frames: &[u32]) -> Vec<candela::app::shell::Cue> {
    use candela::app::shell::{Cue, ShellInput};
    let mut cues = vec![
        Cue::screenshot(20, dir.join("title.png")),
        candela::app::harness::start_cue(LEVEL_ID),
    ];
    let mut at = 0;
    for &frame in frames {
        cues.push(Cue::screenshot(
            frame.saturating_sub(at).max(1),
            dir.join(format!("play_{frame}.png")),
        ));
        at = frame.max(at);
    }
    cues.push(Cue::input(2, ShellInput::Quit));
    cues
}

/// Runs what `args` asks; returns the line to print.
pub fn run(args: &Args) -> anyhow::Result<String> {
    let mut world = RuinsWorld::open(args.level.as_deref())?;
    if args.no_render_areas {
        world.level.render_areas.clear();
    }
    if args.bench {
        return crate::bench::bench(&world, args.bench_seconds, args.denoise, args.bench_output);
    }
    if args.headless {
        let Some(replay) = &args.replay else {
            bail!("--headless plays a recording: give --replay FILE");
        };
        let summary = play_replay(&world, replay)?;
        if let Some(out) = &args.camera_path {
            let areas = &world.level.render_areas;
            std::fs::write(
                out,
                crate::camera_areas::path_csv(areas, &summary.camera_path),
            )
            .with_context(|| format!("writing the camera path {}", out.display()))?;
            eprintln!(
                "{}",
                crate::camera_areas::shares_line(areas, &summary.camera_path)
            );
        }
        let line = summary.line();
        if !summary.solved() {
            bail!(
                "{line}: the recording {} did not reach the ending with every artifact",
                replay.display()
            );
        }
        return Ok(line);
    }
    let mut game = TimeGame::new(world.clone());
    if let Some(path) = &args.replay {
        if args.record.is_some() {
            bail!("--record records the devices: it cannot be given with --replay");
        }
        game.start_with(StepInput::Replay(open_replay(&world, path)?));
    }
    if let Some(path) = &args.record {
        game.start_with(StepInput::record(recorder(&world)?, path));
    }
    let playing_at_once = args.replay.is_some() || args.record.is_some();
    let cues = match (&args.screenshots, playing_at_once) {
        (Some(dir), true) if !args.shots_at.is_empty() => replay_shots(dir, &args.shots_at),
        (Some(dir), true) => play_shots(dir, LEVEL_ID, 20, 400),
        (Some(dir), false) => tour_shots(dir, &[LEVEL_ID.to_string()], 30, 120),
        (None, true) => vec![candela::app::harness::start_cue(LEVEL_ID)],
        (None, false) => Vec::new(),
    };
    let play = WindowedPlay {
        title: "It's About Time".into(),
        app: "its_about_time".into(),
        cues,
        stats: args.stats,
        denoise: args.denoise,
        max_exposure_ev: Some(crate::game::NIGHT_MAX_EV),
    };
    let report = play_windowed(&world, &mut game, play)?;
    Ok(format!("{} frames", report.frames))
}
