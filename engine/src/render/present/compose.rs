//! Composing the displayed frame (render thread): the film tonemapped and upscaled into a
//! target by `shaders/present.wgsl`, then the egui overlay over it; and an offscreen frame
//! texture of the window's format that the presenter copies to the surface and reads back
//! for screenshots.
//!
//! Owns: the present pipeline, its uniforms, the upload buffer for a host (CPU tracer) film,
//! the offscreen frame texture and the overlay painter. Works without any surface, so it is
//! tested headless. Must not: acquire or present surface textures (see `presenter.rs`).

use std::sync::Arc;

use super::overlay::{OverlayPainter, TexturesToFree};
use super::readback::{Screenshot, encode_readback};
use crate::commit::Overlay;
use crate::layout::GpuPresentUniforms;
use crate::render::film::TonemapSettings;
use crate::render::gpu::{GpuContext, PRESENT, PRESENT_SHARED, compose_with};
use crate::render::tracer::{FilmView, RenderError};

/// The offscreen frame: what the window shows.
#[derive(Clone)]
pub struct FrameTarget {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub size: (u32, u32),
}

/// Tonemap + overlay into a target of one format.
pub struct FrameComposer {
    context: Arc<GpuContext>,
    format: wgpu::TextureFormat,
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    uniforms: wgpu::Buffer,
    /// The CPU tracer's film, uploaded as one vec4 per pixel (grown as needed).
    host_film: Option<wgpu::Buffer>,
    frame: Option<FrameTarget>,
    overlay: OverlayPainter,
}

