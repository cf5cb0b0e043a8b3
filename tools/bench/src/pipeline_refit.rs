//! `bench pipeline --only refit`: the evidence for `REBUILD_RATIO` (`engine/src/accel/upkeep.rs`).
//!
//! Mesh: the demo's pool (a 24 m grid of 128 × 128 quads, 32,768 triangles). Deformations, at
//! 30 frames per second for `--refit-frames` frames: `waves` (the demo's own built-in waves,
//! vertical motion only) and `swirl` (the same waves turned about the centre by
//! `0.8 rad/s · t / (1 + r / 3 m)`: a whirlpool whose shear stretches triangles across the tree,
//! the hard case for refitting). Policies, all run in lockstep on the same frames: rebuild every
//! frame (ratio 0), refit and rebuild when SAH cost > `rebuild_bound(ratio, …)` (ratio × the
//! estimated cost of a fresh build, at most ratio × the cost at the last build: the engine's
//! policy) for ratios 1.05 … 3, and refit only (∞). Every 10th frame each policy's tree (and a fresh build, the
//! ideal) traces the same 20,000 rays on one thread — 10,000 camera-like rays from one point
//! above the pool, 10,000 incoherent rays between random points above it and on it — in
//! rotating order, median of 3 passes; hit counts must agree (same geometry, same hits).
//! Per frame cost of a policy for N rays into this mesh: upkeep + N × time per ray.

use std::time::Instant;

use candela::accel::{Blas, build_blas, rebuild_bound, refit_blas, sah_cost, triangle_area_ratio};
use candela::app::{Waves, waves_system};
use candela::assets::SceneDesc;
use candela::ecs::Deformable;
use candela::render::cpu::rng::Rng;
use candela::trace::{Ray, closest_blas};
use glam::{Quat, Vec3};

use super::pipeline::{PipelineArgs, write_csv};
use crate::machine::median;

const RATIOS: [f32; 9] = [0.0, 1.05, 1.1, 1.2, 1.3, 1.5, 2.0, 3.0, f32::INFINITY];
const SAMPLE_EVERY: u32 = 10;
const SECONDS_PER_FRAME: f64 = 1.0 / 30.0;

struct Policy {
    ratio: f32,
    blas: Blas,
    built_cost: f32,
    built_area: f32,
    rebuilds: u32,
    upkeep: Vec<f64>,
    ray_seconds: Vec<f64>,
}

fn label(ratio: f32) -> String {
    match ratio {
        0.0 => "rebuild every frame".into(),
        r if r.is_infinite() => "refit only".into(),
        r => format!("ratio {r}"),
    }
}

fn rays(extent: f32) -> Vec<Ray> {
    let mut rng = Rng::new(7, 11, 13, 17);
    let mut u = || rng.next_f32();
    let mut out = Vec::with_capacity(20_000);
    for i in 0..20_000 {
        let target = Vec3::new((u() - 0.5) * extent, 0.0, (u() - 0.5) * extent);
        let origin = if i < 10_000 {
            Vec3::new(0.0, 12.0, 18.0)
        } else {
            Vec3::new((u() - 0.5) * extent, 1.0 + 3.0 * u(), (u() - 0.5) * extent)
        };
        out.push(Ray::new(origin, (target - origin).normalize()));
    }
    out
}

/// Seconds per ray (median of 3 passes) and hits of `blas` on `rays`.
fn trace(blas: &Blas, rays: &[Ray]) -> (f64, usize) {
    let mut times = Vec::new();
    let mut hits = 0;
    for _ in 0..3 {
        let started = Instant::now();
        hits = rays
            .iter()
            .filter(|r| closest_blas(&blas.nodes, &blas.blocks, r).is_some())
            .count();
        times.push(started.elapsed().as_secs_f64());
    }
    (median(&times) / rays.len() as f64, hits)
}

fn deform(world: &mut hecs::World, entity: hecs::Entity, frame: u32, swirl: bool) -> Vec<Vec3> {
    let t = frame as f64 * SECONDS_PER_FRAME;
    waves_system(world, t);
    let Ok(d) = world.get::<&Deformable>(entity) else {
        return Vec::new();
    };
    if !swirl {
        return d.positions.clone();
    }
    d.positions
        .iter()
        .map(|p| {
            let r = p.x.hypot(p.z);
            let angle = 0.8 * t as f32 / (1.0 + r / 3.0);
            Quat::from_rotation_y(angle) * *p
        })
        .collect()
}

