//! `bench picture`: the error of the picture a Reflect player sees (issue 30, target 2). Each
//! chamber's committed replay runs through the game's real frame loop, headless
//! (`picture_run.rs`), at each configuration: 160×90 and 320×180 traced, one sample per pixel
//! per frame, denoiser off and on, with the converging and temporal accumulation the game
//! uses. Every `--every`-th frame (at most `--per-chamber` of them, spread over the replay) the
//! displayed film is compared with a `--reference-spp` render of the very same view, rendered
//! by the engine's CPU tracer from that frame's own scene and uniforms (`picture_tracer.rs`),
//! at the traced size (the comparison is at the displayed film's size, before the window's
//! upscale: the traced size, or with temporal upscaling (TAAU, `denoise::upscale`) the
//! upscaled one).
//! Figures (`picture_metrics.rs`): relative MSE on linear radiance and RMSE of the tonemapped
//! sRGB picture, beside the reference's own noise; then the temporal stability
//! (`picture_stability.rs`). Prints Markdown tables and writes `picture.csv` into `--out-dir`
//! (`picture_report.rs`) and the chart (`picture_plot.rs`). `--quick` runs the same code at a
//! tiny size in seconds; `--denoised-only` runs the game's (denoised) rows, `--frames` compares
//! chosen frames, `--worst` and `--dump-dir` show where an error comes from
//! (`picture_outliers.rs`).
//!
//! Owns: the plan and the measurement loop. Main thread. Must not: draw or format.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use reflect::world::ReflectWorld;

use super::picture_metrics::{reference_noise, rel_mse, rmse, srgb};
use super::picture_report::{tables, write_csv};
use super::picture_run::{Config, Drive, play, replay_frames};
use super::picture_stability::{Stability, stability};
use super::picture_tracer::References;

#[derive(Args, Debug, Clone)]
pub struct PictureArgs {
    /// Folder for the CSV file.
    #[arg(long, default_value = "tools/bench/results/picture")]
    pub out_dir: PathBuf,
    /// The chart.
    #[arg(long, default_value = "docs/charts/picture_error.png")]
    pub chart: PathBuf,
    /// Compare every N-th frame of a replay.
    #[arg(long, default_value_t = 30)]
    pub every: u64,
    /// At most this many compared frames per chamber, spread evenly over the replay.
    #[arg(long, default_value_t = 3)]
    pub per_chamber: usize,
    /// Only the first this many frames of each replay (0: all of it): bounds the runs' length.
    #[arg(long, default_value_t = 0)]
    pub within: u64,
    /// Samples per pixel of each reference (two independent halves).
    #[arg(long, default_value_t = 1024)]
    pub reference_spp: u32,
    /// Chambers (ids); all when empty.
    #[arg(long, value_delimiter = ',')]
    pub chambers: Vec<String>,
    /// The chamber of the temporal-stability figures.
    #[arg(long, default_value = "chamber_1")]
    pub stability_chamber: String,
    /// Mouse counts per frame of the slow turn.
    #[arg(long, default_value_t = 4.0)]
    pub turn_counts: f32,
    /// Frames before the stability figures are taken.
    #[arg(long, default_value_t = 30)]
    pub settle_frames: u64,
    /// Consecutive frame pairs of the stability figures.
    #[arg(long, default_value_t = 4)]
    pub pairs: u64,
    /// Tiny sizes, few samples, one chamber, one compared frame: a smoke run in seconds
    /// (prints only; writes nothing).
    #[arg(long)]
    pub quick: bool,
    /// Only the denoised configurations (the game's): 160×90, 320×180 and TAAU ×2.
    #[arg(long)]
    pub denoised_only: bool,
    /// Above 1: also both sizes denoised with one pixel in this many (2 or 4) tracing indirect
    /// light (`render/cpu/interleave.rs`), measured after the others.
    #[arg(long, default_value_t = 1)]
    pub indirect_every: u32,
    /// Also both sizes denoised (with `--indirect-every`'s interleaving) with the guides taken
    /// from the tracer's first hits at the frame's jitter (`RenderConfig::first_hit_guides`,
    /// what the games play with since 2026-12-07), instead of the guide pass; measured last.
    #[arg(long)]
    pub first_hit_guides: bool,
    /// Print the N pixels of each compared frame that add most to its relative MSE
    /// (`picture_outliers.rs`).
    #[arg(long, default_value_t = 0)]
    pub worst: usize,
    /// Compare exactly these frames of each replay (overrides `--every` and `--per-chamber`).
    #[arg(long, value_delimiter = ',')]
    pub frames: Vec<u64>,
    /// Write each compared frame and its reference as zoomed PNGs into this folder, and for the
    /// stability figures each pair's first displayed frame and its change map (the absolute
    /// sRGB change summed over the channels, ×4, white = large).
    #[arg(long)]
    pub dump_dir: Option<PathBuf>,
    /// The denoiser's à-trous kernels for every denoised configuration: `5x5` (the default),
    /// `3x3` or `5x5-then-3x3` (`denoise::AtrousKernel`).
    #[arg(long, default_value = "5x5")]
    pub atrous_kernel: String,
}

