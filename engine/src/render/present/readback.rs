//! Reading the presented frame back (render thread): a copy of the offscreen frame texture
//! into a mappable buffer, then 8-bit sRGB RGBA rows for a [`Screenshot`].
//!
//! Owns: [`Screenshot`] and the row padding wgpu requires (256-byte rows).
//! Must not: decide when to read back (the commit's present request says).

use std::path::Path;

use crate::render::film::{ImageIoError, write_png_rgb8};
use crate::render::tracer::RenderError;

/// What the window showed: 8-bit sRGB RGBA, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Screenshot {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
}

impl Screenshot {
    /// The pixel at (x, y) as [r, g, b] (8-bit sRGB), or `None` outside the image.
    pub fn rgb(&self, x: u32, y: u32) -> Option<[u8; 3]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let i = (y as usize * self.width as usize + x as usize) * 4;
        self.rgba.get(i..i + 3).map(|p| [p[0], p[1], p[2]])
    }

    /// Writes the screenshot as an 8-bit sRGB RGB PNG (atomically).
    pub fn save_png(&self, path: &Path) -> Result<(), ImageIoError> {
        let rgb: Vec<u8> = self
            .rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        write_png_rgb8(path, self.width, self.height, &rgb)
    }
}

/// A texture copy on its way to the host.
pub(super) struct PendingReadback {
    buffer: wgpu::Buffer,
    width: u32,
    height: u32,
    padded_row: u32,
    bgra: bool,
}

/// Encodes a copy of `texture` (8-bit RGBA or BGRA, `size`) into a mappable buffer.
pub(super) fn encode_readback(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    texture: &wgpu::Texture,
    size: (u32, u32),
) -> PendingReadback {
    let padded_row = (size.0 * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("screenshot"),
        size: padded_row as u64 * size.1 as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded_row),
                rows_per_image: Some(size.1),
            },
        },
        wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        },
    );
    let bgra = matches!(
        texture.format(),
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
    );
    PendingReadback {
        buffer,
        width: size.0,
        height: size.1,
        padded_row,
        bgra,
    }
}

impl PendingReadback {
    /// Waits for the copy (submitted by the caller) and unpads the rows.
    pub(super) fn finish(self, device: &wgpu::Device) -> Result<Screenshot, RenderError> {
        crate::render::gpu::map_for_reading(device, &self.buffer)?;
        let mapped = self
            .buffer
            .get_mapped_range(..)
            .map_err(|e| RenderError::Device(e.to_string()))?;
        let row = self.width as usize * 4;
        let mut rgba = Vec::with_capacity(row * self.height as usize);
        for y in 0..self.height as usize {
            let start = y * self.padded_row as usize;
            rgba.extend_from_slice(&mapped[start..start + row]);
        }
        drop(mapped);
        self.buffer.unmap();
        if self.bgra {
            for p in rgba.chunks_exact_mut(4) {
                p.swap(0, 2);
            }
        }
        Ok(Screenshot {
            width: self.width,
            height: self.height,
            rgba,
        })
    }
}
