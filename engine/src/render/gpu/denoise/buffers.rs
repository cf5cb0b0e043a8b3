//! The GPU denoiser's buffers for one image size ([`Sized`]): making them, and the bind groups
//! over them, when the size or the pass count changes, and growing the instance-motion buffer.
//!
//! Render thread, inside [`GpuDenoiser`]'s calls. Must not: record passes or read back.

use super::GpuDenoiser;
use crate::layout::{GpuDenoiseUniforms, GpuMotion, GpuReprojectUniforms};
use crate::render::gpu::denoise_passes::{ATROUS, REPROJECT, TEMPORAL, VARIANCE, group};

/// Buffers of one image size and the bind groups over them.
pub(super) struct Sized {
    pub(super) width: u32,
    pub(super) height: u32,
    pub(super) guides: wgpu::Buffer,
    pub(super) albedo: wgpu::Buffer,
    pub(super) frame: wgpu::Buffer,
    pub(super) history: wgpu::Buffer,
    pub(super) moments: wgpu::Buffer,
    pub(super) output: wgpu::Buffer,
    pub(super) ids: wgpu::Buffer,
    pub(super) prev_guides: wgpu::Buffer,
    pub(super) prev_ids: wgpu::Buffer,
    /// The previous frame's history rows, then its moments.
    pub(super) prev_history: wgpu::Buffer,
    /// Uniforms: [temporal/variance, à-trous pass 0, 1, …].
    pub(super) uniforms: Vec<wgpu::Buffer>,
    pub(super) reproject_uniforms: wgpu::Buffer,
    /// Instance motions (room for `motion_capacity`) and the reprojection's group over them.
    pub(super) motions: wgpu::Buffer,
    pub(super) motion_capacity: usize,
    /// Built once the buffers it binds are in place.
    pub(super) reproject: Option<wgpu::BindGroup>,
    pub(super) temporal: wgpu::BindGroup,
    pub(super) variance: wgpu::BindGroup,
    pub(super) atrous: Vec<wgpu::BindGroup>,
    pub(super) _work: [wgpu::Buffer; 2],
}

impl GpuDenoiser {
    fn motion_buffer(device: &wgpu::Device, capacity: usize) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("denoise motions"),
            size: (capacity.max(1) * size_of::<GpuMotion>()) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn reproject_group(&self, s: &Sized) -> wgpu::BindGroup {
        group(
            &self.context.device,
            &self.passes.reproject,
            &REPROJECT,
            &[
                &s.uniforms[0],
                &s.guides,
                &s.reproject_uniforms,
                &s.ids,
                &s.prev_guides,
                &s.prev_ids,
                &s.prev_history,
                &s.motions,
                &s.history,
                &s.moments,
            ],
        )
    }

    pub(super) fn ensure_size(&mut self, width: u32, height: u32) {
        if self.sized.as_ref().is_some_and(|s| {
            s.width == width && s.height == height && s.atrous.len() == self.pass_count()
        }) {
            return;
        }
        let device = &self.context.device;
        let bytes = (width as u64 * height as u64 * 16).max(16);
        let storage = |label: &str, bytes: u64| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: bytes,
                usage: wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            })
        };
        let uniform = |size: usize| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("denoise uniforms"),
                size: size as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        };
        let (guides, albedo, frame) = (
            storage("guides", bytes),
            storage("albedo", bytes),
            storage("frame", bytes),
        );
        let (history, moments, output) = (
            storage("history", bytes),
            storage("moments", bytes),
            storage("denoised", bytes),
        );
        let (ids, prev_guides, prev_ids) = (
            storage("denoise ids", bytes),
            storage("previous guides", bytes),
            storage("previous ids", bytes),
        );
        let prev_history = storage("previous history", 2 * bytes);
        let work = [
            storage("denoise work a", bytes),
            storage("denoise work b", bytes),
        ];
        let n = self.pass_count();
        let uniforms: Vec<wgpu::Buffer> = (0..=n)
            .map(|_| uniform(size_of::<GpuDenoiseUniforms>()))
            .collect();
        let reproject_uniforms = uniform(size_of::<GpuReprojectUniforms>());
        let p = &self.passes;
        let temporal = group(
            device,
            &p.temporal,
            &TEMPORAL,
            &[
                &uniforms[0],
                &guides,
                &albedo,
                &frame,
                &history,
                &moments,
                &reproject_uniforms,
            ],
        );
        let variance = group(
            device,
            &p.variance,
            &VARIANCE,
            &[&uniforms[0], &guides, &albedo, &history, &moments, &work[0]],
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
                    &p.atrous,
                    &ATROUS,
                    &[&uniforms[k + 1], &guides, &albedo, input, out],
                )
            })
            .collect();
        let motions = Self::motion_buffer(device, 1);
        let mut sized = Sized {
            width,
            height,
            guides,
            albedo,
            frame,
            history,
            moments,
            output,
            ids,
            prev_guides,
            prev_ids,
            prev_history,
            uniforms,
            reproject_uniforms,
            motions,
            motion_capacity: 1,
            reproject: None,
            temporal,
            variance,
            atrous,
            _work: work,
        };
        sized.reproject = Some(self.reproject_group(&sized));
        self.sized = Some(sized);
        self.prev = None;
        self.fresh = true;
    }

    /// Room for `count` motions (a new buffer and group when it grows).
    pub(super) fn ensure_motions(&mut self, count: usize) {
        let Some(mut s) = self.sized.take() else {
            return;
        };
        if count > s.motion_capacity {
            s.motion_capacity = count.next_power_of_two();
            s.motions = Self::motion_buffer(&self.context.device, s.motion_capacity);
            s.reproject = Some(self.reproject_group(&s));
        }
        self.sized = Some(s);
    }
}