/// The à-trous kernels `--atrous-kernel` chose (set once by [`run`]).
pub static ATROUS_KERNEL: std::sync::OnceLock<candela::render::denoise::AtrousKernel> =
    std::sync::OnceLock::new();

/// One compared frame.
#[derive(Clone, Debug)]
pub struct Compared {
    pub chamber: String,
    pub config: Config,
    pub frame: u64,
    pub rel_mse: f64,
    pub srgb_rmse: f64,
    /// Samples per pixel of the reference at this size.
    pub reference_spp: u32,
    /// The reference's own noise, as the two figures above would count it.
    pub reference_rel_mse: f64,
    pub reference_srgb_rmse: f64,
}

/// Everything one `bench picture` measured.
pub struct Outcome {
    pub configs: Vec<Config>,
    pub compared: Vec<Compared>,
    /// Median trace + denoise milliseconds per frame, per configuration (median over chambers).
    pub frame_ms: Vec<f64>,
    pub stability: Vec<Stability>,
}

impl PictureArgs {
    /// The configurations measured: 160×90 and 320×180 (`--quick`: 32×18 and 64×36), denoiser
    /// off then on; then the small size traced and upscaled ×2 to the large one by temporal
    /// upscaling, denoiser on (last: the large plain runs render the references it reuses).
    /// `--denoised-only` keeps the denoised ones; `--indirect-every N` adds both sizes denoised
    /// with interleaved indirect light, after them; `--first-hit-guides` both sizes again with the
    /// guides from the first hits, last.
    pub fn configs(&self) -> Vec<Config> {
        let sizes = if self.quick {
            [(32, 18), (64, 36)]
        } else {
            [(160, 90), (320, 180)]
        };
        let mut configs: Vec<Config> = sizes
            .iter()
            .flat_map(|&(width, height)| {
                [false, true].map(|denoise| Config {
                    width,
                    height,
                    denoise,
                    upscale: 1,
                    indirect_every: 1,
                    first_hit_guides: false,
                })
            })
            .collect();
        configs.push(Config {
            width: sizes[1].0,
            height: sizes[1].1,
            denoise: true,
            upscale: 2,
            indirect_every: 1,
            first_hit_guides: false,
        });
        if self.denoised_only {
            configs.retain(|c| c.denoise);
        }
        if self.indirect_every > 1 {
            configs.extend(sizes.iter().map(|&(width, height)| Config {
                width,
                height,
                denoise: true,
                upscale: 1,
                indirect_every: self.indirect_every,
                first_hit_guides: false,
            }));
        }
        if self.first_hit_guides {
            configs.extend(sizes.iter().map(|&(width, height)| Config {
                width,
                height,
                denoise: true,
                upscale: 1,
                indirect_every: self.indirect_every.max(1),
                first_hit_guides: true,
            }));
        }
        configs
    }

    /// `--quick`'s overrides.
    pub fn effective(&self) -> Self {
        let mut a = self.clone();
        if a.quick {
            a.every = 10;
            a.per_chamber = 1;
            a.reference_spp = a.reference_spp.min(64);
            a.chambers = vec![a.stability_chamber.clone()];
            a.settle_frames = 4;
            a.pairs = 2;
        }
        a
    }
}

/// Up to `most` frames among every `every`-th of `frames`, spread evenly.
pub fn sampled_frames(frames: u64, every: u64, most: usize) -> BTreeSet<u64> {
    let candidates: Vec<u64> = (1..=frames / every.max(1)).map(|j| j * every).collect();
    if candidates.len() <= most {
        return candidates.into_iter().collect();
    }
    (0..most)
        .map(|i| candidates[(i * candidates.len() + candidates.len() / 2) / most])
        .collect()
}

/// The references' samples per pixel and the size they are rendered at: the largest
/// configuration's, with `--reference-spp` at the smallest size (a block of the largest size's
/// pixels averages to one of the smallest's, so it holds `f²` times the samples).
pub fn reference_plan(args: &PictureArgs, configs: &[Config]) -> (u32, (u32, u32)) {
    let largest = configs
        .iter()
        .map(|c| (c.width, c.height))
        .max()
        .unwrap_or((1, 1));
    let smallest = configs.iter().map(|c| c.width).min().unwrap_or(1);
    let f = (largest.0 / smallest.max(1)).max(1);
    ((args.reference_spp / (f * f)).max(2), largest)
}

/// The order the configurations run in: the largest size first (it renders the references).
pub fn run_order(configs: &[Config]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..configs.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(configs[k].width));
    order
}

/// A progress bar counting reference samples (pixels × samples per pixel).
pub fn progress_bar(total: u64) -> ProgressBar {
    let bar = ProgressBar::new(total);
    bar.set_style(
        ProgressStyle::with_template(
            "{msg:36} [{elapsed_precise}] {bar:30} {human_pos}/{human_len} reference samples (eta {eta})",
        )
        .expect("progress template"),
    );
    bar
}

