//! Image files: PNG (tonemapped 8-bit sRGB) and OpenEXR (linear float radiance).
//!
//! Owns: writing films as PNG or EXR (and screenshots, already 8-bit, as PNG), and reading linear RGB EXR images (reference renders).
//! Files are written atomically: to a temporary name beside the target, then renamed.
//! Must not: know tracers.

use std::path::{Path, PathBuf};

use glam::Vec3;

use super::tonemap::{TonemapSettings, linear_to_srgb8};

/// Errors of image input and output, naming the file.
#[derive(Debug, thiserror::Error)]
pub enum ImageIoError {
    #[error("{path}: {message}")]
    Write { path: PathBuf, message: String },
    #[error("{path}: {message}")]
    Read { path: PathBuf, message: String },
}

fn temp_beside(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "image".into());
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

fn finish(temp: &Path, path: &Path) -> Result<(), ImageIoError> {
    std::fs::rename(temp, path).map_err(|e| ImageIoError::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

fn ensure_parent(path: &Path) -> Result<(), ImageIoError> {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => {
            std::fs::create_dir_all(parent).map_err(|e| ImageIoError::Write {
                path: path.to_path_buf(),
                message: format!("cannot create folder {}: {e}", parent.display()),
            })
        }
        _ => Ok(()),
    }
}

/// Writes `pixels` (linear radiance, rows top to bottom) as an 8-bit sRGB PNG.
pub fn write_png(
    path: &Path,
    width: u32,
    height: u32,
    pixels: &[Vec3],
    settings: &TonemapSettings,
) -> Result<(), ImageIoError> {
    ensure_parent(path)?;
    let mut bytes = Vec::with_capacity(pixels.len() * 3);
    for p in pixels {
        bytes.extend_from_slice(&linear_to_srgb8(*p, settings));
    }
    let temp = temp_beside(path);
    image::save_buffer_with_format(
        &temp,
        &bytes,
        width,
        height,
        image::ExtendedColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(|e| ImageIoError::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    finish(&temp, path)
}

/// Writes already encoded 8-bit sRGB RGB pixels (`width × height × 3` bytes, rows top to
/// bottom) as a PNG: screenshots of what a window showed.
pub fn write_png_rgb8(
    path: &Path,
    width: u32,
    height: u32,
    rgb: &[u8],
) -> Result<(), ImageIoError> {
    ensure_parent(path)?;
    let temp = temp_beside(path);
    image::save_buffer_with_format(
        &temp,
        rgb,
        width,
        height,
        image::ExtendedColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(|e| ImageIoError::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    finish(&temp, path)
}

/// Writes `pixels` (linear radiance, rows top to bottom) as a 32-bit float RGB OpenEXR.
pub fn write_exr(
    path: &Path,
    width: u32,
    height: u32,
    pixels: &[Vec3],
) -> Result<(), ImageIoError> {
    ensure_parent(path)?;
    let temp = temp_beside(path);
    let w = width as usize;
    exr::prelude::write_rgb_file(&temp, w, height as usize, |x, y| {
        let p = pixels[y * w + x];
        (p.x, p.y, p.z)
    })
    .map_err(|e| ImageIoError::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    finish(&temp, path)
}

/// Reads the RGB channels of an OpenEXR file as linear radiance: (width, height, rows top to
/// bottom).
pub fn read_exr(path: &Path) -> Result<(u32, u32, Vec<Vec3>), ImageIoError> {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |resolution, _| {
            (
                resolution.width(),
                vec![Vec3::ZERO; resolution.width() * resolution.height()],
            )
        },
        |(width, pixels): &mut (usize, Vec<Vec3>),
         position,
         (r, g, b, _a): (f32, f32, f32, f32)| {
            pixels[position.y() * *width + position.x()] = Vec3::new(r, g, b);
        },
    )
    .map_err(|e| ImageIoError::Read {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    let size = image.layer_data.size;
    Ok((
        size.width() as u32,
        size.height() as u32,
        image.layer_data.channel_data.pixels.1,
    ))
}
