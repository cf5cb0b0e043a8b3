//! `bench pipeline --only wading`: the frame pipeline with the water rippling under a wading
//! character (issue 35 "Show"): BVH upkeep per frame against a full rebuild of the same scene,
//! and commit bytes per frame against Brigade's 2 MB.
//!
//! Scene: the wading test level (`assets/test_scenes/wading/wading.ron`: a 5 m simulated
//! grid water, the skinned explorer), its water grid set to `--water-divisions` quads per side
//! (96: 18,432 triangles, the paper's water; 0 keeps the level's 80 × 80), plus two movers the
//! bench adds: a kinematic paddle swept through the water along z and a ball dropped into it.
//! The explorer walks a circle of 1.2 m radius through the water for the whole run, so its
//! skinned mesh deforms, its capsule pushes the water in every fixed step and the ripples
//! never settle. Frames of 1/60 s (one fixed step each), headless CPU tracer at 16 × 9, 1 spp
//! (the render thread barely competes), the per-step settle on as in the third-person game.
//!
//! Full rebuild: every mesh of the level and the explorer's mesh built afresh (in parallel on
//! the rayon pool), then the TLAS over every placement: what the upkeep would pay if it rebuilt
//! instead of refitting. Runs on the main thread; touches no engine internals.

use std::path::Path;
use std::time::Instant;

use anyhow::Context;
use candela::accel::{Aabb, Blas, build_blas, build_tlas};
use candela::app::{Engine, Environment, FrameReport, Phase, Step};
use candela::assets::{AssetRoot, Level, Mesh};
use candela::ecs::Transform;
use candela::level::{PlayableLevel, playable_from_level};
use candela::render::RenderConfig;
use candela::sim::physics::CharacterInput;
use glam::{Mat4, Vec3};
use rayon::prelude::*;

use super::pipeline::{PipelineArgs, write_csv};
use crate::machine::median;

/// The level the row measures, relative to the repository root.
const LEVEL: &str = "assets/test_scenes/wading/wading.ron";
/// Its asset root (the hero's model is `common/hero/hero.glb`).
const ASSETS: &str = "assets";
/// The movers the bench adds to the level (its "stone" material).
const MOVERS: &str = r#"Level(
    boxes: [(name: "bench_ball", size: (0.4, 0.4, 0.4), material: "stone"),
            (name: "bench_paddle", size: (0.3, 0.8, 0.6), material: "stone")],
    instances: [
        (model: "bench_ball", name: "bench_ball", transform: (translation: (-1.8, 1.5, 1.8)),
         body: Dynamic(shape: Sphere(radius: 0.2), mass: 3)),
        (model: "bench_paddle", name: "bench_paddle", transform: (translation: (2.0, 0.4, 0)),
         body: Kinematic(shape: Box)),
    ],
    camera: (position: (0, 1, 0), look_at: (0, 0, 0), vertical_fov_deg: 40),
)"#;
const SECONDS_PER_FRAME: f64 = 1.0 / 60.0;
/// Metres: the circle the explorer walks, about the pool's centre.
const CIRCLE: f32 = 1.2;
/// Brigade's commit budget per frame, bytes.
const BRIGADE_COMMIT: f64 = 2_000_000.0;

/// The wading level with `divisions` quads per side of its water (0: as written) and the
/// bench's movers.
fn level(divisions: u32) -> anyhow::Result<PlayableLevel> {
    let path = Path::new(LEVEL);
    let mut level = Level::read(path)?;
    if divisions > 0 {
        let water = level
            .grids
            .iter_mut()
            .find(|g| g.name == "pool_water")
            .context("the wading level has no grid \"pool_water\"")?;
        water.divisions = [divisions, divisions];
    }
    let movers = Level::parse(Path::new("pipeline_wading.rs"), MOVERS)?;
    level.boxes.extend(movers.boxes);
    level.instances.extend(movers.instances);
    Ok(playable_from_level(path, &level, &AssetRoot::new(ASSETS)?)?)
}

