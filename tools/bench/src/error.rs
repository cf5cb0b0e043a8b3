//! `bench error`: time for each tracer to reach a fixed error against the Cornell reference,
//! and Mitsuba 3's time to the same error on the same kind of machine.
//!
//! Error: relative MSE per pixel and channel, (ours − ref)² / (ref² + 0.01), averaged, minus the
//! reference's own variance on the same scale (see `tests/cross/accuracy.rs`). A render of n spp is
//! made, its error e(n) measured; the accuracy tests show the error falls as 1/n (no bias), so
//! the samples needed for a target error T are n · e(n) / T and the time is that many samples at
//! the measured seconds per sample. Mitsuba: the reference's standard error σ_ref at 32,768 spp
//! gives its per-sample variance (σ_ref² · 32768), hence its error after n samples, and its
//! scene.md gives its time per sample (484 s / 32,768 spp for cornell_box on a 2-core VM).

use std::path::PathBuf;

use candela::assets::{AssetRoot, load_scene};
use candela::render::film::read_exr;
use candela::render::{FrameSettings, frame_uniforms};
use candela::scene::RenderScene;
use clap::Args;
use glam::Vec3;

#[derive(Args, Debug)]
pub struct ErrorArgs {
    /// `shared/external`.
    #[arg(long, default_value = "../shared/external")]
    external: PathBuf,
    /// Target relative MSE.
    #[arg(long, default_value_t = 1e-3)]
    target: f64,
    /// Samples per pixel of the measuring render (per tracer).
    #[arg(long, default_value_t = 64)]
    spp: u32,
    /// Mitsuba's wall time for 32,768 spp of cornell_box at 256×256, seconds: scene.md's 484 s
    /// (128 processes of 256 spp, start-up included) unless measured here (see PERFORMANCE.md).
    #[arg(long, default_value_t = 484.0)]
    mitsuba_seconds: f64,
    /// Skip the GPU tracer.
    #[arg(long)]
    no_gpu: bool,
}

pub fn run(args: &ErrorArgs) -> anyhow::Result<()> {
    let dir = args.external.join("reference/cornell_box");
    let (_, _, reference) = read_exr(&dir.join("reference.exr"))?;
    let (_, _, stderr) = read_exr(&dir.join("reference_stderr.exr"))?;
    let scale = |r: f32| (r as f64).powi(2) + 0.01;
    // Mitsuba: relative MSE after n samples = mean over pixels/channels of σ_sample² / n / scale.
    let pixels = reference.len() as f64;
    let mut per_sample = 0.0;
    let mut ref_var = Vec::with_capacity(reference.len());
    for (r, s) in reference.iter().zip(&stderr) {
        let mut v = [0.0f64; 3];
        for c in 0..3 {
            v[c] = (s[c] as f64).powi(2);
            per_sample += v[c] * 32768.0 / scale(r[c]);
        }
        ref_var.push(v);
    }
    per_sample /= pixels;
    let mitsuba_spp = per_sample / args.target;
    let mitsuba_time = mitsuba_spp * args.mitsuba_seconds / 32768.0;
    println!(
        "target relative MSE {:.1e} on cornell_box 256×256\n",
        args.target
    );
    println!(
        "| renderer | measured at | rel. MSE there | spp to target | seconds per spp | time to target | Mitsuba time / ours |\n|---|---|---|---|---|---|---|"
    );
    println!(
        "| Mitsuba 3.9.1 llvm_ad_rgb (its reference; time: --mitsuba-seconds {}) | 32768 spp | {:.2e} | {:.0} | {:.4} | {:.2} s | 1.00 |",
        args.mitsuba_seconds,
        per_sample / 32768.0,
        mitsuba_spp,
        args.mitsuba_seconds / 32768.0,
        mitsuba_time
    );
    let level = PathBuf::from("assets/test_scenes/reference/cornell_box.ron");
    let desc = load_scene(&level, &AssetRoot::new(&dir)?)?;
    let scene = RenderScene::build(&desc);
    let mut tracers: Vec<Box<dyn candela::render::Tracer>> =
        vec![Box::new(candela::render::cpu::CpuTracer::new())];
    if !args.no_gpu {
        let context = candela::render::gpu::GpuContext::headless()?;
        tracers.push(Box::new(candela::render::gpu::GpuTracer::new(
            context, &scene,
        )?));
    }
    for tracer in &mut tracers {
        // Warm-up (shader compile on the GPU), then the measured render in batches of 8 spp.
        let warm = FrameSettings::new(256, 256, 1, 99, &desc.render);
        let u = frame_uniforms(&desc.camera, None, &desc.sky, &warm, &scene.header());
        tracer.render(&scene, &u)?;
        tracer.clear();
        let mut seconds = 0.0;
        let mut done = 0;
        while done < args.spp {
            let batch = 8.min(args.spp - done);
            let s = FrameSettings::new(256, 256, batch, 1, &desc.render).continuing(done);
            let u = frame_uniforms(&desc.camera, None, &desc.sky, &s, &scene.header());
            seconds += tracer.render(&scene, &u)?.seconds;
            done += batch;
        }
        let image = tracer.film()?.mean;
        let mut e = 0.0;
        for ((a, r), v) in image.iter().zip(&reference).zip(&ref_var) {
            let d: Vec3 = *a - *r;
            for c in 0..3 {
                e += ((d[c] as f64).powi(2) - v[c]) / scale(r[c]);
            }
        }
        e /= pixels;
        let spp_needed = args.spp as f64 * e / args.target;
        let per_spp = seconds / args.spp as f64;
        let time = spp_needed * per_spp;
        println!(
            "| Candela {} ({}) | {} spp | {e:.2e} | {spp_needed:.0} | {per_spp:.4} | {time:.2} s | {:.2} |",
            tracer.name(),
            tracer.device(),
            args.spp,
            mitsuba_time / time
        );
    }
    Ok(())
}
