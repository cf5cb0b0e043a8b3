//! [`GpuTracer`]: the path tracer as a wgpu compute pass (render thread only).
//!
//! Owns: uploading a `RenderScene` once (storage buffers in `layout` form, bound as in
//! `shaders/shared/bindings.wgsl`), the film and ray-counter buffers, dispatching the tracing
//! pass, and reading results back.
//! Must not: modify the scene on the CPU side or know about windows (the presenter reads the
//! film buffer through `Tracer::film_view`).

use std::sync::Arc;

use glam::Vec3;
use wgpu::util::DeviceExt;

use super::context::GpuContext;
use super::shaders::compose_trace;
use crate::layout::{GpuFrameUniforms, GpuLine, GpuTexture, GpuTri4, GpuTriangle, GpuVertex};
use crate::render::film::Film;
use crate::render::tracer::{FilmView, RenderError, RenderStats, Tracer};
use crate::scene::{MAX_LINES, RenderScene};

/// Workgroup edge of `trace_main` (8×8 invocations).
pub(super) const WORKGROUP: u32 = 8;

/// The GPU path tracer.
pub struct GpuTracer {
    pub(super) context: Arc<GpuContext>,
    pub(super) pipeline: wgpu::ComputePipeline,
    pub(super) layout: wgpu::BindGroupLayout,
    /// Uniforms, then the nine scene buffers (bindings 0..=9), then the light tree's nodes and
    /// lookup (bindings 13 and 14), the line emitters (15, rewritten whole on each update) and
    /// the sky-view table (16, rewritten when the scene's table changes): binding
    /// [`scene_binding`]`(i)` of each index `i`.
    pub(super) scene_buffers: Vec<wgpu::Buffer>,
    pub(super) film: Option<FilmBuffers>,
    /// The sky-view texels last written to binding 16 (compared by pointer on each update).
    pub(super) sky_texels: Arc<Vec<[f32; 4]>>,
    /// The cloud optical depths last appended to binding 16 (compared by pointer).
    pub(super) cloud_texels: Arc<Vec<f32>>,
    pub(super) samples: u32,
    /// Created on first use by `trace_rays` (see `ray_batch.rs`).
    pub(super) ray_batch: Option<super::ray_batch::RayBatchPipeline>,
}

pub(super) struct FilmBuffers {
    width: u32,
    height: u32,
    pub(super) film: wgpu::Buffer,
    pub(super) counters: wgpu::Buffer,
    /// The work units to render (binding 12): their count, then each unit's index.
    pub(super) units: wgpu::Buffer,
    pub(super) bind_group: wgpu::BindGroup,
}

/// The binding of `scene_buffers[index]`: 0..=9, then 13..=16 (10..=12 are the film's).
pub(super) fn scene_binding(index: usize) -> u32 {
    if index <= 9 {
        index as u32
    } else {
        index as u32 + 3
    }
}

/// The line emitters' buffer (binding 15): always [`MAX_LINES`]` + 1` lines, the scene's
/// first, then zeroed ones (a zero radius ends the list in `shaders/shared/lines.wgsl`).
pub(super) fn line_bytes(scene: &RenderScene) -> Vec<u8> {
    let mut lines = scene.lines();
    lines.resize(MAX_LINES + 1, GpuLine::default());
    bytemuck::cast_slice(&lines).to_vec()
}

/// Bytes of `data`, or one zeroed element when it is empty (bindings may not be empty).
fn non_empty<T: bytemuck::Pod + bytemuck::Zeroable>(data: &[T]) -> Vec<u8> {
    if data.is_empty() {
        bytemuck::bytes_of(&T::zeroed()).to_vec()
    } else {
        bytemuck::cast_slice(data).to_vec()
    }
}

