//! `bench bounce-budget`: how many bounces a Reflect chamber needs in play. For each chamber's
//! view (its file's camera, as `bench chamber-rays` takes it: the game's own scene and frame
//! uniforms) and each bounce cap asked for, the CPU tracer renders `--frames` one-sample frames;
//! each is timed and compared with a converged reference of the same view at
//! `--reference-bounces` (more than any cap measured, so that what a cap leaves out counts as
//! error). Printed per chamber and cap: median ms per frame, the relative MSE of one frame
//! (what a moving view shows: noise plus bias²), that error times the frame time (error at
//! equal time: lower is better), the relative MSE of the mean of all frames, and the bias: the
//! relative MSE of a render of the cap converged like the reference (`--reference-spp`), beside
//! the reference's own noise floor (two halves of it against each other, a quarter of their
//! relative MSE; the bias column holds about twice that floor besides the bias²). A still view
//! converges to the cap's converged render, so its bias is what a player sees when standing.
//!
//! Beside the caps, `--roulette-starts` and `--light-sampling` measure the other render settings
//! a level declares (when Russian roulette may start ending paths; power table or light tree)
//! in every combination, so each chamber's settings are chosen at equal time.
//!
//! The caps are measured interleaved (frame by frame) so that load on a shared machine falls
//! on all of them alike.
//!
//! Owns: [`run`]. Main thread (the rayon pool renders). Must not: change the game or the tracer.

use candela::assets::LightSampling;
use candela::layout::{GpuFrameUniforms, METHOD_LIGHT_TREE, METHOD_LIGHTS_BY_POWER};
use candela::render::Tracer;
use candela::render::cpu::CpuTracer;
use candela::render::method_of;
use candela::scene::RenderScene;
use clap::Parser;
use glam::Vec3;

use super::chamber_rays::{ChamberRaysArgs, capture};
use super::machine::median;
use super::picture_metrics::rel_mse;

#[derive(Parser, Debug)]
pub struct BounceBudgetArgs {
    /// Chambers (from 1), comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "1,2,3,4,5")]
    pub chambers: Vec<usize>,
    /// Bounce caps to compare, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "2,3")]
    pub bounces: Vec<u32>,
    /// Scattering events before Russian roulette may end a path, comma-separated, each measured
    /// with every cap (empty: the level's own `render.roulette_start`).
    #[arg(long, value_delimiter = ',')]
    pub roulette_starts: Vec<u32>,
    /// How next-event estimation picks an emissive triangle (`power`, `tree`), comma-separated,
    /// each measured with every cap and roulette start (empty: the level's own).
    #[arg(long, value_delimiter = ',', value_parser = parse_sampling)]
    pub light_sampling: Vec<LightSampling>,
    /// Traced width in pixels.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// Traced height in pixels.
    #[arg(long, default_value_t = 90)]
    pub height: u32,
    /// One-sample frames per cap.
    #[arg(long, default_value_t = 24)]
    pub frames: u32,
    /// Samples per pixel of the reference.
    #[arg(long, default_value_t = 512)]
    pub reference_spp: u32,
    /// Bounce cap of the reference.
    #[arg(long, default_value_t = 8)]
    pub reference_bounces: u32,
}

/// `power` or `tree`.
fn parse_sampling(s: &str) -> Result<LightSampling, String> {
    match s {
        "power" => Ok(LightSampling::Power),
        "tree" => Ok(LightSampling::Tree),
        other => Err(format!("unknown light sampling {other:?} (power, tree)")),
    }
}

/// Mean radiance of `spp` samples per pixel of `u`'s view at `max_bounces` (and `u`'s
/// roulette), rendered in chunks of 16 samples from sample base `base`.
fn converged(
    tracer: &mut CpuTracer,
    scene: &RenderScene,
    u: &GpuFrameUniforms,
    max_bounces: u32,
    spp: u32,
    base: u32,
) -> anyhow::Result<Vec<Vec3>> {
    const CHUNK: u32 = 16;
    let chunks = spp.div_ceil(CHUNK).max(1);
    let mut sum = vec![Vec3::ZERO; (u.width * u.height) as usize];
    for c in 0..chunks {
        let frame = GpuFrameUniforms {
            spp: CHUNK,
            sample_base: base + c * CHUNK,
            film_blend: 1.0,
            max_bounces,
            ..*u
        };
        tracer.clear();
        tracer.render(scene, &frame)?;
        for (s, p) in sum.iter_mut().zip(&tracer.film()?.mean) {
            *s += *p;
        }
    }
    Ok(sum.into_iter().map(|s| s / chunks as f32).collect())
}

