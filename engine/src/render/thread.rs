//! The render thread (Brigade §4.2, Figure 7): receive commit → apply → trace → converge →
//! present → report.
//!
//! When the GPU device is lost mid-run the thread goes on with the CPU tracer, rendering the
//! frame in hand again, and says so once (`device_loss`, [`Rendered::notice`]).
//!
//! Owns: the tracer (and with it the wgpu device for the GPU tracer), the render side's copy of
//! the flattened scene, the converging state and workload scaling, and in a window the
//! presenter (the device is then opened for the window's surface and shared with the GPU
//! tracer). It never reads game state: all it sees are sealed commits. Results (statistics,
//! the film or a screenshot when a commit asks for it) go back on a channel. Dropping the
//! sender side ends the thread cleanly. With `RenderConfig::denoise` the frame is denoised
//! after tracing (`denoise_stage`) and the denoised film is what is captured and presented. Headless, it opens no surface and presents nothing; a
//! present request's surface size still sets the render size, as a window's would.
//! Must not: touch the ECS, the main thread's upkeep or the window's events.

use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread::JoinHandle;

use super::denoise::SvgfParams;
use super::denoise_stage::DenoiseStage;
use super::film::{Converge, ConvergePolicy, Film};
use super::frame_render::render_one;
use super::present::{PresentTarget, Presenter, Screenshot};
use super::scaling::{Scaling, ScalingGoal, ScalingTarget};
use super::tracer::{RenderError, RenderStats, Tracer};
use crate::commit::{Commit, CommitReceiver, CommitSender, commit_channel};
use crate::scene::RenderScene;

/// Which tracer the render thread runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TracerChoice {
    /// The GPU tracer on a real GPU, the CPU tracer when the only adapter is a software one or
    /// there is none (`render/auto.rs`); one log line says which and why.
    #[default]
    Auto,
    /// The WGSL tracer on wgpu (a real GPU, or lavapipe on the CPU).
    Gpu,
    /// The Rust tracer on all CPU cores.
    Cpu,
    /// Several tracers on one frame, balanced (`render::balance::PoolTracer`).
    Pool(super::balance::PoolSpec),
}

/// How the render thread renders.
#[derive(Clone, Copy, Debug)]
pub struct RenderConfig {
    pub tracer: TracerChoice,
    /// Output size in pixels (the film may be smaller when scaling lowers the resolution). In a
    /// window the output follows the window's size from the first commit on.
    pub width: u32,
    pub height: u32,
    /// Samples per pixel per frame (the starting point when scaling is on).
    pub spp: u32,
    pub seed: u32,
    pub converge: ConvergePolicy,
    /// Hold a frame time by adapting spp, roulette and resolution (`None`: fixed workload).
    pub scaling: Option<ScalingTarget>,
    /// Denoise every frame (SVGF, `render::denoise`): the tracer renders each frame alone and
    /// the denoiser's history accumulates them. Off for captures and references (biased), on
    /// in games.
    pub denoise: bool,
    /// Temporal upscaling by this factor (with the denoiser on; `denoise::upscale`): the film
    /// the denoiser keeps and presents is the size scaling chooses (the output size without
    /// scaling), the tracer traces this factor less each way, its samples offset by one
    /// Halton offset per frame (`render::jitter`). `None` or 1: no upscaling, bit-identical to
    /// before.
    pub temporal_upscale: Option<u32>,
    /// How lights are picked, overriding the level's `render.light_sampling` (`None`: the
    /// level's; `capture --light-sampling`).
    pub light_sampling: Option<crate::assets::LightSampling>,
    /// One pixel in this many traces indirect light, overriding the level's
    /// `render.indirect_every` (`None`: the level's; 1, 2 or 4; `render/cpu/interleave.rs`).
    pub indirect_every: Option<u32>,
    /// With the denoiser on (and no temporal upscaling), take its guides from the CPU tracer's
    /// first hits at the frame's jitter (`cpu::guides::FirstHit`) instead of a guide pass of
    /// their own (one centre ray per pixel). Windowed play and the games' benches turn it on
    /// (`harness::windowed_render`): no guide pass, a lower displayed error, and a still view
    /// as steady as with the pass since the reprojection keeps edge pixels' history
    /// (`denoise::reproject_edge`; `docs/ACCURACY.md`). Off in [`RenderConfig::cpu`], which
    /// tests and tools start from.
    pub first_hit_guides: bool,
    /// The denoiser's à-trous kernels (`denoise::AtrousKernel`; the default is the 5×5 B3
    /// spline on every pass, `docs/PERFORMANCE.md` "The à-trous kernel").
    pub atrous_kernel: super::denoise::AtrousKernel,
    /// How the physical sky's table follows a moving sun: `Blocking` (captures, tests: the
    /// table always matches the commit) or `Background` (games in play: rebuilt on a worker
    /// thread while frames go on; `scene::SkyTable`).
    pub sky_rebuild: crate::scene::SkyRebuild,
}