/// `--worst` and `--dump-dir` for one compared frame (`picture_outliers.rs`).
fn outliers(
    args: &PictureArgs,
    bar: &ProgressBar,
    name: &str,
    shown: &[glam::Vec3],
    reference: &[glam::Vec3],
    width: u32,
) -> anyhow::Result<()> {
    use super::picture_outliers::{describe, dump, worst_pixels};
    if args.worst > 0 {
        let text = describe(name, &worst_pixels(shown, reference, width, args.worst));
        bar.suspend(|| eprint!("{text}"));
    }
    if let Some(dir) = &args.dump_dir {
        dump(dir, &format!("{name}_shown"), shown, width)?;
        dump(dir, &format!("{name}_reference"), reference, width)?;
    }
    Ok(())
}

/// Runs the whole measurement.
pub fn measure(
    args: &PictureArgs,
    world: &ReflectWorld,
    replays: &Path,
) -> anyhow::Result<Outcome> {
    let args = args.effective();
    let configs = args.configs();
    let chambers: Vec<usize> = if args.chambers.is_empty() {
        (0..world.chambers.len()).collect()
    } else {
        args.chambers
            .iter()
            .map(|id| {
                world
                    .chamber_index(id)
                    .ok_or_else(|| anyhow::anyhow!("no chamber {id:?}"))
            })
            .collect::<anyhow::Result<_>>()?
    };
    let mut plans = Vec::new();
    for &c in &chambers {
        let replay = replays.join(format!("{}.replay", world.chambers[c].id));
        let mut length = replay_frames(world, &replay)?;
        if args.within > 0 {
            length = length.min(args.within);
        }
        let frames = if args.frames.is_empty() {
            sampled_frames(length, args.every, args.per_chamber)
        } else {
            args.frames
                .iter()
                .copied()
                .filter(|&f| f <= length)
                .collect()
        };
        plans.push((c, replay, frames));
    }
    let (spp, largest) = reference_plan(&args, &configs);
    let frames_total: u64 = plans.iter().map(|p| p.2.len() as u64).sum();
    let bar = progress_bar(frames_total * u64::from(largest.0 * largest.1) * u64::from(spp));
    let started = std::time::Instant::now();
    let mut compared = Vec::new();
    let mut times: BTreeMap<usize, Vec<f64>> = BTreeMap::new();
    for (c, replay, frames) in &plans {
        let id = &world.chambers[*c].id;
        // One set of references per chamber, rendered by the first (largest) run.
        let shared = Arc::new(Mutex::new(References {
            wanted: frames.clone(),
            spp,
            ..Default::default()
        }));
        for k in run_order(&configs) {
            let config = configs[k];
            bar.set_message(format!("{id}, {}", config.label()));
            let last = frames.last().copied().unwrap_or(0) + 1;
            let played = play(
                world,
                *c,
                Drive::Replay(replay),
                config,
                last,
                frames,
                shared.clone(),
                bar.clone(),
            )?;
            times.entry(k).or_default().push(played.frame_ms);
            bar.suspend(|| {
                eprintln!(
                    "{id}, {}: {} frames, {:.1} ms a frame, {:.0} s so far",
                    config.label(),
                    played.frames,
                    played.frame_ms,
                    started.elapsed().as_secs_f64()
                )
            });
            let refs = shared.lock().expect("references lock");
            for f in frames {
                let (Some(shown), Some(reference)) = (played.displayed.get(f), refs.done.get(f))
                else {
                    anyhow::bail!(
                        "{id}: frame {f} missing (the replay ran {} frames)",
                        played.frames
                    );
                };
                let reference = reference.at_width(config.width);
                let mean = reference.mean();
                let noise = reference_noise(&reference);
                let name = format!("{id}_{}_{f}", config.label());
                outliers(&args, &bar, &name, shown, &mean, config.width)?;
                compared.push(Compared {
                    chamber: id.clone(),
                    config,
                    frame: *f,
                    rel_mse: rel_mse(shown, &mean),
                    srgb_rmse: rmse(&srgb(shown), &srgb(&mean)),
                    reference_spp: reference.spp,
                    reference_rel_mse: noise.0,
                    reference_srgb_rmse: noise.1,
                });
            }
        }
    }
    bar.finish_with_message("compared frames done");
    let frame_ms = (0..configs.len())
        .map(|k| super::machine::median(times.get(&k).map_or(&[][..], Vec::as_slice)))
        .collect();
    let stability = stability(&args, world, &configs)?;
    Ok(Outcome {
        configs,
        compared,
        frame_ms,
        stability,
    })
}

pub fn run(args: &PictureArgs) -> anyhow::Result<()> {
    let _ = ATROUS_KERNEL.set(super::denoise_frame::parse_kernel(&args.atrous_kernel)?);
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let replays = root.path().join("reflect/replays");
    let outcome = measure(args, &world, &replays)?;
    println!("{}", tables(&outcome));
    if args.quick {
        return Ok(());
    }
    let csv = write_csv(&args.out_dir, &outcome)?;
    super::picture_plot::chart(&args.chart, &outcome)?;
    println!("wrote {} and {}", csv.display(), args.chart.display());
    Ok(())
}
