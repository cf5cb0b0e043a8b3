//! `bench chart`: error against time for every estimator the engine offers, on the reference
//! scenes, for both tracers; CSV, PNG charts and the generated part of `docs/ACCURACY.md`.
//!
//! For each scene × tracer × method, one render accumulates at doubling sample counts
//! (1, 2, 4, … spp, an exact running mean), and after each stage records the wall time so far,
//! the rays traced, and the error against the Mitsuba reference: relative MSE (per pixel and
//! channel (ours − ref)² / (ref² + 0.01), minus the reference's own variance), RMSE, and the mean
//! bias per channel (image mean minus reference mean). Methods: BSDF sampling only; NEE without
//! MIS; NEE + MIS with lights picked uniformly or by power (the default); the default with at
//! most 1, 2 or 4 bounces (biased against the 7-bounce reference: the bias shows as a plateau);
//! and two roulette settings. The CPU tracer renders at 256×256, the GPU tracer (lavapipe here)
//! at 64×64 against the reference box-averaged to that size.

use std::path::PathBuf;
use std::time::Instant;

use candela::assets::{AssetRoot, load_level};
use candela::layout::{METHOD_DEFAULT, METHOD_LIGHTS_BY_POWER, METHOD_MIS, METHOD_NEE};
use candela::render::film::read_exr;
use candela::render::{FrameSettings, RenderScene, Tracer, frame_uniforms};
use clap::Args;
use glam::Vec3;

#[derive(Args, Debug)]
pub struct ChartArgs {
    /// `shared/external`.
    #[arg(long, default_value = "../shared/external")]
    pub external: PathBuf,
    /// Highest sample count of the CPU curves (a power of two).
    #[arg(long, default_value_t = 256)]
    pub cpu_spp: u32,
    /// Highest sample count of the GPU curves.
    #[arg(long, default_value_t = 64)]
    pub gpu_spp: u32,
    /// Skip the GPU tracer.
    #[arg(long)]
    pub no_gpu: bool,
    /// Where the CSV and charts go.
    #[arg(long, default_value = "docs/charts")]
    pub out: PathBuf,
    /// The document whose generated section is rewritten.
    #[arg(long, default_value = "docs/ACCURACY.md")]
    pub doc: PathBuf,
}

/// One estimator configuration.
#[derive(Clone, Copy, Debug)]
pub struct Method {
    pub name: &'static str,
    pub method: u32,
    /// `None`: the level's max bounces.
    pub max_bounces: Option<u32>,
    pub roulette_start: Option<u32>,
    pub roulette_scale: f32,
}

pub const METHODS: &[Method] = &[
    Method {
        name: "BSDF sampling only",
        method: 0,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "NEE, no MIS",
        method: METHOD_NEE,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "NEE+MIS, uniform lights",
        method: METHOD_NEE | METHOD_MIS,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "NEE+MIS, lights by power (default)",
        method: METHOD_NEE | METHOD_MIS | METHOD_LIGHTS_BY_POWER,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "default, 1 bounce",
        method: METHOD_DEFAULT,
        max_bounces: Some(1),
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "default, 2 bounces",
        method: METHOD_DEFAULT,
        max_bounces: Some(2),
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "default, 4 bounces",
        method: METHOD_DEFAULT,
        max_bounces: Some(4),
        roulette_start: None,
        roulette_scale: 1.0,
    },
    Method {
        name: "default, roulette from bounce 1",
        method: METHOD_DEFAULT,
        max_bounces: None,
        roulette_start: Some(1),
        roulette_scale: 1.0,
    },
    Method {
        name: "default, roulette scale 0.5",
        method: METHOD_DEFAULT,
        max_bounces: None,
        roulette_start: None,
        roulette_scale: 0.5,
    },
];

/// One measured point.
#[derive(Clone, Debug)]
pub struct Point {
    pub scene: String,
    pub tracer: String,
    pub method: &'static str,
    pub spp: u32,
    pub seconds: f64,
    pub rays: u64,
    pub rel_mse: f64,
    pub rmse: f64,
    pub bias: [f64; 3],
    /// Standard error of the reference's image mean per channel (the bias floor we can see).
    pub bias_floor: [f64; 3],
}

/// The reference of a scene at `size × size` (box-averaged): mean and variance per pixel.
pub struct Reference {
    pub mean: Vec<Vec3>,
    pub var: Vec<[f64; 3]>,
}

pub fn reference(external: &std::path::Path, scene: &str, size: u32) -> anyhow::Result<Reference> {
    let dir = external.join("reference").join(scene);
    let (w, _, mean) = read_exr(&dir.join("reference.exr"))?;
    let (_, _, se) = read_exr(&dir.join("reference_stderr.exr"))?;
    let f = (w / size) as usize;
    let n = (f * f) as f64;
    let mut out = Reference {
        mean: Vec::new(),
        var: Vec::new(),
    };
    for y in 0..size as usize {
        for x in 0..size as usize {
            let mut m = Vec3::ZERO;
            let mut v = [0.0f64; 3];
            for dy in 0..f {
                for dx in 0..f {
                    let i = (y * f + dy) * w as usize + x * f + dx;
                    m += mean[i];
                    for c in 0..3 {
                        v[c] += (se[i][c] as f64).powi(2);
                    }
                }
            }
            out.mean.push(m / n as f32);
            out.var.push(v.map(|v| v / (n * n)));
        }
    }
    Ok(out)
}

