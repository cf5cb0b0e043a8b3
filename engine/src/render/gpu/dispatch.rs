//! Dispatching the tracing pass over a list of work units (render thread only): the whole
//! frame for [`crate::render::Tracer::render`], a tracer pool's share of it for
//! `render::balance::PoolTracer`.
//!
//! Owns: writing the unit list (binding 12) and the uniforms, the dispatch, and waiting for the
//! ray counters. Must not: read the film back (the caller does when it needs it).

use std::sync::Arc;
use std::time::Instant;

use super::tracer::{GpuTracer, WORKGROUP};
use crate::layout::{GpuFrameUniforms, UNIT_ROWS};
use crate::render::tracer::{RayCounts, RenderError, RenderStats};

impl GpuTracer {
    /// Starts tracing the work units `units` (of [`UNIT_ROWS`] rows each, in any order) of
    /// the frame `u` describes and returns without waiting; [`GpuTracer::finish`] waits. Only
    /// those units' pixels of the film change (blended by `u.film_blend`). Returns the start
    /// time.
    pub fn submit_units(
        &mut self,
        u: &GpuFrameUniforms,
        units: &[u32],
    ) -> Result<Instant, RenderError> {
        if u.width == 0 || u.height == 0 {
            return Err(RenderError::BadSize {
                width: u.width,
                height: u.height,
                reason: "width and height must be positive".into(),
            });
        }
        let started = Instant::now();
        self.film_buffers(u.width, u.height)?;
        let unit_count = crate::render::balance::unit_count(u.height) as u32;
        if units.len() > unit_count as usize || units.iter().any(|&unit| unit >= unit_count) {
            return Err(RenderError::Device(format!(
                "{} work units asked for, of a frame of {unit_count}",
                units.len()
            )));
        }
        let context = Arc::clone(&self.context);
        let Some(film) = self.film.as_ref() else {
            return Err(RenderError::Device("film buffers missing".into()));
        };
        let mut list = Vec::with_capacity(units.len() + 1);
        list.push(units.len() as u32);
        list.extend_from_slice(units);
        context
            .queue
            .write_buffer(&self.scene_buffers[0], 0, bytemuck::bytes_of(u));
        context
            .queue
            .write_buffer(&film.units, 0, bytemuck::cast_slice(&list));
        let mut encoder = context.device.create_command_encoder(&Default::default());
        encoder.clear_buffer(&film.counters, 0, None);
        if !units.is_empty() {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("trace"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &film.bind_group, &[]);
            let rows = units.len() as u32 * UNIT_ROWS;
            pass.dispatch_workgroups(u.width.div_ceil(WORKGROUP), rows.div_ceil(WORKGROUP), 1);
        }
        context.queue.submit([encoder.finish()]);
        Ok(started)
    }

    /// Waits for the work [`GpuTracer::submit_units`] started at `started` and returns its
    /// ray counts and time.
    pub fn finish(
        &mut self,
        u: &GpuFrameUniforms,
        started: Instant,
    ) -> Result<RenderStats, RenderError> {
        let Some(film) = self.film.as_ref() else {
            return Err(RenderError::Device("film buffers missing".into()));
        };
        let counters_bytes = self.read_buffer(&film.counters)?;
        let c: &[u32] = bytemuck::cast_slice(&counters_bytes);
        self.samples = if u.film_blend >= 1.0 {
            u.spp
        } else {
            self.samples + u.spp
        };
        Ok(RenderStats {
            counts: RayCounts {
                camera: c[0] as u64,
                bounce: c[1] as u64,
                shadow: c[2] as u64,
                dropped: c[3] as u64,
            },
            seconds: started.elapsed().as_secs_f64(),
        })
    }
}
