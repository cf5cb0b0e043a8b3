//! `bench balance`: Brigade's Table 1 and Figure 9 (§4.3) reproduced on recorded per-unit costs
//! of the demo city, and our schemes beside the paper's four.
//!
//! Reads the cost files in `--data-dir` (`slow.csv`, `fast.csv`; `--record` records them first
//! on the CPU tracer, `balance_record.rs`), replays each on simulated tracers
//! (`candela::render::balance::simulate`: 2 and 3 tracers of equal speed as in the paper, and
//! of unequal speeds), and prints Markdown tables of the mean idle share over the frames and the
//! worst frame per scheme. Writes `table.csv` and `frames.csv` into `--out-dir` and the
//! Figure 9 charts (idle share per frame per scheme) into `--chart-dir`.
//! Owns: the experiment plan and the tables. Must not: hold scheme logic (the engine does).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::Context;
use candela::render::balance::{
    Balancer, CostModel, CostTrace, Interleaved, PerfectSmooth, SchemeKind, SimReport, simulate,
};
use clap::Args;

use super::balance_plot::{Panel, figure};
use super::balance_record::{SPINS, record};

#[derive(Args, Debug)]
pub struct BalanceArgs {
    /// Record the cost files anew (CPU tracer, a few minutes) before replaying them.
    #[arg(long)]
    pub record: bool,
    /// Folder of the cost files.
    #[arg(long, default_value = "tools/bench/data/balance")]
    pub data_dir: PathBuf,
    /// Folder for table.csv and frames.csv.
    #[arg(long, default_value = "tools/bench/results/balance")]
    pub out_dir: PathBuf,
    /// Folder for the Figure 9 charts.
    #[arg(long, default_value = "docs/charts")]
    pub chart_dir: PathBuf,
    /// Frames to record.
    #[arg(long, default_value_t = 128)]
    pub frames: u32,
    /// Recording resolution.
    #[arg(long, default_value_t = 384)]
    pub width: u32,
    #[arg(long, default_value_t = 216)]
    pub height: u32,
    /// Samples per pixel of the recorded frames.
    #[arg(long, default_value_t = 2)]
    pub spp: u32,
    /// Extra Perfect Smooth rows at these α (the paper gives none; ours defaults to 0.5).
    #[arg(long, value_delimiter = ',', default_value = "0.25,0.75")]
    pub alphas: Vec<f64>,
    /// Extra rows of our schemes at these cost blends β (ours defaults to
    /// `candela::render::balance::COST_BLEND`).
    #[arg(long, value_delimiter = ',', default_value = "0.25,1")]
    pub blends: Vec<f64>,
    /// Also run every scheme on a real pool of CPU tracers (`--pool-threads`) for
    /// `--pool-frames` frames of the slow camera.
    #[arg(long)]
    pub pool: bool,
    #[arg(long, default_value_t = 32)]
    pub pool_frames: u32,
    #[arg(long, value_delimiter = ',', default_value = "1,1")]
    pub pool_threads: Vec<usize>,
    /// Also run every scheme on a real pool of the GPU tracer and `--pool-gpu-cpus` one-thread
    /// CPU tracers (`PoolTracer`, as `TracerChoice::Pool` runs it) for `--pool-frames` frames.
    #[arg(long)]
    pub pool_gpu: bool,
    #[arg(long, default_value_t = 1)]
    pub pool_gpu_cpus: u8,
    /// Replay ray counts instead of measured times as the cost of a unit.
    #[arg(long)]
    pub rays: bool,
}

/// A set of simulated tracers.
struct Devices {
    label: &'static str,
    speeds: &'static [f64],
}

/// The paper's setups (equal GPUs), then unequal ones (a fast and a slow device, as a GPU and a
/// CPU tracer would be).
const DEVICES: [Devices; 4] = [
    Devices {
        label: "2 equal",
        speeds: &[1.0, 1.0],
    },
    Devices {
        label: "3 equal",
        speeds: &[1.0, 1.0, 1.0],
    },
    Devices {
        label: "2 unequal (1 : 0.4)",
        speeds: &[1.0, 0.4],
    },
    Devices {
        label: "3 unequal (1 : 0.7 : 0.3)",
        speeds: &[1.0, 0.7, 0.3],
    },
];

