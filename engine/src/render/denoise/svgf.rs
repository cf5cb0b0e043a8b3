//! The CPU denoiser (the reference of the GPU twin `render/gpu/denoise.rs`): spatiotemporal
//! variance-guided filtering (Schied et al. 2017) of one frame at a time.
//!
//! Owns: [`Svgf`] — the history between frames and the order of the stages: demodulate by the
//! albedo and blend over time (`temporal`), estimate the variance (`variance`), `iterations`
//! à-trous passes with steps 1, 2, 4, … (`atrous`), the last one remodulating. Input: this
//! frame's mean radiance per pixel (linear, rows top to bottom, not yet blended with earlier
//! frames), its [`Guides`], and the blend factor `film::Converge` chose. Output: a [`Film`] of
//! denoised linear radiance, every pixel finite. Unlike the paper, the history keeps the
//! unfiltered illumination (no feedback of the first à-trous pass), so a still camera still
//! converges to the unbiased mean and the filter relaxes with its variance. Runs on the
//! render thread (its passes on rayon's pool).
//! Must not: trace rays or touch the tracer's film.

use glam::{Affine3A, Vec3, Vec4};
use rayon::prelude::*;

use super::atrous::{Pass, filter};
use super::guides::Guides;
use super::planes::{ColourPlanes, GuidePlanes};
use super::reproject::{PrevFrame, ReprojectStats, reproject_into};
use super::temporal::{History, Reprojection, accumulate, accumulate_albedo};
use super::variance::{HistoryPlanes, estimate};
use super::view::View;
use crate::render::film::Film;

/// The filter's knobs (Schied et al.'s, but for the kernel; σ_n = 128 is fixed, see `weights`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvgfParams {
    /// À-trous passes (1–8); 5 with the 3×3 kernel reach 1+2+4+8+16 = 31 pixels, with the
    /// 5×5 kernel 62.
    pub iterations: u32,
    /// The à-trous kernel of each pass (`docs/PERFORMANCE.md`, "The à-trous kernel").
    pub kernel: AtrousKernel,
    /// Depth weight scale (times the depth gradient along the offset).
    pub sigma_z: f32,
    /// Luminance weight scale, in standard deviations of the luminance estimate.
    pub sigma_l: f32,
}

impl Default for SvgfParams {
    fn default() -> Self {
        Self {
            iterations: 5,
            kernel: AtrousKernel::B3Spline5x5,
            sigma_z: 1.0,
            sigma_l: 4.0,
        }
    }
}

/// The à-trous passes' kernels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AtrousKernel {
    /// 5×5 B3 spline, (1/16, ¼, ⅜, ¼, 1/16) per axis, every pass (Schied et al. 2017): 25 taps.
    #[default]
    B3Spline5x5,
    /// 3×3, weights (¼, ½, ¼) per axis, every pass: 9 taps.
    Gauss3x3,
    /// The B3 spline on the first pass (step 1), the 3×3 Gaussian on the others.
    B3ThenGauss3x3,
}

impl SvgfParams {
    /// Pass `k`'s kernel radius in taps (1: 3×3, 2: 5×5; the GPU twin's `radius` uniform).
    pub fn radius(&self, k: u32) -> u32 {
        match (self.kernel, k) {
            (AtrousKernel::B3Spline5x5, _) | (AtrousKernel::B3ThenGauss3x3, 0) => 2,
            _ => 1,
        }
    }

    /// The passes in order (the iteration count clamped to 1–8).
    pub fn passes(&self) -> Vec<Pass> {
        let n = self.iterations.clamp(1, 8);
        (0..n)
            .map(|k| Pass {
                step: 1 << k,
                radius: self.radius(k) as i32,
                sigma_z: self.sigma_z,
                sigma_l: self.sigma_l,
                remodulate: k + 1 == n,
            })
            .collect()
    }
}

/// Inputs that do not fit together.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum DenoiseError {
    #[error(
        "temporal upscaling: the traced frame is {traced_width}×{traced_height} \
         ({frame} pixels) but the guides are {width}×{height}, not a whole multiple of it"
    )]
    UpscaleMismatch {
        frame: usize,
        traced_width: u32,
        traced_height: u32,
        width: u32,
        height: u32,
    },
    #[error("the frame has {frame} pixels but the guides are {width}×{height} ({guides} values)")]
    SizeMismatch {
        frame: usize,
        width: u32,
        height: u32,
        guides: usize,
    },
}

