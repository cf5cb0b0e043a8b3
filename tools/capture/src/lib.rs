//! The capture tool as a library, so tests can run exactly what the command line runs.
//!
//! Owns: argument definitions, loading the level, building the scene, choosing the tracer,
//! rendering in batches with a progress bar, writing PNG/EXR and the final report.
//! Must not: contain rendering logic (the engine does it).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use candela::assets::{AssetRoot, load_level};
use candela::render::film::{TonemapSettings, write_exr, write_png};
use candela::render::{FrameSettings, RenderError, RenderScene, Tracer, frame_uniforms};
use clap::{Parser, ValueEnum};

/// Which tracer renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TracerKind {
    /// wgpu compute (a real GPU, or Mesa's lavapipe on the CPU when there is none).
    Gpu,
    /// The Rust tracer on all CPU cores.
    Cpu,
}

/// Render a level to an image file without any display.
#[derive(Clone, Debug, Parser)]
#[command(name = "capture", version)]
pub struct CaptureArgs {
    /// The level file (RON).
    pub level: PathBuf,
    #[arg(long, value_enum, default_value = "gpu")]
    pub tracer: TracerKind,
    /// Samples per pixel.
    #[arg(long, default_value_t = 64)]
    pub spp: u32,
    #[arg(long, default_value_t = 640)]
    pub width: u32,
    #[arg(long, default_value_t = 360)]
    pub height: u32,
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
}

/// What a capture did.
#[derive(Clone, Debug)]
pub struct CaptureReport {
    pub tracer: &'static str,
    pub device: String,
    pub triangles: usize,
    pub build_seconds: f64,
    pub render_seconds: f64,
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
             {:.3} M samples/s, {:.3} M rays/s",
            self.out.display(),
            self.tracer,
            self.device,
            self.triangles,
            self.build_seconds,
            self.render_seconds,
            self.samples as f64 / t / 1e6,
            self.rays as f64 / t / 1e6,
        )
    }
}

/// Opens the requested tracer over `scene`.
pub fn open_tracer(kind: TracerKind, scene: &RenderScene) -> Result<Box<dyn Tracer>, RenderError> {
    Ok(match kind {
        TracerKind::Cpu => Box::new(candela::render::cpu::CpuTracer::new()),
        TracerKind::Gpu => {
            let context = candela::render::gpu::GpuContext::headless()?;
            Box::new(candela::render::gpu::GpuTracer::new(context, scene)?)
        }
    })
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

/// Runs a capture as the command line would.
pub fn run(args: &CaptureArgs) -> anyhow::Result<CaptureReport> {
    if args.spp == 0 || args.width == 0 || args.height == 0 {
        anyhow::bail!("--spp, --width and --height must be positive");
    }
    let root = level_root(&args.level, args.asset_root.as_deref())?;
    let started = Instant::now();
    let desc = load_level(&args.level, &root)?;
    let scene = RenderScene::build(&desc);
    let build_seconds = started.elapsed().as_secs_f64();
    let mut tracer = open_tracer(args.tracer, &scene)
        .with_context(|| format!("cannot open the {:?} tracer", args.tracer))?;

    let progress = if args.quiet {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(args.spp as u64)
    };
    progress.set_style(
        indicatif::ProgressStyle::with_template(
            "{spinner} {msg} [{bar:40}] {pos}/{len} spp, {elapsed} (eta {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    progress.set_message(format!("{} tracer", tracer.name()));
    let mut rays = 0u64;
    let mut render_seconds = 0.0;
    let mut done = 0;
    while done < args.spp {
        let batch = args.batch.max(1).min(args.spp - done);
        let settings = FrameSettings::new(args.width, args.height, batch, args.seed, &desc.render)
            .continuing(done);
        let uniforms = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            scene.lights.count,
            scene.lights.weight_total,
            scene.tlas_root,
        );
        let stats = tracer.render(&scene, &uniforms)?;
        rays += stats.rays();
        render_seconds += stats.seconds;
        done += batch;
        progress.set_position(done as u64);
    }
    progress.finish_and_clear();
    let film = tracer.film()?;
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
        samples: args.spp as u64 * args.width as u64 * args.height as u64,
        rays,
        out: args.out.clone(),
    })
}
