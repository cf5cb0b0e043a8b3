//! Temporal upscaling (TAAU; issue 30, "Temporal reuse"): the tracer traces a small grid
//! (e.g. 160×90, one sample per pixel) whose samples all sit at one sub-pixel offset per frame
//! (`render::jitter`, Halton 2, 3), and the denoiser's history lives at `factor` times that
//! size (e.g. 320×180). Each traced sample lands in exactly one history pixel — the one its
//! offset falls in — and is blended there as the temporal stage blends (`temporal_pixel`, the
//! weight `max(blend · factor², 1 / (samples + 1))`: about an exact mean while the camera is
//! still, and an old history fades within as many frames as without upscaling); so over
//! the jitter's frames every history pixel receives samples of its own footprint, and a still
//! picture converges to the high-resolution one, not to an upscaled low-resolution one.
//!
//! Owns: [`Svgf::denoise_upscaled`] (reproject the high-resolution history with the existing
//! guide-based rejection — instance, normal, depth: a disoccluded pixel starts afresh, so
//! nothing ghosts —, splat, then SVGF's variance and à-trous passes at the high resolution),
//! [`splat`] and [`filled`]. A history pixel that has no sample yet (the first frames, a
//! disocclusion, a specular first hit) is shown, for the filter only, with the mean of this
//! frame's samples on its instance around it; it keeps no history until a sample lands in it. Linear radiance; render thread, rows on rayon's pool.
//! Must not: trace rays (the guide pass traces the guides at the high resolution) or choose
//! the jitter (the render thread does, from the frame number).

use glam::{Affine3A, Vec3, Vec4};
use rayon::prelude::*;

use super::guides::Guides;
use super::reproject::{PrevFrame, ReprojectStats, reproject};
use super::svgf::{DenoiseError, Svgf};
use super::temporal::{History, temporal_pixel};
use super::view::View;
use super::weights::{demodulator, finite3, luminance};
use crate::render::film::Film;

/// One traced (low-resolution) frame: mean radiance per pixel (linear, rows top to bottom) and
/// the offset of every sample inside its pixel (traced pixels, [0, 1)², x right, y down).
#[derive(Clone, Copy, Debug)]
pub struct Traced<'a> {
    pub mean: &'a [Vec3],
    pub width: u32,
    pub height: u32,
    pub jitter: (f32, f32),
}

impl Svgf {
    /// Denoises one traced frame into the history at the guides' size (a whole multiple of
    /// the traced size), seen from `view` (the guides' size) with the instances at
    /// `world_from_object`. `blend` is the converging factor (1 restarts). Returns the film at
    /// the guides' size and, when a previous frame was reprojected, how many pixels kept their
    /// history.
    pub fn denoise_upscaled(
        &mut self,
        traced: Traced<'_>,
        guides: &Guides,
        blend: f32,
        view: View,
        world_from_object: Vec<Affine3A>,
    ) -> Result<(Film, Option<ReprojectStats>), DenoiseError> {
        let factor = check(&traced, guides)?;
        let (width, height) = (guides.width, guides.height);
        if self.history.width != width || self.history.height != height {
            self.history = History::new(width, height);
            self.prev = None;
        }
        let restart = blend.is_nan() || blend >= 1.0;
        let stats = match self.prev.take() {
            Some(prev) if !restart => {
                let (moved, stats) =
                    reproject(&self.history, &prev, guides, &view, &world_from_object);
                self.history = moved;
                Some(stats)
            }
            _ => {
                self.history = History::new(width, height);
                None
            }
        };
        splat(&mut self.history, &traced, factor, &guides.albedo, blend);
        let shown = filled(&self.history, &traced, factor, guides);
        self.prev = Some(PrevFrame {
            view,
            guides: guides.clone(),
            world_from_object,
        });
        Ok((self.filter(&shown, guides), stats))
    }
}

/// The upscaling factor, or why the sizes do not fit.
fn check(traced: &Traced<'_>, guides: &Guides) -> Result<u32, DenoiseError> {
    let error = || DenoiseError::UpscaleMismatch {
        frame: traced.mean.len(),
        traced_width: traced.width,
        traced_height: traced.height,
        width: guides.width,
        height: guides.height,
    };
    let n = traced.width as usize * traced.height as usize;
    if n == 0 || traced.mean.len() != n || !guides.is_consistent() {
        return Err(error());
    }
    let factor = guides.width / traced.width;
    if factor == 0
        || guides.width != traced.width * factor
        || guides.height != traced.height * factor
    {
        return Err(error());
    }
    Ok(factor)
}

