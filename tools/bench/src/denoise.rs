//! `bench denoise`: the denoiser's cost and benefit. Time per frame of the CPU denoiser (and of
//! the CPU guide pass) at 320×180 and 1280×720, medians of repeated runs, after a cut (every
//! history restarted) and with a converged history, side by side with the per-pixel denoiser
//! it replaced (`denoise_reference.rs`; the largest relative difference of their outputs is
//! printed), and of the GPU twin on this machine's adapter (lavapipe without a GPU; upload,
//! passes and readback; the converged row with its per-pixel reprojection pass). Then the RMSE
//! against a converged reference of the Cornell box at 1, 2 and 4 spp with and without the
//! denoiser (mean and spread over seeds, one frame each), and the bias it adds to a converged
//! image (64 frames of 16 spp through its history, against the reference). Prints Markdown
//! tables, writes `denoise.csv` into `--out-dir` and the chart `docs/charts/denoise_rmse.png`.
//!
//! Owns: the measurements. Must not: draw (see `denoise_plot.rs`).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::{Svgf, SvgfParams, View, world_from_object};
use candela::render::gpu::{GpuContext, GpuDenoiser};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use clap::Args;
use glam::Vec3;

use super::denoise_reference::Reference;

#[derive(Args, Debug)]
pub struct DenoiseArgs {
    /// Folder for the CSV file.
    #[arg(long, default_value = "tools/bench/results/denoise")]
    pub out_dir: PathBuf,
    /// The chart.
    #[arg(long, default_value = "docs/charts/denoise_rmse.png")]
    pub chart: PathBuf,
    /// Image size of the error figures.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    #[arg(long, default_value_t = 90)]
    pub height: u32,
    /// Samples per pixel of the reference.
    #[arg(long, default_value_t = 2048)]
    pub reference_spp: u32,
    /// Seeds per sample count.
    #[arg(long, default_value_t = 4)]
    pub seeds: u32,
    /// Timed runs per size (the median is reported).
    #[arg(long, default_value_t = 5)]
    pub runs: usize,
    /// Skip the GPU twin's timing.
    #[arg(long)]
    pub no_gpu: bool,
    /// Only the times (writes `denoise_time.csv`, no error figures or chart).
    #[arg(long)]
    pub time_only: bool,
}

/// One error figure: samples per pixel, mean and spread of the RMSE without and with, away
/// from the lamp (its edge pixels, a fraction of 17 W·sr⁻¹·m⁻² set by the jitter, are left as
/// they are by design) and over the whole image.
pub struct ErrorRow {
    pub spp: u32,
    pub noisy: (f64, f64),
    pub denoised: (f64, f64),
    pub whole_noisy: (f64, f64),
    pub whole_denoised: (f64, f64),
}

/// Pixels that neither see a lamp nor touch one (3×3).
fn away_from_lamps(g: &candela::render::denoise::Guides) -> Vec<bool> {
    let (w, h) = (g.width as i32, g.height as i32);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            !(-1..=1).any(|dy| {
                (-1..=1).any(|dx| {
                    let (qx, qy) = (x + dx, y + dy);
                    qx >= 0 && qy >= 0 && qx < w && qy < h && g.emissive[(qy * w + qx) as usize]
                })
            })
        })
        .collect()
}

fn rmse_where(a: &[Vec3], b: &[Vec3], keep: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0f64, 0usize);
    for ((x, y), k) in a.iter().zip(b).zip(keep) {
        if *k {
            sum += (*x - *y).length_squared() as f64;
            n += 1;
        }
    }
    (sum / (3 * n.max(1)) as f64).sqrt()
}

struct Cornell {
    desc: SceneDesc,
    scene: RenderScene,
}

impl Cornell {
    fn uniforms(&self, w: u32, h: u32, spp: u32, seed: u32, base: u32) -> GpuFrameUniforms {
        let mut s = FrameSettings::new(w, h, spp, seed, &self.desc.render);
        s.sample_base = base;
        let d = &self.desc;
        frame_uniforms(&d.camera, d.sun.as_ref(), &d.sky, &s, &self.scene.header())
    }

    fn frame(&self, u: &GpuFrameUniforms) -> anyhow::Result<Vec<Vec3>> {
        let mut tracer = CpuTracer::new();
        tracer.render(&self.scene, u)?;
        Ok(tracer.film()?.mean)
    }
}

fn rmse(a: &[Vec3], b: &[Vec3]) -> f64 {
    let sum: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).length_squared() as f64)
        .sum();
    (sum / (3 * a.len().max(1)) as f64).sqrt()
}

fn mean_std(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, var.sqrt())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