/// Relative MSE, RMSE and per-channel bias of `image` against `r`.
pub fn errors(image: &[Vec3], r: &Reference) -> (f64, f64, [f64; 3], [f64; 3]) {
    let n = image.len() as f64;
    let (mut rel, mut sq) = (0.0, 0.0);
    let mut bias = [0.0f64; 3];
    let mut floor = [0.0f64; 3];
    for ((a, b), v) in image.iter().zip(&r.mean).zip(&r.var) {
        for c in 0..3 {
            let d = (a[c] - b[c]) as f64;
            rel += (d * d - v[c]) / ((b[c] as f64).powi(2) + 0.01);
            sq += d * d;
            bias[c] += d;
            floor[c] += v[c];
        }
    }
    (
        rel / (3.0 * n),
        (sq / (3.0 * n)).sqrt(),
        bias.map(|b| b / n),
        floor.map(|f| f.sqrt() / n),
    )
}

fn run_curve(
    tracer: &mut dyn Tracer,
    scene: &RenderScene,
    desc: &candela::assets::SceneDesc,
    size: u32,
    max_spp: u32,
    method: &Method,
    r: &Reference,
    labels: (&str, &str),
) -> anyhow::Result<Vec<Point>> {
    let mut render = desc.render;
    if let Some(b) = method.max_bounces {
        render.max_bounces = b;
    }
    if let Some(s) = method.roulette_start {
        render.roulette_start = s;
    }
    tracer.clear();
    let mut points = Vec::new();
    let (mut done, mut seconds, mut rays) = (0u32, 0.0f64, 0u64);
    let mut stage = 1;
    while stage <= max_spp {
        let batch = stage - done;
        let mut s = FrameSettings::new(size, size, batch, 7, &render).continuing(done);
        s.method = method.method;
        s.roulette_scale = method.roulette_scale;
        let u = frame_uniforms(&desc.camera, None, &desc.sky, &s, &scene.header());
        let started = Instant::now();
        let stats = tracer.render(scene, &u)?;
        seconds += started.elapsed().as_secs_f64();
        rays += stats.rays();
        done = stage;
        let film = tracer.film()?;
        let (rel_mse, rmse, bias, bias_floor) = errors(&film.mean, r);
        points.push(Point {
            scene: labels.0.into(),
            tracer: labels.1.into(),
            method: method.name,
            spp: done,
            seconds,
            rays,
            rel_mse,
            rmse,
            bias,
            bias_floor,
        });
        stage *= 2;
    }
    Ok(points)
}

/// Runs every curve; a progress bar over curves.
pub fn measure(args: &ChartArgs) -> anyhow::Result<Vec<Point>> {
    let scenes = ["cornell_box", "cornell_mirror_glass"];
    let tracers: Vec<&str> = if args.no_gpu {
        vec!["cpu"]
    } else {
        vec!["cpu", "gpu"]
    };
    let total = (scenes.len() * tracers.len() * METHODS.len()) as u64;
    let progress = indicatif::ProgressBar::new(total);
    progress.set_style(
        indicatif::ProgressStyle::with_template(
            "{msg} [{bar:40}] {pos}/{len} curves, {elapsed} (eta {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let mut points = Vec::new();
    for scene_name in scenes {
        let dir = args.external.join("reference").join(scene_name);
        let level = PathBuf::from(format!("assets/test_scenes/reference/{scene_name}.ron"));
        let desc = load_level(&level, &AssetRoot::new(&dir)?)?;
        let scene = RenderScene::build(&desc);
        for &tracer_name in &tracers {
            let (size, max_spp) = if tracer_name == "gpu" {
                (64, args.gpu_spp)
            } else {
                (256, args.cpu_spp)
            };
            let r = reference(&args.external, scene_name, size)?;
            let mut tracer: Box<dyn Tracer> = if tracer_name == "gpu" {
                let context = candela::render::gpu::GpuContext::headless()?;
                Box::new(candela::render::gpu::GpuTracer::new(context, &scene)?)
            } else {
                Box::new(candela::render::cpu::CpuTracer::new())
            };
            // Warm-up (the GPU compiles its shader on the first dispatch).
            let warm = FrameSettings::new(size, size, 1, 99, &desc.render);
            let u = frame_uniforms(&desc.camera, None, &desc.sky, &warm, &scene.header());
            tracer.render(&scene, &u)?;
            for method in METHODS {
                progress.set_message(format!("{scene_name} {tracer_name} {}", method.name));
                points.extend(run_curve(
                    tracer.as_mut(),
                    &scene,
                    &desc,
                    size,
                    max_spp,
                    method,
                    &r,
                    (scene_name, tracer_name),
                )?);
                progress.inc(1);
            }
        }
    }
    progress.finish_and_clear();
    Ok(points)
}
