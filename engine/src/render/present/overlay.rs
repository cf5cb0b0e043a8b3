//! Drawing the egui overlay that arrived in a commit over the tonemapped frame (render thread).
//!
//! Owns: the egui-wgpu renderer (its font atlas and other egui textures live on the render
//! thread's device). Texture changes are applied for every overlay that arrives, even when
//! nothing is presented that frame, so that the atlas never misses an update.
//! Must not: run egui itself (the main thread does, where the window events are).

use crate::commit::Overlay;

/// egui's painter on the render thread.
pub struct OverlayPainter {
    renderer: egui_wgpu::Renderer,
}

impl OverlayPainter {
    /// A painter that draws into targets of `format`.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let options = egui_wgpu::RendererOptions {
            msaa_samples: 1,
            // The overlay is flat text and boxes: dithering would only add noise.
            dithering: false,
            ..Default::default()
        };
        Self {
            renderer: egui_wgpu::Renderer::new(device, format, options),
        }
    }

    /// Uploads the overlay's new or changed textures and frees the ones egui let go of (after
    /// this, `overlay.textures_delta` is empty). Call once per overlay, before drawing it.
    pub fn apply_textures(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        overlay: &mut Overlay,
    ) -> TexturesToFree {
        let delta = std::mem::take(&mut overlay.textures_delta);
        for (id, changes) in &delta.set {
            for change in changes {
                self.renderer.update_texture(device, queue, *id, change);
            }
        }
        TexturesToFree(delta.free.iter().copied().collect())
    }

    /// Encodes `overlay` over `target` (`size` in physical pixels; the target's content is
    /// kept). Returns command buffers that must be submitted before `encoder`'s.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        overlay: &Overlay,
    ) -> Vec<wgpu::CommandBuffer> {
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [size.0, size.1],
            pixels_per_point: overlay.pixels_per_point.max(0.1),
        };
        let extra =
            self.renderer
                .update_buffers(device, queue, encoder, &overlay.primitives, &screen);
        let mut pass = encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("overlay"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Load,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime();
        self.renderer
            .render(&mut pass, &overlay.primitives, &screen);
        extra
    }

    /// Frees textures egui no longer uses (after the frame that last drew them was encoded).
    pub fn free(&mut self, textures: TexturesToFree) {
        for id in &textures.0 {
            self.renderer.free_texture(id);
        }
    }
}

/// egui textures to free once the current frame is encoded.
#[must_use = "free them with OverlayPainter::free after drawing"]
pub struct TexturesToFree(Vec<egui::TextureId>);
