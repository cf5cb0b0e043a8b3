//! The denoiser on the render thread: after the tracer has rendered a frame (with film blend 1,
//! so that its film holds this frame alone), trace the guides on the CPU (`cpu::guides`),
//! hand the frame, the guides and the converging blend factor to the CPU denoiser
//! (`denoise::Svgf`, whose history then does the accumulating), and keep the denoised film for
//! the capture and the presenter.
//!
//! With temporal upscaling (`RenderConfig::temporal_upscale`) the guides are traced at the
//! upscaled size and the denoiser's history lives there (`denoise::upscale`).
//!
//! The denoiser reprojects its history per pixel with this frame's camera and instance
//! transforms (`denoise::reproject`), so a moving camera keeps what is still in view.
//!
//! Owns: [`DenoiseStage`]. Both tracers go through the CPU denoiser here (the GPU tracer's
//! frame is read back); the WGSL twin (`gpu::GpuDenoiser`) is not wired in yet: it needs the
//! guides on the device (a WGSL guide pass) to pay off. Render thread only.
//! Must not: change the tracer's algorithm or the scene.

use std::time::Instant;

use super::cpu::guides::trace_guides;
use super::denoise::{Svgf, SvgfParams, Traced, View, world_from_object};
use super::film::Film;
use super::jitter::unpack;
use super::tracer::{FilmView, RenderError, Tracer};
use crate::layout::GpuFrameUniforms;
use crate::scene::RenderScene;

/// The render thread's denoiser and its last output.
pub struct DenoiseStage {
    svgf: Svgf,
    film: Film,
}

impl DenoiseStage {
    pub fn new(params: SvgfParams) -> Self {
        Self {
            svgf: Svgf::new(params),
            film: Film::new(0, 0),
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
        let frame = tracer.film()?;
        let transforms = scene.instances.iter().map(world_from_object).collect();
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
            let guides = {
                puffin::profile_scope!("guides");
                trace_guides(scene, uniforms)
            };
            puffin::profile_scope!("svgf");
            self.svgf
                .denoise_moving(&frame.mean, &guides, blend, View::of(uniforms), transforms)
        }
        .map_err(|e| RenderError::Device(format!("denoiser: {e}")))?;
        self.film = film;
        Ok(started.elapsed().as_secs_f64())
    }

    /// The last denoised film.
    pub fn film(&self) -> &Film {
        &self.film
    }

    /// The last denoised film for the presenter (`None` before the first frame).
    pub fn film_view(&self) -> Option<FilmView<'_>> {
        (self.film.width > 0 && self.film.height > 0).then_some(FilmView::Host(&self.film))
    }
}
