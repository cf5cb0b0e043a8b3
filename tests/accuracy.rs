//! Accuracy against the independent reference renders in `shared/external/reference/` (Mitsuba 3,
//! 32,768 spp, 256×256, with a per-pixel standard-error image), for both tracers.
//!
//! Each scene is loaded from its level in `assets/test_scenes/reference/` (pointing at the
//! reference's own OBJ files) and rendered in K = 5 independent batches of n samples per pixel.
//! Renders smaller than 256×256 are compared with the reference box-averaged to the same pixel
//! grid (a box-filtered pixel is the mean over its footprint, so averaging 2×2 or 4×4 reference
//! pixels gives exactly the larger pixel), with standard errors combined in quadrature.
//!
//! * **No bias.** Means over the whole image and over a 4×4 grid of regions, per channel, must
//!   agree with the reference within 4.5 σ, σ = sqrt(σ_ours² + σ_ref²): σ_ours from the spread of
//!   the batches of every pixel (see `candela_tests`), σ_ref from the reference's standard-error
//!   image. 51 checks per scene and tracer at 4.5σ: a false alarm has probability ~3e-4 in all.
//! * **Monte-Carlo rate.** Batch 0 (n spp) and batches 1–4 (4n spp, independent of batch 0) are
//!   two renders at two sample counts. Their relative mean squared error against the reference,
//!   minus the reference's own variance, must fall by the factor 4 the sample counts differ by: an unbiased
//!   estimator's excess error is pure variance, ∝ 1/spp, while a bias would flatten the ratio.
//!   Tolerance 4.5 σ of the ratio, σ propagated from the standard errors of the two MSEs
//!   (pixels are independent, so SE(MSE) = sd(per-pixel squared error)/√pixels).

use candela::assets::{AssetRoot, load_level};
use candela::render::film::read_exr;
use candela_tests::{Batches, Which, external, region_stat, render_batches, repo};
use glam::Vec3;

struct Reference {
    mean: Vec<Vec3>,
    /// Variance of each reference pixel's mean (standard error squared).
    var: Vec<[f64; 3]>,
}

/// The reference of `scene`, box-averaged down to `size × size`.
fn reference(scene: &str, size: u32) -> Reference {
    let dir = external().join("reference").join(scene);
    let (w, h, mean) = read_exr(&dir.join("reference.exr")).expect("reference.exr");
    let (_, _, se) = read_exr(&dir.join("reference_stderr.exr")).expect("reference_stderr.exr");
    assert_eq!((w, h), (256, 256));
    let f = (256 / size) as usize;
    let n = (f * f) as f64;
    let mut out_mean = Vec::new();
    let mut out_var = Vec::new();
    for y in 0..size as usize {
        for x in 0..size as usize {
            let mut m = Vec3::ZERO;
            let mut v = [0.0f64; 3];
            for dy in 0..f {
                for dx in 0..f {
                    let i = (y * f + dy) * 256 + x * f + dx;
                    m += mean[i];
                    for c in 0..3 {
                        v[c] += (se[i][c] as f64).powi(2);
                    }
                }
            }
            out_mean.push(m / n as f32);
            out_var.push(v.map(|v| v / (n * n)));
        }
    }
    Reference {
        mean: out_mean,
        var: out_var,
    }
}

fn render(scene: &str, which: Which, size: u32, spp: u32) -> Batches {
    let level = repo().join(format!("assets/test_scenes/reference/{scene}.ron"));
    let root = AssetRoot::new(external().join("reference").join(scene)).expect("asset root");
    let desc = load_level(&level, &root).expect("level loads");
    render_batches(which, &desc, size, size, spp, 5, 11).expect("render")
}

