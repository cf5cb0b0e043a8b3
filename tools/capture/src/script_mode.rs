//! `capture --script file.ron [--out-dir DIR]`: runs a capture script on the engine with a
//! progress bar over frames, writes its screenshots and `frames.csv` (one row per frame: time
//! split and commit bytes) into the output folder, and prints where the time per frame went and
//! what the engine computed over the run (the level's features, instances, BVH work, lights).
//!
//! Owns: the command-line side of a script run (overrides, progress, summary). Must not: run
//! frames itself (`candela::app::run_script` does).

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::Context;
use candela::app::{
    FrameTiming, RunOptions, Script, ScriptReport, ScriptTracer, WorkTotals, run_script,
};

use super::{CaptureArgs, TracerKind};

/// What a script run did, for printing.
#[derive(Clone, Debug)]
pub struct ScriptSummary {
    pub script: PathBuf,
    pub report: ScriptReport,
    pub csv: Option<PathBuf>,
}

/// Reads one figure of a frame.
type Column = fn(&FrameTiming) -> f64;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    if v.is_empty() { 0.0 } else { v[v.len() / 2] }
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

impl std::fmt::Display for ScriptSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let frames = &self.report.frames;
        let n = frames.len();
        writeln!(
            f,
            "{}: {n} frames on the {} tracer in {:.2} s ({:.1} ms per frame)",
            self.script.display(),
            match self.report.tracer {
                ScriptTracer::Cpu => "cpu",
                ScriptTracer::Gpu => "gpu",
            },
            self.report.wall_seconds,
            self.report.wall_seconds * 1e3 / n.max(1) as f64
        )?;
        let column = |get: fn(&FrameTiming) -> f64| frames.iter().map(get).collect::<Vec<f64>>();
        writeln!(f, "time per frame, ms      median     mean")?;
        let rows: [(&str, Column); 5] = [
            ("update (main)", |t| t.update_seconds),
            ("upkeep (main)", |t| t.upkeep_seconds),
            ("hand-off wait (main)", |t| t.handoff_seconds),
            ("apply (render)", |t| t.apply_seconds),
            ("render (render)", |t| t.render_seconds),
        ];
        for (name, get) in rows {
            let v = column(get);
            writeln!(
                f,
                "  {name:<21} {:>8.3} {:>8.3}",
                median(v.clone()) * 1e3,
                mean(&v) * 1e3
            )?;
        }
        let bytes: Vec<f64> = frames.iter().map(|t| t.commit_bytes as f64).collect();
        let steady: Vec<f64> = bytes.iter().skip(1).copied().collect();
        writeln!(
            f,
            "commit bytes per frame: first {:.0}, then median {:.0}, max {:.0}",
            bytes.first().copied().unwrap_or(0.0),
            median(steady.clone()),
            steady.iter().copied().fold(0.0, f64::max)
        )?;
        writeln!(f, "level needs: {}", self.report.needs)?;
        writeln!(
            f,
            "{}",
            WorkTotals::of(self.report.frames.iter().map(|t| &t.work))
        )?;
        for shot in &self.report.screenshots {
            for file in shot.png.iter().chain(&shot.exr) {
                writeln!(f, "wrote {} (frame {})", file.display(), shot.frame)?;
            }
        }
        if let Some(csv) = &self.csv {
            write!(f, "wrote {}", csv.display())?;
        }
        Ok(())
    }
}

/// The per-frame figures as CSV.
pub fn frames_csv(frames: &[FrameTiming]) -> String {
    let mut out = String::from(
        "frame,update_ms,upkeep_ms,handoff_ms,apply_ms,render_ms,commit_bytes,instances_written,\
         blas_refits,blas_rebuilds,tlas_builds,light_table_builds,upkeep_bvh_ms,static_instances,\
         dynamic_instances,geometry_bytes,lights,max_bounces,awake_bodies\n",
    );
    for t in frames {
        let _ = writeln!(
            out,
            "{},{:.4},{:.4},{:.4},{:.4},{:.4},{},{},{},{},{},{},{:.4},{},{},{},{},{},{}",
            t.frame,
            t.update_seconds * 1e3,
            t.upkeep_seconds * 1e3,
            t.handoff_seconds * 1e3,
            t.apply_seconds * 1e3,
            t.render_seconds * 1e3,
            t.commit_bytes,
            t.upkeep.instances_written,
            t.upkeep.blas_refits,
            t.upkeep.blas_rebuilds,
            t.upkeep.tlas_builds,
            t.upkeep.light_table_builds,
            t.upkeep.seconds * 1e3,
            t.work.static_instances,
            t.work.dynamic_instances,
            t.work.geometry_bytes,
            t.work.lights,
            t.work.max_bounces,
            t.work.awake_bodies
        );
    }
    out
}

/// Runs `args.script` as the command line does.
pub fn run_script_mode(args: &CaptureArgs) -> anyhow::Result<ScriptSummary> {
    let Some(path) = &args.script else {
        anyhow::bail!("--script is required for the script mode");
    };
    let script = Script::read(path)?;
    let desc = script.load_level()?;
    let size = match (args.width, args.height) {
        (None, None) => None,
        (w, h) => Some((
            w.unwrap_or(script.render.width),
            h.unwrap_or(script.render.height),
        )),
    };
    let options = RunOptions {
        out_dir: Some(args.out_dir.clone()),
        tracer: args.tracer.map(|t| match super::resolve(t) {
            TracerKind::Gpu => ScriptTracer::Gpu,
            TracerKind::Cpu | TracerKind::Auto => ScriptTracer::Cpu,
        }),
        size,
        spp: args.spp,
        light_sampling: args.light_sampling,
    };
    let progress = if args.quiet {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(script.frames as u64)
    };
    progress.set_style(
        indicatif::ProgressStyle::with_template(
            "{spinner} {msg} [{bar:40}] frame {pos}/{len}, {elapsed} (eta {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    progress.set_message(format!("{}", path.display()));
    let report = run_script(&script, &desc, &options, &mut |frame| {
        progress.set_position(frame as u64 + 1)
    })?;
    progress.finish_and_clear();
    std::fs::create_dir_all(&args.out_dir)
        .with_context(|| format!("cannot create {}", args.out_dir.display()))?;
    let csv = args.out_dir.join("frames.csv");
    std::fs::write(&csv, frames_csv(&report.frames))
        .with_context(|| format!("cannot write {}", csv.display()))?;
    Ok(ScriptSummary {
        script: path.clone(),
        report,
        csv: Some(csv),
    })
}
