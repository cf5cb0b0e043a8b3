//! [`Presenter`]: after each rendered frame, show the film in the window (render thread).
//!
//! Owns: the window surface and the frame composer. Per frame: apply the overlay's texture
//! changes, follow the window size and vsync choice, acquire the surface texture, compose
//! (tonemap + upscale + overlay) into the offscreen frame and copy it to the surface — or,
//! where the surface refuses copies, compose straight into it — present, and read the frame
//! back when a screenshot was asked for. With the GPU tracer the film buffer is read in place
//! (same device). The CPU tracer's film is composed on the CPU (`cpu_compose.rs`), the overlay
//! drawn over it on the CPU too (`cpu_overlay.rs`), straight into a `softbuffer` buffer put to
//! the window (`soft.rs`, the default) — or, with `CANDELA_PRESENT=wgpu` or when softbuffer
//! cannot start, copied into the wgpu surface (the overlay by the device on an sRGB surface;
//! a screenshot frame then takes the shader path, whose offscreen frame it reads back).
//! Must not: render, converge or touch the scene.

use std::sync::Arc;
use std::time::Instant;

use super::compose::FrameComposer;
use super::cpu_compose::{HostCompose, PixelLayout};
use super::cpu_overlay::CpuOverlay;
use super::readback::{PendingReadback, Screenshot, encode_readback};
use super::soft::{HostPresent, SoftSurface};
use super::surface::{Acquired, PresentTarget, WindowSurface};
use crate::commit::PresentRequest;
use crate::render::film::Film;
use crate::render::gpu::GpuContext;
use crate::render::tracer::{FilmView, RenderError};

/// Whether a host film is composed on the CPU (softbuffer's buffer or the surface texture);
/// `CANDELA_PRESENT=shader` sends it through the present shader instead (for comparing,
/// docs/PERFORMANCE.md).
fn host_blit_enabled() -> bool {
    HostPresent::from_env() != HostPresent::Shader
}

/// The softbuffer surface, opened at the first host film.
enum Soft {
    Untried,
    Ready(SoftSurface),
    /// Not asked for, or it could not start or failed: the wgpu path.
    Off,
}

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
    /// egui's textures on the CPU, for the host-film path's overlay.
    cpu_overlay: CpuOverlay,
    /// The host-film path's compose, its taps and buffers kept between frames.
    host_compose: HostCompose,
    /// The window, for the softbuffer surface.
    target: PresentTarget,
    soft: Soft,
}

impl Presenter {
    /// Opens the device for `target`'s surface; the tracer must be created on the returned
    /// context so that the presenter can read its film in place.
    pub fn open(target: &PresentTarget) -> Result<(Self, Arc<GpuContext>), RenderError> {
        let (surface, context) = WindowSurface::open(target)?;
        let composer = FrameComposer::new(Arc::clone(&context), surface.format())?;
        let cpu_overlay = CpuOverlay::default();
        Ok((
            Self {
                surface,
                composer,
                cpu_overlay,
                host_compose: HostCompose::default(),
                target: target.clone(),
                soft: match HostPresent::from_env() {
                    HostPresent::Softbuffer => Soft::Untried,
                    HostPresent::Wgpu | HostPresent::Shader => Soft::Off,
                },
            },
            context,
        ))
    }

    /// Why the window's device was lost, if it was (the presenter must then be reopened).
    pub fn device_lost(&self) -> Option<String> {
        self.composer.context().lost()
    }

    /// Shows `film` as `request` asks.
    pub fn present(
        &mut self,
        film: Option<FilmView<'_>>,
        request: &mut PresentRequest,
    ) -> Result<Presented, RenderError> {
        let started = Instant::now();
        let context = Arc::clone(self.composer.context());
        // The CPU copies of egui's textures follow every overlay, as the device's do.
        let cpu_free = match &request.overlay {
            Some(o) => {
                self.cpu_overlay.apply(&o.textures_delta);
                o.textures_delta.free.clone()
            }
            None => Default::default(),
        };
        let to_free = request
            .overlay
            .as_mut()
            .map(|o| self.composer.apply_overlay_textures(o));
        let mut presented = Presented::default();
        let outcome = if request.surface_size.0 == 0 || request.surface_size.1 == 0 {
            presented.skipped = Some("the window is minimised");
            Ok(None)
        } else if let Some(FilmView::Host(host)) = film
            && let Some(shot) = self.draw_soft(host, request)
        {
            presented.screenshot = shot;
            Ok(None)
        } else {
            self.draw(&context, film, request, &mut presented)
        };
        if let Some(textures) = to_free {
            self.composer.free_overlay_textures(textures);
        }
        self.cpu_overlay.free(&cpu_free);
        if let Some(readback) = outcome? {
            presented.screenshot = Some(readback.finish(&context.device)?);
        }
        presented.seconds = started.elapsed().as_secs_f64();
        Ok(presented)
    }