impl FrameComposer {
    /// Builds the present pipeline for targets of `format` (an 8-bit RGBA or BGRA format).
    pub fn new(context: Arc<GpuContext>, format: wgpu::TextureFormat) -> Result<Self, RenderError> {
        let device = &context.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("present"),
            entries: &[
                entry(0, wgpu::BufferBindingType::Uniform),
                entry(1, wgpu::BufferBindingType::Storage { read_only: true }),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("present"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("present.wgsl"),
            source: wgpu::ShaderSource::Wgsl(compose_with(PRESENT_SHARED, PRESENT).into()),
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("present"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("present_vs"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("present_fs"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("present uniforms"),
            size: size_of::<GpuPresentUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Device(format!("present pipeline: {error}")));
        }
        let overlay = OverlayPainter::new(device, format);
        Ok(Self {
            context,
            format,
            pipeline,
            layout,
            uniforms,
            host_film: None,
            frame: None,
            overlay,
        })
    }

    pub fn context(&self) -> &Arc<GpuContext> {
        &self.context
    }

    /// The offscreen frame of `size` (physical pixels), recreated when the size changes.
    pub fn frame(&mut self, size: (u32, u32)) -> FrameTarget {
        if let Some(frame) = &self.frame
            && frame.size == size
        {
            return frame.clone();
        }
        let texture = self
            .context
            .device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("frame"),
                size: wgpu::Extent3d {
                    width: size.0.max(1),
                    height: size.1.max(1),
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: self.format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
        let view = texture.create_view(&Default::default());
        let frame = FrameTarget {
            texture,
            view,
            size,
        };
        self.frame = Some(frame.clone());
        frame
    }

    /// Applies an overlay's texture changes (see [`OverlayPainter::apply_textures`]).
    pub fn apply_overlay_textures(&mut self, overlay: &mut Overlay) -> TexturesToFree {
        self.overlay
            .apply_textures(&self.context.device, &self.context.queue, overlay)
    }

    /// Frees egui textures after the frame that last used them was encoded.
    pub fn free_overlay_textures(&mut self, textures: TexturesToFree) {
        self.overlay.free(textures);
    }

    /// Encodes the film (black when there is none yet), tonemapped and scaled to `size`, into
    /// `target`, then `overlay` over it. Returns command buffers to submit before `encoder`'s.
    pub fn encode(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        film: Option<FilmView<'_>>,
        target: &wgpu::TextureView,
        size: (u32, u32),
        tonemap: &TonemapSettings,
        overlay: Option<&Overlay>,
    ) -> Result<Vec<wgpu::CommandBuffer>, RenderError> {
        let source = self.film_source(film)?;
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("present"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if let Some((buffer, width, height)) = source {
                let uniforms = GpuPresentUniforms {
                    film_width: width,
                    film_height: height,
                    target_width: size.0.max(1),
                    target_height: size.1.max(1),
                    exposure_scale: tonemap.exposure_ev.exp2(),
                    filmic: tonemap.filmic as u32,
                    encode_srgb: !self.format.is_srgb() as u32,
                    _padding: 0,
                };
                self.context
                    .queue
                    .write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
                let group = self
                    .context
                    .device
                    .create_bind_group(&wgpu::BindGroupDescriptor {
                        label: Some("present"),
                        layout: &self.layout,
                        entries: &[
                            wgpu::BindGroupEntry {
                                binding: 0,
                                resource: self.uniforms.as_entire_binding(),
                            },
                            wgpu::BindGroupEntry {
                                binding: 1,
                                resource: buffer.as_entire_binding(),
                            },
                        ],
                    });
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, &group, &[]);
                pass.draw(0..3, 0..1);
            }
        }
        Ok(match overlay {
            Some(overlay) => self.overlay.encode(
                &self.context.device,
                &self.context.queue,
                encoder,
                target,
                size,
                overlay,
            ),
            None => Vec::new(),
        })
    }

    /// Encodes `overlay` (if any) over `target`, keeping its content. Returns command buffers
    /// to submit before `encoder`'s.
    pub fn encode_overlay(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        overlay: Option<&Overlay>,
    ) -> Vec<wgpu::CommandBuffer> {
        match overlay {
            Some(overlay) => self.overlay.encode(
                &self.context.device,
                &self.context.queue,
                encoder,
                target,
                size,
                overlay,
            ),
            None => Vec::new(),
        }
    }

    /// The buffer the present pass reads and the film's size: the tracer's own buffer, or the
    /// host film uploaded into ours.
    fn film_source(
        &mut self,
        film: Option<FilmView<'_>>,
    ) -> Result<Option<(wgpu::Buffer, u32, u32)>, RenderError> {
        Ok(match film {
            None => None,
            Some(FilmView::Device {
                buffer,
                width,
                height,
            }) => Some((buffer.clone(), width, height)),
            Some(FilmView::Host(film)) => {
                if film.width == 0 || film.height == 0 {
                    return Ok(None);
                }
                let texels: Vec<[f32; 4]> =
                    film.mean.iter().map(|c| [c.x, c.y, c.z, 0.0]).collect();
                let bytes: &[u8] = bytemuck::cast_slice(&texels);
                let needed = bytes.len() as u64;
                if needed > self.context.limits.max_storage_buffer_binding_size as u64 {
                    return Err(RenderError::BadSize {
                        width: film.width,
                        height: film.height,
                        reason: "the film does not fit one storage buffer of this device".into(),
                    });
                }
                if self.host_film.as_ref().is_none_or(|b| b.size() < needed) {
                    self.host_film =
                        Some(self.context.device.create_buffer(&wgpu::BufferDescriptor {
                            label: Some("host film"),
                            size: needed,
                            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                            mapped_at_creation: false,
                        }));
                }
                let Some(buffer) = self.host_film.clone() else {
                    return Ok(None);
                };
                self.context.queue.write_buffer(&buffer, 0, bytes);
                Some((buffer, film.width, film.height))
            }
        })
    }

    /// Composes the frame offscreen at `size` and reads it back: what a window of that size
    /// would show (headless screenshots, tests).
    pub fn compose_offscreen(
        &mut self,
        film: Option<FilmView<'_>>,
        size: (u32, u32),
        tonemap: &TonemapSettings,
        overlay: Option<&mut Overlay>,
    ) -> Result<Screenshot, RenderError> {
        let frame = self.frame(size);
        let to_free = overlay.map(|o| (self.apply_overlay_textures(o), &*o));
        let device = self.context.device.clone();
        let mut encoder = device.create_command_encoder(&Default::default());
        let extra = self.encode(
            &mut encoder,
            film,
            &frame.view,
            size,
            tonemap,
            to_free.as_ref().map(|(_, o)| *o),
        )?;
        let readback = encode_readback(&device, &mut encoder, &frame.texture, size);
        self.context
            .queue
            .submit(extra.into_iter().chain([encoder.finish()]));
        if let Some((textures, _)) = to_free {
            self.free_overlay_textures(textures);
        }
        readback.finish(&device)
    }
}
