//! `bench picture-ruins`: the error of the picture an It's About Time player sees, per render
//! area, measured as `bench picture` measures Reflect's (`docs/ACCURACY.md`, "The picture a
//! player sees"). For each puzzle (`assets/its_about_time/replays/<puzzle>.replay`):
//! 1. the replay is played once untraced to find where the follow camera stands after each
//!    frame; the compared frames are every `--every`-th frame with the camera inside that
//!    puzzle's render area (at most `--per-area`, spread evenly, at least `--warmup` frames
//!    apart);
//! 2. a reference run renders, on the compared frames, a converged reference of the same
//!    camera, game state and time of day (`picture_tracer.rs`: two halves on seeds of their
//!    own) with the level's bounces and roulette, render areas off (every emitter in the light
//!    table: the full light) and the sky's table exact for the frame (built before it);
//! 3. the game's runs, at each traced size with the denoiser on (and off with `--raw`): render
//!    areas on, the sky's table following on a worker thread, as the game plays; each compared
//!    frame is traced after a camera cut `--warmup` frames before it (frames outside those
//!    windows are not traced: `picture_skip.rs`), so its history holds at most that many frames.
//!
//! Figures as `bench picture`'s (`picture_metrics.rs`): relative MSE on linear radiance, RMSE of
//! the 8-bit sRGB picture exposed as the game exposes it (`Engine::sky_exposure_ev`, capped at
//! `NIGHT_MAX_EV`), the reference's own noise beside each; with `--still`, the still-view
//! stability figure (`picture_ruins_stability.rs`). Printed as Markdown and written to
//! `picture_ruins.csv` (`picture_ruins_report.rs`).
//!
//! Owns: the plan and the measurement loop. Main thread. Must not: draw or format.

use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use candela::assets::RenderArea;
use candela::render::RenderConfig;
use candela::scene::SkyRebuild;
use clap::Args;
use indicatif::ProgressBar;
use its_about_time::replays::named;
use its_about_time::world::RuinsWorld;

use super::picture::progress_bar;
use super::picture_metrics::{reference_noise_at, rel_mse, rmse, srgb_at};
use super::picture_ruins_run::{RuinsRun, play_ruins};
use super::picture_run::Config;
use super::picture_tracer::References;

/// The five puzzles whose replays are measured by default.
pub const PUZZLES: [&str; 5] = [
    "sun_gate",
    "water_stair",
    "weights",
    "rolling_stone",
    "night_shrine",
];

#[derive(Args, Debug, Clone)]
pub struct RuinsPictureArgs {
    /// Folder for the CSV file.
    #[arg(long, default_value = "tools/bench/results/picture_ruins")]
    pub out_dir: PathBuf,
    /// Puzzles (their replays' names); all five when empty.
    #[arg(long, value_delimiter = ',')]
    pub puzzles: Vec<String>,
    /// Candidate frames: every N-th frame with the camera in the puzzle's render area.
    #[arg(long, default_value_t = 15)]
    pub every: u64,
    /// At most this many compared frames per puzzle, spread evenly over its candidates.
    #[arg(long, default_value_t = 1)]
    pub per_area: usize,
    /// Only the first this many frames of each replay (0: all of it).
    #[arg(long, default_value_t = 0)]
    pub within: u64,
    /// Frames traced before each compared frame, after a camera cut.
    #[arg(long, default_value_t = 60)]
    pub warmup: u64,
    /// Samples per pixel of each reference at the smaller size (two independent halves; the
    /// reference is rendered at the larger size with a quarter of them per pixel).
    #[arg(long, default_value_t = 1024)]
    pub reference_spp: u32,
    /// The smaller traced width; the larger size is twice it each way.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// The smaller traced height.
    #[arg(long, default_value_t = 90)]
    pub height: u32,
    /// Also both sizes with the denoiser off.
    #[arg(long)]
    pub raw: bool,
    /// Also the still-view stability figure (`picture_ruins_stability.rs`).
    #[arg(long)]
    pub still: bool,
    /// With `--still`: frames before the figure is taken.
    #[arg(long, default_value_t = 30)]
    pub settle_frames: u64,
    /// With `--still`: consecutive frame pairs compared.
    #[arg(long, default_value_t = 4)]
    pub pairs: u64,
    /// A smoke run: 32×18 and 64×36, 16-spp references, the sun gate's first 150 frames, one
    /// compared frame, 4 warm-up frames (prints only; writes nothing).
    #[arg(long)]
    pub quick: bool,
}

