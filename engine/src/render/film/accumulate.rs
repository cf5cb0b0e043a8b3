//! Accumulated radiance: per-pixel sums of samples and the mean image they give.
//!
//! Owns: [`Film`], a `width × height` image of linear RGB radiance, rows top to bottom.
//! Must not: tonemap or write files (see `tonemap`, `image_io`).

use glam::Vec3;

/// Linear radiance per pixel: the sum of all samples and how many there were.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: u32,
    pub height: u32,
    /// Sum of sample radiance per pixel (linear RGB), rows top to bottom.
    pub sum: Vec<Vec3>,
    /// Samples per pixel accumulated in `sum`.
    pub samples: u32,
}

impl Film {
    /// An empty film.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sum: vec![Vec3::ZERO; width as usize * height as usize],
            samples: 0,
        }
    }

    /// Mean radiance per pixel.
    pub fn mean(&self) -> Vec<Vec3> {
        let scale = 1.0 / self.samples.max(1) as f32;
        self.sum.iter().map(|s| *s * scale).collect()
    }

    /// Mean radiance over the whole image (per channel), in f64 for stable statistics.
    pub fn image_mean(&self) -> [f64; 3] {
        let mut acc = [0.0f64; 3];
        for s in &self.sum {
            for c in 0..3 {
                acc[c] += s[c] as f64;
            }
        }
        let n = self.sum.len().max(1) as f64 * self.samples.max(1) as f64;
        acc.map(|a| a / n)
    }
}