impl RenderConfig {
    /// The CPU tracer at `width` × `height`, 1 sample per pixel per frame, seed 1, default
    /// converging, no scaling: small headless engines (tests, tools).
    pub fn cpu(width: u32, height: u32) -> Self {
        Self {
            tracer: TracerChoice::Cpu,
            width,
            height,
            spp: 1,
            seed: 1,
            converge: ConvergePolicy::default(),
            scaling: None,
            denoise: false,
            temporal_upscale: None,
            light_sampling: None,
            indirect_every: None,
            first_hit_guides: false,
            atrous_kernel: Default::default(),
            sky_rebuild: crate::scene::SkyRebuild::Blocking,
        }
    }
}

/// What the render thread did with one commit.
#[derive(Clone, Debug)]
pub struct Rendered {
    pub frame: u64,
    /// The tracer that rendered it ("gpu" or "cpu"; what `auto` chose).
    pub tracer: &'static str,
    pub stats: RenderStats,
    /// Seconds spent applying the commit (CPU copy and GPU upload).
    pub apply_seconds: f64,
    /// Seconds spent tracing.
    pub render_seconds: f64,
    /// Seconds spent denoising (guides included); 0 with the denoiser off.
    pub denoise_seconds: f64,
    /// The converging blend factor used.
    pub blend: f32,
    /// Samples per pixel, roulette scale and film size used.
    pub spp: u32,
    pub roulette_scale: f32,
    pub film_size: (u32, u32),
    /// Bytes of scene data the commit carried.
    pub commit_bytes: usize,
    /// Emissive triangles in the render side's light sampling distribution (its alias table)
    /// this frame.
    pub lights: u32,
    /// The converged film, when the commit asked for it.
    pub film: Option<Film>,
    /// Seconds spent presenting (tonemap, overlay, copy, present, readback); 0 headless.
    pub present_seconds: f64,
    /// Why the window was not updated this frame (occluded, minimised…), if it was not.
    pub present_skipped: Option<&'static str>,
    /// What the window showed, when the commit's present request asked for it.
    pub screenshot: Option<Screenshot>,
    /// Set on the one frame where the render thread changed course, saying why: the GPU device
    /// was lost and the CPU tracer took over (this frame is already the CPU tracer's), or the
    /// window's device was lost and the presenter was reopened.
    pub notice: Option<String>,
}

/// A running render thread.
pub struct RenderThread {
    sender: Option<CommitSender>,
    results: Receiver<Result<Rendered, RenderError>>,
    handle: Option<JoinHandle<()>>,
}

type Opened = (Box<dyn Tracer>, Option<Presenter>);

/// Makes the render thread's tracer on the render thread, from the window's device when there
/// is one and the (empty) scene: a seam for tests that need a tracer of their own, such as one
/// that loses its device ([`RenderThread::spawn_with_tracer`]).
pub type OpenTracer = Box<
    dyn FnOnce(
            Option<std::sync::Arc<super::gpu::GpuContext>>,
            &RenderScene,
        ) -> Result<Box<dyn Tracer>, RenderError>
        + Send,
