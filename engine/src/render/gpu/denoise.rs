//! The GPU denoiser: the SVGF passes of `render::denoise` (the CPU reference) as wgpu compute
//! passes (`shaders/denoise_temporal.wgsl`, `denoise_variance.wgsl`, `denoise_atrous.wgsl`).
//!
//! Owns: [`GpuDenoiser`] — its pipelines, the history and work buffers on the device, the
//! upload of one frame's radiance and guides, one submission per frame (temporal, variance,
//! `iterations` à-trous passes, the last remodulating into the output), and reading the
//! output (and the history, for tests) back. Linear radiance in and out; render thread.
//! Output rows are `vec4<f32>` (xyz = denoised radiance), like the GPU tracer's film, so a
//! presenter on the same device can read [`GpuDenoiser::output_view`] in place.
//! Must not: trace rays or know the scene.

use std::sync::Arc;

use glam::{Vec3, Vec4};

use super::context::{GpuContext, map_for_reading};
use super::shaders::{
    DENOISE_ATROUS, DENOISE_SHARED, DENOISE_TEMPORAL, DENOISE_VARIANCE, compose_with,
};
use crate::layout::GpuDenoiseUniforms;
use crate::render::denoise::{Guides, SvgfParams};
use crate::render::film::Film;
use crate::render::tracer::{FilmView, RenderError};

/// Workgroup edge of every denoiser pass (8×8).
const GROUP: u32 = 8;

struct Pipeline {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

/// Buffers of one image size and the bind groups over them.
struct Sized {
    width: u32,
    height: u32,
    guides: wgpu::Buffer,
    albedo: wgpu::Buffer,
    frame: wgpu::Buffer,
    history: wgpu::Buffer,
    moments: wgpu::Buffer,
    output: wgpu::Buffer,
    /// Uniforms: [temporal/variance, à-trous pass 0, 1, …].
    uniforms: Vec<wgpu::Buffer>,
    temporal: wgpu::BindGroup,
    variance: wgpu::BindGroup,
    atrous: Vec<wgpu::BindGroup>,
    _work: [wgpu::Buffer; 2],
}

/// SVGF on the wgpu device.
pub struct GpuDenoiser {
    context: Arc<GpuContext>,
    pub params: SvgfParams,
    temporal: Pipeline,
    variance: Pipeline,
    atrous: Pipeline,
    sized: Option<Sized>,
}

fn pipeline(
    device: &wgpu::Device,
    source: super::shaders::ShaderSource,
    entry: &str,
    writable: &[bool],
) -> Pipeline {
    let buffer = |binding: u32, ty: wgpu::BufferBindingType| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let mut entries = vec![
        buffer(0, wgpu::BufferBindingType::Uniform),
        buffer(1, wgpu::BufferBindingType::Storage { read_only: true }),
        buffer(2, wgpu::BufferBindingType::Storage { read_only: true }),
    ];
    for (k, &w) in writable.iter().enumerate() {
        entries.push(buffer(
            3 + k as u32,
            wgpu::BufferBindingType::Storage { read_only: !w },
        ));
    }
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(entry),
        entries: &entries,
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(entry),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(source.name),
        source: wgpu::ShaderSource::Wgsl(compose_with(DENOISE_SHARED, source).into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: Some(&pipeline_layout),
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    });
    Pipeline { pipeline, layout }
}

fn group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    buffers: &[&wgpu::Buffer],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = buffers
        .iter()
        .enumerate()
        .map(|(k, b)| wgpu::BindGroupEntry {
            binding: k as u32,
            resource: b.as_entire_binding(),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("denoise"),
        layout,
        entries: &entries,
    })
}