/// The CPU SVGF denoiser and its history.
#[derive(Clone, Debug, Default)]
pub struct Svgf {
    pub params: SvgfParams,
    pub(super) history: History,
    /// The previous frame, kept by [`Svgf::denoise_moving`] for reprojection.
    pub(super) prev: Option<PrevFrame>,
    scratch: Scratch,
}

impl Svgf {
    pub fn new(params: SvgfParams) -> Self {
        Self {
            params,
            ..Default::default()
        }
    }

    /// Forgets the history (the next frame starts afresh whatever its blend factor).
    pub fn reset(&mut self) {
        self.history = History::new(self.history.width, self.history.height);
        self.prev = None;
    }

    /// The history so far (for tests and the GPU twin's comparison).
    pub fn history(&self) -> &History {
        &self.history
    }

    /// Denoises one frame: `frame` is this frame's mean radiance per pixel, `blend` its weight
    /// against the history (1 restarts). The history is resized (and so restarted) when the
    /// guides' size changes.
    pub fn denoise(
        &mut self,
        frame: &[Vec3],
        guides: &Guides,
        blend: f32,
    ) -> Result<Film, DenoiseError> {
        self.check(frame, guides)?;
        let albedo = &guides.albedo;
        accumulate(
            &mut self.history,
            frame,
            albedo,
            blend,
            Reprojection::Identity,
        );
        self.prev = None;
        Ok(self.filter_history(guides))
    }

    /// Denoises one frame seen from `view` with the instances at `world_from_object` (by
    /// instance index), reprojecting the history of the previous frame given here onto this
    /// frame's pixels (`reproject`): a moving camera or object keeps the history of every
    /// surface still in view. `blend` is the weight of the new frame where the history is
    /// long (1 restarts every pixel: a cut). Returns the film and, when a previous frame was
    /// reprojected, how many pixels kept their history.
    pub fn denoise_moving(
        &mut self,
        frame: &[Vec3],
        guides: &Guides,
        blend: f32,
        view: View,
        world_from_object: Vec<Affine3A>,
    ) -> Result<(Film, Option<ReprojectStats>), DenoiseError> {
        self.check(frame, guides)?;
        let albedo = &guides.albedo;
        let restart = blend.is_nan() || blend >= 1.0;
        // Guides at a jittered offset (the tracer's first hits): remodulate by the albedo's
        // mean over the pixel's frames. Guides at the centres keep no albedo history.
        let jittered = view.jitter != (0.5, 0.5);
        if !jittered {
            self.history.albedo.clear();
            self.history.normal_depth.clear();
        }
        // This frame's (albedo, emissive) and (normal, depth), into buffers kept between frames.
        let s = &mut self.scratch;
        if jittered {
            let n = guides.albedo.len();
            s.surface.resize(n, Vec4::ZERO);
            s.normal_depth.resize(n, Vec4::ZERO);
            (s.surface.par_iter_mut().zip(s.normal_depth.par_iter_mut()))
                .zip(guides.albedo.par_iter().zip(guides.emissive.par_iter()))
                .zip(guides.normal.par_iter().zip(guides.depth.par_iter()))
                .for_each(|(((a, nd), (al, &e)), (n, &z))| {
                    *a = al.extend(if e { 1.0 } else { 0.0 });
                    *nd = n.extend(z);
                });
        }
        let prev = self.prev.take();
        let stats = match &prev {
            Some(prev) if !restart => {
                let inputs = (prev, guides, &view, world_from_object.as_slice());
                let stats = reproject_into(&self.history, inputs, &mut s.spare, &mut s.points);
                std::mem::swap(&mut self.history, &mut s.spare);
                if jittered {
                    let moved = Reprojection::Moved;
                    let (surface, nd) = (&s.surface, &s.normal_depth);
                    accumulate_albedo(&mut self.history, surface, nd, blend, moved);
                }
                accumulate(&mut self.history, frame, albedo, blend, Reprojection::Moved);
                Some(stats)
            }
            _ => {
                if jittered {
                    let same = Reprojection::Identity;
                    let (surface, nd) = (&s.surface, &s.normal_depth);
                    accumulate_albedo(&mut self.history, surface, nd, blend, same);
                }
                accumulate(
                    &mut self.history,
                    frame,
                    albedo,
                    blend,
                    Reprojection::Identity,
                );
                None
            }
        };
        // The previous frame's buffers are reused for this one's copy.
        let mut kept = prev.unwrap_or_else(|| PrevFrame {
            view,
            guides: Guides::default(),
            world_from_object: Vec::new(),
        });
        kept.view = view;
        kept.guides.copy_from(guides);
        kept.world_from_object = world_from_object;
        self.prev = Some(kept);
        if jittered
            && self.history.albedo.len() == guides.albedo.len()
            && self.history.normal_depth.len() == guides.depth.len()
        {
            // The filter sees the pixels' means over their frames: albedo, normal and depth, and
            // emissive where most of the frames' guides were.
            let mut mean = std::mem::take(&mut self.scratch.mean);
            mean.copy_from(guides);
            (mean.albedo.par_iter_mut().zip(mean.emissive.par_iter_mut()))
                .zip(self.history.albedo.par_iter())
                .for_each(|((a, e), s)| {
                    *a = s.truncate();
                    *e = s.w >= 0.5;
                });
            (mean.normal.par_iter_mut().zip(mean.depth.par_iter_mut()))
                .zip(self.history.normal_depth.par_iter())
                .for_each(|((n, z), nd)| {
                    *n = nd.truncate().normalize_or_zero();
                    *z = nd.w;
                });
            let film = self.filter_history(&mean);
            self.scratch.mean = mean;
            return Ok((film, stats));
        }
        Ok((self.filter_history(guides), stats))
    }