impl GpuTracer {
    /// Uploads `scene` and builds the pipeline.
    pub fn new(context: Arc<GpuContext>, scene: &RenderScene) -> Result<Self, RenderError> {
        let device = &context.device;
        let max_binding = context.limits.max_storage_buffer_binding_size;
        let contents: [(&str, Vec<u8>); 13] = [
            ("nodes", non_empty(&scene.nodes)),
            ("blocks", non_empty::<GpuTri4>(&scene.blocks)),
            ("instances", non_empty(&scene.instances)),
            ("triangles", non_empty::<GpuTriangle>(&scene.triangles)),
            ("vertices", non_empty::<GpuVertex>(&scene.vertices)),
            ("materials", non_empty(&scene.materials)),
            ("textures", non_empty::<GpuTexture>(&scene.textures)),
            ("texels", non_empty(&scene.texels)),
            ("lights", non_empty(&scene.lights.lights)),
            ("light nodes", non_empty(&scene.lights.tree.nodes)),
            ("light lookup", non_empty(&scene.lights.tree.lookup)),
            ("lines", line_bytes(scene)),
            ("sky view", super::upload::sky_bytes(scene)),
        ];
        for (name, bytes) in &contents {
            if bytes.len() as u64 > max_binding {
                return Err(RenderError::TooLarge(format!(
                    "{name} need {} bytes; this device binds at most {max_binding} bytes per buffer",
                    bytes.len()
                )));
            }
        }
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let mut scene_buffers = vec![device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("frame uniforms"),
            size: size_of::<GpuFrameUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })];
        for (name, bytes) in &contents {
            scene_buffers.push(
                device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(name),
                    contents: bytes,
                    usage: wgpu::BufferUsages::STORAGE
                        | wgpu::BufferUsages::COPY_DST
                        | wgpu::BufferUsages::COPY_SRC,
                }),
            );
        }
        let storage = |binding: u32, read_only: bool| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let mut entries = vec![wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }];
        entries.extend((1..=9).map(|b| storage(b, true)));
        entries.push(storage(10, false));
        entries.push(storage(11, false));
        entries.push(storage(12, true));
        entries.push(storage(13, true));
        entries.push(storage(14, true));
        entries.push(storage(15, true));
        entries.push(storage(16, true));
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("trace bindings"),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("trace"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let source = compose_trace();
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("trace.wgsl"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("trace"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("trace_main"),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Device(error.to_string()));
        }
        Ok(Self {
            context,
            pipeline,
            layout,
            scene_buffers,
            film: None,
            sky_texels: Arc::clone(&scene.sky.texels),
            cloud_texels: Arc::clone(&scene.sky.clouds),
            samples: 0,
            ray_batch: None,
        })
    }

    pub(super) fn film_buffers(
        &mut self,
        width: u32,
        height: u32,
    ) -> Result<&FilmBuffers, RenderError> {
        let matches = matches!(&self.film, Some(f) if f.width == width && f.height == height);
        if !matches {
            let device = &self.context.device;
            let bytes = width as u64 * height as u64 * 16;
            if bytes > self.context.limits.max_storage_buffer_binding_size {
                return Err(RenderError::BadSize {
                    width,
                    height,
                    reason: "the film does not fit one storage buffer of this device".into(),
                });
            }
            let film = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("film"),
                size: bytes,
                usage: wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_SRC
                    | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let counters = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("ray counters"),
                size: 16,
                usage: wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_SRC
                    | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let units = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("work units"),
                size: (crate::render::balance::unit_count(height) as u64 + 1) * 4,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind_group = self.bind_group(&film, &counters, &units);
            self.film = Some(FilmBuffers {
                width,
                height,
                film,
                counters,
                units,
                bind_group,
            });
            self.samples = 0;
        }
        self.film
            .as_ref()
            .ok_or_else(|| RenderError::Device("film buffers missing".into()))
    }

    /// The group-0 bind group over the current scene buffers, `film`, `counters` and `units`.
    pub(super) fn bind_group(
        &self,
        film: &wgpu::Buffer,
        counters: &wgpu::Buffer,
        units: &wgpu::Buffer,
    ) -> wgpu::BindGroup {
        let mut entries: Vec<wgpu::BindGroupEntry> = self
            .scene_buffers
            .iter()
            .enumerate()
            .map(|(i, b)| wgpu::BindGroupEntry {
                binding: scene_binding(i),
                resource: b.as_entire_binding(),
            })
            .collect();
        entries.push(wgpu::BindGroupEntry {
            binding: 10,
            resource: film.as_entire_binding(),
        });
        entries.push(wgpu::BindGroupEntry {
            binding: 11,
            resource: counters.as_entire_binding(),
        });
        entries.push(wgpu::BindGroupEntry {
            binding: 12,
            resource: units.as_entire_binding(),
        });
        self.context
            .device
            .create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("trace"),
                layout: &self.layout,
                entries: &entries,
            })
    }

    /// Rebuilds the film's bind group after a scene buffer was replaced.
    pub(super) fn rebind(&mut self) {
        if let Some(film) = self.film.take() {
            let bind_group = self.bind_group(&film.film, &film.counters, &film.units);
            self.film = Some(FilmBuffers { bind_group, ..film });
        }
    }

    /// The device this tracer runs on (shared with a window's presenter).
    pub fn context(&self) -> &Arc<GpuContext> {
        &self.context
    }

    /// `result`, except that any error once the device is lost is [`RenderError::DeviceLost`]
    /// (a lost device makes every call fail, with whatever message the failing call has).
    pub(crate) fn lost_or<T>(&self, result: Result<T, RenderError>) -> Result<T, RenderError> {
        match (result, self.context.lost()) {
            (Err(RenderError::DeviceLost(reason)), _) | (Err(_), Some(reason)) => {
                Err(RenderError::DeviceLost(reason))
            }
            (result, _) => result,
        }
    }

    pub(super) fn film_buffers_ref(&self) -> Option<&FilmBuffers> {
        self.film.as_ref()
    }

    /// Copies `buffer` into a mappable buffer and returns its bytes.
    pub(super) fn read_buffer(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>, RenderError> {
        let device = &self.context.device;
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: buffer.size(),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
        self.context.queue.submit([encoder.finish()]);
        super::context::map_for_reading(device, &staging)?;
        let bytes = staging
            .get_mapped_range(..)
            .map_err(|e| RenderError::Device(e.to_string()))?
            .to_vec();
        staging.unmap();
        Ok(bytes)
    }
}

