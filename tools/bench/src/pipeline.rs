//! `bench pipeline`: the frame pipeline on the demo level (`assets/test_scenes/demo/`), four
//! measurements, each printed as a Markdown table and written as CSV into `--out-dir`:
//!
//! * **upkeep** — per-frame BVH upkeep of the flythrough (extraction, instance rows, the pool's
//!   refit or rebuild, TLAS, light table: `UpkeepStats`) against rebuilding every BLAS and the
//!   TLAS every frame; commit bytes per frame. The script runs at 16 × 9 pixels, 1 spp, so the
//!   render thread barely competes for the cores.
//! * **refit** — the evidence for `REBUILD_RATIO` (`pipeline_refit.rs`).
//! * **queries** — `Upkeep::queries()` throughput on the demo (`pipeline_queries.rs`).
//! * **overlap** — frame time against max(update, render) and their sum with both loaded
//!   (`pipeline_overlap.rs`).
//! * **wading** — the same upkeep against rebuild and commit bytes on the wading test level,
//!   the water rippling under the walking explorer, with movers (`pipeline_wading.rs`).
//!
//! Machine noise: the figures that are compared (upkeep against full rebuild, policies against
//! each other) are taken in the same run, interleaved where it matters; medians of `--reps`.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use candela::accel::{Aabb, Blas, build_blas, build_tlas};
use candela::app::{RunOptions, Script, ScriptTracer, run_script};
use candela::assets::SceneDesc;
use candela::level::PlayableLevel;
use clap::{Args, ValueEnum};
use rayon::prelude::*;

use crate::machine::median;

/// One part of the measurement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Part {
    Upkeep,
    Refit,
    Queries,
    Overlap,
    Wading,
}

#[derive(Args, Debug)]
pub struct PipelineArgs {
    /// The capture script that moves the demo (its level is the scene).
    #[arg(long, default_value = "assets/test_scenes/demo/flythrough.ron")]
    pub script: PathBuf,
    /// Folder for the CSV files.
    #[arg(long, default_value = "tools/bench/results/pipeline")]
    pub out_dir: PathBuf,
    /// Run only these parts (default: all).
    #[arg(long, value_enum)]
    pub only: Vec<Part>,
    #[arg(long, default_value_t = 5)]
    pub reps: usize,
    /// Frames of deformation for the refit measurement.
    #[arg(long, default_value_t = 600)]
    pub refit_frames: u32,
    /// Rayon threads for the whole process (overlap with busy work wants 1: the main thread
    /// then has a core to itself). Default: rayon's (all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Overlap: load the game update with busy work instead of sleep.
    #[arg(long)]
    pub busy: bool,
    /// Wading: quads per side of the water grid, one row each (0: the level's own 80 × 80).
    #[arg(long, value_delimiter = ',', default_values_t = [96, 0])]
    pub water_divisions: Vec<u32>,
    /// Wading: frames of 1/60 s to run (the first 60 are not measured).
    #[arg(long, default_value_t = 660)]
    pub wading_frames: u32,
}

pub fn run(args: &PipelineArgs) -> anyhow::Result<()> {
    if let Some(n) = args.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .context("cannot size the rayon pool")?;
    }
    println!("rayon threads: {}\n", rayon::current_num_threads());
    std::fs::create_dir_all(&args.out_dir)
        .with_context(|| format!("cannot create {}", args.out_dir.display()))?;
    let wants = |p| args.only.is_empty() || args.only.contains(&p);
    if wants(Part::Wading) {
        crate::pipeline_wading::run(args)?;
    }
    if args.only == [Part::Wading] {
        return Ok(());
    }
    let script = Script::read(&args.script)?;
    let level = script.load_level()?;
    let desc = &level.scene;
    if wants(Part::Upkeep) {
        upkeep(&script, &level, args)?;
    }
    if wants(Part::Refit) {
        crate::pipeline_refit::run(desc, args)?;
    }
    if wants(Part::Queries) {
        crate::pipeline_queries::run(desc, args)?;
    }
    if wants(Part::Overlap) {
        crate::pipeline_overlap::run(&level, args)?;
    }
    Ok(())
}

/// Writes `text` to `dir/name` and says so.
pub fn write_csv(dir: &Path, name: &str, text: &str) -> anyhow::Result<()> {
    let path = dir.join(name);
    std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))?;
    println!("wrote {}\n", path.display());
    Ok(())
}

