//! The capture tool as a library, so tests can run exactly what the command line runs.
//!
//! Owns: argument definitions, and the single-frame mode: loading the level, building the
//! scene, choosing the tracer, rendering in batches with a progress bar (each batch a frame of
//! the denoiser with `--denoise`), writing PNG/EXR and the final report. The script mode (`--script`) is in `script_mode.rs`.
//! Must not: contain rendering logic (the engine does it).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use candela::assets::{AssetRoot, LightSampling, load_scene};
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::Svgf;
use candela::render::film::{TonemapSettings, write_exr, write_png};
use candela::render::{FrameSettings, RenderError, Tracer, TracerChoice, frame_uniforms};
use candela::scene::RenderScene;
use clap::{Parser, ValueEnum};

mod script_mode;
pub use script_mode::{ScriptSummary, run_script_mode};

/// Which tracer renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TracerKind {
    /// The GPU tracer on a real GPU, the CPU tracer when the only adapter is a software one
    /// (lavapipe) or there is none; the log says which.
    Auto,
    /// wgpu compute (a real GPU, or Mesa's lavapipe on the CPU when there is none).
    Gpu,
    /// The Rust tracer on all CPU cores.
    Cpu,
}

/// Render a level to an image file without any display, or run a capture script.
#[derive(Clone, Debug, Parser)]
#[command(name = "capture", version)]
pub struct CaptureArgs {
    /// The level file (RON); not with `--script`.
    #[arg(required_unless_present = "script", conflicts_with = "script")]
    pub level: Option<PathBuf>,
    /// Run a capture script (RON, see `engine/src/app/script/desc.rs`): its frames, camera, motions,
    /// light switches and screenshots. `--tracer`, `--spp`, `--width`, `--height` override it.
    #[arg(long)]
    pub script: Option<PathBuf>,
    /// Folder for the script's screenshots and `frames.csv`.
    #[arg(long, default_value = "capture_out")]
    pub out_dir: PathBuf,
    /// Tracer [default: auto (the GPU tracer on a real GPU, else the CPU tracer); with --script:
    /// the script's].
    #[arg(long, value_enum)]
    pub tracer: Option<TracerKind>,
    /// Samples per pixel [default: 64, or no cap with --seconds; with --script: the script's,
    /// per frame].
    #[arg(long)]
    pub spp: Option<u32>,
    /// Stop at a time budget instead of a sample count: render batches of `--batch` samples
    /// until the tracer's render time reaches this many seconds (the last batch may end past
    /// it), then write the image. `--spp`, if given, still caps the samples. Not with --script.
    #[arg(long, conflicts_with = "script")]
    pub seconds: Option<f64>,
    /// Width in pixels [default: 640; with --script: the script's].
    #[arg(long)]
    pub width: Option<u32>,
    /// Height in pixels [default: 360; with --script: the script's].
    #[arg(long)]
    pub height: Option<u32>,
    /// Output PNG (tonemapped 8-bit sRGB).
    #[arg(long, default_value = "frame.png")]
    pub out: PathBuf,
    /// Also write linear radiance as 32-bit float OpenEXR.
    #[arg(long)]
    pub exr: Option<PathBuf>,
    /// Random seed: the same seed and settings give the same image.
    #[arg(long, default_value_t = 0)]
    pub seed: u32,
    /// Folder every path of the level must stay in (default: the level file's folder).
    #[arg(long)]
    pub asset_root: Option<PathBuf>,
    /// Exposure in stops for the PNG.
    #[arg(long, default_value_t = 0.0)]
    pub exposure: f32,
    /// Samples per pixel per dispatch (the progress bar moves once per batch).
    #[arg(long, default_value_t = 4)]
    pub batch: u32,
    /// Hide the progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Denoise (SVGF, `candela::render::denoise`): each batch of `--batch` samples is one frame
    /// of the denoiser's history, guides from the CPU guide pass. Biased: off by default.
    #[arg(long)]
    pub denoise: bool,
    /// How lights are picked: `power` (one table by power) or `tree` (the light tree, by
    /// importance from each point) [default: the level's `render.light_sampling`].
    #[arg(long, value_parser = clap::builder::TypedValueParser::map(
        clap::builder::PossibleValuesParser::new(["power", "tree"]),
        |s: String| if s == "tree" { LightSampling::Tree } else { LightSampling::Power },
    ))]
    pub light_sampling: Option<LightSampling>,
}

/// What a capture did.
#[derive(Clone, Debug)]
pub struct CaptureReport {
    pub tracer: &'static str,
    pub device: String,
    pub triangles: usize,
    pub build_seconds: f64,
    pub render_seconds: f64,
    /// Render seconds of the slowest batch (with `--seconds`, the run stops at the first batch
    /// that ends past the budget, so `render_seconds - slowest_batch_seconds` is under it).
    pub slowest_batch_seconds: f64,
    /// Samples per pixel rendered (the requested count, or what fit in `--seconds`).
    pub spp: u32,
    pub samples: u64,
    pub rays: u64,
    pub out: PathBuf,
}

impl std::fmt::Display for CaptureReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = self.render_seconds.max(1e-9);
        write!(
            f,
            "wrote {}\n{} tracer on {}: {} triangles, scene build {:.3} s, render {:.3} s, \
             {} spp, {:.3} M samples/s, {:.3} M rays/s",
            self.out.display(),
            self.tracer,
            self.device,
            self.triangles,
            self.build_seconds,
            self.render_seconds,
            self.spp,
            self.samples as f64 / t / 1e6,
            self.rays as f64 / t / 1e6,
        )
    }
}

