//! The `Tracer` trait: what every tracer (GPU or CPU) offers the frame loop and the tools.
//!
//! Owns: the trait, render statistics and render errors. Both implementations run the same
//! algorithm over the same `RenderScene` buffers with the same RNG, so their films agree
//! within Monte-Carlo noise (`tests/cross/gpu_matches_cpu.rs`).
//! Must not: hold scene data itself.

pub use super::cpu::integrator::RayCounts;
use super::film::Film;
use crate::layout::GpuFrameUniforms;
use crate::scene::RenderScene;
use crate::scene::SceneWrite;

/// What one `render` call did.
#[derive(Clone, Copy, Debug, Default)]
pub struct RenderStats {
    pub counts: RayCounts,
    /// Wall time of the call, seconds.
    pub seconds: f64,
}

impl RenderStats {
    /// All rays traced (camera + bounce + shadow).
    pub fn rays(&self) -> u64 {
        self.counts.camera + self.counts.bounce + self.counts.shadow
    }
}

/// Things that can go wrong while rendering.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error(
        "no GPU adapter found (not even a software Vulkan driver such as Mesa's lavapipe); \
         install mesa-vulkan-drivers, or use the CPU tracer (--tracer cpu)"
    )]
    NoAdapter,
    #[error("GPU device error: {0}")]
    Device(String),
    /// The device went away under the tracer (driver reset, GPU unplugged or hung); nothing on
    /// it can be used again. The render thread goes on with the CPU tracer.
    #[error("the GPU device was lost: {0}")]
    DeviceLost(String),
    #[error("the scene does not fit the GPU: {0}")]
    TooLarge(String),
    /// The scene asks for something this tracer cannot render (yet); nothing was drawn.
    #[error("this tracer cannot render the scene: {0}")]
    Unsupported(String),
    #[error("image size {width}×{height} is not allowed: {reason}")]
    BadSize {
        width: u32,
        height: u32,
        reason: String,
    },
}

/// Where a tracer's film lies, for the presenter to read without a round trip.
#[derive(Clone, Copy, Debug)]
pub enum FilmView<'a> {
    /// On the tracer's device: one `vec4<f32>` per pixel (xyz = mean radiance), rows top to
    /// bottom. The presenter must use the same device.
    Device {
        buffer: &'a wgpu::Buffer,
        width: u32,
        height: u32,
    },
    /// In host memory (the CPU tracer): the presenter uploads it.
    Host(&'a Film),
}

/// A path tracer that accumulates samples into its film.
pub trait Tracer {
    /// "gpu" or "cpu".
    fn name(&self) -> &'static str;
    /// A description of the device (adapter name, thread count).
    fn device(&self) -> String;
    /// Traces `uniforms.spp` samples per pixel (starting at `uniforms.sample_base`) of `scene`
    /// and blends their mean into the film: `film = mix(film, mean, uniforms.film_blend)`. The
    /// film is resized and cleared when the image size changes. `scene` must be the scene the
    /// tracer was created with, brought up to date with [`Tracer::update`].
    fn render(
        &mut self,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError>;
    /// Brings the tracer's copy of the scene up to date after `writes` (a commit's deltas)
    /// were applied to `scene`. The CPU tracer reads `scene` itself and has nothing to do.
    fn update(&mut self, scene: &RenderScene, writes: &[SceneWrite]) -> Result<(), RenderError>;
    /// The converged image so far (mean radiance per pixel).
    fn film(&mut self) -> Result<Film, RenderError>;
    /// The film in place (no copy, no readback); `None` before the first render.
    fn film_view(&self) -> Option<FilmView<'_>>;
    /// Forgets every accumulated sample.
    fn clear(&mut self);
    /// Why the device under this tracer was lost, if it was (`None` for tracers without one).
    /// An error from a tracer whose device is lost is treated as [`RenderError::DeviceLost`].
    fn device_lost(&self) -> Option<String> {
        None
    }
    /// Take the denoiser's guides of each frame from the tracer's own first hits (the CPU
    /// tracer does, `cpu::guides`), instead of a guide pass of their own. Tracers that cannot
    /// ignore it.
    fn record_guides(&mut self, _on: bool) {}
    /// The guides the last frame recorded (see [`Tracer::record_guides`]), once.
    fn take_guides(&mut self) -> Option<crate::render::denoise::Guides> {
        None
    }
    /// The wgpu device the film lives on (`None`: the film is in host memory), so that the
    /// denoiser can run on the same device and read the film in place (`denoise_stage`).
    fn gpu_context(&self) -> Option<std::sync::Arc<super::gpu::GpuContext>> {
        None
    }
}
