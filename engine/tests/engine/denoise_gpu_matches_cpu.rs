//! The GPU denoiser (`render/gpu/denoise.rs`, WGSL) and the CPU one (`render/denoise/`, Rust)
//! agree on the same inputs: the Cornell box's CPU-traced frames (1 spp, 64×36, with a few
//! NaN/inf pixels) and guides, over eight frames, so both the spatial (history < 4 frames) and
//! the temporal variance are exercised.
//!
//! Tolerance, per pixel and channel: |gpu − cpu| ≤ 2·10⁻³·|cpu| + 10⁻⁴·m, m the image's mean
//! radiance. Derivation: both sides evaluate the same formulas in the same order, so they
//! differ only where WGSL's arithmetic may round differently — `exp` (WGSL allows 3 + 2|x| ULP;
//! the weights that matter have |x| ≤ ~20, so ≤ 43 ULP ≈ 3·10⁻⁶ relative), division (2.5 ULP),
//! `sqrt`, and fused multiply-adds the driver may form (1 ULP each). σ_n = 128 is seven exact
//! squarings, not `pow`. A weighted mean Σwᵢxᵢ/Σwᵢ whose weights carry relative errors ≤ δ moves
//! by ≤ 2δ·max|xᵢ − x̄|; the luminance weight also feeds an input error ε back as ε/(σ_l·√Var),
//! ≤ ~1 here. With δ ≈ 10⁻⁵ (three weights and the kernel per tap), neighbourhood ranges up to
//! ~10× the pixel (the lamp's edge) and five passes compounding: 5 · 2 · 10⁻⁵ · 10 = 10⁻³
//! relative, doubled for margin; the absolute term covers black pixels next to bright ones. The
//! temporal history is plain arithmetic: it must agree to 10⁻⁵ relative.

use crate::denoise_common;

use candela::render::denoise::{Svgf, SvgfParams};
use candela::render::gpu::{GpuContext, GpuDenoiser};
use denoise_common::Cornell;
use glam::Vec3;

const W: u32 = 64;
const H: u32 = 36;

#[test]
fn gpu_and_cpu_denoisers_agree() -> anyhow::Result<()> {
    let cornell = Cornell::load(W, H)?;
    let guides = cornell.guides();
    let context = GpuContext::headless()?;
    let params = SvgfParams::default();
    let mut gpu = GpuDenoiser::new(context, params)?;
    let mut cpu = Svgf::new(params);
    let (mut worst_ratio, mut worst_abs) = (0.0f32, 0.0f32);
    for k in 0..8u32 {
        let mut frame = cornell.frame(1, 11, k)?;
        frame[100 + k as usize] = Vec3::new(f32::NAN, 0.0, 0.0);
        frame[900] = Vec3::splat(f32::INFINITY);
        let blend = 1.0 / (k + 1) as f32;
        let c = cpu.denoise(&frame, &guides, blend)?;
        gpu.denoise(&frame, &guides, blend)?;
        let g = gpu.read_output()?;
        assert_eq!(g.mean.len(), c.mean.len());
        let (gh, gm) = gpu.read_history()?;
        let h = cpu.history();
        for (i, (a, b)) in h.illumination.iter().zip(&gh).enumerate() {
            let d = (*a - *b).abs().max_element();
            assert!(
                d <= 1e-5 * (1.0 + a.abs().max_element()),
                "frame {k} history {i}: {a} {b}"
            );
        }
        for (i, (a, b)) in h.moments.iter().zip(&gm).enumerate() {
            let d = (*a - *b).abs().max_element();
            assert!(
                d <= 1e-5 * (1.0 + a.abs().max_element()),
                "frame {k} moments {i}: {a} {b}"
            );
        }
        let m = c.mean.iter().map(|p| p.element_sum() / 3.0).sum::<f32>() / c.mean.len() as f32;
        for (i, (a, b)) in c.mean.iter().zip(&g.mean).enumerate() {
            assert!(
                b.is_finite(),
                "frame {k} pixel {i}: GPU output {b} not finite"
            );
            for ch in 0..3 {
                let tolerance = 2e-3 * a[ch].abs() + 1e-4 * m;
                let d = (a[ch] - b[ch]).abs();
                worst_ratio = worst_ratio.max(d / tolerance);
                worst_abs = worst_abs.max(d);
                assert!(
                    d <= tolerance,
                    "frame {k} pixel {i} channel {ch}: cpu {a} gpu {b}"
                );
            }
        }
    }
    eprintln!("worst difference: {worst_abs:e} ({worst_ratio:.4} of the tolerance)");
    Ok(())
}
