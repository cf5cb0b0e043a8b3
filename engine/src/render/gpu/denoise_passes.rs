//! The GPU denoiser's passes as wgpu objects, and the packing of the reprojection's inputs:
//! each pass's bindings, pipeline and bind groups (`shaders/denoise_reproject.wgsl`,
//! `denoise_temporal.wgsl`, `denoise_variance.wgsl`, `denoise_atrous.wgsl`), the
//! [`GpuReprojectUniforms`] of a frame's two views, the [`GpuMotion`] rows of the instances'
//! motions and the per-pixel ids (instance, specular, raw depth) the reprojection compares.
//!
//! Owns: nothing between frames (`denoise.rs` keeps the buffers). Render thread.
//! Must not: decide what to reproject (the CPU reference `render::denoise::reproject` and
//! `denoise.rs` do).

use glam::Affine3A;

use super::shaders::{
    DENOISE_ATROUS, DENOISE_REPROJECT, DENOISE_SHARED, DENOISE_TEMPORAL, DENOISE_VARIANCE,
    ShaderSource, compose_with,
};
use crate::layout::{GpuMotion, GpuReprojectUniforms};
use crate::render::denoise::{Guides, View};

/// How a pass uses one of its bindings.
#[derive(Clone, Copy)]
pub(super) enum Use {
    Uniform,
    Read,
    Write,
}

pub(super) struct Pipeline {
    pub pipeline: wgpu::ComputePipeline,
    pub layout: wgpu::BindGroupLayout,
}

/// The four passes, compiled.
pub(super) struct Passes {
    pub reproject: Pipeline,
    pub temporal: Pipeline,
    pub variance: Pipeline,
    pub atrous: Pipeline,
}

/// Bindings of the reprojection: 0 denoise uniforms, 1 guides, 3 reprojection uniforms, 4 ids,
/// 5 previous guides, 6 previous ids, 7 previous history (rows 0..n) and moments (n..2n),
/// 8 motions, 9 history, 10 moments (binding 2, the albedo, is not used).
pub(super) const REPROJECT: [(u32, Use); 10] = [
    (0, Use::Uniform),
    (1, Use::Read),
    (3, Use::Uniform),
    (4, Use::Read),
    (5, Use::Read),
    (6, Use::Read),
    (7, Use::Read),
    (8, Use::Read),
    (9, Use::Write),
    (10, Use::Write),
];
/// 0 uniforms, 1 guides, 2 albedo, 3 frame, 4 history, 5 moments, 6 reprojection uniforms.
pub(super) const TEMPORAL: [(u32, Use); 7] = [
    (0, Use::Uniform),
    (1, Use::Read),
    (2, Use::Read),
    (3, Use::Read),
    (4, Use::Write),
    (5, Use::Write),
    (6, Use::Uniform),
];
/// 0 uniforms, 1 guides, 2 albedo, 3 history, 4 moments, 5 out.
pub(super) const VARIANCE: [(u32, Use); 6] = [
    (0, Use::Uniform),
    (1, Use::Read),
    (2, Use::Read),
    (3, Use::Read),
    (4, Use::Read),
    (5, Use::Write),
];
/// 0 uniforms, 1 guides, 2 albedo, 3 in, 4 out.
pub(super) const ATROUS: [(u32, Use); 5] = [
    (0, Use::Uniform),
    (1, Use::Read),
    (2, Use::Read),
    (3, Use::Read),
    (4, Use::Write),
];

impl Passes {
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            reproject: pipeline(device, DENOISE_REPROJECT, "denoise_reproject", &REPROJECT),
            temporal: pipeline(device, DENOISE_TEMPORAL, "denoise_temporal", &TEMPORAL),
            variance: pipeline(device, DENOISE_VARIANCE, "denoise_variance", &VARIANCE),
            atrous: pipeline(device, DENOISE_ATROUS, "denoise_atrous", &ATROUS),
        }
    }
}

fn pipeline(
    device: &wgpu::Device,
    source: ShaderSource,
    entry: &str,
    bindings: &[(u32, Use)],
) -> Pipeline {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
        .iter()
        .map(|&(binding, usage)| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: match usage {
                    Use::Uniform => wgpu::BufferBindingType::Uniform,
                    Use::Read => wgpu::BufferBindingType::Storage { read_only: true },
                    Use::Write => wgpu::BufferBindingType::Storage { read_only: false },
                },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        })
        .collect();
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

/// A bind group of `pass` over `buffers`, in the order of the pass's bindings.
pub(super) fn group(
    device: &wgpu::Device,
    pass: &Pipeline,
    bindings: &[(u32, Use)],
    buffers: &[&wgpu::Buffer],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = bindings
        .iter()
        .zip(buffers)
        .map(|(&(binding, _), b)| wgpu::BindGroupEntry {
            binding,
            resource: b.as_entire_binding(),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("denoise"),
        layout: &pass.layout,
        entries: &entries,
    })
}

/// The reprojection's uniforms: this frame's `view`, the previous frame's `prev` (`None`: the
/// identity, mode 0), and the count of motions uploaded.
pub(super) fn reproject_uniforms(
    view: &View,
    prev: Option<&View>,
    instances: u32,
) -> GpuReprojectUniforms {
    let p = prev.unwrap_or(view);
    GpuReprojectUniforms {
        camera_position: view.position.into(),
        mode: prev.is_some() as u32,
        camera_forward: view.forward.into(),
        instances,
        camera_right: view.right.into(),
        jitter_x: view.jitter.0,
        camera_up: view.up.into(),
        jitter_y: view.jitter.1,
        prev_position: p.position.into(),
        prev_width: p.width,
        prev_forward: p.forward.into(),
        prev_height: p.height,
        prev_right: p.right.into(),
        prev_jitter_x: p.jitter.0,
        prev_up: p.up.into(),
        prev_jitter_y: p.jitter.1,
    }
}

/// Each motion and its inverse (glam's, as the CPU reference takes it) as three rows of a 3×4
/// matrix each.
pub(super) fn motion_rows(motions: &[Affine3A]) -> Vec<GpuMotion> {
    let rows = |m: &Affine3A| {
        let (c, t) = (m.matrix3, m.translation);
        [
            [c.x_axis.x, c.y_axis.x, c.z_axis.x, t.x],
            [c.x_axis.y, c.y_axis.y, c.z_axis.y, t.y],
            [c.x_axis.z, c.y_axis.z, c.z_axis.z, t.z],
        ]
    };
    motions
        .iter()
        .map(|m| GpuMotion {
            prev_from_now: rows(m),
            now_from_prev: rows(&m.inverse()),
        })
        .collect()
}

/// (instance, specular, raw depth bits, 0) per pixel: what the reprojection compares.
pub(super) fn pixel_ids(guides: &Guides) -> Vec<[u32; 4]> {
    guides
        .instance
        .iter()
        .zip(&guides.specular)
        .zip(&guides.depth)
        .map(|((&instance, &specular), depth)| [instance, specular as u32, depth.to_bits(), 0])
        .collect()
}
