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
//! * **Monte-Carlo rate.** The relative mean squared error against the reference (minus the
//!   reference's own variance) at 5n spp must be the error at n spp divided by 5: an unbiased
//!   estimator's excess error is pure variance, ∝ 1/spp, while a bias flattens the fall. See
//!   `check_rate` for the statistic; tolerance 4.5 σ, σ from the spread over pixels.

use candela::assets::{AssetRoot, load_scene};
use candela::render::film::read_exr;
use candela_tests::{Batches, Which, external, region_stat, repo};
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
    let (mean, var) = candela::render::film::box_average(256, &mean, &se, size);
    assert_eq!(
        mean.len(),
        (size * size) as usize,
        "256 is a multiple of {size}"
    );
    Reference { mean, var }
}

fn render(scene: &str, which: Which, size: u32, spp: u32) -> Batches {
    render_method(scene, which, size, spp, candela::layout::METHOD_DEFAULT)
}

fn render_method(scene: &str, which: Which, size: u32, spp: u32, method: u32) -> Batches {
    let level = repo().join(format!("assets/test_scenes/reference/{scene}.ron"));
    let root = AssetRoot::new(external().join("reference").join(scene)).expect("asset root");
    let desc = load_scene(&level, &root).expect("level loads");
    candela_tests::render_batches_with(which, &desc, size, size, spp, 5, 11, method)
        .expect("render")
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

/// The Monte-Carlo rate check: the error at K·n spp must equal the error at n spp divided by K.
///
/// Per pixel and channel, scaled by 1/(ref² + 0.01) (relative error, so the few very bright
/// light pixels do not dominate): e_n = mean over the K batches of (batch − ref)² − var_ref (the
/// excess error of an n-spp render, averaged over K of them) and e_Kn = (mean − ref)² − var_ref
/// (the excess error of the K·n-spp render made of the same samples). For an unbiased estimator
/// E[e_n] = σ²/n and E[e_Kn] = σ²/(K n); a bias b adds b² to both, so the ratio falls below K.
/// The statistic g = e_n − K·e_Kn has expectation −(K − 1)·b², zero exactly when unbiased; its
/// standard error comes from the spread of g over pixels (independent). Because both errors
/// use the same samples, a rare firefly inflates both alike and the test stays calibrated.
fn check_rate(label: &str, b: &Batches, r: &Reference) {
    let k = b.batches.len() as f64;
    let mean = b.mean();
    let mut e_n = 0.0;
    let mut e_kn = 0.0;
    let mut g = Vec::with_capacity(mean.len() * 3);
    for (p, (m, (rp, vp))) in mean.iter().zip(r.mean.iter().zip(&r.var)).enumerate() {
        for c in 0..3 {
            let scale = (rp[c] as f64).powi(2) + 0.01;
            let single = b
                .batches
                .iter()
                .map(|batch| ((batch[p][c] - rp[c]) as f64).powi(2))
                .sum::<f64>()
                / k;
            let low = (single - vp[c]) / scale;
            let high = (((m[c] - rp[c]) as f64).powi(2) - vp[c]) / scale;
            e_n += low;
            e_kn += high;
            g.push(low - k * high);
        }
    }
    let n = g.len() as f64;
    let (e_n, e_kn) = (e_n / n, e_kn / n);
    let g_mean = g.iter().sum::<f64>() / n;
    let g_se = (g.iter().map(|x| (x - g_mean).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt();
    let z = g_mean / g_se;
    eprintln!(
        "{label}: relative MSE {e_n:.3e} at {} spp, {e_kn:.3e} at {} spp: ratio {:.3} (expected {k}); rate test {z:.2} σ",
        b.spp_per_batch,
        b.spp_per_batch * k as u32,
        e_n / e_kn,
    );
    assert!(
        z.abs() <= 4.5,
        "{label}: the error does not fall at the Monte-Carlo rate: e_n − K·e_Kn = {g_mean:.3e} ± {g_se:.3e} ({z:.2} σ)"
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
    accuracy("cornell_mirror_glass", Which::Gpu, 64, 64);
}

/// Every estimator the engine offers for measurements (BSDF sampling only; NEE without MIS;
/// NEE + MIS with lights picked uniformly; the default, by power) is unbiased: the same region
/// test against the reference, at 64×64 on the CPU.
#[test]
fn cpu_every_method_is_unbiased() {
    use candela::layout::{METHOD_LIGHTS_BY_POWER, METHOD_MIS, METHOD_NEE};
    let r = reference("cornell_box", 64);
    for (name, method, spp) in [
        ("BSDF sampling only", 0, 128),
        ("NEE without MIS", METHOD_NEE, 32),
        ("NEE + MIS, uniform lights", METHOD_NEE | METHOD_MIS, 32),
        (
            "NEE + MIS, lights by power",
            METHOD_NEE | METHOD_MIS | METHOD_LIGHTS_BY_POWER,
            32,
        ),
    ] {
        let b = render_method("cornell_box", Which::Cpu, 64, spp, method);
        check_bias(&format!("cornell_box/Cpu 64×64 {name}"), &b, &r);
    }
}

/// The light tree (`LightSampling::Tree`, `METHOD_LIGHT_TREE`) is unbiased on both references:
/// the same bias and rate checks on the CPU tracer.
fn accuracy_light_tree(scene: &str, size: u32, spp: u32) {
    use candela::layout::{METHOD_DEFAULT, METHOD_LIGHT_TREE};
    let label = format!("{scene}/Cpu {size}×{size} light tree");
    let r = reference(scene, size);
    let b = render_method(
        scene,
        Which::Cpu,
        size,
        spp,
        METHOD_DEFAULT | METHOD_LIGHT_TREE,
    );
    check_bias(&label, &b, &r);
    check_rate(&label, &b, &r);
}

#[test]
fn cpu_cornell_box_light_tree() {
    accuracy_light_tree("cornell_box", 128, 32);
}

#[test]
fn cpu_cornell_mirror_glass_light_tree() {
    accuracy_light_tree("cornell_mirror_glass", 128, 64);
}
