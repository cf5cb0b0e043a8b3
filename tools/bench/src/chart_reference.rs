//! References and error measures of `bench chart`.
//!
//! Owns: [`Reference`] (a converged image and its per-pixel variance, box-averaged to the size
//! of the curve it judges), reading one from a folder with `reference.exr` and
//! `reference_stderr.exr` (Mitsuba's, or the engine's own from `chart_self_ref.rs`, which
//! writes the same two files), and [`errors`]: relative MSE, RMSE and mean bias.
//! Must not: render or decide which reference a scene uses (`chart_scenes.rs`).

use std::path::Path;

use candela::render::film::read_exr;
use glam::Vec3;

/// A reference at `size × size`: mean and variance of the mean per pixel and channel
/// (linear radiance, and its square).
pub struct Reference {
    pub mean: Vec<Vec3>,
    pub var: Vec<[f64; 3]>,
    /// Mean radiance of the whole image per channel.
    pub image_mean: [f64; 3],
}

impl Reference {
    /// Reads `dir/reference.exr` and `dir/reference_stderr.exr` (standard error of each
    /// pixel's mean) and box-averages them to `size × size`. The files must be square with an
    /// edge that is a multiple of `size`.
    pub fn load(dir: &Path, size: u32) -> anyhow::Result<Reference> {
        let (w, h, mean) = read_exr(&dir.join("reference.exr"))?;
        let (sw, sh, se) = read_exr(&dir.join("reference_stderr.exr"))?;
        if w != h || (sw, sh) != (w, h) || size == 0 || w % size != 0 {
            anyhow::bail!(
                "{}: reference {w}×{h} (stderr {sw}×{sh}) cannot be box-averaged to {size}×{size}",
                dir.display()
            );
        }
        Ok(box_average(w, &mean, &se, size))
    }
}

/// Box-averages a `width × width` mean and standard-error image to `size × size` (`size`
/// divides `width`): means average, variances of the mean add over the box and divide by its
/// pixel count squared.
pub fn box_average(width: u32, mean: &[Vec3], stderr: &[Vec3], size: u32) -> Reference {
    let (mean, var) = candela::render::film::box_average(width, mean, stderr, size);
    let pixels = mean.len().max(1) as f64;
    let mut image_mean = [0.0f64; 3];
    for m in &mean {
        for (c, s) in image_mean.iter_mut().enumerate() {
            *s += m[c] as f64;
        }
    }
    Reference {
        mean,
        var,
        image_mean: image_mean.map(|s| s / pixels),
    }
}

/// Errors of one image against a reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Errors {
    /// Mean over pixels and channels of (ours − ref)² / (ref² + 0.01), minus the reference's
    /// own variance on the same scale.
    pub rel_mse: f64,
    /// Root of the mean of (ours − ref)² (radiance units).
    pub rmse: f64,
    /// Image mean minus reference mean, per channel (radiance units).
    pub bias: [f64; 3],
    /// Standard error of the reference's image mean per channel: the smallest bias we can see.
    pub bias_floor: [f64; 3],
}

/// Errors of `image` against `r` (same size).
pub fn errors(image: &[Vec3], r: &Reference) -> Errors {
    let n = image.len() as f64;
    let (mut rel, mut sq) = (0.0, 0.0);
    let mut bias = [0.0f64; 3];
    let mut floor = [0.0f64; 3];
    for ((a, b), v) in image.iter().zip(&r.mean).zip(&r.var) {
        for c in 0..3 {
            let d = (a[c] - b[c]) as f64;
            rel += (d * d - v[c]) / ((b[c] as f64).powi(2) + 0.01);
            sq += d * d;
            bias[c] += d;
            floor[c] += v[c];
        }
    }
    Errors {
        rel_mse: rel / (3.0 * n),
        rmse: (sq / (3.0 * n)).sqrt(),
        bias: bias.map(|b| b / n),
        bias_floor: floor.map(|f| f.sqrt() / n),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_average_keeps_the_mean_and_shrinks_the_variance() {
        // 4×4 ramp with standard error 0.2 everywhere, averaged to 2×2.
        let mean: Vec<Vec3> = (0..16).map(|i| Vec3::splat(i as f32)).collect();
        let se = vec![Vec3::splat(0.2); 16];
        let r = box_average(4, &mean, &se, 2);
        assert_eq!(r.mean[0], Vec3::splat((0.0 + 1.0 + 4.0 + 5.0) / 4.0));
        assert!((r.var[0][0] - 0.04 / 4.0).abs() < 1e-8);
        assert!((r.image_mean[1] - 7.5).abs() < 1e-9);
    }

    #[test]
    fn errors_of_the_reference_itself_are_minus_its_variance() {
        let mean = vec![Vec3::new(1.0, 0.5, 0.0); 4];
        let se = vec![Vec3::ZERO; 4];
        let r = box_average(2, &mean, &se, 2);
        let e = errors(&mean, &r);
        assert_eq!((e.rel_mse, e.rmse, e.bias), (0.0, 0.0, [0.0; 3]));
        let brighter: Vec<Vec3> = mean.iter().map(|m| *m + Vec3::splat(0.1)).collect();
        let e = errors(&brighter, &r);
        assert!((e.bias[0] - 0.1).abs() < 1e-6 && (e.rmse - 0.1).abs() < 1e-6);
    }
}
