//! Fault: the GPU device is lost mid-run. The render thread must go on with the CPU tracer —
//! the frame in hand rendered again, every later frame too, none lost or out of order — and
//! say so once (`Rendered::notice`, on the frame where it happened).
//!
//! Two seams: a tracer that stands in for a GPU tracer and fails as a lost device does (in
//! `render` with `RenderError::DeviceLost`, or in `update` with a plain device error while it
//! reports its device lost), on the CPU, fast; and the real GPU tracer whose wgpu device is
//! destroyed part-way (`GpuContext::destroy_device`, wgpu's own device-lost path; lavapipe
//! without a GPU).

use candela::app::{Engine, Step};
use candela::ecs::{Renderable, Static, Transform};
use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::film::Film;
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{FilmView, OpenTracer, RenderError, RenderStats, Rendered, Tracer};
use candela::scene::{RenderScene, SceneWrite};
use glam::Vec3;

use crate::pipeline_common::{config, environment, quad_model};

/// Frames run in each test; the device is lost at render call [`LOSE_AT`].
const FRAMES: u64 = 24;
const LOSE_AT: u64 = 6;

/// Where the stand-in's device fails.
#[derive(Clone, Copy, Debug)]
enum FailIn {
    Render,
    Update,
}

/// A "GPU" tracer (it renders on the CPU) whose device is lost at its `LOSE_AT`-th frame.
struct LosingTracer {
    inner: CpuTracer,
    frames: u64,
    fail_in: FailIn,
    lost: bool,
}

impl LosingTracer {
    fn lose_now(&mut self) -> bool {
        if self.frames == LOSE_AT {
            self.lost = true;
        }
        self.lost
    }
}

impl Tracer for LosingTracer {
    fn name(&self) -> &'static str {
        "gpu"
    }
    fn device(&self) -> String {
        "a stand-in GPU that gets lost".into()
    }
    fn render(
        &mut self,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        let lost = matches!(self.fail_in, FailIn::Render) && self.lose_now();
        self.frames += 1;
        if lost || self.lost {
            return Err(RenderError::DeviceLost("simulated driver reset".into()));
        }
        self.inner.render(scene, uniforms)
    }
    fn update(&mut self, scene: &RenderScene, writes: &[SceneWrite]) -> Result<(), RenderError> {
        if matches!(self.fail_in, FailIn::Update) && self.lose_now() {
            // As wgpu does: the failing call's own message, the device reported lost.
            return Err(RenderError::Device(
                "buffer write on an invalid device".into(),
            ));
        }
        self.inner.update(scene, writes)
    }
    fn film(&mut self) -> Result<Film, RenderError> {
        self.inner.film()
    }
    fn film_view(&self) -> Option<FilmView<'_>> {
        self.inner.film_view()
    }
    fn clear(&mut self) {
        self.inner.clear()
    }
    fn device_lost(&self) -> Option<String> {
        self.lost.then(|| "simulated driver reset".to_string())
    }
}

/// The real GPU tracer, whose device is destroyed before its `LOSE_AT`-th frame.
struct DestroyedGpu {
    inner: GpuTracer,
    frames: u64,
}

impl Tracer for DestroyedGpu {
    fn name(&self) -> &'static str {
        self.inner.name()
    }
    fn device(&self) -> String {
        self.inner.device()
    }
    fn render(
        &mut self,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        if self.frames == LOSE_AT {
            self.inner.context().destroy_device();
        }
        self.frames += 1;
        self.inner.render(scene, uniforms)
    }
    fn update(&mut self, scene: &RenderScene, writes: &[SceneWrite]) -> Result<(), RenderError> {
        self.inner.update(scene, writes)
    }
    fn film(&mut self) -> Result<Film, RenderError> {
        self.inner.film()
    }
    fn film_view(&self) -> Option<FilmView<'_>> {
        self.inner.film_view()
    }
    fn clear(&mut self) {
        self.inner.clear()
    }
    fn device_lost(&self) -> Option<String> {
        self.inner.device_lost()
    }
}