pub fn run(args: &BounceBudgetArgs) -> anyhow::Result<()> {
    anyhow::ensure!(!args.bounces.is_empty(), "--bounces: give at least one cap");
    println!(
        "{}×{} traced, {} one-sample frames per cap, reference {} spp at {} bounces\n",
        args.width, args.height, args.frames, args.reference_spp, args.reference_bounces
    );
    println!(
        "| chamber | max bounces | roulette from | lights | ms per frame (median) | rel. MSE, 1 frame | rel. MSE × ms | rel. MSE, mean of {} frames | rel. MSE converged (bias² + noise) | reference noise floor |\n|---|---:|---:|---|---:|---:|---:|---:|---:|---:|",
        args.frames
    );
    let mut tracer = CpuTracer::new();
    for &chamber in &args.chambers {
        let (scene, u) = capture(&ChamberRaysArgs {
            chamber,
            width: args.width,
            height: args.height,
            frames: 0,
            rounds: 0,
            threads: 0,
            warm_frames: 4,
            light_tree: false,
            indirect_every: 1,
        })?;
        let half = (args.reference_spp / 2).max(1);
        let halves = [1u32 << 20, 1 << 21]
            .map(|base| converged(&mut tracer, &scene, &u, args.reference_bounces, half, base));
        let [a, b] = halves;
        let (a, b) = (a?, b?);
        let floor = rel_mse(&a, &b) / 4.0;
        let reference: Vec<Vec3> = a.iter().zip(&b).map(|(x, y)| (*x + *y) * 0.5).collect();
        let starts = if args.roulette_starts.is_empty() {
            vec![u.roulette_start]
        } else {
            args.roulette_starts.clone()
        };
        // The level's own light sampling keeps its other method bits (a level's view).
        let samplings: Vec<(&str, u32)> = if args.light_sampling.is_empty() {
            vec![("level", u.method)]
        } else {
            let others = u.method & !(METHOD_LIGHT_TREE | METHOD_LIGHTS_BY_POWER);
            args.light_sampling
                .iter()
                .map(|&l| (l.name(), others | method_of(l)))
                .collect()
        };
        // Every (cap, roulette start, light sampling), measured interleaved.
        let configs: Vec<(u32, u32, &str, u32)> = args
            .bounces
            .iter()
            .flat_map(|&b| starts.iter().map(move |&s| (b, s)))
            .flat_map(|(b, s)| samplings.iter().map(move |&(name, m)| (b, s, name, m)))
            .collect();
        let caps = configs.len();
        let mut ms = vec![Vec::new(); caps];
        let mut errors = vec![Vec::new(); caps];
        let mut sums = vec![vec![Vec3::ZERO; reference.len()]; caps];
        for f in 0..args.frames {
            for (i, &(bounces, roulette_start, _, method)) in configs.iter().enumerate() {
                let frame = GpuFrameUniforms {
                    sample_base: f * u.spp.max(1),
                    film_blend: 1.0,
                    max_bounces: bounces,
                    roulette_start,
                    method,
                    ..u
                };
                tracer.clear();
                let stats = tracer.render(&scene, &frame)?;
                ms[i].push(stats.seconds * 1e3);
                let film = tracer.film()?;
                errors[i].push(rel_mse(&film.mean, &reference));
                for (s, p) in sums[i].iter_mut().zip(&film.mean) {
                    *s += *p;
                }
            }
        }
        for (i, &(bounces, roulette_start, sampling, method)) in configs.iter().enumerate() {
            let mean: Vec<Vec3> = sums[i]
                .iter()
                .map(|s| *s / args.frames.max(1) as f32)
                .collect();
            let frame_ms = median(&ms[i]);
            let error = errors[i].iter().sum::<f64>() / errors[i].len().max(1) as f64;
            let with = GpuFrameUniforms {
                roulette_start,
                method,
                ..u
            };
            let still = converged(&mut tracer, &scene, &with, bounces, 2 * half, 1 << 22)?;
            println!(
                "| {chamber} | {bounces} | {roulette_start} | {sampling} | {frame_ms:.2} | {error:.4} | {:.3} | {:.4} | {:.4} | {floor:.4} |",
                error * frame_ms,
                rel_mse(&mean, &reference),
                rel_mse(&still, &reference)
            );
        }
    }
    Ok(())
}