impl Tracer for GpuTracer {
    fn name(&self) -> &'static str {
        "gpu"
    }

    fn device(&self) -> String {
        self.context.describe()
    }

    fn render(
        &mut self,
        _scene: &RenderScene,
        u: &GpuFrameUniforms,
    ) -> Result<RenderStats, RenderError> {
        self.context.check_alive()?;
        let all: Vec<u32> = (0..crate::render::balance::unit_count(u.height) as u32).collect();
        let result = self
            .submit_units(u, &all)
            .and_then(|started| self.finish(u, started));
        self.lost_or(result)
    }

    fn update(
        &mut self,
        scene: &RenderScene,
        writes: &[crate::scene::SceneWrite],
    ) -> Result<(), RenderError> {
        self.context.check_alive()?;
        let result = self.upload(scene, writes);
        self.lost_or(result)
    }

    fn film(&mut self) -> Result<Film, RenderError> {
        self.context.check_alive()?;
        let Some(film) = self.film.as_ref() else {
            return Ok(Film::new(0, 0));
        };
        let bytes = self.lost_or(self.read_buffer(&film.film))?;
        let texels: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
        Ok(Film {
            width: film.width,
            height: film.height,
            mean: texels.iter().map(|t| Vec3::new(t[0], t[1], t[2])).collect(),
            samples: self.samples,
        })
    }

    fn film_view(&self) -> Option<FilmView<'_>> {
        self.film.as_ref().map(|f| FilmView::Device {
            buffer: &f.film,
            width: f.width,
            height: f.height,
        })
    }

    fn clear(&mut self) {
        if let Some(film) = &self.film {
            let mut encoder = self
                .context
                .device
                .create_command_encoder(&Default::default());
            encoder.clear_buffer(&film.film, 0, None);
            self.context.queue.submit([encoder.finish()]);
        }
        self.samples = 0;
    }

    fn device_lost(&self) -> Option<String> {
        self.context.lost()
    }

    fn gpu_context(&self) -> Option<Arc<GpuContext>> {
        Some(self.context.clone())
    }
}