/// The explorer's wish this step: along the circle about the origin, steered back onto it.
fn walk_direction(feet: Vec3) -> Vec3 {
    let flat = Vec3::new(feet.x, 0.0, feet.z);
    let r = flat.length();
    if r < 1e-3 {
        return Vec3::X;
    }
    let radial = flat / r;
    let tangent = Vec3::new(-radial.z, 0.0, radial.x);
    (tangent + radial * (CIRCLE - r).clamp(-1.0, 1.0) * 2.0).normalize_or_zero()
}

/// One run: every frame's report, and the meshes a full rebuild builds (the level's and the
/// explorer's) with their placements' transforms.
struct Run {
    frames: Vec<FrameReport>,
    water_triangles: usize,
    meshes: Vec<(Mesh, Vec<Mat4>)>,
}

fn run_level(level: &PlayableLevel, frames: u32) -> anyhow::Result<Run> {
    let desc = &level.scene;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), Environment::of(desc))?;
    engine.settle_every_step(true);
    let spawned = engine.spawn_level(level);
    let body = spawned
        .characters
        .get("hero")
        .context("the wading level has no character \"hero\"")?
        .body;
    let paddle = *spawned
        .by_name
        .get("bench_paddle")
        .context("no paddle spawned")?;
    let mut reports = Vec::with_capacity(frames as usize);
    for _ in 0..frames {
        let mut steer = |step: &mut Step<'_>| {
            let t = (step.index + 1) as f32 * step.step_seconds as f32;
            if let Ok(mut transform) = step.world.get::<&mut Transform>(paddle) {
                transform.translation = Vec3::new(2.0, 0.4, 1.6 * (0.7 * t).sin());
            }
            let feet = step
                .world
                .get::<&Transform>(body)
                .map(|t| t.translation)
                .unwrap_or(Vec3::ZERO);
            if let Ok(mut input) = step.world.get::<&mut CharacterInput>(body) {
                input.move_direction = walk_direction(feet);
            }
        };
        reports.push(engine.frame(SECONDS_PER_FRAME, &mut steer)?);
        let _ = engine.rendered();
    }
    let feet = engine.world().get::<&Transform>(body)?.translation;
    anyhow::ensure!(
        (Vec3::new(feet.x, 0.0, feet.z).length() - CIRCLE).abs() < 0.5,
        "the explorer did not walk the circle: feet at {feet}"
    );
    drop(engine.shutdown());
    let water_triangles = desc
        .instances
        .iter()
        .find(|i| i.name.as_deref() == Some("pool"))
        .and_then(|i| desc.models[i.model].meshes.first())
        .map_or(0, |m| m.triangles.len());
    let mut meshes = Vec::new();
    for inst in &desc.instances {
        let model = &desc.models[inst.model];
        for (k, mesh) in model.meshes.iter().enumerate() {
            let placed = model
                .placements
                .iter()
                .filter(|p| p.mesh == k)
                .map(|p| inst.world_from_model * p.model_from_mesh)
                .collect();
            meshes.push((mesh.clone(), placed));
        }
    }
    for character in &level.characters {
        for (k, mesh) in character.model.meshes.iter().enumerate() {
            let placed = character
                .model
                .placements
                .iter()
                .filter(|p| p.mesh == k)
                .map(|p| p.model_from_mesh)
                .collect();
            meshes.push((mesh.clone(), placed));
        }
    }
    Ok(Run {
        frames: reports,
        water_triangles,
        meshes,
    })
}

/// Seconds to build every BLAS of `meshes` (in parallel) and the TLAS over their placements:
/// (BLAS, TLAS).
fn full_rebuild(meshes: &[(Mesh, Vec<Mat4>)]) -> (f64, f64) {
    let started = Instant::now();
    let built: Vec<Blas> = meshes
        .par_iter()
        .map(|(mesh, _)| build_blas(&mesh.positions, &mesh.triangles))
        .collect();
    let blas_seconds = started.elapsed().as_secs_f64();
    let started = Instant::now();
    let bounds: Vec<Aabb> = built
        .iter()
        .zip(meshes)
        .flat_map(|(blas, (_, placed))| placed.iter().map(|m| blas.bounds.transformed(m)))
        .collect();
    std::hint::black_box(build_tlas(&bounds));
    (blas_seconds, started.elapsed().as_secs_f64())
}

