//! `bench denoise`'s "before": the CPU denoiser as it ran until 2026-12-06, rebuilt from the
//! engine's per-pixel reference functions (`temporal_pixel`, `variance_pixel`, `atrous_pixel`,
//! the shape the WGSL twin mirrors): every pixel of every stage on its own, rows on rayon's
//! pool, packed `vec4` rows, `f32::exp`. Timed in the same run as the engine's row kernels, so
//! the two figures compare on one machine under one load, and its output bounds how far the
//! kernels drift from it.
//!
//! Owns: [`Reference`]. Main thread (rows on rayon's pool). Must not: be used by the engine.

use candela::render::denoise::weights::demodulator;
use candela::render::denoise::{
    Guides, History, SvgfParams, atrous_pixel, temporal_pixel, variance_pixel,
};
use glam::{Vec3, Vec4};
use rayon::prelude::*;

/// The per-pixel denoiser and its history (identity reprojection: a still camera).
pub struct Reference {
    params: SvgfParams,
    history: History,
}

impl Reference {
    pub fn new(params: SvgfParams) -> Self {
        Self {
            params,
            history: History::default(),
        }
    }

    /// Denoised linear radiance of `frame` (this frame's mean radiance, `guides`' size) blended
    /// with weight `blend` into the history (1 restarts).
    pub fn denoise(&mut self, frame: &[Vec3], guides: &Guides, blend: f32) -> Vec<Vec3> {
        let (width, height) = (guides.width, guides.height);
        if self.history.width != width || self.history.height != height {
            self.history = History::new(width, height);
        }
        let h = &mut self.history;
        h.illumination
            .par_iter_mut()
            .zip(h.moments.par_iter_mut())
            .zip(frame.par_iter().zip(guides.albedo.par_iter()))
            .for_each(|((h, m), (c, a))| {
                [*h, *m] = temporal_pixel(*h, *m, *c, demodulator(*a), blend);
            });
        let nd = guides.packed_normal_depth();
        let albedo = guides.packed_albedo();
        let n = width as usize * height as usize;
        let (mut a, mut b) = (vec![Vec4::ZERO; n], vec![Vec4::ZERO; n]);
        let h = &self.history;
        let sigma_z = self.params.sigma_z;
        a.par_chunks_mut(width as usize)
            .enumerate()
            .for_each(|(y, row)| {
                for (x, o) in row.iter_mut().enumerate() {
                    *o = variance_pixel(
                        &h.illumination,
                        &h.moments,
                        &nd,
                        width,
                        height,
                        x as i32,
                        y as i32,
                        sigma_z,
                    );
                }
            });
        for pass in self.params.passes() {
            let input = &a;
            b.par_chunks_mut(width as usize)
                .enumerate()
                .for_each(|(y, row)| {
                    for (x, o) in row.iter_mut().enumerate() {
                        *o = atrous_pixel(
                            input, &nd, &albedo, width, height, x as i32, y as i32, &pass,
                        );
                    }
                });
            std::mem::swap(&mut a, &mut b);
        }
        a.iter().map(|v| v.truncate()).collect()
    }
}