/// Seconds to rebuild every BLAS of `desc` (every mesh of every model in parallel on the rayon
/// pool) and then the TLAS over every placement; returns (BLAS, TLAS) seconds.
fn full_rebuild(desc: &SceneDesc) -> (f64, f64) {
    let started = Instant::now();
    let meshes: Vec<(usize, usize)> = desc
        .models
        .iter()
        .enumerate()
        .flat_map(|(m, model)| (0..model.meshes.len()).map(move |k| (m, k)))
        .collect();
    let built: Vec<Blas> = meshes
        .par_iter()
        .map(|&(m, k)| {
            let mesh = &desc.models[m].meshes[k];
            build_blas(&mesh.positions, &mesh.triangles)
        })
        .collect();
    let mut blas: Vec<Vec<Blas>> = desc.models.iter().map(|_| Vec::new()).collect();
    for ((m, _), b) in meshes.iter().zip(built) {
        blas[*m].push(b);
    }
    let blas_seconds = started.elapsed().as_secs_f64();
    let started = Instant::now();
    let bounds: Vec<Aabb> = desc
        .instances
        .iter()
        .flat_map(|inst| {
            let model = &desc.models[inst.model];
            let built = &blas[inst.model];
            model.placements.iter().map(move |p| {
                built[p.mesh]
                    .bounds
                    .transformed(&(inst.world_from_model * p.model_from_mesh))
            })
        })
        .collect();
    std::hint::black_box(build_tlas(&bounds));
    (blas_seconds, started.elapsed().as_secs_f64())
}

fn upkeep(script: &Script, level: &PlayableLevel, args: &PipelineArgs) -> anyhow::Result<()> {
    let desc = &level.scene;
    println!("## Upkeep per frame: {}\n", args.script.display());
    let options = RunOptions {
        out_dir: None,
        tracer: Some(ScriptTracer::Cpu),
        size: Some((16, 9)),
        spp: Some(1),
        ..Default::default()
    };
    let report = run_script(script, level, &options, &mut |_| {})?;
    // Frame 0 loads the level (every BLAS built once); the steady state is frames 1…
    let steady = &report.frames[1..];
    let ms = |get: &dyn Fn(&candela::app::FrameTiming) -> f64| -> (f64, f64) {
        let v: Vec<f64> = steady.iter().map(get).collect();
        (
            median(&v) * 1e3,
            v.iter().copied().fold(0.0, f64::max) * 1e3,
        )
    };
    let (upkeep_median, upkeep_max) = ms(&|t| t.upkeep_seconds);
    let (bvh_median, bvh_max) = ms(&|t| t.upkeep.seconds);
    let bytes: Vec<f64> = steady.iter().map(|t| t.commit_bytes as f64).collect();
    let typical = steady[steady.len() / 2].upkeep;

    let _ = full_rebuild(desc); // warm-up
    let runs: Vec<(f64, f64)> = (0..args.reps).map(|_| full_rebuild(desc)).collect();
    let full: Vec<f64> = runs.iter().map(|(b, t)| b + t).collect();
    let full_ms = median(&full) * 1e3;
    let blas_ms = median(&runs.iter().map(|r| r.0).collect::<Vec<_>>()) * 1e3;
    let tlas_ms = median(&runs.iter().map(|r| r.1).collect::<Vec<_>>()) * 1e3;
    let triangles: usize = desc
        .models
        .iter()
        .flat_map(|m| &m.meshes)
        .map(|m| m.triangles.len())
        .sum();
    println!(
        "{} frames after the first; per frame: {} instance rows written, {} refit(s), {} rebuild(s), \
         {} TLAS build(s), {} light table build(s)\n",
        steady.len(),
        typical.instances_written,
        typical.blas_refits,
        typical.blas_rebuilds,
        typical.tlas_builds,
        typical.light_table_builds
    );
    println!("| per frame | median | max |\n|---|---:|---:|");
    println!(
        "| upkeep (extract + instances + refit + TLAS + lights), ms | {upkeep_median:.2} | {upkeep_max:.2} |"
    );
    println!(
        "| of which refit/rebuild + TLAS (`UpkeepStats::seconds`), ms | {bvh_median:.2} | {bvh_max:.2} |"
    );
    println!(
        "| commit, bytes | {:.0} | {:.0} |",
        median(&bytes),
        bytes.iter().copied().fold(0.0, f64::max)
    );
    println!(
        "| full rebuild of every BLAS ({triangles} triangles) + TLAS, ms | {full_ms:.1} (BLAS {blas_ms:.1}, TLAS {tlas_ms:.2}) | |"
    );
    println!(
        "\nfull rebuild / upkeep (medians): **{:.1}×**; first frame's commit (the whole level): {} bytes\n",
        full_ms / upkeep_median.max(1e-9),
        report.frames[0].commit_bytes
    );
    let mut csv = String::from(
        "frame,upkeep_ms,bvh_ms,commit_bytes,instances_written,blas_refits,blas_rebuilds,tlas_builds,light_table_builds\n",
    );
    for t in &report.frames {
        csv += &format!(
            "{},{:.4},{:.4},{},{},{},{},{},{}\n",
            t.frame,
            t.upkeep_seconds * 1e3,
            t.upkeep.seconds * 1e3,
            t.commit_bytes,
            t.upkeep.instances_written,
            t.upkeep.blas_refits,
            t.upkeep.blas_rebuilds,
            t.upkeep.tlas_builds,
            t.upkeep.light_table_builds
        );
    }
    write_csv(&args.out_dir, "upkeep.csv", &csv)?;
    write_csv(
        &args.out_dir,
        "full_rebuild.csv",
        &format!(
            "what,median_ms\nblas_all,{blas_ms:.3}\ntlas,{tlas_ms:.3}\ntotal,{full_ms:.3}\nupkeep_median,{upkeep_median:.3}\n"
        ),
    )
}