impl RuinsPictureArgs {
    /// `--quick`'s overrides.
    pub fn effective(&self) -> Self {
        let mut a = self.clone();
        if a.quick {
            (a.width, a.height) = (32, 18);
            a.reference_spp = a.reference_spp.min(16);
            a.puzzles = vec!["sun_gate".into()];
            a.within = 150;
            a.every = 10;
            a.per_area = 1;
            a.warmup = 4;
            a.settle_frames = 4;
            a.pairs = 2;
        }
        if a.puzzles.is_empty() {
            a.puzzles = PUZZLES.iter().map(|p| p.to_string()).collect();
        }
        a
    }

    /// The configurations: both sizes denoised (the game's), then with `--raw` both raw.
    pub fn configs(&self) -> Vec<Config> {
        let sizes = [(self.width, self.height), (2 * self.width, 2 * self.height)];
        let denoise = if self.raw {
            &[true, false][..]
        } else {
            &[true]
        };
        denoise
            .iter()
            .flat_map(|&denoise| {
                sizes.map(|(width, height)| Config {
                    width,
                    height,
                    denoise,
                    upscale: 1,
                    indirect_every: 1,
                    first_hit_guides: false,
                })
            })
            .collect()
    }
}

/// One compared frame.
#[derive(Clone, Debug)]
pub struct RuinsCompared {
    pub puzzle: String,
    pub config: Config,
    pub frame: u64,
    /// Local solar time of the frame, hours.
    pub local_hours: f64,
    /// The exposure the game showed it with, stops.
    pub exposure_ev: f32,
    pub rel_mse: f64,
    pub srgb_rmse: f64,
    /// Samples per pixel of the reference at this size.
    pub reference_spp: u32,
    /// The reference's own noise, as the two figures above would count it.
    pub reference_rel_mse: f64,
    pub reference_srgb_rmse: f64,
}

/// Everything one run measured.
pub struct RuinsOutcome {
    pub configs: Vec<Config>,
    pub compared: Vec<RuinsCompared>,
    /// Median trace + denoise ms of a traced frame, per (puzzle, configuration index).
    pub frame_ms: BTreeMap<(String, usize), f64>,
    /// The still-view figures (empty without `--still`).
    pub still: Vec<super::picture_ruins_stability::Still>,
}

/// The compared frames of a camera path (`cameras[f]`: after frame `f`): every `every`-th
/// frame from `warmup` on with the camera in `area`, at most `most` spread evenly, each more
/// than `warmup` frames after the one before (so that no window's cut falls in another's).
pub fn chosen_frames(
    cameras: &[[f32; 3]],
    area: &RenderArea,
    every: u64,
    warmup: u64,
    most: usize,
) -> BTreeSet<u64> {
    let candidates: Vec<u64> = (warmup..cameras.len() as u64)
        .filter(|f| f % every.max(1) == 0 && area.contains(cameras[*f as usize]))
        .collect();
    let n = candidates.len();
    let picked: Vec<u64> = if n <= most {
        candidates
    } else {
        (0..most)
            .map(|i| candidates[(i * n + n / 2) / most])
            .collect()
    };
    let mut out = BTreeSet::new();
    for f in picked {
        if out.last().is_none_or(|&last| f > last + warmup) {
            out.insert(f);
        }
    }
    out
}

/// The camera path of `replay` (at most `frames` frames), nothing traced.
fn camera_path(
    world: &RuinsWorld,
    replay: &std::path::Path,
    frames: u64,
) -> anyhow::Result<Vec<[f32; 3]>> {
    let run = RuinsRun {
        world,
        replay: Some(replay),
        render: RenderConfig {
            sky_rebuild: SkyRebuild::Background,
            ..RenderConfig::cpu(16, 9)
        },
        frames,
        live: BTreeSet::new(),
        cuts: BTreeSet::new(),
        keep: BTreeSet::new(),
    };
    let refs = Arc::new(Mutex::new(References::default()));
    Ok(play_ruins(&run, refs, ProgressBar::hidden())?.cameras)
}

