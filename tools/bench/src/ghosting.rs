//! `bench ghosting`: error on a fast-moving object and its trail for several converging
//! policies (`candela::app::measure_ghosting`: an emissive square crossing a dark backdrop,
//! headless engine, CPU tracer, against a fresh many-sample render of the last frame). Prints a
//! Markdown table and writes `ghosting.csv` into `--out-dir`. Errors are RMS over the region of
//! the per-pixel RGB mean, relative to the square's radiance; the figures are deterministic for
//! a given seed (CPU tracer, fixed workload), so one run suffices.

use std::path::PathBuf;

use anyhow::Context;
use candela::app::{GhostSetup, measure_ghosting};
use candela::render::film::ConvergePolicy;
use clap::Args;

#[derive(Args, Debug)]
pub struct GhostingArgs {
    /// Folder for the CSV file.
    #[arg(long, default_value = "tools/bench/results/ghosting")]
    pub out_dir: PathBuf,
    /// Blend floors while objects move (1 = reset on motion: only the newest frame counts).
    #[arg(long, value_delimiter = ',', default_value = "0,0.1,0.25,0.5,1")]
    pub floors: Vec<f32>,
    /// Samples per pixel per frame.
    #[arg(long, default_value_t = 2)]
    pub spp: u32,
    /// Metres the square moves per frame.
    #[arg(long, default_value_t = 0.25)]
    pub metres_per_frame: f32,
    /// Seeds to average over (the table shows the mean and the spread).
    #[arg(long, default_value_t = 4)]
    pub seeds: u32,
}

pub fn run(args: &GhostingArgs) -> anyhow::Result<()> {
    let policies: Vec<ConvergePolicy> = args
        .floors
        .iter()
        .map(|&moving_floor| ConvergePolicy {
            moving_floor,
            ..Default::default()
        })
        .collect();
    let engine_floor = ConvergePolicy::default().moving_floor;
    let mut rows: Vec<Vec<[f64; 4]>> = vec![Vec::new(); policies.len()];
    let mut setup = GhostSetup {
        spp: args.spp,
        metres_per_frame: args.metres_per_frame,
        ..Default::default()
    };
    for seed in 0..args.seeds.max(1) {
        setup.seed = 7 + seed;
        let errors = measure_ghosting(&setup, &policies)?;
        for (row, e) in rows.iter_mut().zip(&errors) {
            row.push([e.object, e.trail, e.moving, e.rest]);
        }
    }
    println!(
        "## Ghosting: {}×{} px, {} spp per frame, square {} m moving {} m per frame, {} frames, \
         reference {} spp, {} seeds\n",
        setup.width,
        setup.height,
        setup.spp,
        setup.object_size,
        setup.metres_per_frame,
        setup.frames,
        setup.reference_spp,
        args.seeds.max(1)
    );
    println!("| moving floor | object | trail | object + trail | rest of image |");
    println!("|---|---:|---:|---:|---:|");
    let mut csv = String::from("moving_floor,seed,object,trail,moving,rest\n");
    for (policy, row) in policies.iter().zip(&rows) {
        let mean = |k: usize| row.iter().map(|r| r[k]).sum::<f64>() / row.len().max(1) as f64;
        let label = match policy.moving_floor {
            f if f >= 1.0 => format!("{f} (reset on motion)"),
            f if f == engine_floor => format!("{f} (engine default)"),
            0.0 => "0 (pure accumulation)".to_string(),
            f => format!("{f}"),
        };
        println!(
            "| {label} | {:.4} | {:.4} | {:.4} | {:.4} |",
            mean(0),
            mean(1),
            mean(2),
            mean(3)
        );
        for (seed, r) in row.iter().enumerate() {
            csv.push_str(&format!(
                "{},{},{:.6},{:.6},{:.6},{:.6}\n",
                policy.moving_floor,
                7 + seed,
                r[0],
                r[1],
                r[2],
                r[3]
            ));
        }
    }
    std::fs::create_dir_all(&args.out_dir)
        .with_context(|| format!("cannot create {}", args.out_dir.display()))?;
    let path = args.out_dir.join("ghosting.csv");
    std::fs::write(&path, csv).with_context(|| format!("cannot write {}", path.display()))?;
    println!("\nwrote {}", path.display());
    Ok(())
}
