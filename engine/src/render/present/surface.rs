//! The window's swap chain (render thread): creating the wgpu instance and surface for a winit
//! window, choosing its format and present mode, configuring it to the window's size, and
//! acquiring the next texture (reconfiguring when the surface is outdated or lost).
//!
//! Owns: [`PresentTarget`] (what the window runner hands the render thread) and
//! [`WindowSurface`]. Must not: draw (the composer does) or touch the window itself beyond
//! keeping it alive while the surface exists.

use std::sync::Arc;

use winit::event_loop::OwnedDisplayHandle;
use winit::window::Window;

use crate::render::gpu::GpuContext;
use crate::render::tracer::RenderError;

/// A window to present into, handed to the render thread by the window runner.
#[derive(Clone, Debug)]
pub struct PresentTarget {
    pub window: Arc<Window>,
    /// The event loop's display connection (wgpu 30 wants it when the instance is created).
    pub display: OwnedDisplayHandle,
}

/// 8-bit formats the presenter can write and read back, best first. The plain ones first: the
/// present shader then applies the sRGB curve itself (tested equal to the CPU's within one
/// step of 255), and egui, which blends in gamma space, draws as designed (on an sRGB target
/// its translucent panels come out lighter, and egui-wgpu warns).
const FORMATS: [wgpu::TextureFormat; 4] = [
    wgpu::TextureFormat::Bgra8Unorm,
    wgpu::TextureFormat::Rgba8Unorm,
    wgpu::TextureFormat::Bgra8UnormSrgb,
    wgpu::TextureFormat::Rgba8UnormSrgb,
];

/// A configured surface.
pub struct WindowSurface {
    instance: wgpu::Instance,
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    caps: wgpu::SurfaceCapabilities,
    vsync: bool,
}

/// What acquiring the next texture gave.
pub enum Acquired {
    Texture(wgpu::SurfaceTexture),
    /// Nothing to draw into this time (occluded, timed out, zero size): skip presenting.
    Skip(&'static str),
}

impl WindowSurface {
    /// Creates the instance with the window system's display, the surface, and a device
    /// that can present to it.
    pub fn open(target: &PresentTarget) -> Result<(Self, Arc<GpuContext>), RenderError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(
                Box::new(target.display.clone()),
            ));
        let surface = instance
            .create_surface(Arc::clone(&target.window))
            .map_err(|e| RenderError::Device(format!("cannot create a window surface: {e}")))?;
        let context = GpuContext::for_surface(&instance, &surface)?;
        let caps = surface.get_capabilities(&context.adapter);
        let Some(format) = FORMATS.into_iter().find(|f| caps.formats.contains(f)) else {
            return Err(RenderError::Device(format!(
                "the window surface offers no 8-bit RGBA/BGRA format (it offers {:?})",
                caps.formats
            )));
        };
        let size = target.window.inner_size();
        let mut usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        if caps.usages.contains(wgpu::TextureUsages::COPY_DST) {
            usage |= wgpu::TextureUsages::COPY_DST;
        }
        let config = wgpu::SurfaceConfiguration {
            usage,
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width: size.width.max(1),
            height: size.height.max(1),
            desired_maximum_frame_latency: 2,
            present_mode: wgpu::PresentMode::Fifo,
            alpha_mode: caps
                .alpha_modes
                .first()
                .copied()
                .unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: vec![],
        };
        log::info!(
            "window surface: {format:?}, present modes {:?}, copies {}",
            caps.present_modes,
            if usage.contains(wgpu::TextureUsages::COPY_DST) {
                "accepted"
            } else {
                "refused (drawing straight into it)"
            }
        );
        let mut this = Self {
            instance,
            window: Arc::clone(&target.window),
            surface,
            config,
            caps,
            vsync: true,
        };
        this.configure(&context);
        Ok((this, context))
    }

    /// The surface's texture format (the presenter draws its frame in this format).
    pub fn format(&self) -> wgpu::TextureFormat {
        self.config.format
    }

    /// Whether the surface takes a copy of the offscreen frame (else the frame is drawn into it).
    pub fn accepts_copies(&self) -> bool {
        self.config.usage.contains(wgpu::TextureUsages::COPY_DST)
    }

    /// Current size in physical pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.config.width, self.config.height)
    }

    /// The present mode that vsync on/off maps to on this surface: FIFO with vsync; otherwise
    /// mailbox, else immediate, else FIFO (always offered).
    fn present_mode(&self, vsync: bool) -> wgpu::PresentMode {
        let offered = |m| self.caps.present_modes.contains(&m);
        if vsync {
            wgpu::PresentMode::Fifo
        } else if offered(wgpu::PresentMode::Mailbox) {
            wgpu::PresentMode::Mailbox
        } else if offered(wgpu::PresentMode::Immediate) {
            wgpu::PresentMode::Immediate
        } else {
            wgpu::PresentMode::Fifo
        }
    }

    fn configure(&mut self, context: &GpuContext) {
        self.config.present_mode = self.present_mode(self.vsync);
        self.surface.configure(&context.device, &self.config);
    }

    /// Follows the window's size and the vsync choice; reconfigures only when one changed.
    pub fn update(&mut self, context: &GpuContext, size: (u32, u32), vsync: bool) {
        let (width, height) = (size.0.max(1), size.1.max(1));
        if (width, height) != self.size() || vsync != self.vsync {
            self.config.width = width;
            self.config.height = height;
            self.vsync = vsync;
            self.configure(context);
        }
    }

    /// The next texture to draw into. Reconfigures once when the surface is outdated, and
    /// recreates it when it was lost.
    pub fn acquire(&mut self, context: &GpuContext) -> Result<Acquired, RenderError> {
        for attempt in 0..2 {
            match self.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(t) => return Ok(Acquired::Texture(t)),
                // Still presentable; the window's next size change reconfigures anyway, and
                // some platforms report this every frame, where reconfiguring would stall.
                wgpu::CurrentSurfaceTexture::Suboptimal(t) => return Ok(Acquired::Texture(t)),
                wgpu::CurrentSurfaceTexture::Timeout => return Ok(Acquired::Skip("timeout")),
                wgpu::CurrentSurfaceTexture::Occluded => return Ok(Acquired::Skip("occluded")),
                wgpu::CurrentSurfaceTexture::Outdated => self.configure(context),
                wgpu::CurrentSurfaceTexture::Lost => {
                    log::warn!("window surface lost: recreating it");
                    self.surface = self
                        .instance
                        .create_surface(Arc::clone(&self.window))
                        .map_err(|e| {
                            RenderError::Device(format!("cannot recreate the surface: {e}"))
                        })?;
                    self.configure(context);
                }
                wgpu::CurrentSurfaceTexture::Validation => {
                    return Err(RenderError::Device(format!(
                        "validation error acquiring the window's texture (attempt {})",
                        attempt + 1
                    )));
                }
            }
        }
        Ok(Acquired::Skip("outdated twice in a row"))
    }
}