    /// Checks the sizes and resizes (so restarts) the history when the guides' size changed.
    fn check(&mut self, frame: &[Vec3], guides: &Guides) -> Result<(), DenoiseError> {
        let (width, height) = (guides.width, guides.height);
        let n = width as usize * height as usize;
        if frame.len() != n || !guides.is_consistent() {
            return Err(DenoiseError::SizeMismatch {
                frame: frame.len(),
                width,
                height,
                guides: guides.len(),
            });
        }
        if self.history.width != width || self.history.height != height {
            self.history = History::new(width, height);
            self.prev = None;
        }
        Ok(())
    }

    /// Variance estimate and the à-trous passes over the current history.
    fn filter_history(&mut self, guides: &Guides) -> Film {
        let history = std::mem::take(&mut self.history);
        let film = self.filter(&history, guides);
        self.history = history;
        film
    }

    /// Variance estimate and the à-trous passes over `history` (the guides' size).
    pub(super) fn filter(&mut self, history: &History, guides: &Guides) -> Film {
        let (width, height) = (guides.width, guides.height);
        let s = &mut self.scratch;
        s.guides.fill(guides);
        estimate(
            history,
            &s.guides,
            self.params.sigma_z,
            &mut s.history,
            &mut s.a,
        );
        for pass in self.params.passes() {
            filter(&s.a, &s.guides, &pass, &mut s.b);
            std::mem::swap(&mut s.a, &mut s.b);
        }
        let samples = history
            .illumination
            .iter()
            .map(|h| h.w as u32)
            .max()
            .unwrap_or(0);
        Film {
            width,
            height,
            mean: s.a.rgb(),
            samples,
        }
    }
}

/// The planes the passes work in, kept between frames so that a frame allocates nothing but
/// its output.
#[derive(Clone, Debug, Default)]
struct Scratch {
    /// The reprojected history's buffers (swapped with the history each frame) and the
    /// previous pixels' guide points.
    spare: History,
    points: Vec<Vec3>,
    /// This frame's (albedo, emissive) and (normal, depth) for the albedo history.
    surface: Vec<Vec4>,
    normal_depth: Vec<Vec4>,
    /// The guides the filter sees with jittered guides (their means over the frames).
    mean: Guides,
    guides: GuidePlanes,
    history: HistoryPlanes,
    a: ColourPlanes,
    b: ColourPlanes,
}
