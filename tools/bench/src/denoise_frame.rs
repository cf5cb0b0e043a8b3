//! `bench denoise-frame`: the CPU denoise stage's time per frame on a Reflect chamber's view, as
//! the game runs it (issue 30, target 4: ≤ 10 ms at 320×180 on two cores).
//!
//! The chamber's scene and uniforms are kept as `bench chamber-rays` keeps them. Each frame is
//! traced by the engine's [`CpuTracer`] at the frame's jitter with first-hit guides recorded,
//! then handed to the engine's own [`DenoiseStage`] (SVGF with per-pixel reprojection, as
//! `render::frame_render` runs it in play); only the stage is timed, wall clock and this
//! process's CPU seconds. `--turn-degrees` yaws the camera by that much per frame (a slow turn:
//! the reprojection moves every pixel); 0 is a still view. The blend is 1 on the first frame,
//! then 1/(n+1) down to 0.1. The printed hash covers every denoised film of the round, so two
//! builds whose denoisers differ only in speed print the same hash: run them interleaved for
//! an A/B.
//!
//! Owns: [`run`]. Main thread; the rayon pool (`--threads`) for the trace and the stage.
//! Must not: change the game, the tracer or the denoiser.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::time::Instant;

use candela::render::cpu::CpuTracer;
use candela::render::denoise::{AtrousKernel, SvgfParams};
use candela::render::{DenoiseStage, Tracer, jitter};
use clap::Parser;
use glam::{Quat, Vec3};

use super::chamber_rays::{ChamberRaysArgs, capture, cpu_seconds};
use super::machine::median;

#[derive(Parser, Debug)]
pub struct DenoiseFrameArgs {
    /// Chamber number, from 1.
    #[arg(long, default_value_t = 1)]
    pub chamber: usize,
    /// Traced (and denoised) width in pixels.
    #[arg(long, default_value_t = 320)]
    pub width: u32,
    /// Traced (and denoised) height in pixels.
    #[arg(long, default_value_t = 180)]
    pub height: u32,
    /// Frames per round (the first restarts the history and is not timed).
    #[arg(long, default_value_t = 30)]
    pub frames: u32,
    /// Rounds (one line each).
    #[arg(long, default_value_t = 2)]
    pub rounds: u32,
    /// Rayon threads (0: all cores).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Camera yaw per frame in degrees (0: a still view).
    #[arg(long, default_value_t = 0.0)]
    pub turn_degrees: f32,
    /// The à-trous kernels: `5x5` (the default), `3x3` or `5x5-then-3x3`.
    #[arg(long, default_value = "5x5")]
    pub atrous_kernel: String,
}

/// `--atrous-kernel`'s value as the denoiser's kernel choice.
pub fn parse_kernel(name: &str) -> anyhow::Result<AtrousKernel> {
    match name {
        "5x5" => Ok(AtrousKernel::B3Spline5x5),
        "3x3" => Ok(AtrousKernel::Gauss3x3),
        "5x5-then-3x3" => Ok(AtrousKernel::B3ThenGauss3x3),
        other => anyhow::bail!("--atrous-kernel {other}: expected 5x5, 3x3 or 5x5-then-3x3"),
    }
}

/// Yaws the uniforms' camera about world Y by `degrees`.
fn yaw(u: &mut candela::layout::GpuFrameUniforms, degrees: f32) {
    let q = Quat::from_rotation_y(degrees.to_radians());
    let turn = |v: [f32; 3]| (q * Vec3::from(v)).to_array();
    u.camera_right = turn(u.camera_right);
    u.camera_up = turn(u.camera_up);
    u.camera_forward = turn(u.camera_forward);
}

pub fn run(args: &DenoiseFrameArgs) -> anyhow::Result<()> {
    let (scene, base) = capture(&ChamberRaysArgs {
        chamber: args.chamber,
        width: args.width,
        height: args.height,
        frames: 1,
        rounds: 1,
        threads: 0,
        warm_frames: 4,
        light_tree: false,
        indirect_every: 1,
    })?;
    let threads = match args.threads {
        0 => rayon::current_num_threads(),
        n => n,
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()?;
    println!(
        "chamber {} at its file's camera, {}×{}, method {:#x}, turn {}° per frame, {} threads, \
         à-trous {}",
        args.chamber,
        base.width,
        base.height,
        base.method,
        args.turn_degrees,
        threads,
        args.atrous_kernel
    );
    println!(
        "| round | frames timed | denoise ms (median) | min | max | CPU ms per frame | trace ms (median) | films hash |\n|---:|---:|---:|---:|---:|---:|---:|---|"
    );
    let mut tracer = CpuTracer::new();
    for round in 0..args.rounds {
        let mut stage = DenoiseStage::new(SvgfParams {
            kernel: parse_kernel(&args.atrous_kernel)?,
            ..SvgfParams::default()
        });
        let mut u = base;
        let (mut ms, mut trace_ms, mut cpu_total) = (Vec::new(), Vec::new(), 0.0);
        let mut hasher = DefaultHasher::new();
        for f in 0..args.frames {
            let frame = candela::layout::GpuFrameUniforms {
                sample_base: f * u.spp.max(1),
                film_blend: 1.0,
                pixel_jitter: jitter::pack(jitter::frame_jitter(f as u64)),
                ..u
            };
            tracer.clear();
            tracer.record_guides(true);
            let started = Instant::now();
            pool.install(|| tracer.render(&scene, &frame))?;
            trace_ms.push(started.elapsed().as_secs_f64() * 1e3);
            let blend = if f == 0 {
                1.0
            } else {
                (1.0 / (f as f32 + 1.0)).max(0.1)
            };
            let cpu = cpu_seconds();
            let seconds = pool.install(|| stage.run(&scene, &frame, &mut tracer, blend, 1))?;
            if f > 0 {
                cpu_total += cpu_seconds() - cpu;
                ms.push(seconds * 1e3);
            }
            for p in &stage.capture()?.mean {
                p.to_array().map(f32::to_bits).hash(&mut hasher);
            }
            yaw(&mut u, args.turn_degrees);
        }
        let timed = ms.len().max(1) as f64;
        let lo = ms.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = ms.iter().copied().fold(0.0, f64::max);
        println!(
            "| {} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:016x} |",
            round + 1,
            ms.len(),
            median(&ms),
            lo,
            hi,
            cpu_total * 1e3 / timed,
            median(&trace_ms),
            hasher.finish()
        );
    }
    Ok(())
}
