//! The film: the converged image, per-pixel mean radiance, and how new renders blend into it.
//!
//! Owns: [`Film`], a `width × height` image of linear RGB radiance, rows top to bottom.
//! Must not: tonemap or write files (see `tonemap`, `image_io`).

use glam::Vec3;

/// Linear radiance per pixel (W·sr⁻¹·m⁻²), rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: u32,
    pub height: u32,
    /// The current estimate of each pixel: blended from renders by
    /// `mean = mix(mean, new, film_blend)`.
    pub mean: Vec<Vec3>,
    /// Samples per pixel the current estimate holds (for an exact running mean; informative
    /// when the converging policy blends with a floor).
    pub samples: u32,
}

impl Film {
    /// A black film.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            mean: vec![Vec3::ZERO; width as usize * height as usize],
            samples: 0,
        }
    }

    /// Mean radiance over the whole image (per channel), in f64 for stable statistics.
    pub fn image_mean(&self) -> [f64; 3] {
        let mut acc = [0.0f64; 3];
        for s in &self.mean {
            for c in 0..3 {
                acc[c] += s[c] as f64;
            }
        }
        acc.map(|a| a / self.mean.len().max(1) as f64)
    }
}
