//! The CPU denoiser's row kernels (`render/denoise/planes.rs`, `variance::estimate`,
//! `atrous::filter`) give what the per-pixel reference functions give (`temporal_pixel`,
//! `variance_pixel`, `atrous_pixel`, the shape the WGSL twin mirrors): on the Cornell box over
//! frames with short and long histories, and on synthetic guides with every odd case (sky,
//! emissive, NaN and negative depths, turned normals, non-finite samples, images narrower than
//! the taps' reach).
//!
//! Tolerance, per pixel and channel: |kernels − reference| ≤ 10⁻⁴·|reference| + 10⁻⁶·m, m the
//! image's mean. Both evaluate the same operations in the same order except the exponential
//! (`exp_neg`, within 3·10⁻⁷ of `f32::exp`); a weighted mean whose weights carry relative
//! errors ≤ δ moves by ≤ 2δ·max|xᵢ − x̄|, so with neighbourhood ranges up to ~10× the pixel
//! and six passes compounding, 6 · 2 · 3·10⁻⁷ · 10 ≈ 4·10⁻⁵, rounded up.

use crate::denoise_common;

use candela::render::denoise::weights::demodulator;
use candela::render::denoise::{
    AtrousKernel, Guides, History, Svgf, SvgfParams, atrous_pixel, temporal_pixel, variance_pixel,
};
use denoise_common::{Cornell, Noise, flat_guides};
use glam::{Vec3, Vec4};

/// The denoiser built from the per-pixel functions, one pixel at a time (a still camera).
fn reference(
    history: &mut History,
    frame: &[Vec3],
    guides: &Guides,
    blend: f32,
    params: SvgfParams,
) -> Vec<Vec3> {
    let (w, h) = (guides.width, guides.height);
    if history.width != w || history.height != h {
        *history = History::new(w, h);
    }
    for (i, c) in frame.iter().enumerate() {
        let d = demodulator(guides.albedo[i]);
        let (il, mo) = (history.illumination[i], history.moments[i]);
        [history.illumination[i], history.moments[i]] = temporal_pixel(il, mo, *c, d, blend);
    }
    let nd = guides.packed_normal_depth();
    let albedo = guides.packed_albedo();
    let pixels = || (0..h as i32).flat_map(move |y| (0..w as i32).map(move |x| (x, y)));
    let mut a: Vec<Vec4> = pixels()
        .map(|(x, y)| {
            let (il, mo) = (&history.illumination, &history.moments);
            variance_pixel(il, mo, &nd, w, h, x, y, params.sigma_z)
        })
        .collect();
    for pass in params.passes() {
        a = pixels()
            .map(|(x, y)| atrous_pixel(&a, &nd, &albedo, w, h, x, y, &pass))
            .collect();
    }
    a.iter().map(|v| v.truncate()).collect()
}

fn assert_close(what: &str, kernels: &[Vec3], reference: &[Vec3]) {
    let m = reference.iter().map(|p| p.element_sum() / 3.0).sum::<f32>() / reference.len() as f32;
    let mut worst = 0.0f32;
    for (i, (a, b)) in kernels.iter().zip(reference).enumerate() {
        assert!(a.is_finite(), "{what} pixel {i}: {a} not finite");
        for ch in 0..3 {
            let tolerance = 1e-4 * b[ch].abs() + 1e-6 * m.abs() + f32::MIN_POSITIVE;
            let d = (a[ch] - b[ch]).abs();
            worst = worst.max(d / tolerance);
            assert!(
                d <= tolerance,
                "{what} pixel {i} channel {ch}: {a} against {b}"
            );
        }
    }
    eprintln!("{what}: worst difference {worst:.4} of the tolerance");
}

/// Every à-trous kernel choice, each against its per-pixel reference.
fn compare(what: &str, frames: &[Vec<Vec3>], guides: &Guides) -> anyhow::Result<()> {
    let kernels = [
        AtrousKernel::B3Spline5x5,
        AtrousKernel::Gauss3x3,
        AtrousKernel::B3ThenGauss3x3,
    ];
    for kernel in kernels {
        let params = SvgfParams {
            kernel,
            ..SvgfParams::default()
        };
        let mut svgf = Svgf::new(params);
        let mut history = History::default();
        for (k, frame) in frames.iter().enumerate() {
            let blend = 1.0 / (k + 1) as f32;
            let out = svgf.denoise(frame, guides, blend)?;
            let expected = reference(&mut history, frame, guides, blend, params);
            assert_close(
                &format!("{what} {kernel:?} frame {k}"),
                &out.mean,
                &expected,
            );
        }
    }
    Ok(())
}

#[test]
fn kernels_match_the_per_pixel_reference_on_the_cornell_box() -> anyhow::Result<()> {
    let cornell = Cornell::load(64, 36)?;
    let guides = cornell.guides();
    let mut frames = Vec::new();
    for k in 0..6u32 {
        let mut frame = cornell.frame(1, 5, k)?;
        frame[200 + k as usize] = Vec3::new(f32::NAN, 0.0, 0.0);
        frame[700] = Vec3::splat(f32::INFINITY);
        frames.push(frame);
    }
    compare("cornell", &frames, &guides)
}

#[test]
fn kernels_match_the_per_pixel_reference_on_odd_guides() -> anyhow::Result<()> {
    for (w, h) in [(37u32, 23u32), (3, 40), (40, 2), (1, 1)] {
        let mut guides = flat_guides(w, h, 3.0, Vec3::new(0.6, 0.0, 0.3));
        let mut noise = Noise(7 + w);
        for i in 0..guides.len() {
            match i % 11 {
                0 => guides.depth[i] = 0.0,
                1 => guides.emissive[i] = true,
                2 => guides.normal[i] = Vec3::X,
                3 => guides.depth[i] = f32::NAN,
                4 => guides.depth[i] = -2.0,
                5 => guides.normal[i] = Vec3::new(0.0, 0.6, 0.8),
                _ => guides.depth[i] = 3.0 + 0.3 * noise.next() + 0.01 * (i % w as usize) as f32,
            }
        }
        let frames: Vec<Vec<Vec3>> = (0..6u32)
            .map(|k| {
                let mut n = Noise(100 + k);
                (0..guides.len())
                    .map(|i| match (i + k as usize) % 29 {
                        0 => Vec3::splat(f32::NAN),
                        1 => Vec3::new(-1.0, 2.0, 0.5),
                        _ => Vec3::new(n.next(), n.next() * 4.0, n.next() * 0.1),
                    })
                    .collect()
            })
            .collect();
        compare(&format!("{w}×{h}"), &frames, &guides)?;
    }
    Ok(())
}
