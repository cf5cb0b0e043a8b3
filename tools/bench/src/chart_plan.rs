//! The command line of `bench chart` and the plan it implies: which scenes, panels and
//! tracers, how many samples, and where the outputs go (a full run writes `docs/`, a partial or
//! quick one `target/bench-chart/`, so that it never overwrites the published figures).
//!
//! Owns: [`ChartArgs`], [`Plan`]. Must not: render or write files.

use std::path::PathBuf;

use clap::Args;

use super::chart_methods::Panel;
use super::chart_scenes::{SceneSpec, select};

#[derive(Args, Debug)]
pub struct ChartArgs {
    /// `shared/external`.
    #[arg(long, default_value = "../shared/external")]
    pub external: PathBuf,
    /// Highest sample count of the CPU curves (a power of two) [default: 256; --quick 16].
    #[arg(long)]
    pub cpu_spp: Option<u32>,
    /// Highest sample count of the GPU curves [default: 64; --quick 4].
    #[arg(long)]
    pub gpu_spp: Option<u32>,
    /// Samples per pixel of the test scenes' self-references [default: 4096; --quick 256].
    #[arg(long)]
    pub ref_spp: Option<u32>,
    /// Skip the GPU tracer.
    #[arg(long)]
    pub no_gpu: bool,
    /// A fast smoke run for iterating: low sample counts; writes under target/bench-chart/.
    #[arg(long)]
    pub quick: bool,
    /// Only these scenes (comma-separated): cornell_box, cornell_mirror_glass,
    /// candela_cornell, script_small.
    #[arg(long, value_delimiter = ',')]
    pub scenes: Vec<String>,
    /// Only these panels (comma-separated): estimators, bounces, layouts.
    #[arg(long, value_delimiter = ',')]
    pub panels: Vec<String>,
    /// Where self-references are cached.
    #[arg(long, default_value = "target/bench-refs")]
    pub refs: PathBuf,
    /// Render self-references again even when cached (after a change to the integrators).
    #[arg(long)]
    pub refresh_refs: bool,
    /// Where the CSV and charts go [default: docs/charts; target/bench-chart for partial runs].
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// The document whose generated section is rewritten [default: docs/ACCURACY.md;
    /// target/bench-chart/ACCURACY.md for partial runs].
    #[arg(long)]
    pub doc: Option<PathBuf>,
}

/// What a `bench chart` command will do.
#[derive(Debug)]
pub struct Plan {
    pub scenes: Vec<&'static SceneSpec>,
    pub panels: Vec<Panel>,
    pub tracers: Vec<&'static str>,
    pub cpu_spp: u32,
    pub gpu_spp: u32,
    pub ref_spp: u32,
    pub out: PathBuf,
    pub doc: PathBuf,
    /// Every scene and panel at the default sample counts: the run `docs/` is made from.
    pub full: bool,
}

impl ChartArgs {
    /// The plan: defaults filled in; a partial or quick run writes under `target/bench-chart/`
    /// unless `--out` / `--doc` say otherwise, so it never overwrites the published charts.
    pub fn plan(&self) -> anyhow::Result<Plan> {
        let scenes = select(&self.scenes)?;
        let mut panels = Vec::new();
        for p in Panel::ALL {
            if self.panels.is_empty() || self.panels.iter().any(|n| n == p.key()) {
                panels.push(p);
            }
        }
        for n in &self.panels {
            if !Panel::ALL.iter().any(|p| p.key() == n) {
                anyhow::bail!("unknown panel {n:?}; known: estimators, bounces, layouts");
            }
        }
        let pick = |given: Option<u32>, full: u32, quick: u32| {
            given.unwrap_or(if self.quick { quick } else { full })
        };
        let (cpu_spp, gpu_spp, ref_spp) = (
            pick(self.cpu_spp, 256, 16),
            pick(self.gpu_spp, 64, 4),
            pick(self.ref_spp, 4096, 256),
        );
        if cpu_spp == 0 || gpu_spp == 0 || ref_spp == 0 {
            anyhow::bail!("sample counts must be at least 1");
        }
        let full = !self.quick
            && self.scenes.is_empty()
            && self.panels.is_empty()
            && !self.no_gpu
            && (cpu_spp, gpu_spp, ref_spp) == (256, 64, 4096);
        let scratch = PathBuf::from("target/bench-chart");
        let out = self.out.clone().unwrap_or_else(|| {
            if full {
                PathBuf::from("docs/charts")
            } else {
                scratch.clone()
            }
        });
        let doc = self.doc.clone().unwrap_or_else(|| {
            if full {
                PathBuf::from("docs/ACCURACY.md")
            } else {
                scratch.join("ACCURACY.md")
            }
        });
        let tracers = if self.no_gpu {
            vec!["cpu"]
        } else {
            vec!["cpu", "gpu"]
        };
        Ok(Plan {
            scenes,
            panels,
            tracers,
            cpu_spp,
            gpu_spp,
            ref_spp,
            out,
            doc,
            full,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        chart: ChartArgs,
    }

    fn plan(args: &[&str]) -> anyhow::Result<Plan> {
        let cli = Cli::try_parse_from(std::iter::once("chart").chain(args.iter().copied()))?;
        cli.chart.plan()
    }

    #[test]
    fn the_default_run_is_the_full_one_and_writes_docs() -> anyhow::Result<()> {
        let p = plan(&[])?;
        assert!(p.full);
        assert_eq!((p.cpu_spp, p.gpu_spp, p.ref_spp), (256, 64, 4096));
        assert_eq!(p.out, PathBuf::from("docs/charts"));
        assert_eq!(p.doc, PathBuf::from("docs/ACCURACY.md"));
        assert_eq!(p.panels, Panel::ALL);
        assert_eq!(p.tracers, ["cpu", "gpu"]);
        Ok(())
    }

    #[test]
    fn partial_runs_write_to_scratch_unless_told() -> anyhow::Result<()> {
        let p = plan(&["--quick"])?;
        assert!(!p.full);
        assert_eq!((p.cpu_spp, p.gpu_spp), (16, 4));
        assert_eq!(p.doc, PathBuf::from("target/bench-chart/ACCURACY.md"));
        let p = plan(&[
            "--scenes",
            "script_small,cornell_box",
            "--panels",
            "bounces",
        ])?;
        assert!(!p.full);
        let names: Vec<&str> = p.scenes.iter().map(|s| s.name).collect();
        assert_eq!(names, ["cornell_box", "script_small"]);
        assert_eq!(p.panels, [Panel::Bounces]);
        assert_eq!(p.out, PathBuf::from("target/bench-chart"));
        let p = plan(&["--quick", "--out", "x", "--cpu-spp", "8", "--no-gpu"])?;
        assert_eq!(
            (p.out, p.cpu_spp, p.tracers),
            (PathBuf::from("x"), 8, vec!["cpu"])
        );
        assert!(plan(&["--panels", "colours"]).is_err());
        assert!(plan(&["--scenes", "nowhere"]).is_err());
        assert!(plan(&["--gpu-spp", "0"]).is_err());
        Ok(())
    }
}
