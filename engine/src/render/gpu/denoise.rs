//! The GPU denoiser: the SVGF passes of `render::denoise` (the CPU reference) as wgpu compute
//! passes (`denoise_passes`: `shaders/denoise_reproject.wgsl`, `denoise_temporal.wgsl`,
//! `denoise_variance.wgsl`, `denoise_atrous.wgsl`).
//!
//! Owns: [`GpuDenoiser`] — the history and work buffers on the device, the previous frame's
//! guides, ids and history (copied at the end of each frame) with its view and instance
//! transforms on the host, the upload of one frame's radiance and guides, one submission per
//! frame (reprojection when the camera or an instance may have moved, temporal, variance,
//! `iterations` à-trous passes, the last remodulating into the output), and reading the output
//! (and the history, for tests) back. [`GpuDenoiser::denoise_moving`] twins
//! `Svgf::denoise_moving`, [`GpuDenoiser::denoise`] `Svgf::denoise`. Linear radiance in and
//! out; render thread. Output rows are `vec4<f32>` (xyz = denoised radiance), like the GPU
//! tracer's film, so a presenter on the same device can read [`GpuDenoiser::output_view`] in
//! place; a frame already on the device can be handed over with [`GpuDenoiser::frame_buffer`].
//! The buffers of one image size and their bind groups are made in `denoise/buffers.rs`.
//! Must not: trace rays or know the scene.

use std::sync::Arc;

use glam::{Affine3A, Vec3, Vec4};

use super::context::{GpuContext, map_for_reading};
use super::denoise_passes::{Passes, motion_rows, pixel_ids, reproject_uniforms};
use crate::layout::{GpuDenoiseUniforms, GpuReprojectUniforms};
use crate::render::denoise::{Guides, SvgfParams, View, motions};
use crate::render::film::Film;
use crate::render::tracer::{FilmView, RenderError};

mod buffers;
use buffers::Sized;

/// Workgroup edge of every denoiser pass (8×8).
const GROUP: u32 = 8;

/// What the reprojection keeps of the previous frame on the host.
struct Prev {
    view: View,
    world_from_object: Vec<Affine3A>,
}

/// SVGF on the wgpu device.
pub struct GpuDenoiser {
    context: Arc<GpuContext>,
    pub params: SvgfParams,
    passes: Passes,
    sized: Option<Sized>,
    prev: Option<Prev>,
    /// The buffers were (re)made since the last frame: the next one restarts.
    fresh: bool,
}

