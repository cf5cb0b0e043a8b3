//! The `view` tool as a library, so tests run exactly what the command line runs: open a level
//! in a window with the fly camera and the stats overlay; with `--frames N --screenshot
//! out.png`, leave by itself after N frames and write what the window showed.
//!
//! Owns: argument definitions, loading the level (before any window opens, so that a bad
//! level fails fast), the game hooks (spawn the level and a fly camera; move the camera every
//! frame), and the printed report. Must not: contain engine logic (the engine's window runner
//! does the work).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use anyhow::Context;
use candela::app::edit::{EditHooks, EditTarget};
use candela::app::{
    Engine, Environment, FlyCamera, FrameInput, Game, InputMap, SetupError, SpawnedLevel,
    WindowConfig, WindowReport, fly_camera_system, run_window,
};
use candela::assets::{AssetRoot, SceneDesc};
use candela::level::{PlayableLevel, load_level};
use candela::render::film::{ConvergePolicy, TonemapSettings};
use candela::render::scaling::ScalingTarget;
use candela::render::{RenderConfig, TracerChoice};
use clap::{Parser, ValueEnum};
use glam::{Vec3, Vec4Swizzles};

/// Which tracer renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TracerKind {
    /// The GPU tracer on a real GPU, the CPU tracer when the only adapter is a software one
    /// (lavapipe, where the CPU tracer is far faster) or there is none.
    Auto,
    /// wgpu compute on the window's device (a real GPU, or Mesa's lavapipe).
    Gpu,
    /// The Rust tracer on all CPU cores; its film is uploaded for presenting.
    Cpu,
}

/// Open a level in a window: fly with WASD/QE (shift: faster), click to look around with the
/// mouse, Escape to release the mouse (again to leave), F1 the level editor, F3 stats, F5 the
/// profiler, F4 vsync, F11 fullscreen.
#[derive(Clone, Debug, Parser)]
#[command(name = "view", version)]
pub struct ViewArgs {
    /// The level file (RON).
    pub level: PathBuf,
    /// Folder every path of the level must stay in (default: the level file's folder).
    #[arg(long)]
    pub asset_root: Option<PathBuf>,
    #[arg(long, value_enum, default_value = "auto")]
    pub tracer: TracerKind,
    /// Samples per pixel per frame (the start when --target-fps scales the workload).
    #[arg(long, default_value_t = 1)]
    pub spp: u32,
    /// Window width, physical pixels (the render size follows the window).
    #[arg(long, default_value_t = 1280)]
    pub width: u32,
    #[arg(long, default_value_t = 720)]
    pub height: u32,
    /// Random seed: the same seed, settings and frame count give the same image.
    #[arg(long, default_value_t = 0)]
    pub seed: u32,
    /// Denoise every frame (SVGF; biased: off by default in the viewer).
    #[arg(long)]
    pub denoise: bool,
    /// Exposure in stops.
    #[arg(long, default_value_t = 0.0)]
    pub exposure: f32,
    /// Leave after this many frames.
    #[arg(long)]
    pub frames: Option<u64>,
    /// With --frames: write what the window showed on the last frame (8-bit sRGB PNG).
    #[arg(long, requires = "frames")]
    pub screenshot: Option<PathBuf>,
    /// With --frames: keep the last frame on screen this many seconds before closing.
    #[arg(long, default_value_t = 0.0)]
    pub hold: f64,
    /// Present without waiting for vertical blank (mailbox or immediate).
    #[arg(long)]
    pub no_vsync: bool,
    /// Start frames at most this often (vsync does not pace under Xvfb).
    #[arg(long)]
    pub max_fps: Option<f64>,
    #[arg(long)]
    pub fullscreen: bool,
    /// Scale spp, roulette and resolution to hold this frame rate.
    #[arg(long)]
    pub target_fps: Option<f32>,
    /// Start with the stats overlay hidden (F3 shows it).
    #[arg(long)]
    pub no_stats: bool,
    /// An input map (RON) whose actions replace the defaults of the same name.
    #[arg(long)]
    pub input: Option<PathBuf>,
    /// Fly speed, metres per second (default: the level's size crossed in about 10 s).
    #[arg(long)]
    pub speed: Option<f32>,
}

/// The level's folder, or the one given.
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

/// The diagonal of the level's bounding box, metres (0 for an empty level).
pub fn level_extent(desc: &SceneDesc) -> f32 {
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for instance in &desc.instances {
        let Some(model) = desc.models.get(instance.model) else {
            continue;
        };
        for placement in &model.placements {
            let Some(mesh) = model.meshes.get(placement.mesh) else {
                continue;
            };
            let world_from_mesh = instance.world_from_model * placement.model_from_mesh;
            for p in &mesh.positions {
                let w = (world_from_mesh * p.extend(1.0)).xyz();
                lo = lo.min(w);
                hi = hi.max(w);
            }
        }
    }
    if lo.x <= hi.x {
        (hi - lo).length()
    } else {
        0.0
    }
}