/// The paper's Table 1 (idle %, Aztec scene): per scheme, 2 GPUs slow, fast, 3 GPUs slow, fast.
const PAPER: [(&str, [f64; 4]); 4] = [
    ("none", [46.4, 30.2, 45.1, 47.2]),
    ("Robin Hood", [2.1, 8.2, 4.9, 20.7]),
    ("Perfect", [2.8, 2.4, 12.2, 8.0]),
    ("Perfect Smooth", [1.4, 3.4, 2.8, 6.2]),
];

/// One replay: camera, devices, scheme, outcome.
struct Cell {
    camera: &'static str,
    devices: usize,
    report: SimReport,
    ours: bool,
}

/// Every scheme, plus Perfect Smooth at the extra α values, for `tracers` tracers.
fn schemes(
    units: usize,
    tracers: usize,
    alphas: &[f64],
    blends: &[f64],
) -> Vec<(Box<dyn Balancer>, bool)> {
    let mut out: Vec<(Box<dyn Balancer>, bool)> = Vec::new();
    for kind in SchemeKind::ALL {
        out.push((kind.build(units, tracers), !kind.from_paper()));
        if kind == SchemeKind::PerfectSmooth {
            for &a in alphas {
                out.push((Box::new(PerfectSmooth::new(units, tracers, a)), false));
            }
        }
        if kind == SchemeKind::CostModel {
            for &b in blends {
                out.push((Box::new(CostModel::with_blend(units, tracers, b)), true));
            }
        }
        if kind == SchemeKind::Interleaved {
            for &b in blends {
                out.push((Box::new(Interleaved::with_blend(units, tracers, b)), true));
            }
        }
    }
    out
}

