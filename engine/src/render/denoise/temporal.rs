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
/// frames) and (luminance mean, mean of squared luminance, 0, 0); with jittered guides also
/// the albedo blended over the same frames ([`accumulate_albedo`]; empty otherwise).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    pub width: u32,
    pub height: u32,
    pub illumination: Vec<Vec4>,
    pub moments: Vec<Vec4>,
    /// The demodulation albedo blended with each pixel's frames (linear rgb) and the share of
    /// them whose guide was emissive (a), or empty.
    pub albedo: Vec<Vec4>,
    /// The guides' normal (xyz, not renormalised) and depth (w, metres) blended the same way,
    /// or empty (with `albedo`).
    pub normal_depth: Vec<Vec4>,
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
            albedo: Vec::new(),
            normal_depth: Vec::new(),
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

/// Blends this frame's `albedo` into the history's albedo with the weight [`accumulate`] is
/// about to give the frame's illumination (call it first: the weight depends on the length
/// before the frame), starting afresh where the history is empty or restarts. With guides
/// taken at a jittered offset in each pixel, each frame's albedo is one point of the pixel's
/// texture; the remodulation takes this mean instead, as the illumination's history is a mean
/// over the pixel, so a still view's textures do not shimmer with the jitter.
/// `albedo` holds this frame's (albedo rgb, 1 where the guide is emissive else 0). The normal
/// and depth of the guides are blended the same way (`normal_depth`, this frame's
/// `normal_depth` as (normal, depth)), so that the filter's edge-stopping weights of a still
/// view settle instead of following each frame's offset.
pub fn accumulate_albedo(
    history: &mut History,
    albedo: &[Vec4],
    normal_depth: &[Vec4],
    blend: f32,
    reprojection: Reprojection,
) {
    let restart = blend.is_nan() || blend >= 1.0;
    if history.albedo.len() != history.illumination.len()
        || history.normal_depth.len() != history.illumination.len()
    {
        history.albedo = albedo.to_vec();
        history.normal_depth = normal_depth.to_vec();
        return;
    }
    history
        .albedo
        .par_iter_mut()
        .zip(history.normal_depth.par_iter_mut())
        .zip(history.illumination.par_iter())
        .zip(albedo.par_iter().zip(normal_depth.par_iter()))
        .for_each(|(((old, old_nd), h), (a, nd))| {
            let blend = match reprojection {
                Reprojection::Identity => blend,
                Reprojection::Moved => blend.max(1.0 / (h.w.max(0.0) + 1.0)),
            };
            let fresh = restart
                || h.w <= 0.0
                || !old.is_finite()
                || !old_nd.is_finite()
                || (old_nd.w > 0.0) != (nd.w > 0.0);
            if fresh {
                (*old, *old_nd) = (*a, *nd);
            } else {
                *old += (*a - *old) * blend;
                *old_nd += (*nd - *old_nd) * blend;
            }
        });
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
    fn the_albedo_history_is_the_exact_mean_of_its_frames_and_restarts_with_them() {
        let mut h = History::new(1, 1);
        let albedos = [0.2f32, 0.8, 0.5, 0.1];
        for (k, &a) in albedos.iter().enumerate() {
            let blend = 1.0 / (k + 1) as f32;
            let surface = [Vec4::new(a, a, a, (k % 2) as f32)];
            let nd = [Vec4::new(0.0, 1.0, 0.0, 2.0 + k as f32)];
            accumulate_albedo(&mut h, &surface, &nd, blend, Reprojection::Identity);
            let frame = [Vec3::ONE];
            accumulate(
                &mut h,
                &frame,
                &[Vec3::splat(a)],
                blend,
                Reprojection::Identity,
            );
        }
        assert!((h.albedo[0].x - 0.4).abs() < 1e-6, "{}", h.albedo[0]);
        assert!(
            (h.albedo[0].w - 0.5).abs() < 1e-6,
            "emissive share {}",
            h.albedo[0].w
        );
        assert!(
            (h.normal_depth[0].w - 3.5).abs() < 1e-5,
            "{}",
            h.normal_depth[0]
        );
        let fresh = [Vec4::new(0.9, 0.9, 0.9, 0.0)];
        let nd = [Vec4::new(0.0, 1.0, 0.0, 7.0)];
        accumulate_albedo(&mut h, &fresh, &nd, 1.0, Reprojection::Identity);
        assert_eq!(h.albedo[0], fresh[0], "a restart takes the frame's own");
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
