//! The denoiser on the render thread: after the tracer has rendered a frame (with film blend 1,
//! so that its film holds this frame alone), take the guides the CPU tracer recorded at its
//! first hits ([`Tracer::take_guides`]) or trace them in a pass of their own (`cpu::guides`),
//! hand the frame, the guides and the converging blend factor to a denoiser (whose history
//! then does the accumulating), and keep the denoised film for the capture and the presenter.
//!
//! Which denoiser: with the GPU tracer (its film on the device, [`Tracer::gpu_context`]) the
//! WGSL one (`gpu::GpuDenoiser`) on the tracer's device: the frame is copied on the device, the
//! guides are still traced by the CPU (`cpu::guides::trace_guides`) and uploaded, and the
//! output stays on the device for the presenter (read back only for a capture). With the CPU
//! tracer (or the pool), and with temporal upscaling (`RenderConfig::temporal_upscale`, which
//! only the CPU denoiser does: guides at the upscaled size, `denoise::upscale`), the CPU
//! denoiser (`denoise::Svgf`) — the GPU tracer's frame is then read back. Switching between the
//! two (a lost device hands the frame to the CPU tracer) restarts the history.
//!
//! Both reproject their history per pixel with this frame's camera and instance transforms
//! (`denoise::reproject`, twin `shaders/denoise_reproject.wgsl`), so a moving camera keeps
//! what is still in view; they agree within f32 rounding (`docs/ACCURACY.md`).
//!
//! Owns: [`DenoiseStage`]. Render thread only.
//! Must not: change the tracer's algorithm or the scene.

use std::sync::Arc;
use std::time::Instant;

use glam::Affine3A;

use super::cpu::guides::trace_guides;
use super::denoise::{Svgf, SvgfParams, Traced, View, world_from_object};
use super::film::Film;
use super::gpu::{GpuContext, GpuDenoiser};
use super::jitter::unpack;
use super::tracer::{FilmView, RenderError, Tracer};
use crate::layout::GpuFrameUniforms;
use crate::scene::RenderScene;

/// The render thread's denoiser and its last output.
pub struct DenoiseStage {
    params: SvgfParams,
    svgf: Svgf,
    film: Film,
    /// The WGSL denoiser, made on the GPU tracer's device the first time one is seen.
    gpu: Option<GpuDenoiser>,
    /// The last output is the GPU denoiser's.
    on_gpu: bool,
}

impl DenoiseStage {
    pub fn new(params: SvgfParams) -> Self {
        Self {
            params,
            svgf: Svgf::new(params),
            film: Film::new(0, 0),
            gpu: None,
            on_gpu: false,
        }
    }

    /// Denoises the frame `tracer` just rendered with `uniforms` over `scene`; `blend` is the
    /// converging factor (1 restarts the history); `upscale` > 1 upscales temporally by that
    /// factor (`denoise::upscale`: guides and film at `upscale` times the traced size, the
    /// samples' offset read from `uniforms.pixel_jitter`). Returns the seconds it took (guides
    /// included).
    pub fn run(
        &mut self,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
        tracer: &mut dyn Tracer,
        blend: f32,
        upscale: u32,
    ) -> Result<f64, RenderError> {
        let started = Instant::now();
        let transforms: Vec<Affine3A> = scene.instances.iter().map(world_from_object).collect();
        match tracer.gpu_context().filter(|_| upscale <= 1) {
            Some(context) => self.run_gpu(context, scene, uniforms, &*tracer, blend, transforms)?,
            None => self.run_cpu(scene, uniforms, tracer, blend, upscale, transforms)?,
        }
        Ok(started.elapsed().as_secs_f64())
    }

    /// The GPU tracer's frame, denoised on its device.
    fn run_gpu(
        &mut self,
        context: Arc<GpuContext>,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
        tracer: &dyn Tracer,
        blend: f32,
        transforms: Vec<Affine3A>,
    ) -> Result<(), RenderError> {
        let mut gpu = match self.gpu.take() {
            Some(gpu) if Arc::ptr_eq(gpu.context(), &context) => gpu,
            _ => GpuDenoiser::new(context, self.params)?,
        };
        if !self.on_gpu {
            gpu.reset();
        }
        let guides = {
            puffin::profile_scope!("guides");
            trace_guides(scene, uniforms)
        };
        let Some(FilmView::Device { buffer, .. }) = tracer.film_view() else {
            return Err(RenderError::Device(
                "denoiser: the GPU tracer has no film on its device".into(),
            ));
        };
        {
            puffin::profile_scope!("svgf gpu");
            gpu.denoise_device_frame(buffer, &guides, blend, View::of(uniforms), transforms)?;
        }
        self.gpu = Some(gpu);
        self.on_gpu = true;
        Ok(())
    }

    /// The frame read back (for the GPU tracer) and denoised on the CPU.
    fn run_cpu(
        &mut self,
        scene: &RenderScene,
        uniforms: &GpuFrameUniforms,
        tracer: &mut dyn Tracer,
        blend: f32,
        upscale: u32,
        transforms: Vec<Affine3A>,
    ) -> Result<(), RenderError> {
        if self.on_gpu {
            self.svgf.reset();
            self.on_gpu = false;
        }
        let frame = tracer.film()?;
        // The denoiser also says how many pixels kept their history; nothing reads it here.
        let (film, _kept) = if upscale > 1 {
            let mut high = *uniforms;
            high.width = uniforms.width * upscale;
            high.height = uniforms.height * upscale;
            let guides = {
                puffin::profile_scope!("guides");
                trace_guides(scene, &high)
            };
            puffin::profile_scope!("svgf");
            let traced = Traced {
                mean: &frame.mean,
                width: frame.width,
                height: frame.height,
                jitter: unpack(uniforms.pixel_jitter).unwrap_or((0.5, 0.5)),
            };
            self.svgf
                .denoise_upscaled(traced, &guides, blend, View::of(&high), transforms)
        } else {
            // The tracer's own first hits when it recorded them (the CPU tracer), else a pass.
            // Recorded guides sit where the samples were: at the frame's offset in each pixel.
            let recorded = tracer
                .take_guides()
                .filter(|g| g.width == uniforms.width && g.height == uniforms.height);
            let (guides, view) = match recorded {
                Some(g) => {
                    let at = unpack(uniforms.pixel_jitter).unwrap_or((0.5, 0.5));
                    (g, View::of(uniforms).with_jitter(at))
                }
                None => {
                    puffin::profile_scope!("guides");
                    (trace_guides(scene, uniforms), View::of(uniforms))
                }
            };
            puffin::profile_scope!("svgf");
            self.svgf
                .denoise_moving(&frame.mean, &guides, blend, view, transforms)
        }
        .map_err(|e| RenderError::Device(format!("denoiser: {e}")))?;
        self.film = film;
        Ok(())
    }

    /// The last denoised film (read back from the device when the GPU denoiser made it).
    pub fn capture(&self) -> Result<Film, RenderError> {
        match (&self.gpu, self.on_gpu) {
            (Some(gpu), true) => gpu.read_output(),
            _ => Ok(self.film.clone()),
        }
    }

    /// The last denoised film for the presenter (`None` before the first frame): on the
    /// device when the GPU denoiser made it.
    pub fn film_view(&self) -> Option<FilmView<'_>> {
        match (&self.gpu, self.on_gpu) {
            (Some(gpu), true) => gpu.output_view(),
            _ => {
                (self.film.width > 0 && self.film.height > 0).then_some(FilmView::Host(&self.film))
            }
        }
    }
}