fn one(desc: &SceneDesc, args: &PipelineArgs, swirl: bool) -> anyhow::Result<()> {
    let name = if swirl { "swirl" } else { "waves" };
    let pool = desc
        .instances
        .iter()
        .find(|i| i.name.as_deref() == Some("pool"))
        .ok_or_else(|| anyhow::anyhow!("the level has no instance named \"pool\""))?;
    let wave = pool
        .waves
        .ok_or_else(|| anyhow::anyhow!("the pool does not wave"))?;
    let mesh = &desc.models[pool.model].meshes[0];
    let triangles = &mesh.triangles;
    let mut world = hecs::World::new();
    let entity = world.spawn((
        Waves::new(wave, mesh.positions.clone()),
        Deformable {
            mesh: 0,
            positions: mesh.positions.clone(),
            normals: None,
            dirty: false,
        },
    ));
    let start = deform(&mut world, entity, 0, swirl);
    let extent = mesh
        .positions
        .iter()
        .map(|p| p.x.abs().max(p.z.abs()))
        .fold(0.0, f32::max)
        * 2.0;
    let rays = rays(extent);
    let mut policies: Vec<Policy> = RATIOS
        .iter()
        .map(|&ratio| {
            let blas = build_blas(&start, triangles);
            Policy {
                ratio,
                built_cost: sah_cost(&blas.nodes, &blas.blocks),
                built_area: triangle_area_ratio(&blas),
                blas,
                rebuilds: 0,
                upkeep: Vec::new(),
                ray_seconds: Vec::new(),
            }
        })
        .collect();
    let first_cost = policies[0].built_cost;
    let mut fresh_seconds = Vec::new();
    let mut degradation = String::from(
        "frame,sah_refit_over_first_build,sah_refit_over_fresh,trace_refit_over_fresh\n",
    );
    let mut refit_seconds = Vec::new();
    let mut build_seconds = Vec::new();
    for frame in 1..=args.refit_frames {
        let positions = deform(&mut world, entity, frame, swirl);
        for p in &mut policies {
            let started = Instant::now();
            let cost = refit_blas(&mut p.blas, &positions, triangles);
            let refit = started.elapsed().as_secs_f64();
            let area = triangle_area_ratio(&p.blas);
            if cost > rebuild_bound(p.ratio, p.built_cost, p.built_area, area) {
                let started = Instant::now();
                p.blas = build_blas(&positions, triangles);
                p.built_cost = sah_cost(&p.blas.nodes, &p.blas.blocks);
                p.built_area = triangle_area_ratio(&p.blas);
                p.rebuilds += 1;
                build_seconds.push(started.elapsed().as_secs_f64());
            }
            if p.ratio.is_infinite() {
                refit_seconds.push(refit);
            }
            p.upkeep.push(started.elapsed().as_secs_f64());
        }
        if frame % SAMPLE_EVERY != 0 {
            continue;
        }
        let fresh = build_blas(&positions, triangles);
        let (fresh_time, fresh_hits) = trace(&fresh, &rays);
        fresh_seconds.push(fresh_time);
        let n = policies.len();
        for k in 0..n {
            let p = &mut policies[(k + frame as usize / SAMPLE_EVERY as usize) % n];
            let (time, hits) = trace(&p.blas, &rays);
            anyhow::ensure!(
                hits == fresh_hits,
                "{name} frame {frame}: {} hits {hits} rays, a fresh build {fresh_hits}",
                label(p.ratio)
            );
            p.ray_seconds.push(time);
        }
        if let Some(refit) = policies.last() {
            let fresh_cost = sah_cost(&fresh.nodes, &fresh.blocks);
            let cost = sah_cost(&refit.blas.nodes, &refit.blas.blocks);
            degradation += &format!(
                "{frame},{:.4},{:.4},{:.4}\n",
                cost / first_cost,
                cost / fresh_cost,
                refit.ray_seconds.last().copied().unwrap_or(0.0) / fresh_time
            );
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    let fresh_ray = mean(&fresh_seconds);
    println!(
        "### {name}: {} triangles, {} frames; refit {:.2} ms, rebuild {:.2} ms (medians, one thread)\n",
        triangles.len(),
        args.refit_frames,
        median(&refit_seconds) * 1e3,
        median(&build_seconds) * 1e3
    );
    let budgets = [1e5, 1e6, 1e7];
    println!(
        "| policy | rebuilds | upkeep ms/frame | ns/ray | vs fresh build | ms/frame at 0.1M / 1M / 10M rays |\n|---|---:|---:|---:|---:|---|"
    );
    let mut csv =
        String::from("policy,ratio,rebuilds,upkeep_ms_per_frame,ns_per_ray,slowdown_vs_fresh\n");
    for p in &policies {
        let upkeep = mean(&p.upkeep);
        let ray = mean(&p.ray_seconds);
        let costs: Vec<String> = budgets
            .iter()
            .map(|n| format!("{:.2}", (upkeep + n * ray) * 1e3))
            .collect();
        println!(
            "| {} | {} | {:.3} | {:.1} | {:.3} | {} |",
            label(p.ratio),
            p.rebuilds,
            upkeep * 1e3,
            ray * 1e9,
            ray / fresh_ray,
            costs.join(" / ")
        );
        csv += &format!(
            "{},{},{},{:.4},{:.3},{:.4}\n",
            label(p.ratio),
            p.ratio,
            p.rebuilds,
            upkeep * 1e3,
            ray * 1e9,
            ray / fresh_ray
        );
    }
    println!();
    write_csv(&args.out_dir, &format!("refit_{name}_policies.csv"), &csv)?;
    write_csv(
        &args.out_dir,
        &format!("refit_{name}_degradation.csv"),
        &degradation,
    )
}

pub fn run(desc: &SceneDesc, args: &PipelineArgs) -> anyhow::Result<()> {
    println!("## REBUILD_RATIO: refit against rebuild on the demo's pool\n");
    one(desc, args, false)?;
    one(desc, args, true)
}
