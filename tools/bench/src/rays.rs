//! `bench rays`: rays per second of each tracer's traversal for camera, shadow and
//! diffuse-bounce rays on a level.
//!
//! Rays (made once, traced by everyone): camera rays through the pixel centres of the level's
//! camera; for every camera-ray hit, a shadow ray towards a point on an emissive triangle picked
//! by power (or towards the sun) and a cosine-distributed bounce ray around the geometric normal
//! (facing the camera ray), both starting just off the surface. Closest hit for camera and
//! bounce rays, any hit for shadow rays.
//!
//! CPU: `candela::trace::TraceScene` on 1 thread and on all threads (rayon, chunks of 64 rays),
//! median of `--reps` measurements of ≥ 100 ms (whole passes) after a warm-up pass. GPU: the batch ray pass (`ray_batch.wgsl`)
//! on the wgpu adapter (lavapipe without a GPU), median of `--reps` dispatches after a warm-up
//! dispatch (which also compiles the shader). Hit counts of the two are printed side by side.

use std::path::PathBuf;
use std::time::Instant;

use candela::assets::{AssetRoot, load_scene};
use candela::layout::{GpuRay, INVALID};
use candela::render::cpu::rng::Rng;
use candela::render::cpu::sampling::{basis, cosine_hemisphere, to_world, uniform_triangle};
use candela::render::cpu::surface::{offset_origin, resolve};
use candela::render::{FrameSettings, frame_uniforms};
use candela::scene::RenderScene;
use candela::trace::Ray;
use clap::Args;
use glam::{Vec2, Vec3};
use rayon::prelude::*;

use crate::machine::median;

#[derive(Args, Debug)]
pub struct RaysArgs {
    /// The level file.
    level: PathBuf,
    /// Asset root (default: the level's folder).
    #[arg(long)]
    asset_root: Option<PathBuf>,
    #[arg(long, default_value_t = 640)]
    width: u32,
    #[arg(long, default_value_t = 360)]
    height: u32,
    #[arg(long, default_value_t = 5)]
    reps: usize,
    /// Skip the GPU measurement.
    #[arg(long)]
    no_gpu: bool,
}

struct Kind {
    name: &'static str,
    rays: Vec<Ray>,
    any_hit: bool,
}

fn make_rays(
    scene: &RenderScene,
    args: &RaysArgs,
    camera: &candela::assets::CameraDesc,
    sun: Option<[f32; 3]>,
) -> Vec<Kind> {
    let settings = FrameSettings::new(args.width, args.height, 1, 0, &Default::default());
    let u = frame_uniforms(
        camera,
        None,
        &Default::default(),
        &settings,
        &candela::scene::SceneHeader {
            light_count: 0,
            light_weight_total: 0.0,
            ..scene.header()
        },
    );
    let (w, h) = (args.width, args.height);
    let primary: Vec<Ray> = (0..w * h)
        .map(|i| {
            let (px, py) = (i % w, i / w);
            let sx = 2.0 * (px as f32 + 0.5) / w as f32 - 1.0;
            let sy = 1.0 - 2.0 * (py as f32 + 0.5) / h as f32;
            let d = Vec3::from(u.camera_forward)
                + Vec3::from(u.camera_right) * sx
                + Vec3::from(u.camera_up) * sy;
            Ray::with_range(
                Vec3::from(u.camera_position),
                d.normalize(),
                0.0,
                f32::INFINITY,
            )
        })
        .collect();
    let tracer = scene.trace_scene();
    let hits: Vec<_> = primary.par_iter().map(|r| tracer.closest(r)).collect();
    let lights = &scene.lights;
    let mut shadow = Vec::new();
    let mut bounce = Vec::new();
    for (i, (ray, hit)) in primary.iter().zip(&hits).enumerate() {
        let Some(hit) = hit else { continue };
        let s = resolve(scene, hit, ray.direction);
        let n = if s.geometric_normal.dot(ray.direction) < 0.0 {
            s.geometric_normal
        } else {
            -s.geometric_normal
        };
        let origin = offset_origin(s.position, n);
        let mut rng = Rng::new(i as u32, 0, 0, 1);
        let mut xi = || rng.next_f32();
        if lights.count > 0 {
            let pick = ((xi() * lights.count as f32) as usize).min(lights.count as usize - 1);
            let mut l = &lights.lights[pick];
            if xi() >= l.alias_threshold {
                l = &lights.lights[l.alias_index as usize];
            }
            let b = uniform_triangle(Vec2::new(xi(), xi()));
            let (p0, p1, p2) = (Vec3::from(l.p0), Vec3::from(l.p1), Vec3::from(l.p2));
            let to = p0 + (p1 - p0) * b.x + (p2 - p0) * b.y - origin;
            let dist = to.length();
            shadow.push(Ray::with_range(origin, to / dist, 0.0, dist * (1.0 - 1e-4)));
        } else if let Some(sun) = sun {
            shadow.push(Ray::with_range(
                origin,
                Vec3::from(sun).normalize(),
                0.0,
                f32::INFINITY,
            ));
        }
        let (t, b) = basis(n);
        let d = to_world(cosine_hemisphere(Vec2::new(xi(), xi())), t, b, n);
        bounce.push(Ray::with_range(origin, d, 0.0, f32::INFINITY));
    }
    vec![
        Kind {
            name: "camera",
            rays: primary,
            any_hit: false,
        },
        Kind {
            name: "shadow",
            rays: shadow,
            any_hit: true,
        },
        Kind {
            name: "bounce",
            rays: bounce,
            any_hit: false,
        },
    ]
}