pub fn run(args: &BalanceArgs) -> anyhow::Result<()> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    std::fs::create_dir_all(&args.data_dir)
        .with_context(|| format!("cannot create {}", args.data_dir.display()))?;
    let mut traces = Vec::new();
    for spin in SPINS {
        let path = args.data_dir.join(format!("{}.csv", spin.name));
        if args.record {
            let trace = record(&repo, spin, args.frames, args.width, args.height, args.spp)?;
            trace.write(&path)?;
            println!(
                "wrote {} ({} frames, {} units)",
                path.display(),
                trace.frames(),
                trace.units()
            );
        }
        let trace = CostTrace::read(&path).with_context(|| {
            format!(
                "no cost file {}: run `bench balance --record` first",
                path.display()
            )
        })?;
        traces.push((
            spin.name,
            if args.rays {
                trace.rays_as_cost()
            } else {
                trace
            },
        ));
    }
    let mut cells = Vec::new();
    for (camera, trace) in &traces {
        for (d, devices) in DEVICES.iter().enumerate() {
            for (mut scheme, ours) in schemes(
                trace.units(),
                devices.speeds.len(),
                &args.alphas,
                &args.blends,
            ) {
                let report = simulate(trace, devices.speeds, scheme.as_mut());
                cells.push(Cell {
                    camera,
                    devices: d,
                    report,
                    ours,
                });
            }
        }
    }
    let (_, first) = &traces[0];
    println!(
        "\n## Workload balancing (Brigade §4.3, Table 1): demo city, {}×{} px, {} units of 4 rows, \
         {} frames, cost = {}\n",
        first.width,
        first.height,
        first.units(),
        first.frames(),
        if args.rays {
            "rays per unit"
        } else {
            "measured CPU time per unit"
        }
    );
    println!(
        "{}",
        table(&cells, &[0, 1], "Equal tracers (the paper's setup)")
    );
    println!("{}", table(&cells, &[2, 3], "Unequal tracers"));
    println!("{}", paper_table());
    write_csv(args, &cells)?;
    if args.pool {
        let size = (first.width, first.height, args.spp);
        println!(
            "{}",
            super::balance_pool::run(&repo, args.pool_frames, size, &args.pool_threads)?
        );
    }
    if args.pool_gpu {
        let size = (first.width, first.height, args.spp);
        println!(
            "{}",
            super::balance_pool::run_gpu(&repo, args.pool_frames, size, args.pool_gpu_cpus)?
        );
    }
    std::fs::create_dir_all(&args.chart_dir)?;
    for (stem, devices) in [
        ("balance_fig9", [0usize, 1]),
        ("balance_fig9_unequal", [2, 3]),
    ] {
        let path = args.chart_dir.join(format!(
            "{stem}{}.png",
            if args.rays { "_rays" } else { "" }
        ));
        let panels: Vec<Panel<'_>> = devices
            .iter()
            .flat_map(|&d| SPINS.iter().map(move |s| (d, s.name)))
            .map(|(d, camera)| Panel {
                title: format!("{}, {camera} camera", DEVICES[d].label),
                reports: cells
                    .iter()
                    .filter(|c| c.devices == d && c.camera == camera)
                    .filter(|c| !c.report.scheme.contains('α') && !c.report.scheme.contains('β'))
                    .map(|c| &c.report)
                    .collect(),
            })
            .collect();
        figure(
            &path,
            "Idle share per frame (Brigade Figure 9, demo city)",
            &panels,
        )?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// The Markdown table of mean idle % (worst frame %) for two device sets × two cameras.
fn table(cells: &[Cell], devices: &[usize], title: &str) -> String {
    let mut out = format!(
        "### {title}: mean idle % over the frames (worst frame after the first, %)\n\n| scheme |"
    );
    let columns: Vec<(usize, &str)> = devices
        .iter()
        .flat_map(|&d| SPINS.iter().map(move |s| (d, s.name)))
        .collect();
    for (d, camera) in &columns {
        let _ = write!(out, " {}, {camera} |", DEVICES[*d].label);
    }
    out.push_str("\n|---|");
    out.push_str(&"---:|".repeat(columns.len()));
    out.push('\n');
    let names: Vec<(String, bool)> = cells
        .iter()
        .filter(|c| c.devices == devices[0] && c.camera == columns[0].1)
        .map(|c| (c.report.scheme.clone(), c.ours))
        .collect();
    for (name, ours) in names {
        let label = if ours {
            format!("**{name}** (ours)")
        } else {
            name.clone()
        };
        let _ = write!(out, "| {label} |");
        for (d, camera) in &columns {
            if let Some(c) = cells
                .iter()
                .find(|c| c.devices == *d && c.camera == *camera && c.report.scheme == name)
            {
                let _ = write!(
                    out,
                    " {:.1} ({:.1}) |",
                    c.report.mean_idle() * 100.0,
                    c.report.worst().1 * 100.0
                );
            }
        }
        out.push('\n');
    }
    out
}

/// The paper's Table 1 as Markdown.
fn paper_table() -> String {
    let mut out = String::from(
        "### The paper's Table 1 (idle %, Aztec scene, 128 frames)\n\n\
         | scheme | 2 GPUs, slow | 2 GPUs, fast | 3 GPUs, slow | 3 GPUs, fast |\n|---|---:|---:|---:|---:|\n",
    );
    for (name, v) in PAPER {
        let _ = writeln!(
            out,
            "| {name} | {} | {} | {} | {} |",
            v[0], v[1], v[2], v[3]
        );
    }
    out
}

fn write_csv(args: &BalanceArgs, cells: &[Cell]) -> anyhow::Result<()> {
    std::fs::create_dir_all(&args.out_dir)
        .with_context(|| format!("cannot create {}", args.out_dir.display()))?;
    let suffix = if args.rays { "_rays" } else { "" };
    let mut table = String::from(
        "camera,devices,speeds,scheme,ours,mean_idle_pct,worst_idle_pct,worst_frame\n",
    );
    let mut frames = String::from("camera,devices,scheme,frame,idle_pct,counts\n");
    for c in cells {
        let speeds: Vec<String> = c.report.speeds.iter().map(|s| s.to_string()).collect();
        let (worst_frame, worst) = c.report.worst();
        let _ = writeln!(
            table,
            "{},{},{},{},{},{:.3},{:.3},{}",
            c.camera,
            DEVICES[c.devices].label,
            speeds.join(":"),
            c.report.scheme,
            c.ours,
            c.report.mean_idle() * 100.0,
            worst * 100.0,
            worst_frame
        );
        for (i, f) in c.report.frames.iter().enumerate() {
            let counts: Vec<String> = f.counts.iter().map(|n| n.to_string()).collect();
            let _ = writeln!(
                frames,
                "{},{},{},{i},{:.3},{}",
                c.camera,
                DEVICES[c.devices].label,
                c.report.scheme,
                f.idle_share * 100.0,
                counts.join(":")
            );
        }
    }
    for (name, text) in [("table", table), ("frames", frames)] {
        let path = args.out_dir.join(format!("{name}{suffix}.csv"));
        std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
