//! Box-averaging a reference image and its per-pixel standard error to a smaller square, for
//! comparisons against references at test and benchmark resolutions.
//!
//! Owns: [`box_average`]. Must not: read or write files (`image_io` does).

use glam::Vec3;

/// A `width × width` image of per-pixel means and standard errors (linear radiance), averaged
/// over `f × f` boxes (`f = width / size`) to `size × size`: means average; variances of the
/// mean add over the box and divide by its pixel count squared (independent pixels). Returns
/// the means and the variances of the means, row by row. `size` must divide `width` and both
/// slices hold `width²` pixels; otherwise the result is empty.
pub fn box_average(
    width: u32,
    mean: &[Vec3],
    stderr: &[Vec3],
    size: u32,
) -> (Vec<Vec3>, Vec<[f64; 3]>) {
    let pixels = (width as usize) * (width as usize);
    if size == 0 || width % size != 0 || mean.len() != pixels || stderr.len() != pixels {
        return (Vec::new(), Vec::new());
    }
    let f = (width / size) as usize;
    let n = (f * f) as f64;
    let mut out_mean = Vec::with_capacity((size * size) as usize);
    let mut out_var = Vec::with_capacity((size * size) as usize);
    for y in 0..size as usize {
        for x in 0..size as usize {
            let mut m = Vec3::ZERO;
            let mut v = [0.0f64; 3];
            for dy in 0..f {
                for dx in 0..f {
                    let i = (y * f + dy) * width as usize + x * f + dx;
                    m += mean[i];
                    for (c, v) in v.iter_mut().enumerate() {
                        *v += (stderr[i][c] as f64).powi(2);
                    }
                }
            }
            out_mean.push(m / n as f32);
            out_var.push(v.map(|v| v / (n * n)));
        }
    }
    (out_mean, out_var)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn means_average_and_variances_shrink_with_the_box() {
        // 2×2 → 1×1: mean of the four, variance (Σ se²) / 16.
        let mean = [1.0, 2.0, 3.0, 6.0].map(Vec3::splat);
        let se = [Vec3::splat(2.0); 4];
        let (m, v) = box_average(2, &mean, &se, 1);
        assert_eq!(m, vec![Vec3::splat(3.0)]);
        assert_eq!(v, vec![[1.0; 3]]);
        assert!(
            box_average(3, &[Vec3::ZERO; 9], &[Vec3::ZERO; 9], 2)
                .0
                .is_empty()
        );
    }
}