    /// The host film through softbuffer (`soft.rs`): composed and overlaid on the CPU straight
    /// into its buffer, the screenshot (when asked) from the same bytes. `None` when softbuffer
    /// is off or could not start or failed (logged once; the caller takes the wgpu path),
    /// else the screenshot, if any.
    fn draw_soft(&mut self, film: &Film, request: &PresentRequest) -> Option<Option<Screenshot>> {
        let started = Instant::now();
        if matches!(self.soft, Soft::Untried) {
            self.soft = match SoftSurface::open(&self.target) {
                Ok(surface) => {
                    log::info!(
                        "presenting the CPU film through softbuffer (composed into its buffer; \
                         no wgpu copy or swapchain, so no vsync)"
                    );
                    Soft::Ready(surface)
                }
                Err(e) => {
                    log::warn!(
                        "softbuffer cannot start ({e}): presenting the CPU film through wgpu"
                    );
                    Soft::Off
                }
            };
        }
        let Soft::Ready(surface) = &mut self.soft else {
            return None;
        };
        let size = request.surface_size;
        let (compose, overlay) = (&mut self.host_compose, &self.cpu_overlay);
        let shown = surface.frame(size, request.screenshot, started, |bytes| {
            {
                puffin::profile_scope!("compose");
                compose.compose_into(film, size, &request.tonemap, PixelLayout::Xrgb32, bytes);
            }
            log::debug!(
                "present ms: cpu compose {:.2}",
                started.elapsed().as_secs_f64() * 1e3
            );
            if let Some(o) = request.overlay.as_ref() {
                puffin::profile_scope!("overlay");
                // B, G, R at bytes 0–2 as in BGRA; the overlay never writes the fourth byte.
                overlay.draw(bytes, size, true, o);
                log::debug!(
                    "present ms: cpu overlay {:.2}",
                    started.elapsed().as_secs_f64() * 1e3
                );
            }
        });
        match shown {
            Ok(shot) => Some(shot),
            Err(e) => {
                log::warn!("softbuffer failed ({e}): presenting the CPU film through wgpu");
                self.soft = Soft::Off;
                None
            }
        }
    }

    fn draw(
        &mut self,
        context: &GpuContext,
        film: Option<FilmView<'_>>,
        request: &PresentRequest,
        presented: &mut Presented,
    ) -> Result<Option<PendingReadback>, RenderError> {
        let started = Instant::now();
        self.surface
            .update(context, request.surface_size, request.vsync);
        let size = self.surface.size();
        let surface_texture = match self.surface.acquire(context)? {
            Acquired::Texture(t) => {
                log::debug!(
                    "present ms: acquire {:.2}",
                    started.elapsed().as_secs_f64() * 1e3
                );
                Some(t)
            }
            Acquired::Skip(reason) => {
                presented.skipped = Some(reason);
                None
            }
        };
        let overlay = request.overlay.as_ref();
        if let (Some(FilmView::Host(host)), Some(texture)) = (film, &surface_texture)
            && !request.screenshot
            && self.surface.accepts_copies()
            && host_blit_enabled()
        {
            // The CPU tracer's film: composed on the CPU and copied into the surface, the
            // overlay drawn over it (see `cpu_compose.rs`).
            let format = self.surface.format();
            let bgra = matches!(
                format,
                wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
            );
            let pixels = {
                puffin::profile_scope!("compose");
                self.host_compose
                    .compose(host, size, &request.tonemap, bgra)
            };
            log::debug!(
                "present ms: cpu compose {:.2}",
                started.elapsed().as_secs_f64() * 1e3
            );
            // A gamma-space surface: the overlay is drawn here as egui-wgpu would draw it;
            // an sRGB one blends in linear space, which the device's painter does below.
            let cpu_overlay = !format.is_srgb();
            if let (true, Some(overlay)) = (cpu_overlay, overlay) {
                puffin::profile_scope!("overlay");
                self.cpu_overlay.draw(pixels, size, bgra, overlay);
                log::debug!(
                    "present ms: cpu overlay {:.2}",
                    started.elapsed().as_secs_f64() * 1e3
                );
            }
            context.queue.write_texture(
                texture.texture.as_image_copy(),
                pixels,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * size.0),
                    rows_per_image: Some(size.1),
                },
                wgpu::Extent3d {
                    width: size.0,
                    height: size.1,
                    depth_or_array_layers: 1,
                },
            );
            let mut encoder = context.device.create_command_encoder(&Default::default());
            let view = texture.texture.create_view(&Default::default());
            let extra = if cpu_overlay {
                Vec::new()
            } else {
                self.composer
                    .encode_overlay(&mut encoder, &view, size, overlay)
            };
            submit_and_present(
                context,
                extra,
                encoder,
                surface_texture,
                started,
                "host blit: acquire+compose+encode",
            );
            return Ok(None);
        }
        puffin::profile_scope!("compose and overlay (device)");
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
        submit_and_present(
            context,
            extra,
            encoder,
            surface_texture,
            started,
            "acquire+encode",
        );
        Ok(readback)
    }
}

/// Submits `extra` then `encoder`, presents `surface_texture` (if any), and logs (debug) how
/// long encoding (`what`, since `started`), the submit and the present took, in milliseconds.
fn submit_and_present(
    context: &GpuContext,
    extra: Vec<wgpu::CommandBuffer>,
    encoder: wgpu::CommandEncoder,
    surface_texture: Option<wgpu::SurfaceTexture>,
    started: Instant,
    what: &str,
) {
    let encoded = started.elapsed().as_secs_f64();
    context
        .queue
        .submit(extra.into_iter().chain([encoder.finish()]));
    let submitted = started.elapsed().as_secs_f64();
    if let Some(texture) = surface_texture {
        context.queue.present(texture);
    }
    log::debug!(
        "present ms: {what} {:.2} submit {:.2} present {:.2}",
        encoded * 1e3,
        (submitted - encoded) * 1e3,
        (started.elapsed().as_secs_f64() - submitted) * 1e3
    );
}