/// Runs the whole measurement.
pub fn measure(args: &RuinsPictureArgs, world: &RuinsWorld) -> anyhow::Result<RuinsOutcome> {
    let args = args.effective();
    let configs = args.configs();
    let large = (2 * args.width, 2 * args.height);
    // A 2×2 block of the large size's pixels is one of the small size's: a quarter of the spp.
    let spp = (args.reference_spp / 4).max(2);
    let most_frames = if args.within > 0 {
        args.within
    } else {
        u64::MAX
    };
    let mut plans = Vec::new();
    for puzzle in &args.puzzles {
        let area = (world.level.render_areas.iter())
            .find(|a| a.name == *puzzle)
            .ok_or_else(|| anyhow::anyhow!("no render area {puzzle:?} in the level"))?;
        let replay = named(world.root.path(), puzzle);
        let cameras = camera_path(world, &replay, most_frames)?;
        let frames = chosen_frames(&cameras, area, args.every, args.warmup, args.per_area);
        anyhow::ensure!(
            !frames.is_empty(),
            "{puzzle}: the camera is in its area on no {}-th frame from frame {} of {}",
            args.every,
            args.warmup,
            cameras.len()
        );
        eprintln!("{puzzle}: compared frames {frames:?} of {}", cameras.len());
        plans.push((puzzle.clone(), replay, frames, cameras));
    }
    let total: u64 = plans.iter().map(|p| p.2.len() as u64).sum();
    let bar = progress_bar(total * u64::from(large.0 * large.1) * u64::from(spp));
    let mut full = world.clone();
    full.level.render_areas.clear();
    let mut outcome = RuinsOutcome {
        configs: configs.clone(),
        compared: Vec::new(),
        frame_ms: BTreeMap::new(),
        still: Vec::new(),
    };
    for (puzzle, replay, frames, cameras) in &plans {
        let last = frames.last().copied().unwrap_or(0) + 1;
        bar.set_message(format!("{puzzle}, references"));
        let refs = Arc::new(Mutex::new(References {
            wanted: frames.clone(),
            spp,
            ..Default::default()
        }));
        let reference = RuinsRun {
            world: &full,
            replay: Some(replay),
            render: RenderConfig::cpu(large.0, large.1),
            frames: last,
            live: frames.clone(),
            cuts: BTreeSet::new(),
            keep: frames.clone(),
        };
        let reference = play_ruins(&reference, refs.clone(), bar.clone())?;
        // A later run whose camera differs would render a reference of its own: count them.
        let rendered = {
            let mut r = refs.lock().expect("references lock");
            r.spp = 2;
            r.rendered
        };
        for (k, config) in configs.iter().enumerate() {
            bar.set_message(format!("{puzzle}, {}", config.label()));
            let live = (frames.iter())
                .flat_map(|&f| f.saturating_sub(args.warmup)..=f)
                .collect();
            let run = RuinsRun {
                world,
                replay: Some(replay),
                render: RenderConfig {
                    denoise: config.denoise,
                    sky_rebuild: SkyRebuild::Background,
                    ..RenderConfig::cpu(config.width, config.height)
                },
                frames: last,
                live,
                cuts: frames
                    .iter()
                    .map(|&f| f.saturating_sub(args.warmup))
                    .collect(),
                keep: frames.clone(),
            };
            let played = play_ruins(&run, refs.clone(), bar.clone())?;
            let refs = refs.lock().expect("references lock");
            for &f in frames {
                let same = played.cameras.get(f as usize) == cameras.get(f as usize)
                    && reference.cameras.get(f as usize) == cameras.get(f as usize);
                anyhow::ensure!(
                    same && refs.rendered == rendered,
                    "{puzzle}, {}: frame {f}'s camera is not the reference run's (the runs diverged)",
                    config.label()
                );
                let (Some(shown), Some(r)) = (played.displayed.get(&f), refs.done.get(&f)) else {
                    anyhow::bail!("{puzzle}: frame {f} missing");
                };
                let r = r.at_width(config.width);
                let mean = r.mean();
                let ev = played.exposure_ev.get(&f).copied().unwrap_or(0.0);
                let ev_ref = reference.exposure_ev.get(&f).copied().unwrap_or(0.0);
                let noise = reference_noise_at(&r, ev_ref);
                outcome.compared.push(RuinsCompared {
                    puzzle: puzzle.clone(),
                    config: *config,
                    frame: f,
                    local_hours: reference.local_hours.get(&f).copied().unwrap_or(f64::NAN),
                    exposure_ev: ev,
                    rel_mse: rel_mse(shown, &mean),
                    srgb_rmse: rmse(&srgb_at(shown, ev), &srgb_at(&mean, ev_ref)),
                    reference_spp: r.spp,
                    reference_rel_mse: noise.0,
                    reference_srgb_rmse: noise.1,
                });
            }
            outcome
                .frame_ms
                .insert((puzzle.clone(), k), played.frame_ms);
            bar.suspend(|| {
                eprintln!(
                    "{puzzle}, {}: {:.1} ms a traced frame",
                    config.label(),
                    played.frame_ms
                )
            });
        }
    }
    bar.finish_with_message("compared frames done");
    if args.still {
        let frames = (args.settle_frames, args.pairs);
        let still_spp = (spp / 4).max(16);
        outcome.still =
            super::picture_ruins_stability::still(world, &configs, large, still_spp, frames)?;
    }
    Ok(outcome)
}

pub fn run(args: &RuinsPictureArgs) -> anyhow::Result<()> {
    let world = RuinsWorld::open(None)?;
    let outcome = measure(args, &world)?;
    println!("{}", super::picture_ruins_report::tables(&outcome));
    if !args.quick {
        let csv = super::picture_ruins_report::write_csv(&args.out_dir, &outcome)?;
        println!("wrote {}", csv.display());
    }
    Ok(())
}