/// Blends each traced sample into the history pixel its offset falls in (`factor` history
/// pixels per traced pixel each way), demodulated by that pixel's `albedo`, with weight
/// `max(min(1, blend · factor²), 1 / (samples + 1))` (`blend` ≥ 1 restarts the pixel).
pub fn splat(history: &mut History, traced: &Traced<'_>, factor: u32, albedo: &[Vec3], blend: f32) {
    let f = factor as usize;
    let (hw, tw) = (history.width as usize, traced.width as usize);
    let sub = |j: f32| ((j.clamp(0.0, 1.0) * factor as f32) as usize).min(f - 1);
    let (dx, dy) = (sub(traced.jitter.0), sub(traced.jitter.1));
    let restart = blend.is_nan() || blend >= 1.0;
    // A history pixel gets a sample every f² frames or so: the frame's floor scaled by f²
    // fades an old history within as many frames as without upscaling (a surface's light
    // changed, or a history reprojection kept wrongly: no longer ghosts f² times as long).
    let floor = (blend * (f * f) as f32).min(1.0);
    history
        .illumination
        .par_chunks_mut(hw * f)
        .zip(history.moments.par_chunks_mut(hw * f))
        .enumerate()
        .for_each(|(y, (il, mo))| {
            for x in 0..tw {
                let (Some(&c), j) = (traced.mean.get(y * tw + x), dy * hw + x * f + dx) else {
                    continue;
                };
                let a = albedo.get((y * f + dy) * hw + x * f + dx).copied();
                let demod = demodulator(a.unwrap_or(Vec3::ONE));
                let h = il[j];
                let weight = if restart {
                    1.0
                } else {
                    floor.max(1.0 / (h.w.max(0.0) + 1.0))
                };
                [il[j], mo[j]] = temporal_pixel(h, mo[j], c, demod, weight);
            }
        });
}

/// The history as the filter sees it: a pixel without any sample yet takes the mean of this
/// frame's samples (among the 3×3 traced pixels around it) that landed on the same instance,
/// else the traced pixel covering it; demodulated by its own albedo, one frame long. The other
/// pixels are unchanged. `guides` are the history's.
///
/// The mean, not the nearest sample: a pixel whose first hit is specular (a mirror, smooth
/// glass) keeps no history (`reproject`), so each frame most of its displayed pixels are
/// filled. Copying one sample there copied a single path's outlier (glass picking the
/// reflection that sees a light strip: 6–7 where the converged picture has 0–0.1, in Reflect's
/// chamber 1) into three to eight displayed pixels; the mean of up to nine samples spreads
/// it as a traced-size picture's pixel would, at a ninth of the strength.
pub fn filled(history: &History, traced: &Traced<'_>, factor: u32, guides: &Guides) -> History {
    let mut shown = history.clone();
    let (hw, tw, f) = (
        history.width as usize,
        traced.width as usize,
        factor as usize,
    );
    let th = traced.height as usize;
    let sub = |j: f32| ((j.clamp(0.0, 1.0) * factor as f32) as usize).min(f - 1);
    let (dx, dy) = (sub(traced.jitter.0), sub(traced.jitter.1));
    shown
        .illumination
        .par_iter_mut()
        .zip(shown.moments.par_iter_mut())
        .enumerate()
        .filter(|(_, (h, _))| h.w <= 0.0)
        .for_each(|(i, (h, m))| {
            let (px, py) = (i % hw, i / hw);
            let (x, y) = (px / f, py / f);
            let instance = guides.instance.get(i).copied();
            // The mean of the samples on the same instance, else the covering pixel's.
            let (mut sum, mut count) = (Vec3::ZERO, 0u32);
            for ty in y.saturating_sub(1)..(y + 2).min(th) {
                for tx in x.saturating_sub(1)..(x + 2).min(tw) {
                    let (sx, sy) = (tx * f + dx, ty * f + dy);
                    if guides.instance.get(sy * hw + sx).copied() != instance {
                        continue;
                    }
                    match traced.mean.get(ty * tw + tx) {
                        Some(&c) if finite3(c) => {
                            sum += c;
                            count += 1;
                        }
                        _ => {}
                    }
                }
            }
            let c = match (count, traced.mean.get(y * tw + x)) {
                (0, Some(&c)) => c,
                (0, None) => return,
                (n, _) => sum / n as f32,
            };
            if !finite3(c) {
                return;
            }
            let albedo = guides.albedo.get(i).copied().unwrap_or(Vec3::ONE);
            let illum = c.max(Vec3::ZERO) / demodulator(albedo);
            let l = luminance(illum);
            *h = illum.extend(1.0);
            *m = Vec4::new(l, l * l, 0.0, 0.0);
        });
    shown
}

#[cfg(test)]
#[path = "upscale_tests.rs"]
mod tests;