impl GpuDenoiser {
    /// Compiles the passes on `context`'s device.
    pub fn new(context: Arc<GpuContext>, params: SvgfParams) -> Result<Self, RenderError> {
        let device = &context.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let passes = Passes::new(device);
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(RenderError::Device(error.to_string()));
        }
        Ok(Self {
            context,
            params,
            passes,
            sized: None,
            prev: None,
            fresh: false,
        })
    }

    /// The device the denoiser runs on.
    pub fn context(&self) -> &Arc<GpuContext> {
        &self.context
    }

    fn pass_count(&self) -> usize {
        self.params.passes().len()
    }

    /// Forgets the history (the next frame starts afresh).
    pub fn reset(&mut self) {
        self.prev = None;
        if let Some(s) = &self.sized {
            let mut encoder = self
                .context
                .device
                .create_command_encoder(&Default::default());
            encoder.clear_buffer(&s.history, 0, None);
            encoder.clear_buffer(&s.moments, 0, None);
            encoder.clear_buffer(&s.prev_history, 0, None);
            self.context.queue.submit([encoder.finish()]);
        }
    }

    /// Denoises one frame, as `Svgf::denoise` does (each pixel keeps its own history):
    /// `frame` is this frame's mean radiance per pixel, `blend` its weight against the history
    /// (1 restarts). The output stays on the device ([`GpuDenoiser::output_view`],
    /// [`GpuDenoiser::read_output`]).
    pub fn denoise(
        &mut self,
        frame: &[Vec3],
        guides: &Guides,
        blend: f32,
    ) -> Result<(), RenderError> {
        self.upload_frame(frame, guides)?;
        self.run(guides, blend, None)
    }

    /// Denoises one frame seen from `view` with the instances at `world_from_object` (by
    /// instance index), as `Svgf::denoise_moving` does: the history of the previous frame given
    /// here is reprojected onto this frame's pixels (`shaders/denoise_reproject.wgsl`, twin of
    /// `denoise::reproject`) unless `blend` restarts (NaN or ≥ 1). `view` must be the guides'
    /// size.
    pub fn denoise_moving(
        &mut self,
        frame: &[Vec3],
        guides: &Guides,
        blend: f32,
        view: View,
        world_from_object: Vec<Affine3A>,
    ) -> Result<(), RenderError> {
        self.upload_frame(frame, guides)?;
        self.run(guides, blend, Some((view, world_from_object)))
    }

    /// Like [`GpuDenoiser::denoise_moving`] with the frame already on this device: `film` holds
    /// `vec4<f32>` rows (xyz = mean radiance) of the guides' size, as the GPU tracer's film.
    pub fn denoise_device_frame(
        &mut self,
        film: &wgpu::Buffer,
        guides: &Guides,
        blend: f32,
        view: View,
        world_from_object: Vec<Affine3A>,
    ) -> Result<(), RenderError> {
        let bytes = guides.len() as u64 * 16;
        if film.size() < bytes {
            return Err(RenderError::BadSize {
                width: guides.width,
                height: guides.height,
                reason: format!("the device film holds {} bytes, not {bytes}", film.size()),
            });
        }
        self.check(guides.len(), guides)?;
        self.ensure_size(guides.width, guides.height);
        if let Some(s) = &self.sized {
            let mut encoder = self
                .context
                .device
                .create_command_encoder(&Default::default());
            encoder.copy_buffer_to_buffer(film, 0, &s.frame, 0, bytes);
            self.context.queue.submit([encoder.finish()]);
        }
        self.run(guides, blend, Some((view, world_from_object)))
    }

    fn check(&self, frame: usize, guides: &Guides) -> Result<(), RenderError> {
        let (width, height) = (guides.width, guides.height);
        if width == 0 || height == 0 || !guides.is_consistent() || frame != guides.len() {
            return Err(RenderError::BadSize {
                width,
                height,
                reason: format!("{frame} frame pixels for {} guide pixels", guides.len()),
            });
        }
        Ok(())
    }

    fn upload_frame(&mut self, frame: &[Vec3], guides: &Guides) -> Result<(), RenderError> {
        self.check(frame.len(), guides)?;
        self.ensure_size(guides.width, guides.height);
        if let Some(s) = &self.sized {
            let rows: Vec<Vec4> = frame.iter().map(|c| c.extend(0.0)).collect();
            self.context
                .queue
                .write_buffer(&s.frame, 0, bytemuck::cast_slice(&rows));
        }
        Ok(())
    }

    /// One frame over the uploaded radiance: `moving` is this frame's view and instance
    /// transforms (`None`: identity, as `Svgf::denoise`).
    fn run(
        &mut self,
        guides: &Guides,
        blend: f32,
        moving: Option<(View, Vec<Affine3A>)>,
    ) -> Result<(), RenderError> {
        let (width, height) = (guides.width, guides.height);
        if let Some((view, _)) = &moving
            && (view.width != width || view.height != height)
        {
            return Err(RenderError::BadSize {
                width,
                height,
                reason: format!("the view is {}×{}", view.width, view.height),
            });
        }
        let restart = blend.is_nan() || blend >= 1.0;
        let prev = self.prev.take();
        let (ru, motion) = match &moving {
            Some((view, now)) => match prev {
                Some(prev) if !restart => {
                    let moved = motions(&prev.world_from_object, now);
                    let ru = reproject_uniforms(view, Some(&prev.view), moved.len() as u32);
                    (ru, Some(motion_rows(&moved)))
                }
                _ => (reproject_uniforms(view, None, 0), None),
            },
            None => (GpuReprojectUniforms::default(), None),
        };
        if let Some(rows) = &motion {
            self.ensure_motions(rows.len());
        }
        self.prev = moving.map(|(view, world_from_object)| Prev {
            view,
            world_from_object,
        });
        let Some(s) = &self.sized else {
            return Err(RenderError::Device("denoiser buffers missing".into()));
        };
        let resized = std::mem::take(&mut self.fresh);
        let queue = &self.context.queue;
        queue.write_buffer(
            &s.guides,
            0,
            bytemuck::cast_slice(&guides.packed_normal_depth()),
        );
        queue.write_buffer(&s.albedo, 0, bytemuck::cast_slice(&guides.packed_albedo()));
        queue.write_buffer(&s.ids, 0, bytemuck::cast_slice(&pixel_ids(guides)));
        queue.write_buffer(&s.reproject_uniforms, 0, bytemuck::bytes_of(&ru));
        if let Some(rows) = &motion
            && !rows.is_empty()
        {
            queue.write_buffer(&s.motions, 0, bytemuck::cast_slice(rows));
        }
        let mut base = GpuDenoiseUniforms {
            width,
            height,
            step: 1,
            remodulate: 0,
            blend: if resized { 1.0 } else { blend },
            sigma_z: self.params.sigma_z,
            sigma_l: self.params.sigma_l,
            radius: self.params.radius(0),
        };
        queue.write_buffer(&s.uniforms[0], 0, bytemuck::bytes_of(&base));
        for (k, pass) in self.params.passes().iter().enumerate() {
            base.step = pass.step as u32;
            base.remodulate = pass.remodulate as u32;
            base.radius = pass.radius as u32;
            queue.write_buffer(&s.uniforms[k + 1], 0, bytemuck::bytes_of(&base));
        }
        let groups = (width.div_ceil(GROUP), height.div_ceil(GROUP));
        let p = &self.passes;
        let mut encoder = self
            .context
            .device
            .create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("denoise"),
                timestamp_writes: None,
            });
            if let (1, Some(reproject)) = (ru.mode, &s.reproject) {
                pass.set_pipeline(&p.reproject.pipeline);
                pass.set_bind_group(0, reproject, &[]);
                pass.dispatch_workgroups(groups.0, groups.1, 1);
            }
            pass.set_pipeline(&p.temporal.pipeline);
            pass.set_bind_group(0, &s.temporal, &[]);
            pass.dispatch_workgroups(groups.0, groups.1, 1);
            pass.set_pipeline(&p.variance.pipeline);
            pass.set_bind_group(0, &s.variance, &[]);
            pass.dispatch_workgroups(groups.0, groups.1, 1);
            pass.set_pipeline(&p.atrous.pipeline);
            for g in &s.atrous {
                pass.set_bind_group(0, g, &[]);
                pass.dispatch_workgroups(groups.0, groups.1, 1);
            }
        }
        // What the next frame reprojects from.
        let bytes = width as u64 * height as u64 * 16;
        encoder.copy_buffer_to_buffer(&s.history, 0, &s.prev_history, 0, bytes);
        encoder.copy_buffer_to_buffer(&s.moments, 0, &s.prev_history, bytes, bytes);
        encoder.copy_buffer_to_buffer(&s.guides, 0, &s.prev_guides, 0, bytes);
        encoder.copy_buffer_to_buffer(&s.ids, 0, &s.prev_ids, 0, bytes);
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