fn check_bias(label: &str, b: &Batches, r: &Reference) {
    let size = b.width;
    let ours_mean = b.mean();
    let ours_var = b.variance_of_mean();
    let mut regions: Vec<(String, Box<dyn Fn(u32, u32) -> bool>)> =
        vec![("image".into(), Box::new(|_, _| true))];
    let cell = size / 4;
    for ry in 0..4 {
        for rx in 0..4 {
            regions.push((
                format!("region ({rx},{ry})"),
                Box::new(move |x, y| x / cell == rx && y / cell == ry),
            ));
        }
    }
    let mut worst = 0.0f64;
    for (name, keep) in &regions {
        let ours = region_stat(size, &ours_mean, &ours_var, keep);
        let theirs = region_stat(size, &r.mean, &r.var, keep);
        for c in 0..3 {
            let sigma = (ours.std_error[c].powi(2) + theirs.std_error[c].powi(2)).sqrt();
            let z = (ours.mean[c] - theirs.mean[c]) / sigma;
            worst = worst.max(z.abs());
            if z.abs() > 2.5 {
                eprintln!(
                    "{label}: {name} channel {c}: {z:.2} σ (ours {:.5} ± {:.5}, reference {:.5})",
                    ours.mean[c], ours.std_error[c], theirs.mean[c]
                );
            }
            assert!(
                z.abs() <= 4.5,
                "{label}: {name} channel {c}: ours {:.5} ± {:.5}, reference {:.5} ± {:.5}: {z:.2} σ",
                ours.mean[c],
                ours.std_error[c],
                theirs.mean[c],
                theirs.std_error[c]
            );
        }
    }
    eprintln!(
        "{label}: bias check passed, worst |z| = {worst:.2} over {} checks",
        regions.len() * 3
    );
}

/// Excess relative MSE of `image` against `r` and its standard error: per pixel and channel
/// (ours − ref)² / (ref² + 0.01), minus the reference's own variance on the same scale. The
/// relative form keeps the few very bright pixels (the light, 17 W·sr⁻¹·m⁻², whose partially
/// covered edge pixels vary by ±17 between samples) from dominating the mean.
fn excess_mse(image: &[Vec3], r: &Reference) -> (f64, f64) {
    let per_pixel: Vec<f64> = image
        .iter()
        .zip(&r.mean)
        .zip(&r.var)
        .map(|((a, b), v)| {
            (0..3)
                .map(|c| {
                    let scale = (b[c] as f64).powi(2) + 0.01;
                    (((a[c] - b[c]) as f64).powi(2) - v[c]) / scale
                })
                .sum::<f64>()
        })
        .collect();
    let n = per_pixel.len() as f64;
    let mean = per_pixel.iter().sum::<f64>() / n;
    let var = per_pixel.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

fn check_rate(label: &str, b: &Batches, r: &Reference) {
    let low = &b.batches[0];
    let k = b.batches.len();
    let high: Vec<Vec3> = (0..low.len())
        .map(|p| b.batches[1..].iter().map(|batch| batch[p]).sum::<Vec3>() / (k - 1) as f32)
        .collect();
    let (e_low, se_low) = excess_mse(low, r);
    let (e_high, se_high) = excess_mse(&high, r);
    let ratio = e_low / e_high;
    let expected = (k - 1) as f64;
    let sigma = ratio * ((se_low / e_low).powi(2) + (se_high / e_high).powi(2)).sqrt();
    eprintln!(
        "{label}: relative MSE {:.3e} at {} spp, {:.3e} at {} spp: ratio {ratio:.3} ± {sigma:.3} (expected {expected})",
        e_low,
        b.spp_per_batch,
        e_high,
        b.spp_per_batch * (k as u32 - 1),
    );
    assert!(
        (ratio - expected).abs() <= 4.5 * sigma,
        "{label}: excess MSE ratio {ratio:.3} ± {sigma:.3} differs from {expected} by more than 4.5 σ"
    );
}

fn accuracy(scene: &str, which: Which, size: u32, spp: u32) {
    let label = format!("{scene}/{which:?} {size}×{size}");
    let r = reference(scene, size);
    let b = render(scene, which, size, spp);
    check_bias(&label, &b, &r);
    check_rate(&label, &b, &r);
}

#[test]
fn cpu_cornell_box() {
    accuracy("cornell_box", Which::Cpu, 128, 32);
}

#[test]
fn cpu_cornell_mirror_glass() {
    accuracy("cornell_mirror_glass", Which::Cpu, 128, 64);
}

#[test]
fn gpu_cornell_box() {
    accuracy("cornell_box", Which::Gpu, 64, 16);
}

#[test]
fn gpu_cornell_mirror_glass() {
    accuracy("cornell_mirror_glass", Which::Gpu, 64, 32);
}

#[test]
fn cpu_cornell_mirror_glass_small() {
    accuracy("cornell_mirror_glass", Which::Cpu, 64, 32);
}
