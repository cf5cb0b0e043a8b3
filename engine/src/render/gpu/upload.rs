//! Uploading scene deltas to the GPU: the [`SceneWrite`]s of a commit become buffer writes.
//!
//! Owns: mapping each write to its storage buffer and byte range, and growing a buffer (to at
//! least twice its size, within the device's binding limit) when a write ends past it, copying
//! the old contents on the GPU and rebinding. Render thread only.
//! Must not: decide what to write (the commit says).

use super::tracer::GpuTracer;
use crate::render::scene::RenderScene;
use crate::render::scene_writes::SceneWrite;
use crate::render::tracer::RenderError;

impl GpuTracer {
    /// Applies `writes` (already applied to `scene`, which is unused here but kept for symmetry
    /// with the CPU tracer) to the GPU buffers.
    pub(super) fn upload(
        &mut self,
        _scene: &RenderScene,
        writes: &[SceneWrite],
    ) -> Result<(), RenderError> {
        let mut grown = false;
        for w in writes {
            let (index, offset, bytes): (usize, u64, &[u8]) = match w {
                SceneWrite::Nodes { first, data } => {
                    (1, *first as u64 * 256, bytemuck::cast_slice(data))
                }
                SceneWrite::Blocks { first, data } => {
                    (2, *first as u64 * 160, bytemuck::cast_slice(data))
                }
                SceneWrite::Instances { first, data } => {
                    (3, *first as u64 * 128, bytemuck::cast_slice(data))
                }
                SceneWrite::Triangles { first, data } => {
                    (4, *first as u64 * 16, bytemuck::cast_slice(data))
                }
                SceneWrite::Vertices { first, data } => {
                    (5, *first as u64 * 48, bytemuck::cast_slice(data))
                }
                SceneWrite::Materials { first, data } => {
                    (6, *first as u64 * 96, bytemuck::cast_slice(data))
                }
                SceneWrite::Textures { first, data } => {
                    (7, *first as u64 * 16, bytemuck::cast_slice(data))
                }
                SceneWrite::Texels { first, data } => {
                    (8, *first as u64 * 8, bytemuck::cast_slice(data))
                }
                SceneWrite::Lights { first, data } => {
                    (9, *first as u64 * 64, bytemuck::cast_slice(data))
                }
                SceneWrite::TruncateInstances { .. } => continue,
            };
            if bytes.is_empty() {
                continue;
            }
            let end = offset + bytes.len() as u64;
            if end > self.scene_buffers[index].size() {
                self.grow(index, end)?;
                grown = true;
            }
            self.context
                .queue
                .write_buffer(&self.scene_buffers[index], offset, bytes);
        }
        if grown {
            self.rebind();
        }
        Ok(())
    }

    /// Replaces scene buffer `index` by one of at least `needed` bytes, keeping its contents.
    fn grow(&mut self, index: usize, needed: u64) -> Result<(), RenderError> {
        let limit = self.context.limits.max_storage_buffer_binding_size as u64;
        let old = &self.scene_buffers[index];
        let size = (old.size() * 2).max(needed).min(limit);
        if needed > limit {
            return Err(RenderError::TooLarge(format!(
                "scene buffer {index} needs {needed} bytes; this device binds at most {limit}"
            )));
        }
        let device = &self.context.device;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(
                [
                    "uniforms",
                    "nodes",
                    "blocks",
                    "instances",
                    "triangles",
                    "vertices",
                    "materials",
                    "textures",
                    "texels",
                    "lights",
                ][index],
            ),
            size: size.next_multiple_of(4),
            usage: wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::COPY_DST
                | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(old, 0, &buffer, 0, old.size());
        self.context.queue.submit([encoder.finish()]);
        self.scene_buffers[index] = buffer;
        Ok(())
    }
}
