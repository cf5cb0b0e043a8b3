//! SVGF's temporal stage (Schied et al. 2017, §4.1–4.2; twin: `shaders/denoise_temporal.wgsl`):
//! each pixel's demodulated illumination and the first two moments of its luminance are
//! blended over frames, with the history length per pixel.
//!
//! Owns: [`History`] and [`accumulate`]. Inputs: this frame's mean radiance per pixel (linear,
//! not yet blended with earlier frames), the albedo guide, and the blend factor of the new
//! frame chosen by `film::Converge` (1 restarts: camera cut, camera motion, resize).
//! The history is either the same pixel's ([`Reprojection::Identity`]) or was moved onto this
//! frame's pixels by `reproject` ([`Reprojection::Moved`]: motion vectors with depth, normal
//! and instance rejection, a rejected pixel's length 0); then each pixel's weight is at least
//! 1/(its history length + 1), so a pixel revealed a frame ago is an exact mean of its two
//! frames, not a floored blend. Render thread.
//! Must not: filter spatially (see `variance`, `atrous`).

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use super::weights::{demodulator, finite3, luminance};

/// Where each pixel's history comes from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Reprojection {
    /// The same pixel (a still camera; camera motion resets through the blend factor).
    #[default]
    Identity,
    /// The history was reprojected onto this frame's pixels (`reproject`): per-pixel weight
    /// `max(blend, 1 / (length + 1))`.
    Moved,
}

/// The denoiser's memory between frames: per pixel (illumination rgb, history length in
/// frames) and (luminance mean, mean of squared luminance, 0, 0).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    pub width: u32,
    pub height: u32,
    pub illumination: Vec<Vec4>,
    pub moments: Vec<Vec4>,
}

impl History {
    /// Empty history (length 0 everywhere) for a `width × height` image.
    pub fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self {
            width,
            height,
            illumination: vec![Vec4::ZERO; n],
            moments: vec![Vec4::ZERO; n],
        }
    }
}

/// One pixel's update: the history (illumination, length) and moments after blending the
/// frame's radiance `c` demodulated by `demod` with weight `blend`. A non-finite sample leaves
/// the history as it was (a pixel with length 0 stays without any); negative radiance counts
/// as 0. The length grows by one per frame and is capped at 1/blend (rounded), the frames an
/// exact mean with that weight holds.
pub fn temporal_pixel(history: Vec4, moments: Vec4, c: Vec3, demod: Vec3, blend: f32) -> [Vec4; 2] {
    let restart = blend.is_nan() || blend >= 1.0;
    if !finite3(c) {
        return if restart {
            [Vec4::ZERO, Vec4::ZERO]
        } else {
            [history, moments]
        };
    }
    let illum = c.max(Vec3::ZERO) / demod;
    let l = luminance(illum);
    if restart || history.w <= 0.0 {
        return [illum.extend(1.0), Vec4::new(l, l * l, 0.0, 0.0)];
    }
    let old = history.truncate();
    let mixed = old + (illum - old) * blend;
    let m1 = moments.x + (l - moments.x) * blend;
    let m2 = moments.y + (l * l - moments.y) * blend;
    let cap = (1.0 / blend + 0.5).floor().max(1.0);
    let length = (history.w + 1.0).min(cap);
    [mixed.extend(length), Vec4::new(m1, m2, 0.0, 0.0)]
}

/// Blends `frame` (mean radiance per pixel, rows top to bottom) into `history` with weight
/// `blend`, demodulating by `albedo` (the guides' albedo). Sizes must match (the caller checks).
pub fn accumulate(
    history: &mut History,
    frame: &[Vec3],
    albedo: &[Vec3],
    blend: f32,
    reprojection: Reprojection,
) {
    history
        .illumination
        .par_iter_mut()
        .zip(history.moments.par_iter_mut())
        .zip(frame.par_iter().zip(albedo.par_iter()))
        .for_each(|((h, m), (c, a))| {
            let blend = match reprojection {
                Reprojection::Identity => blend,
                Reprojection::Moved => blend.max(1.0 / (h.w.max(0.0) + 1.0)),
            };
            let [nh, nm] = temporal_pixel(*h, *m, *c, demodulator(*a), blend);
            *h = nh;
            *m = nm;
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_mean_and_moments_for_still_frames() {
        let (mut h, mut m) = (Vec4::ZERO, Vec4::ZERO);
        let samples = [1.0f32, 3.0, 2.0, 6.0];
        for (k, &s) in samples.iter().enumerate() {
            let blend = 1.0 / (k + 1) as f32;
            [h, m] = temporal_pixel(h, m, Vec3::splat(s), Vec3::ONE, blend);
        }
        assert!((h.x - 3.0).abs() < 1e-6, "{h}");
        assert_eq!(h.w, 4.0);
        let mean_sq = samples.iter().map(|s| s * s).sum::<f32>() / 4.0;
        assert!((m.y - mean_sq).abs() < 1e-5);
    }

    #[test]
    fn non_finite_samples_keep_the_history() {
        let [h, m] = temporal_pixel(Vec4::ZERO, Vec4::ZERO, Vec3::ONE, Vec3::splat(0.5), 1.0);
        assert_eq!(h, Vec4::new(2.0, 2.0, 2.0, 1.0));
        let [h2, m2] = temporal_pixel(h, m, Vec3::new(f32::NAN, 0.0, 0.0), Vec3::ONE, 0.5);
        assert_eq!((h2, m2), (h, m));
        let [h3, _] = temporal_pixel(h, m, Vec3::splat(f32::INFINITY), Vec3::ONE, 1.0);
        assert_eq!(h3, Vec4::ZERO);
    }
}
