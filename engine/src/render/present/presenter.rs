//! [`Presenter`]: after each rendered frame, show the film in the window (render thread).
//!
//! Owns: the window surface and the frame composer. Per frame: apply the overlay's texture
//! changes, follow the window size and vsync choice, acquire the surface texture, compose
//! (tonemap + upscale + overlay) into the offscreen frame and copy it to the surface — or,
//! where the surface refuses copies, compose straight into it — present, and read the frame
//! back when a screenshot was asked for. With the GPU tracer the film buffer is read in place
//! (same device); the CPU tracer's film is uploaded.
//! Must not: render, converge or touch the scene.

use std::sync::Arc;
use std::time::Instant;

use super::compose::FrameComposer;
use super::readback::{PendingReadback, Screenshot, encode_readback};
use super::surface::{Acquired, PresentTarget, WindowSurface};
use crate::commit::PresentRequest;
use crate::render::gpu::GpuContext;
use crate::render::tracer::{FilmView, RenderError};

/// What presenting one frame did.
#[derive(Clone, Debug, Default)]
pub struct Presented {
    /// Seconds spent composing, presenting and (when asked) reading back.
    pub seconds: f64,
    /// Why nothing reached the window this frame (occluded, minimised, …), if so.
    pub skipped: Option<&'static str>,
    /// The frame as the window showed it, when the request asked for it.
    pub screenshot: Option<Screenshot>,
}

/// The window side of the render thread.
pub struct Presenter {
    surface: WindowSurface,
    composer: FrameComposer,
}

impl Presenter {
    /// Opens the device for `target`'s surface; the tracer must be created on the returned
    /// context so that the presenter can read its film in place.
    pub fn open(target: &PresentTarget) -> Result<(Self, Arc<GpuContext>), RenderError> {
        let (surface, context) = WindowSurface::open(target)?;
        let composer = FrameComposer::new(Arc::clone(&context), surface.format())?;
        Ok((Self { surface, composer }, context))
    }

    /// Shows `film` as `request` asks.
    pub fn present(
        &mut self,
        film: Option<FilmView<'_>>,
        request: &mut PresentRequest,
    ) -> Result<Presented, RenderError> {
        let started = Instant::now();
        let context = Arc::clone(self.composer.context());
        let to_free = request
            .overlay
            .as_mut()
            .map(|o| self.composer.apply_overlay_textures(o));
        let mut presented = Presented::default();
        let outcome = if request.surface_size.0 == 0 || request.surface_size.1 == 0 {
            presented.skipped = Some("the window is minimised");
            Ok(None)
        } else {
            self.draw(&context, film, request, &mut presented)
        };
        if let Some(textures) = to_free {
            self.composer.free_overlay_textures(textures);
        }
        presented.screenshot = match outcome? {
            Some(readback) => Some(readback.finish(&context.device)?),
            None => None,
        };
        presented.seconds = started.elapsed().as_secs_f64();
        Ok(presented)
    }

    fn draw(
        &mut self,
        context: &GpuContext,
        film: Option<FilmView<'_>>,
        request: &PresentRequest,
        presented: &mut Presented,
    ) -> Result<Option<PendingReadback>, RenderError> {
        self.surface
            .update(context, request.surface_size, request.vsync);
        let size = self.surface.size();
        let surface_texture = match self.surface.acquire(context)? {
            Acquired::Texture(t) => Some(t),
            Acquired::Skip(reason) => {
                presented.skipped = Some(reason);
                None
            }
        };
        let overlay = request.overlay.as_ref();
        let direct = surface_texture.is_some() && !self.surface.accepts_copies();
        let mut encoder = context.device.create_command_encoder(&Default::default());
        let mut extra = Vec::new();
        if let (true, Some(texture)) = (direct, &surface_texture) {
            let view = texture.texture.create_view(&Default::default());
            extra.extend(self.composer.encode(
                &mut encoder,
                film,
                &view,
                size,
                &request.tonemap,
                overlay,
            )?);
        }
        let mut readback = None;
        if !direct || request.screenshot {
            let frame = self.composer.frame(size);
            extra.extend(self.composer.encode(
                &mut encoder,
                film,
                &frame.view,
                size,
                &request.tonemap,
                overlay,
            )?);
            if let (false, Some(texture)) = (direct, &surface_texture) {
                encoder.copy_texture_to_texture(
                    frame.texture.as_image_copy(),
                    texture.texture.as_image_copy(),
                    wgpu::Extent3d {
                        width: size.0,
                        height: size.1,
                        depth_or_array_layers: 1,
                    },
                );
            }
            if request.screenshot {
                readback = Some(encode_readback(
                    &context.device,
                    &mut encoder,
                    &frame.texture,
                    size,
                ));
            }
        }
        context
            .queue
            .submit(extra.into_iter().chain([encoder.finish()]));
        if let Some(texture) = surface_texture {
            context.queue.present(texture);
        }
        Ok(readback)
    }
}