/// Median Mrays/s of the CPU traversal on `threads` threads, and the hit count.
fn cpu_rate(
    scene: &RenderScene,
    kind: &Kind,
    threads: usize,
    reps: usize,
) -> anyhow::Result<(f64, usize)> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?;
    let tracer = scene.trace_scene();
    let pass = || -> usize {
        kind.rays
            .par_chunks(64)
            .map(|chunk| {
                chunk
                    .iter()
                    .filter(|r| {
                        if kind.any_hit {
                            tracer.occluded(r)
                        } else {
                            tracer.closest(r).is_some()
                        }
                    })
                    .count()
            })
            .sum()
    };
    let hits = pool.install(pass);
    // As the peer benchmark: passes per measurement so that one measurement lasts ≥ 100 ms.
    let started = Instant::now();
    std::hint::black_box(pool.install(pass));
    let passes = (0.1 / started.elapsed().as_secs_f64().max(1e-6))
        .ceil()
        .max(1.0) as usize;
    let times: Vec<f64> = (0..reps)
        .map(|_| {
            let started = Instant::now();
            for _ in 0..passes {
                std::hint::black_box(pool.install(pass));
            }
            started.elapsed().as_secs_f64() / passes as f64
        })
        .collect();
    Ok((kind.rays.len() as f64 / median(&times) / 1e6, hits))
}

pub fn run(args: &RaysArgs) -> anyhow::Result<()> {
    let root_dir = match &args.asset_root {
        Some(r) => r.clone(),
        None => args
            .level
            .parent()
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from(".")),
    };
    let desc = load_scene(&args.level, &AssetRoot::new(root_dir)?)?;
    let scene = RenderScene::build(&desc);
    let kinds = make_rays(&scene, args, &desc.camera, desc.sun.map(|s| s.direction));
    let name = args
        .level
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    println!(
        "scene {name}: {} triangles placed ({} stored), {} instances, {} lights; {}×{} camera rays\n",
        scene.stats.instanced_triangles,
        scene.stats.unique_triangles,
        scene.stats.instances,
        scene.lights.count,
        args.width,
        args.height
    );
    println!(
        "| scene | tracer | threads | kind | rays | hits | Mrays/s |\n|---|---|---|---|---|---|---|"
    );
    let all = rayon::current_num_threads();
    for kind in &kinds {
        for threads in [1, all] {
            let (rate, hits) = cpu_rate(&scene, kind, threads, args.reps)?;
            println!(
                "| {name} | cpu | {threads} | {} | {} | {hits} | {rate:.3} |",
                kind.name,
                kind.rays.len()
            );
        }
    }
    if args.no_gpu {
        return Ok(());
    }
    let context = candela::render::gpu::GpuContext::headless()?;
    let device = context.describe();
    let mut gpu = candela::render::gpu::GpuTracer::new(context, &scene)?;
    for kind in &kinds {
        let rays: Vec<GpuRay> = kind
            .rays
            .iter()
            .map(|r| GpuRay {
                origin: r.origin.to_array(),
                t_min: r.t_min,
                direction: r.direction.to_array(),
                t_max: r.t_max.min(3.0e38),
            })
            .collect();
        let (hits, _) = gpu.trace_rays(&rays, kind.any_hit, scene.tlas_root)?;
        let found = hits.iter().filter(|h| h.instance != INVALID).count();
        let mut times = Vec::new();
        for _ in 0..args.reps.min(3) {
            times.push(gpu.trace_rays(&rays, kind.any_hit, scene.tlas_root)?.1);
        }
        let rate = rays.len() as f64 / median(&times) / 1e6;
        println!(
            "| {name} | gpu ({device}) | - | {} | {} | {found} | {rate:.3} |",
            kind.name,
            rays.len()
        );
    }
    Ok(())
}