/// Median and largest of `values`.
fn spread(values: &[f64]) -> (f64, f64) {
    (median(values), values.iter().copied().fold(0.0, f64::max))
}

/// One row of the table and its CSV of frames.
fn one(divisions: u32, args: &PipelineArgs) -> anyhow::Result<String> {
    let level = level(divisions)?;
    let run = run_level(&level, args.wading_frames)?;
    // Frame 0 loads the level; one second of entering the water before measuring.
    let steady = run.frames.get(60..).unwrap_or(&[]);
    anyhow::ensure!(!steady.is_empty(), "--wading-frames must exceed 60");
    let get = |f: &dyn Fn(&FrameReport) -> f64| -> Vec<f64> { steady.iter().map(f).collect() };
    let (upkeep, upkeep_max) = spread(&get(&|r| r.upkeep_seconds() * 1e3));
    let (bvh, bvh_max) = spread(&get(&|r| r.upkeep.seconds * 1e3));
    let (steps, steps_max) = spread(&get(&|r| r.phases.get(Phase::Steps) * 1e3));
    let (pose, _) = spread(&get(&|r| r.phases.get(Phase::Pose) * 1e3));
    let (bytes, bytes_max) = spread(&get(&|r| r.commit_bytes as f64));
    let refits = steady
        .iter()
        .map(|r| r.upkeep.blas_refits)
        .max()
        .unwrap_or(0);
    let rebuilds: u32 = steady.iter().map(|r| r.upkeep.blas_rebuilds).sum();
    let _ = full_rebuild(&run.meshes); // warm-up
    let rebuilt: Vec<(f64, f64)> = (0..args.reps).map(|_| full_rebuild(&run.meshes)).collect();
    let full = median(
        &rebuilt
            .iter()
            .map(|(b, t)| (b + t) * 1e3)
            .collect::<Vec<_>>(),
    );
    let triangles: usize = run.meshes.iter().map(|(m, _)| m.triangles.len()).sum();
    println!(
        "water {} triangles, scene {triangles} triangles; {} frames measured; refits per frame \
         up to {refits}, {rebuilds} rebuild(s) in all; fixed steps {steps:.2} ms (max \
         {steps_max:.2}), pose {pose:.2} ms (medians)",
        run.water_triangles,
        steady.len()
    );
    let mut csv = String::from("frame,steps,upkeep_ms,bvh_ms,commit_bytes,refits,rebuilds\n");
    for r in &run.frames {
        csv += &format!(
            "{},{},{:.4},{:.4},{},{},{}\n",
            r.frame,
            r.steps,
            r.upkeep_seconds() * 1e3,
            r.upkeep.seconds * 1e3,
            r.commit_bytes,
            r.upkeep.blas_refits,
            r.upkeep.blas_rebuilds
        );
    }
    write_csv(
        &args.out_dir,
        &format!("wading_{}.csv", run.water_triangles),
        &csv,
    )?;
    Ok(format!(
        "| {} | {upkeep:.2} / {upkeep_max:.2} | {bvh:.2} / {bvh_max:.2} | {full:.1} | **{:.0}×** | \
         {:.0} / {:.0} | {:.0} % |",
        run.water_triangles,
        full / upkeep.max(1e-9),
        bytes,
        bytes_max,
        100.0 * bytes_max / BRIGADE_COMMIT
    ))
}

pub fn run(args: &PipelineArgs) -> anyhow::Result<()> {
    println!("## Upkeep per frame with the water rippling under the wading explorer\n");
    let mut rows = Vec::new();
    for &divisions in &args.water_divisions {
        rows.push(one(divisions, args)?);
    }
    println!(
        "\n| water triangles | upkeep ms (median / max) | of which refit + TLAS ms | full \
         rebuild ms | rebuild / upkeep | commit bytes (median / max) | max of 2 MB |\n\
         |---:|---|---|---:|---:|---|---:|"
    );
    for row in &rows {
        println!("{row}");
    }
    println!();
    Ok(())
}