impl GpuDenoiser {
    /// Compiles the passes on `context`'s device.
    pub fn new(context: Arc<GpuContext>, params: SvgfParams) -> Result<Self, RenderError> {
        let device = &context.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let temporal = pipeline(
            device,
            DENOISE_TEMPORAL,
            "denoise_temporal",
            &[false, true, true],
        );
        let variance = pipeline(
            device,
            DENOISE_VARIANCE,
            "denoise_variance",
            &[false, false, true],
        );
        let atrous = pipeline(device, DENOISE_ATROUS, "denoise_atrous", &[false, true]);
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Device(error.to_string()));
        }
        Ok(Self {
            context,
            params,
            temporal,
            variance,
            atrous,
            sized: None,
        })
    }

    fn passes(&self) -> usize {
        self.params.passes().len()
    }

    fn ensure_size(&mut self, width: u32, height: u32) {
        if self.sized.as_ref().is_some_and(|s| {
            s.width == width && s.height == height && s.atrous.len() == self.passes()
        }) {
            return;
        }
        let device = &self.context.device;
        let bytes = (width as u64 * height as u64 * 16).max(16);
        let storage = |label: &str| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: bytes,
                usage: wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            })
        };
        let (guides, albedo, frame) = (storage("guides"), storage("albedo"), storage("frame"));
        let (history, moments, output) =
            (storage("history"), storage("moments"), storage("denoised"));
        let work = [storage("denoise work a"), storage("denoise work b")];
        let n = self.passes();
        let uniforms: Vec<wgpu::Buffer> = (0..=n)
            .map(|_| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("denoise uniforms"),
                    size: size_of::<GpuDenoiseUniforms>() as u64,
                    usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            })
            .collect();
        let common = [&uniforms[0], &guides, &albedo];
        let temporal = group(
            device,
            &self.temporal.layout,
            &[common[0], common[1], common[2], &frame, &history, &moments],
        );
        let variance = group(
            device,
            &self.variance.layout,
            &[
                common[0], common[1], common[2], &history, &moments, &work[0],
            ],
        );
        let atrous = (0..n)
            .map(|k| {
                let input = &work[k % 2];
                let out = if k + 1 == n {
                    &output
                } else {
                    &work[(k + 1) % 2]
                };
                group(
                    device,
                    &self.atrous.layout,
                    &[&uniforms[k + 1], &guides, &albedo, input, out],
                )
            })
            .collect();
        self.sized = Some(Sized {
            width,
            height,
            guides,
            albedo,
            frame,
            history,
            moments,
            output,
            uniforms,
            temporal,
            variance,
            atrous,
            _work: work,
        });
    }

    /// Forgets the history (the next frame starts afresh).
    pub fn reset(&mut self) {
        if let Some(s) = &self.sized {
            let mut encoder = self
                .context
                .device
                .create_command_encoder(&Default::default());
            encoder.clear_buffer(&s.history, 0, None);
            encoder.clear_buffer(&s.moments, 0, None);
            self.context.queue.submit([encoder.finish()]);
        }
    }

    /// Denoises one frame, as `Svgf::denoise` does: `frame` is this frame's mean radiance per
    /// pixel, `blend` its weight against the history (1 restarts). The output stays on the
    /// device ([`GpuDenoiser::output_view`], [`GpuDenoiser::read_output`]).
    pub fn denoise(
        &mut self,
        frame: &[Vec3],
        guides: &Guides,
        blend: f32,
    ) -> Result<(), RenderError> {
        let (width, height) = (guides.width, guides.height);
        if width == 0 || height == 0 || !guides.is_consistent() || frame.len() != guides.len() {
            return Err(RenderError::BadSize {
                width,
                height,
                reason: format!(
                    "{} frame pixels for {} guide pixels",
                    frame.len(),
                    guides.len()
                ),
            });
        }
        let resized = self
            .sized
            .as_ref()
            .is_none_or(|s| s.width != width || s.height != height);
        self.ensure_size(width, height);
        let Some(s) = &self.sized else {
            return Err(RenderError::Device("denoiser buffers missing".into()));
        };
        let queue = &self.context.queue;
        let rows: Vec<Vec4> = frame.iter().map(|c| c.extend(0.0)).collect();
        queue.write_buffer(&s.frame, 0, bytemuck::cast_slice(&rows));
        queue.write_buffer(
            &s.guides,
            0,
            bytemuck::cast_slice(&guides.packed_normal_depth()),
        );
        queue.write_buffer(&s.albedo, 0, bytemuck::cast_slice(&guides.packed_albedo()));
        let passes = self.params.passes();
        let mut base = GpuDenoiseUniforms {
            width,
            height,
            step: 1,
            remodulate: 0,
            blend: if resized { 1.0 } else { blend },
            sigma_z: self.params.sigma_z,
            sigma_l: self.params.sigma_l,
            _padding: 0,
        };
        queue.write_buffer(&s.uniforms[0], 0, bytemuck::bytes_of(&base));
        for (k, pass) in passes.iter().enumerate() {
            base.step = pass.step as u32;
            base.remodulate = pass.remodulate as u32;
            queue.write_buffer(&s.uniforms[k + 1], 0, bytemuck::bytes_of(&base));
        }
        let groups = (width.div_ceil(GROUP), height.div_ceil(GROUP));
        let mut encoder = self
            .context
            .device
            .create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("denoise"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.temporal.pipeline);
            pass.set_bind_group(0, &s.temporal, &[]);
            pass.dispatch_workgroups(groups.0, groups.1, 1);
            pass.set_pipeline(&self.variance.pipeline);
            pass.set_bind_group(0, &s.variance, &[]);
            pass.dispatch_workgroups(groups.0, groups.1, 1);
            pass.set_pipeline(&self.atrous.pipeline);
            for g in &s.atrous {
                pass.set_bind_group(0, g, &[]);
                pass.dispatch_workgroups(groups.0, groups.1, 1);
            }
        }
        queue.submit([encoder.finish()]);
        Ok(())
    }

    /// The output in place, for a presenter on the same device (`None` before the first frame).
    pub fn output_view(&self) -> Option<FilmView<'_>> {
        self.sized.as_ref().map(|s| FilmView::Device {
            buffer: &s.output,
            width: s.width,
            height: s.height,
        })
    }

    fn read(&self, pick: impl Fn(&Sized) -> &wgpu::Buffer) -> Result<Vec<Vec4>, RenderError> {
        let Some(s) = &self.sized else {
            return Ok(Vec::new());
        };
        let buffer = pick(s);
        let device = &self.context.device;
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("denoise readback"),
            size: buffer.size(),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, buffer.size());
        self.context.queue.submit([encoder.finish()]);
        map_for_reading(device, &staging)?;
        let rows: Vec<Vec4> = {
            let bytes = staging
                .get_mapped_range(..)
                .map_err(|e| RenderError::Device(e.to_string()))?;
            bytemuck::cast_slice::<u8, Vec4>(&bytes).to_vec()
        };
        staging.unmap();
        Ok(rows[..(s.width * s.height) as usize].to_vec())
    }

    /// The last output as a film (waits for the device).
    pub fn read_output(&self) -> Result<Film, RenderError> {
        let rows = self.read(|s| &s.output)?;
        let (width, height) = self.sized.as_ref().map_or((0, 0), |s| (s.width, s.height));
        let mut film = Film::new(width, height);
        film.mean = rows.iter().map(|r| r.truncate()).collect();
        Ok(film)
    }

    /// The history rows (illumination rgb, length) and moments, for comparing with the CPU's.
    pub fn read_history(&self) -> Result<(Vec<Vec4>, Vec<Vec4>), RenderError> {
        Ok((self.read(|s| &s.history)?, self.read(|s| &s.moments)?))
    }
}
