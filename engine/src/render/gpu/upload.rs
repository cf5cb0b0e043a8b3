//! Uploading scene deltas to the GPU: the [`SceneWrite`]s of a commit become buffer writes.
//!
//! Owns: mapping each write to its storage buffer and byte range, and growing a buffer (to at
//! least twice its size, within the device's binding limit) when a write ends past it, copying
//! the old contents on the GPU and rebinding; rewriting the sky-view table (binding 16) when the
//! scene's `SkyTable` was rebuilt or its clouds rebaked. Render thread only.
//! Must not: decide what to write (the commit says).

use super::tracer::GpuTracer;
use crate::render::tracer::RenderError;
use crate::scene::RenderScene;
use crate::scene::SceneWrite;
use crate::sky::{VIEW_HEIGHT, VIEW_WIDTH};

/// Index of the line emitters' buffer in `GpuTracer::scene_buffers` (binding 15).
const LINES: usize = 12;
/// Index of the sky-view table's buffer in `GpuTracer::scene_buffers` (binding 16).
const SKY_VIEW: usize = 13;

/// The sky-view buffer's contents (binding 16): always 2 × `VIEW_WIDTH × VIEW_HEIGHT` texels,
/// the scene's sun's table then the moon's, zeros where a table is missing (a black sky, as
/// the CPU tracer sees an empty table, when the sky is not physical; no moonlit sky by day).
/// Then the cloud layer's optical depths (`SkyTable::clouds`), four to a texel, the last one
/// padded with zeros (`shaders/shared/clouds.wgsl`).
pub(super) fn sky_bytes(scene: &RenderScene) -> Vec<u8> {
    let len = VIEW_WIDTH * VIEW_HEIGHT;
    let texels = scene.sky.texels.as_slice();
    let texel = std::mem::size_of::<[f32; 4]>();
    let mut bytes = if texels.len() == len || texels.len() == 2 * len {
        bytemuck::cast_slice(texels).to_vec()
    } else {
        Vec::new()
    };
    bytes.resize(2 * len * texel, 0);
    let clouds = scene.sky.clouds.as_slice();
    bytes.extend_from_slice(bytemuck::cast_slice(clouds));
    bytes.resize(bytes.len().next_multiple_of(16), 0);
    bytes
}

/// The write of `data` at element `first` of binding `index`: the binding, the byte offset (from
/// the element type's size) and the bytes.
fn at<T: bytemuck::Pod>(index: usize, first: u32, data: &[T]) -> (usize, u64, &[u8]) {
    (
        index,
        first as u64 * std::mem::size_of::<T>() as u64,
        bytemuck::cast_slice(data),
    )
}

impl GpuTracer {
    /// Applies `writes` (already applied to `scene`) to the GPU buffers, rewrites the line
    /// emitters from `scene`, and the sky-view table when `scene.sky` holds another one.
    pub(super) fn upload(
        &mut self,
        scene: &RenderScene,
        writes: &[SceneWrite],
    ) -> Result<(), RenderError> {
        let mut grown = false;
        for w in writes {
            let (index, offset, bytes): (usize, u64, &[u8]) = match w {
                SceneWrite::Nodes { first, data } => at(1, *first, data),
                SceneWrite::Blocks { first, data } => at(2, *first, data),
                SceneWrite::Instances { first, data } => at(3, *first, data),
                SceneWrite::Triangles { first, data } => at(4, *first, data),
                SceneWrite::Vertices { first, data } => at(5, *first, data),
                SceneWrite::Materials { first, data } => at(6, *first, data),
                SceneWrite::Textures { first, data } => at(7, *first, data),
                SceneWrite::Texels { first, data } => at(8, *first, data),
                SceneWrite::Lights { first, data } => at(9, *first, data),
                SceneWrite::LightNodes { first, data } => at(10, *first, data),
                SceneWrite::LightLookup { first, data } => at(11, *first, data),
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
        if !writes.is_empty() {
            // The line emitters follow the instances and materials: rewritten whole (12 KiB).
            let lines = super::tracer::line_bytes(scene);
            self.context
                .queue
                .write_buffer(&self.scene_buffers[LINES], 0, &lines);
        }
        if !std::sync::Arc::ptr_eq(&self.sky_texels, &scene.sky.texels)
            || !std::sync::Arc::ptr_eq(&self.cloud_texels, &scene.sky.clouds)
        {
            let sky = sky_bytes(scene);
            if sky.len() as u64 > self.scene_buffers[SKY_VIEW].size() {
                self.grow(SKY_VIEW, sky.len() as u64)?;
                grown = true;
            }
            self.context
                .queue
                .write_buffer(&self.scene_buffers[SKY_VIEW], 0, &sky);
            self.sky_texels = std::sync::Arc::clone(&scene.sky.texels);
            self.cloud_texels = std::sync::Arc::clone(&scene.sky.clouds);
        }
        if grown {
            self.rebind();
        }
        Ok(())
    }

    /// Replaces scene buffer `index` by one of at least `needed` bytes, keeping its contents.
    fn grow(&mut self, index: usize, needed: u64) -> Result<(), RenderError> {
        let limit = self.context.limits.max_storage_buffer_binding_size;
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
                    "light nodes",
                    "light lookup",
                    "lines",
                    "sky view",
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