pub fn run(args: &DenoiseArgs) -> anyhow::Result<()> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/test_scenes");
    let desc = load_scene(&assets.join("cornell_box.ron"), &AssetRoot::new(&assets)?)?;
    let scene = RenderScene::build(&desc);
    let cornell = Cornell { desc, scene };
    std::fs::create_dir_all(&args.out_dir)?;
    let mut csv = String::from("kind,size_or_spp,value_a,value_b,value_c,value_d\n");

    println!(
        "\n| size | history | CPU guides, ms | CPU denoiser before, ms | CPU denoiser, ms | \
         speed-up | largest difference | GPU denoiser, ms |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|");
    let mut gpu = if args.no_gpu {
        None
    } else {
        Some(GpuDenoiser::new(
            GpuContext::headless()?,
            SvgfParams::default(),
        )?)
    };
    for (w, h) in [(320u32, 180u32), (1280, 720)] {
        let u = cornell.uniforms(w, h, 1, 1, 0);
        let frame = cornell.frame(&u)?;
        // Frames of independent samples, cycled through the converged history's runs.
        let mut frames = vec![frame.clone()];
        for k in 1..4u32 {
            frames.push(cornell.frame(&cornell.uniforms(w, h, 1, 1, k))?);
        }
        let mut guide_times = Vec::new();
        let mut guides = None;
        for _ in 0..args.runs {
            let t = Instant::now();
            guides = Some(trace_guides(&cornell.scene, &u));
            guide_times.push(t.elapsed().as_secs_f64());
        }
        let guides = guides.context("no runs")?;
        let g_ms = median(guide_times) * 1e3;
        // A cut (blend 1: every pixel's history restarts, the 7×7 spatial variance everywhere),
        // then a still camera's converged history (blend 0.1 after 8 frames: temporal variance).
        for (label, warm, blend) in [("restart", 0u32, 1.0f32), ("converged", 8, 0.1)] {
            let mut svgf = Svgf::new(SvgfParams::default());
            let mut before = Reference::new(SvgfParams::default());
            for k in 0..=warm {
                let b = if k == warm {
                    blend
                } else {
                    1.0 / (k + 1) as f32
                };
                let f = &frames[k as usize % frames.len()];
                svgf.denoise(f, &guides, b)?;
                before.denoise(f, &guides, b);
            }
            let (mut cpu_times, mut before_times, mut worst) = (Vec::new(), Vec::new(), 0.0f32);
            for run in 0..args.runs {
                let f = &frames[(warm as usize + 1 + run) % frames.len()];
                let t = Instant::now();
                let old = before.denoise(f, &guides, blend);
                before_times.push(t.elapsed().as_secs_f64());
                let t = Instant::now();
                let new = svgf.denoise(f, &guides, blend)?;
                cpu_times.push(t.elapsed().as_secs_f64());
                for (a, b) in old.iter().zip(&new.mean) {
                    let d = (*a - *b).abs().max_element() / (1e-3 + a.abs().max_element());
                    worst = worst.max(d);
                }
            }
            // The GPU twin: a cut (identity), or the converged history with the per-pixel
            // reprojection pass running every frame (a still view: `denoise_moving`).
            let gpu_ms = match gpu.as_mut() {
                Some(g) => {
                    let view = View::of(&u);
                    let transforms: Vec<_> = cornell
                        .scene
                        .instances
                        .iter()
                        .map(world_from_object)
                        .collect();
                    let step = |g: &mut GpuDenoiser, f: &[Vec3], b: f32| match label {
                        "restart" => g.denoise(f, &guides, 1.0),
                        _ => g.denoise_moving(f, &guides, b, view, transforms.clone()),
                    };
                    for k in 0..=warm {
                        let b = 1.0 / (k + 1) as f32;
                        step(g, &frames[k as usize % frames.len()], b)?;
                    }
                    g.read_output()?;
                    let mut times = Vec::new();
                    for run in 0..args.runs {
                        let f = &frames[(warm as usize + 1 + run) % frames.len()];
                        let t = Instant::now();
                        step(g, f, blend)?;
                        g.read_output()?;
                        times.push(t.elapsed().as_secs_f64());
                    }
                    median(times) * 1e3
                }
                None => f64::NAN,
            };
            let (b_ms, c_ms) = (median(before_times) * 1e3, median(cpu_times) * 1e3);
            println!(
                "| {w}×{h} | {label} | {g_ms:.1} | {b_ms:.1} | {c_ms:.1} | {:.1}× | {worst:.1e} | \
                 {gpu_ms:.1} |",
                b_ms / c_ms
            );
            if label == "restart" {
                csv += &format!("time_ms,{w}x{h},{g_ms:.3},{c_ms:.3},{gpu_ms:.3},\n");
            }
            csv +=
                &format!("time_before_after_ms,{w}x{h}_{label},{b_ms:.3},{c_ms:.3},{worst:e},\n");
        }
    }
    if args.time_only {
        std::fs::write(args.out_dir.join("denoise_time.csv"), csv)?;
        return Ok(());
    }

    let (w, h) = (args.width, args.height);
    let reference = cornell.frame(&cornell.uniforms(w, h, args.reference_spp, 9_999, 0))?;
    let guides = trace_guides(&cornell.scene, &cornell.uniforms(w, h, 1, 0, 0));
    let keep = away_from_lamps(&guides);
    let mut rows = Vec::new();
    for spp in [1u32, 2, 4] {
        let (mut noisy, mut denoised) = (Vec::new(), Vec::new());
        let (mut whole_noisy, mut whole_denoised) = (Vec::new(), Vec::new());
        for seed in 1..=args.seeds {
            let frame = cornell.frame(&cornell.uniforms(w, h, spp, seed, 0))?;
            let out = Svgf::new(SvgfParams::default()).denoise(&frame, &guides, 1.0)?;
            noisy.push(rmse_where(&frame, &reference, &keep));
            denoised.push(rmse_where(&out.mean, &reference, &keep));
            whole_noisy.push(rmse(&frame, &reference));
            whole_denoised.push(rmse(&out.mean, &reference));
        }
        rows.push(ErrorRow {
            spp,
            noisy: mean_std(&noisy),
            denoised: mean_std(&denoised),
            whole_noisy: mean_std(&whole_noisy),
            whole_denoised: mean_std(&whole_denoised),
        });
    }
    // The bias: a converged image through the denoiser's history.
    let mut svgf = Svgf::new(SvgfParams::default());
    let mut mean = vec![Vec3::ZERO; (w * h) as usize];
    let mut out = Vec::new();
    let (frames, spp) = (64u32, 16u32);
    for k in 0..frames {
        let frame = cornell.frame(&cornell.uniforms(w, h, spp, 7, k * spp))?;
        let blend = 1.0 / (k + 1) as f32;
        for (m, f) in mean.iter_mut().zip(&frame) {
            *m += (*f - *m) * blend;
        }
        out = svgf.denoise(&frame, &guides, blend)?.mean;
    }
    let (converged, biased) = (
        rmse_where(&mean, &reference, &keep),
        rmse_where(&out, &reference, &keep),
    );
    let (whole_converged, whole_biased) = (rmse(&mean, &reference), rmse(&out, &reference));

    println!(
        "\nCornell box {w}×{h}, RMSE against {} spp (mean ± std over {} seeds)\n",
        args.reference_spp, args.seeds
    );
    println!(
        "| spp | away from lamp: without | with denoiser | cut | whole image: without | with | cut |"
    );
    println!("|---|---|---|---|---|---|---|");
    for r in &rows {
        println!(
            "| {} | {:.4} ± {:.4} | {:.4} ± {:.4} | {:.2}× | {:.4} ± {:.4} | {:.4} ± {:.4} | {:.2}× |",
            r.spp,
            r.noisy.0,
            r.noisy.1,
            r.denoised.0,
            r.denoised.1,
            r.noisy.0 / r.denoised.0,
            r.whole_noisy.0,
            r.whole_noisy.1,
            r.whole_denoised.0,
            r.whole_denoised.1,
            r.whole_noisy.0 / r.whole_denoised.0
        );
        csv += &format!(
            "rmse_away_from_lamp,{},{:.6},{:.6},{:.6},{:.6}\n",
            r.spp, r.noisy.0, r.noisy.1, r.denoised.0, r.denoised.1
        );
        csv += &format!(
            "rmse_whole,{},{:.6},{:.6},{:.6},{:.6}\n",
            r.spp, r.whole_noisy.0, r.whole_noisy.1, r.whole_denoised.0, r.whole_denoised.1
        );
    }
    println!(
        "\nconverged ({frames} frames × {spp} spp): away from lamp without {converged:.5}, with \
         {biased:.5}; whole image without {whole_converged:.5}, with {whole_biased:.5}"
    );
    csv += &format!(
        "converged,{},{converged:.6},{biased:.6},{whole_converged:.6},{whole_biased:.6}\n",
        frames * spp
    );
    std::fs::write(args.out_dir.join("denoise.csv"), csv)?;
    super::denoise_plot::chart(&args.chart, &rows, (converged, biased))?;
    println!(
        "wrote {} and {}",
        args.out_dir.join("denoise.csv").display(),
        args.chart.display()
    );
    Ok(())
}