/// Opens the requested tracer over `scene`.
pub fn open_tracer(kind: TracerKind, scene: &RenderScene) -> Result<Box<dyn Tracer>, RenderError> {
    Ok(match resolve(kind) {
        TracerKind::Cpu | TracerKind::Auto => Box::new(candela::render::cpu::CpuTracer::new()),
        TracerKind::Gpu => {
            let context = candela::render::gpu::GpuContext::headless()?;
            Box::new(candela::render::gpu::GpuTracer::new(context, scene)?)
        }
    })
}

/// `kind` with `Auto` resolved to the GPU or the CPU tracer (`candela::render::auto`).
pub fn resolve(kind: TracerKind) -> TracerKind {
    match kind {
        TracerKind::Auto => match candela::render::auto::resolve(TracerChoice::Auto, None) {
            TracerChoice::Gpu => TracerKind::Gpu,
            _ => TracerKind::Cpu,
        },
        other => other,
    }
}

fn level_root(level: &Path, asset_root: Option<&Path>) -> anyhow::Result<AssetRoot> {
    let folder = match asset_root {
        Some(root) => root.to_path_buf(),
        None => level
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .map(Path::to_path_buf)
            .unwrap_or_else(|| PathBuf::from(".")),
    };
    Ok(AssetRoot::new(&folder)?)
}

/// Renders one level to one image, as the command line does without `--script`.
pub fn run(args: &CaptureArgs) -> anyhow::Result<CaptureReport> {
    let Some(level) = &args.level else {
        anyhow::bail!("give a level file, or a capture script with --script");
    };
    let budget = args.seconds;
    if let Some(s) = budget
        && !(s.is_finite() && s > 0.0)
    {
        anyhow::bail!("--seconds must be a positive number of seconds, not {s}");
    }
    let (spp, width, height) = (
        args.spp
            .unwrap_or(if budget.is_some() { u32::MAX } else { 64 }),
        args.width.unwrap_or(640),
        args.height.unwrap_or(360),
    );
    let tracer_kind = args.tracer.unwrap_or(TracerKind::Auto);
    if spp == 0 || width == 0 || height == 0 {
        anyhow::bail!("--spp, --width and --height must be positive");
    }
    let root = level_root(level, args.asset_root.as_deref())?;
    let started = Instant::now();
    let mut desc = load_scene(level, &root)?;
    if let Some(sampling) = args.light_sampling {
        desc.render.light_sampling = sampling;
    }
    let scene = RenderScene::build(&desc);
    let build_seconds = started.elapsed().as_secs_f64();
    let mut tracer = open_tracer(tracer_kind, &scene)
        .with_context(|| format!("cannot open the {tracer_kind:?} tracer"))?;

    // With a time budget the bar counts render milliseconds, else samples per pixel.
    let (length, template) = match budget {
        Some(s) => (
            (s * 1000.0).ceil() as u64,
            "{spinner} {msg} [{bar:40}] {pos}/{len} ms of render time, {elapsed}",
        ),
        None => (
            spp as u64,
            "{spinner} {msg} [{bar:40}] {pos}/{len} spp, {elapsed} (eta {eta})",
        ),
    };
    let progress = if args.quiet {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(length)
    };
    progress.set_style(
        indicatif::ProgressStyle::with_template(template)
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    progress.set_message(format!("{} tracer", tracer.name()));
    let mut rays = 0u64;
    let mut render_seconds = 0.0;
    let mut slowest_batch_seconds = 0.0f64;
    let mut done = 0;
    let mut denoiser = args
        .denoise
        .then(|| Svgf::new(candela::render::denoise::SvgfParams::default()));
    let mut guides = None;
    let mut denoised = None;
    while done < spp && budget.is_none_or(|s| render_seconds < s) {
        let batch = args.batch.max(1).min(spp - done);
        let mut settings =
            FrameSettings::new(width, height, batch, args.seed, &desc.render).continuing(done);
        let blend = settings.film_blend;
        if denoiser.is_some() {
            // The tracer's film holds this batch alone; the denoiser's history blends.
            settings.film_blend = 1.0;
        }
        let uniforms = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            &scene.header(),
        );
        let stats = tracer.render(&scene, &uniforms)?;
        rays += stats.rays();
        render_seconds += stats.seconds;
        slowest_batch_seconds = slowest_batch_seconds.max(stats.seconds);
        if let Some(svgf) = denoiser.as_mut() {
            let g = guides.get_or_insert_with(|| trace_guides(&scene, &uniforms));
            denoised = Some(svgf.denoise(&tracer.film()?.mean, g, blend)?);
        }
        done += batch;
        progress.set_position(match budget {
            Some(_) => (render_seconds * 1000.0) as u64,
            None => done as u64,
        });
    }
    progress.finish_and_clear();
    let film = match denoised {
        Some(film) => film,
        None => tracer.film()?,
    };
    let pixels = &film.mean;
    let tonemap = TonemapSettings {
        exposure_ev: args.exposure,
        ..Default::default()
    };
    write_png(&args.out, film.width, film.height, pixels, &tonemap)?;
    if let Some(exr) = &args.exr {
        write_exr(exr, film.width, film.height, pixels)?;
    }
    Ok(CaptureReport {
        tracer: tracer.name(),
        device: tracer.device(),
        triangles: scene.stats.instanced_triangles,
        build_seconds,
        render_seconds,
        slowest_batch_seconds,
        spp: done,
        samples: done as u64 * width as u64 * height as u64,
        rays,
        out: args.out.clone(),
    })
}