/// The game `view` plays: the level and a fly camera; F1 edits the level file.
struct ViewGame {
    level: PlayableLevel,
    speed: f32,
    edit: EditTarget,
    spawned: SpawnedLevel,
}

impl EditHooks for ViewGame {
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)> {
        Some((self.edit.clone(), self.spawned.clone()))
    }

    fn level_respawned(&mut self, _engine: &mut Engine, spawned: &SpawnedLevel) {
        self.spawned = spawned.clone();
    }
}

impl Game for ViewGame {
    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        Some(self)
    }

    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        self.spawned = engine.spawn_level(&self.level);
        let (camera, transform, rig) = FlyCamera::from_view(&self.level.scene.camera, self.speed);
        engine.world_mut().spawn((camera, transform, rig));
        Ok(())
    }

    fn frame(&mut self, frame: &mut FrameInput<'_>) {
        fly_camera_system(frame.world, frame.input, frame.frame_seconds as f32);
    }
}

/// A stop flag that Ctrl-C (SIGINT) sets, for [`run`]: the window loop then ends at the next
/// frame and the render thread is joined. Call it once per process.
pub fn stop_on_ctrl_c() -> anyhow::Result<Arc<AtomicBool>> {
    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    ctrlc::set_handler(move || flag.store(true, Ordering::Relaxed))
        .context("cannot install the Ctrl-C handler")?;
    Ok(stop)
}

/// Runs the viewer as the command line would; `stop` ends it at the next frame (Ctrl-C).
pub fn run(args: &ViewArgs, stop: Arc<AtomicBool>) -> anyhow::Result<WindowReport> {
    if args.spp == 0 || args.width == 0 || args.height == 0 {
        anyhow::bail!("--spp, --width and --height must be positive");
    }
    let root = level_root(&args.level, args.asset_root.as_deref())?;
    let level = load_level(&args.level, &root)?;
    let desc = &level.scene;
    let mut input = InputMap::fly_camera_defaults();
    if let Some(path) = &args.input {
        input = input.merged(InputMap::load(path)?);
    }
    let config = WindowConfig {
        title: format!("Candela — {}", args.level.display()),
        size: (args.width, args.height),
        fullscreen: args.fullscreen,
        vsync: !args.no_vsync,
        max_fps: args.max_fps,
        tonemap: TonemapSettings {
            exposure_ev: args.exposure,
            ..Default::default()
        },
        auto_exposure: false,
        max_exposure_ev: f32::INFINITY,
        show_stats: !args.no_stats,
        input,
        frames: args.frames,
        screenshot: args.screenshot.clone(),
        hold_seconds: args.hold.max(0.0),
        stop,
    };
    let render = RenderConfig {
        tracer: match args.tracer {
            TracerKind::Auto => TracerChoice::Auto,
            TracerKind::Gpu => TracerChoice::Gpu,
            TracerKind::Cpu => TracerChoice::Cpu,
        },
        width: args.width,
        height: args.height,
        spp: args.spp,
        seed: args.seed,
        converge: ConvergePolicy::default(),
        scaling: args
            .target_fps
            .filter(|f| *f > 0.0)
            .map(|f| ScalingTarget::new(1.0 / f)),
        denoise: args.denoise,
        light_sampling: None,
        indirect_every: None,
        first_hit_guides: true,
        atrous_kernel: Default::default(),
        sky_rebuild: candela::scene::SkyRebuild::Background,
        temporal_upscale: None,
    };
    let speed = args
        .speed
        .unwrap_or_else(|| (level_extent(desc) / 10.0).clamp(0.5, 100.0));
    let environment = Environment::of(desc);
    let mut game = ViewGame {
        level,
        speed,
        edit: EditTarget::single_file(&args.level, root),
        spawned: SpawnedLevel::default(),
    };
    run_window(config, render, environment, &mut game)
        .with_context(|| format!("cannot view {}", args.level.display()))
}

/// The report as printed at the end.
pub fn describe(report: &WindowReport) -> String {
    let mut text = format!(
        "{} frames in {:.2} s, ended by {:?}",
        report.frames, report.seconds, report.ended_by
    );
    if let Some(path) = &report.screenshot {
        text.push_str(&format!("\nwrote {}", path.display()));
    }
    for (label, value) in report.stats.lines() {
        text.push_str(&format!("\n  {label:<15} {value}"));
    }
    text
}
