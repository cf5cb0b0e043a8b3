//! The figures of `bench picture`, computed on two images of the same size: relative MSE on
//! linear radiance (per pixel and channel `(x − r)² / (r² + 0.01)`, averaged: the definition
//! of `bench error` and `bench chart`), the RMSE of the tonemapped 8-bit sRGB picture the
//! player sees (the engine's `linear_to_srgb8` with the game's `TonemapSettings::default()`,
//! in units of full scale, 0–1), the noise left in a reference (from its two independent
//! halves), and the mean frame-to-frame change of a displayed picture.
//!
//! Owns: arithmetic only. Must not: render.

use candela::render::film::{TonemapSettings, linear_to_srgb8};
use glam::Vec3;

use super::picture_tracer::Reference;

/// The offset in the relative MSE's denominator (`bench error`'s).
const REL_EPSILON: f64 = 0.01;

/// The picture the player sees: 8-bit sRGB through the game's tonemap, as 0–1.
pub fn srgb(image: &[Vec3]) -> Vec<[f32; 3]> {
    srgb_at(image, 0.0)
}

/// [`srgb`] exposed by `exposure_ev` stops (radiance × 2^ev: a game exposed for its sky).
pub fn srgb_at(image: &[Vec3], exposure_ev: f32) -> Vec<[f32; 3]> {
    let settings = TonemapSettings {
        exposure_ev,
        ..TonemapSettings::default()
    };
    image
        .iter()
        .map(|&c| linear_to_srgb8(c, &settings).map(|v| f32::from(v) / 255.0))
        .collect()
}

/// Relative MSE of `x` against `r` (linear radiance).
pub fn rel_mse(x: &[Vec3], r: &[Vec3]) -> f64 {
    assert_eq!(x.len(), r.len(), "images of different sizes");
    let mut sum = 0.0;
    for (a, b) in x.iter().zip(r) {
        for c in 0..3 {
            let (a, b) = (f64::from(a[c]), f64::from(b[c]));
            sum += (a - b).powi(2) / (b * b + REL_EPSILON);
        }
    }
    sum / (3 * x.len().max(1)) as f64
}

/// RMSE of two sRGB pictures (0–1).
pub fn rmse(x: &[[f32; 3]], r: &[[f32; 3]]) -> f64 {
    assert_eq!(x.len(), r.len(), "images of different sizes");
    let sum: f64 = x
        .iter()
        .zip(r)
        .flat_map(|(a, b)| (0..3).map(move |c| f64::from(a[c] - b[c]).powi(2)))
        .sum();
    (sum / (3 * x.len().max(1)) as f64).sqrt()
}

/// Mean absolute per-channel difference of two sRGB pictures (0–1): the change from one
/// displayed frame to the next.
pub fn mean_change(x: &[[f32; 3]], r: &[[f32; 3]]) -> f64 {
    assert_eq!(x.len(), r.len(), "images of different sizes");
    let sum: f64 = x
        .iter()
        .zip(r)
        .flat_map(|(a, b)| (0..3).map(move |c| f64::from((a[c] - b[c]).abs())))
        .sum();
    sum / (3 * x.len().max(1)) as f64
}

/// The noise left in a reference, as the figures above would count it against the truth:
/// relative MSE and sRGB RMSE of the mean of the halves, each estimated as a quarter of the
/// halves' squared difference (the variance of a mean of two independent estimates).
pub fn reference_noise(reference: &Reference) -> (f64, f64) {
    reference_noise_at(reference, 0.0)
}

/// [`reference_noise`] with the sRGB picture exposed by `exposure_ev` stops ([`srgb_at`]).
pub fn reference_noise_at(reference: &Reference, exposure_ev: f32) -> (f64, f64) {
    let [a, b] = &reference.halves;
    let mean = reference.mean();
    let mut rel = 0.0;
    for ((x, y), m) in a.iter().zip(b).zip(&mean) {
        for c in 0..3 {
            let d = f64::from(x[c] - y[c]);
            rel += d * d / 4.0 / (f64::from(m[c]).powi(2) + REL_EPSILON);
        }
    }
    let rel = rel / (3 * a.len().max(1)) as f64;
    let srgb_rmse = rmse(&srgb_at(a, exposure_ev), &srgb_at(b, exposure_ev)) / 2.0;
    (rel, srgb_rmse)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figures_of_known_images() {
        let r = vec![Vec3::splat(0.5); 4];
        let x = vec![Vec3::splat(0.6); 4];
        assert_eq!(rel_mse(&r, &r), 0.0);
        let expected = 0.01 / (0.25 + 0.01);
        assert!((rel_mse(&x, &r) - expected).abs() < 1e-6);
        let (sx, sr) = (srgb(&x), srgb(&r));
        assert!(rmse(&sx, &sr) > 0.0 && rmse(&sx, &sr) < 0.1);
        assert!((mean_change(&sx, &sr) - rmse(&sx, &sr)).abs() < 1e-6);
        let same = Reference {
            width: 2,
            height: 2,
            halves: [r.clone(), r.clone()],
            camera: [0.0; 12],
            spp: 2,
        };
        assert_eq!(reference_noise(&same), (0.0, 0.0));
    }
}