/// A lit floor with a moving platform, on the tracer `open` makes; runs [`FRAMES`] frames
/// (capturing the last) and returns every result.
fn run(open: OpenTracer) -> Vec<Result<Rendered, RenderError>> {
    let mut engine = Engine::with_tracer(config(2, 16), environment(), open).expect("engine");
    let floor = engine.add_model(&quad_model(20.0, 0.0));
    let lamp = engine.add_model(&quad_model(2.0, 5.0));
    engine.world_mut().spawn((
        Transform::IDENTITY,
        Renderable {
            model: floor,
            material_override: None,
        },
        Static,
    ));
    let moving = engine.world_mut().spawn((
        Transform::from_translation(Vec3::Y * 4.0),
        Renderable {
            model: lamp,
            material_override: None,
        },
    ));
    for frame in 0..FRAMES {
        if frame == FRAMES - 1 {
            engine.capture_next();
        }
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                if let Ok(mut t) = step.world.get::<&mut Transform>(moving) {
                    t.translation.x = (frame as f32 * 0.1).sin();
                }
            })
            .expect("the main thread's frame");
    }
    engine.shutdown()
}

/// Every frame came back, in order; the "gpu" tracer rendered those before the loss, the CPU
/// tracer the rest; exactly one notice, on the frame of the loss, naming the loss; and the
/// last frame's film (the CPU tracer's) is finite and lit.
fn check(results: Vec<Result<Rendered, RenderError>>, label: &str) {
    let rendered: Vec<Rendered> = results
        .into_iter()
        .map(|r| r.unwrap_or_else(|e| panic!("{label}: a render failed: {e}")))
        .collect();
    let frames: Vec<u64> = rendered.iter().map(|r| r.frame).collect();
    assert_eq!(frames, (0..FRAMES).collect::<Vec<_>>(), "{label}: frames");
    let tracers: Vec<&str> = rendered.iter().map(|r| r.tracer).collect();
    let expected: Vec<&str> = (0..FRAMES)
        .map(|f| if f < LOSE_AT { "gpu" } else { "cpu" })
        .collect();
    assert_eq!(
        tracers, expected,
        "{label}: which tracer rendered each frame"
    );
    let notices: Vec<(u64, &str)> = rendered
        .iter()
        .filter_map(|r| r.notice.as_deref().map(|n| (r.frame, n)))
        .collect();
    assert_eq!(notices.len(), 1, "{label}: one message, got {notices:?}");
    assert_eq!(notices[0].0, LOSE_AT, "{label}: {notices:?}");
    assert!(
        notices[0].1.contains("GPU device was lost") && notices[0].1.contains("CPU tracer"),
        "{label}: {}",
        notices[0].1
    );
    let film = rendered
        .last()
        .and_then(|r| r.film.as_ref())
        .unwrap_or_else(|| panic!("{label}: the last frame's film was not captured"));
    assert_eq!((film.width, film.height), (16, 16), "{label}");
    assert!(
        film.mean.iter().all(|p| p.is_finite()),
        "{label}: non-finite pixel"
    );
    let mean = film.mean.iter().map(|p| p.x + p.y + p.z).sum::<f32>() / film.mean.len() as f32;
    assert!(
        mean > 0.05,
        "{label}: the CPU tracer's film is dark: {mean}"
    );
    assert!(
        rendered[LOSE_AT as usize..]
            .iter()
            .all(|r| r.stats.counts.camera >= 16 * 16 * 2),
        "{label}: a frame after the loss traced fewer camera rays than its pixels × spp"
    );
}

#[test]
fn a_gpu_device_lost_mid_run_hands_the_frames_to_the_cpu_tracer() {
    for fail_in in [FailIn::Render, FailIn::Update] {
        let open: OpenTracer = Box::new(move |_, _| {
            Ok(Box::new(LosingTracer {
                inner: CpuTracer::new(),
                frames: 0,
                fail_in,
                lost: false,
            }) as Box<dyn Tracer>)
        });
        check(run(open), &format!("lost in {fail_in:?}"));
    }
}

#[test]
fn a_destroyed_wgpu_device_hands_the_frames_to_the_cpu_tracer() {
    let open: OpenTracer = Box::new(|_, scene| {
        let inner = GpuTracer::new(GpuContext::headless()?, scene)?;
        Ok(Box::new(DestroyedGpu { inner, frames: 0 }) as Box<dyn Tracer>)
    });
    check(run(open), "wgpu device destroyed");
}
