//! The report of `bench picture-ruins`: one Markdown row per area (puzzle) and configuration,
//! the figures averaged over its compared frames, and `picture_ruins.csv`, one row per
//! compared frame.
//!
//! Owns: formatting only. Must not: measure.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::picture_ruins::{RuinsCompared, RuinsOutcome};

/// "14:05" for 14.08 hours, "-" when unknown.
fn clock(hours: f64) -> String {
    if hours.is_finite() {
        its_about_time::game::day::clock_label(hours)
    } else {
        "-".into()
    }
}

/// The Markdown table.
pub fn tables(outcome: &RuinsOutcome) -> String {
    let mut out = String::from(
        "| area (replay) | frames | local time | configuration | frame ms (trace + denoise, median) | relative MSE | sRGB RMSE | reference spp | reference's own: rel. MSE | sRGB RMSE |\n|---|---|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut puzzles: Vec<&str> = Vec::new();
    for c in &outcome.compared {
        if !puzzles.contains(&c.puzzle.as_str()) {
            puzzles.push(&c.puzzle);
        }
    }
    for puzzle in puzzles {
        for (k, config) in outcome.configs.iter().enumerate() {
            let rows: Vec<&RuinsCompared> = (outcome.compared.iter())
                .filter(|c| c.puzzle == puzzle && c.config == *config)
                .collect();
            let n = rows.len().max(1) as f64;
            let mean = |f: fn(&RuinsCompared) -> f64| rows.iter().map(|c| f(c)).sum::<f64>() / n;
            let frames: Vec<String> = rows.iter().map(|c| c.frame.to_string()).collect();
            let times: Vec<String> = rows.iter().map(|c| clock(c.local_hours)).collect();
            let ms = (outcome.frame_ms)
                .get(&(puzzle.to_string(), k))
                .copied()
                .unwrap_or(f64::NAN);
            let _ = writeln!(
                out,
                "| {puzzle} | {} | {} | {} | {ms:.1} | {:.4} | {:.4} | {} | {:.5} | {:.4} |",
                frames.join(", "),
                times.join(", "),
                config.label(),
                mean(|c| c.rel_mse),
                mean(|c| c.srgb_rmse.powi(2)).sqrt(),
                rows.first().map_or(0, |c| c.reference_spp),
                mean(|c| c.reference_rel_mse),
                mean(|c| c.reference_srgb_rmse.powi(2)).sqrt(),
            );
        }
    }
    if !outcome.still.is_empty() {
        out += "\n";
        out += &super::picture_ruins_stability::table(&outcome.still);
    }
    out
}

/// `picture_ruins.csv`: one row per compared frame.
pub fn write_csv(dir: &Path, outcome: &RuinsOutcome) -> anyhow::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    let mut csv = String::from(
        "puzzle,width,height,denoise,frame,local_hours,exposure_ev,rel_mse,srgb_rmse,reference_spp,reference_rel_mse,reference_srgb_rmse\n",
    );
    for c in &outcome.compared {
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{:.3},{:.2},{},{},{},{},{}",
            c.puzzle,
            c.config.width,
            c.config.height,
            c.config.denoise,
            c.frame,
            c.local_hours,
            c.exposure_ev,
            c.rel_mse,
            c.srgb_rmse,
            c.reference_spp,
            c.reference_rel_mse,
            c.reference_srgb_rmse,
        );
    }
    let path = dir.join("picture_ruins.csv");
    std::fs::write(&path, csv)?;
    Ok(path)
}