>;

/// The tracer, and in a window the presenter on the same device.
fn open(
    choice: TracerChoice,
    custom: Option<OpenTracer>,
    target: Option<&PresentTarget>,
    scene: &RenderScene,
) -> Result<Opened, RenderError> {
    let (presenter, context) = match target {
        Some(target) => {
            let (presenter, context) = Presenter::open(target)?;
            (Some(presenter), Some(context))
        }
        None => (None, None),
    };
    if let Some(custom) = custom {
        return Ok((custom(context, scene)?, presenter));
    }
    let tracer: Box<dyn Tracer> = match super::auto::resolve(choice, context.as_deref()) {
        TracerChoice::Cpu | TracerChoice::Auto => Box::new(super::cpu::CpuTracer::new()),
        TracerChoice::Gpu => {
            let context = match context {
                Some(context) => context,
                None => super::gpu::GpuContext::headless()?,
            };
            Box::new(super::gpu::GpuTracer::new(context, scene)?)
        }
        TracerChoice::Pool(spec) => {
            Box::new(super::balance::PoolTracer::new(spec, context, scene)?)
        }
    };
    Ok((tracer, presenter))
}

fn run(
    config: RenderConfig,
    target: Option<PresentTarget>,
    custom: Option<OpenTracer>,
    commits: CommitReceiver,
    results: Sender<Result<Rendered, RenderError>>,
) {
    let mut scene = RenderScene::empty();
    let (mut tracer, mut presenter) = match open(config.tracer, custom, target.as_ref(), &scene) {
        Ok(opened) => opened,
        Err(e) => {
            let _ = results.send(Err(e));
            return;
        }
    };
    let mut converge = Converge::new(config.converge);
    let mut scaling = Scaling::new(config.spp, config.scaling);
    let mut output = (config.width, config.height);
    let mut denoiser = config.denoise.then(|| {
        DenoiseStage::new(SvgfParams {
            kernel: config.atrous_kernel,
            ..SvgfParams::default()
        })
    });
    while let Ok(mut commit) = commits.recv() {
        // Profiling (the F5 view): one scope per commit, opened after the wait.
        puffin::profile_scope!("render frame");
        let mut request = commit.present.take();
        if let Some(wanted) = request.as_ref().and_then(|r| r.scaling) {
            scaling.set_goal(ScalingGoal {
                // The player's frame rate, within the bounds the level declared.
                target: wanted.frame_seconds.map(|frame_seconds| ScalingTarget {
                    frame_seconds,
                    ..config
                        .scaling
                        .unwrap_or_else(|| ScalingTarget::new(frame_seconds))
                }),
                max_resolution: wanted.max_resolution,
            });
        }
        if let Some(r) = &request
            && r.surface_size.0 > 0
            && r.surface_size.1 > 0
            && r.surface_size != output
        {
            // The window was resized: the film restarts at the new size.
            output = r.surface_size;
            converge.reset();
        }
        let mut outcome = render_one(
            commit,
            output,
            &config,
            &mut scene,
            &mut tracer,
            &mut converge,
            &mut scaling,
            denoiser.as_mut(),
        );
        if let (Ok(rendered), Some(shown), Some(request), Some(target)) = (
            &mut outcome,
            presenter.as_mut(),
            request.as_mut(),
            target.as_ref(),
        ) {
            let view = match &denoiser {
                Some(d) => d.film_view(),
                None => tracer.film_view(),
            };
            let mut presented = {
                puffin::profile_scope!("present");
                shown.present(view, request)
            };
            if presented.is_err()
                && let Some(reason) = shown.device_lost()
            {
                // The window's device is gone: open the window on a device again (the tracer,
                // if it was on that device, has already moved to the CPU) and show the frame.
                match Presenter::open(target) {
                    Ok((reopened, _context)) => {
                        let message = format!(
                            "the window's GPU device was lost ({reason}); the window was \
                             opened again on a new device"
                        );
                        log::warn!("{message}");
                        rendered.notice.get_or_insert(message);
                        *shown = reopened;
                        let view = match &denoiser {
                            Some(d) => d.film_view(),
                            None => tracer.film_view(),
                        };
                        presented = shown.present(view, request);
                    }
                    Err(e) => presented = Err(e),
                }
            }
            match presented {
                Ok(presented) => {
                    rendered.present_seconds = presented.seconds;
                    rendered.present_skipped = presented.skipped;
                    rendered.screenshot = presented.screenshot;
                }
                Err(e) => outcome = Err(e),
            }
        }
        let failed = outcome.is_err();
        if results.send(outcome).is_err() || failed {
            return;
        }
    }
}

