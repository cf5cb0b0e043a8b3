//! Batch ray tracing on the GPU: a buffer of rays in, a buffer of closest (or any) hits out.
//!
//! Owns: the `ray_batch.wgsl` pipeline and its buffers. Used by benchmarks to measure the GPU
//! traversal alone, per ray kind, on exactly the rays the CPU traverses.
//! Must not: shade or accumulate (that is the tracing pass).

use std::time::Instant;

use wgpu::util::DeviceExt;

use super::shaders::{RAY_BATCH, compose};
use super::tracer::GpuTracer;
use crate::layout::{GpuHit, GpuRay};
use crate::render::tracer::RenderError;

/// Invocations per workgroup of `ray_batch_main`.
const WORKGROUP: u32 = 64;
/// Workgroups per dispatch row (the WebGPU limit per dimension).
const ROW: u32 = 65535;

pub(super) struct RayBatchPipeline {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

impl GpuTracer {
    fn ray_batch_pipeline(&mut self) -> Result<(), RenderError> {
        if self.ray_batch.is_some() {
            return Ok(());
        }
        let device = &self.context.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let entry = |binding: u32, ty: wgpu::BufferBindingType| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ray batch"),
            entries: &[
                entry(0, wgpu::BufferBindingType::Uniform),
                entry(1, wgpu::BufferBindingType::Storage { read_only: true }),
                entry(2, wgpu::BufferBindingType::Storage { read_only: false }),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("ray batch"),
            bind_group_layouts: &[Some(&self.layout), Some(&layout)],
            immediate_size: 0,
        });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("ray_batch.wgsl"),
            source: wgpu::ShaderSource::Wgsl(compose(RAY_BATCH).into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("ray batch"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("ray_batch_main"),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Device(error.to_string()));
        }
        self.ray_batch = Some(RayBatchPipeline { pipeline, layout });
        Ok(())
    }

    /// Traces `rays` (world space) against the scene: closest hits, or any hit when `any_hit`.
    /// Returns the hits and the seconds the dispatch took (upload and readback excluded).
    /// `tlas_root` must be the scene's (it is written into the frame uniforms).
    pub fn trace_rays(
        &mut self,
        rays: &[GpuRay],
        any_hit: bool,
        tlas_root: u32,
    ) -> Result<(Vec<GpuHit>, f64), RenderError> {
        if rays.is_empty() {
            return Ok((Vec::new(), 0.0));
        }
        self.ray_batch_pipeline()?;
        self.film_buffers(1, 1)?;
        let device = self.context.device.clone();
        let queue = self.context.queue.clone();
        let mut uniforms = crate::layout::GpuFrameUniforms::zeroed_for_batch();
        uniforms.tlas_root = tlas_root;
        queue.write_buffer(&self.scene_buffers[0], 0, bytemuck::bytes_of(&uniforms));
        let params = [rays.len() as u32, any_hit as u32, 0, 0];
        let params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("ray batch params"),
            contents: bytemuck::cast_slice(&params),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let ray_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rays"),
            contents: bytemuck::cast_slice(rays),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let hits = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("hits"),
            size: (rays.len() * size_of::<GpuHit>()) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let Some(batch) = self.ray_batch.as_ref() else {
            return Err(RenderError::Device("ray batch pipeline missing".into()));
        };
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("ray batch"),
            layout: &batch.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: params.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: ray_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: hits.as_entire_binding(),
                },
            ],
        });
        // Finish the uploads before timing.
        queue.submit([]);
        device
            .poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout: None,
            })
            .map_err(|e| RenderError::Device(e.to_string()))?;
        let started = Instant::now();
        let groups = (rays.len() as u32).div_ceil(WORKGROUP);
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let Some(film) = self.film_buffers_ref() else {
                return Err(RenderError::Device("film buffers missing".into()));
            };
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("ray batch"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&batch.pipeline);
            pass.set_bind_group(0, &film.bind_group, &[]);
            pass.set_bind_group(1, &group, &[]);
            pass.dispatch_workgroups(groups.min(ROW), groups.div_ceil(ROW), 1);
        }
        queue.submit([encoder.finish()]);
        device
            .poll(wgpu::PollType::Wait {
                submission_index: None,
                timeout: None,
            })
            .map_err(|e| RenderError::Device(e.to_string()))?;
        let seconds = started.elapsed().as_secs_f64();
        let bytes = self.read_buffer(&hits)?;
        Ok((bytemuck::cast_slice(&bytes).to_vec(), seconds))
    }
}