impl RenderThread {
    /// Starts the render thread, headless. Tracer set-up happens on it; a failure there
    /// arrives as the first result.
    pub fn spawn(config: RenderConfig) -> Result<Self, RenderError> {
        Self::start(config, None)
    }

    /// Starts the render thread presenting into `target`'s window: the device is opened for
    /// the window's surface (a failure arrives as the first result).
    pub fn spawn_windowed(
        config: RenderConfig,
        target: PresentTarget,
    ) -> Result<Self, RenderError> {
        Self::start(config, Some(target))
    }

    /// Starts the render thread, headless, on the tracer `open` makes (on the render thread;
    /// `config.tracer` is ignored). For tests that need a tracer of their own, such as one
    /// whose device is lost part-way through.
    pub fn spawn_with_tracer(config: RenderConfig, open: OpenTracer) -> Result<Self, RenderError> {
        Self::start_with(config, None, Some(open))
    }

    fn start(config: RenderConfig, target: Option<PresentTarget>) -> Result<Self, RenderError> {
        Self::start_with(config, target, None)
    }

    fn start_with(
        config: RenderConfig,
        target: Option<PresentTarget>,
        custom: Option<OpenTracer>,
    ) -> Result<Self, RenderError> {
        let (sender, receiver) = commit_channel();
        let (result_tx, results) = channel();
        let handle = std::thread::Builder::new()
            .name("candela-render".into())
            .spawn(move || run(config, target, custom, receiver, result_tx))
            .map_err(|e| RenderError::Device(format!("cannot start the render thread: {e}")))?;
        Ok(Self {
            sender: Some(sender),
            results,
            handle: Some(handle),
        })
    }

    /// Hands a sealed commit over (blocks while the render thread still holds the previous
    /// one). Fails when the render thread has stopped; its error then comes with the results.
    pub fn submit(&self, commit: Commit) -> Result<(), RenderError> {
        self.sender
            .as_ref()
            .ok_or_else(|| RenderError::Device("render thread shut down".into()))?
            .send(commit)
            .map_err(|_| RenderError::Device("the render thread has stopped".into()))
    }

    /// Results that are ready, without waiting.
    pub fn ready(&self) -> Vec<Result<Rendered, RenderError>> {
        self.results.try_iter().collect()
    }

    /// Waits for the next result (`None` once the thread has ended and nothing is left).
    pub fn wait(&self) -> Option<Result<Rendered, RenderError>> {
        self.results.recv().ok()
    }

    /// Ends the thread after it has rendered every submitted commit; returns their results.
    pub fn shutdown(mut self) -> Vec<Result<Rendered, RenderError>> {
        self.sender = None;
        if let Some(handle) = self.handle.take() {
            let _ = handle.join();
        }
        self.results.try_iter().collect()
    }
}

impl Drop for RenderThread {
    fn drop(&mut self) {
        self.sender = None;
        if let Some(handle) = self.handle.take() {
            let _ = handle.join();
        }
    }
}
