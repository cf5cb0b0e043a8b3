//! The report of `bench picture`: the Markdown tables (per configuration, per chamber, the
//! stability table) and `picture.csv`, one row per compared frame.
//!
//! Owns: formatting only. Must not: measure or draw.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::picture::{Compared, Outcome};
use super::picture_run::{Config, FRAME_SECONDS};

/// Mean of the compared frames of `config` (all chambers): relative MSE, sRGB RMSE (RMS over
/// frames), reference noise of each.
pub fn summary(outcome: &Outcome, config: &Config) -> [f64; 4] {
    let rows: Vec<&Compared> = outcome
        .compared
        .iter()
        .filter(|c| c.config == *config)
        .collect();
    let n = rows.len().max(1) as f64;
    let mean = |f: fn(&Compared) -> f64| rows.iter().map(|c| f(c)).sum::<f64>() / n;
    [
        mean(|c| c.rel_mse),
        mean(|c| c.srgb_rmse.powi(2)).sqrt(),
        mean(|c| c.reference_rel_mse),
        mean(|c| c.reference_srgb_rmse.powi(2)).sqrt(),
    ]
}

/// The Markdown tables.
pub fn tables(outcome: &Outcome) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "| configuration | frame ms (trace + denoise, median) | relative MSE | sRGB RMSE | reference spp | reference's own: rel. MSE | sRGB RMSE |\n|---|---:|---:|---:|---:|---:|---:|"
    );
    for (config, ms) in outcome.configs.iter().zip(&outcome.frame_ms) {
        let [rel, rgb, ref_rel, ref_rgb] = summary(outcome, config);
        let spp = outcome
            .compared
            .iter()
            .find(|c| c.config == *config)
            .map_or(0, |c| c.reference_spp);
        let _ = writeln!(
            out,
            "| {} | {ms:.1} | {rel:.4} | {rgb:.4} | {spp} | {ref_rel:.5} | {ref_rgb:.4} |",
            config.label()
        );
    }
    let _ = writeln!(
        out,
        "\nPer chamber, relative MSE / sRGB RMSE (mean over its compared frames):\n"
    );
    let chambers: BTreeSet<&str> = outcome
        .compared
        .iter()
        .map(|c| c.chamber.as_str())
        .collect();
    out += "| chamber | frames |";
    for c in &outcome.configs {
        let _ = write!(out, " {} |", c.label());
    }
    out += "\n|---|---|";
    out += &"---:|".repeat(outcome.configs.len());
    out += "\n";
    for ch in chambers {
        let frames: BTreeSet<u64> = outcome
            .compared
            .iter()
            .filter(|c| c.chamber == ch)
            .map(|c| c.frame)
            .collect();
        let list: Vec<String> = frames.iter().map(u64::to_string).collect();
        let _ = write!(out, "| {ch} | {} |", list.join(", "));
        for config in &outcome.configs {
            let rows: Vec<&Compared> = outcome
                .compared
                .iter()
                .filter(|c| c.chamber == ch && c.config == *config)
                .collect();
            let n = rows.len().max(1) as f64;
            let rel = rows.iter().map(|c| c.rel_mse).sum::<f64>() / n;
            let rgb = (rows.iter().map(|c| c.srgb_rmse.powi(2)).sum::<f64>() / n).sqrt();
            let _ = write!(out, " {rel:.4} / {rgb:.4} |");
        }
        out += "\n";
    }
    out += "\n";
    out += &super::picture_stability::table(&outcome.stability);
    let _ = writeln!(
        out,
        "\nFrames of {:.1} ms game time (two fixed steps); compared at the displayed film's size (the traced size, or the TAAU-upscaled one).",
        FRAME_SECONDS * 1e3
    );
    out
}

/// `picture.csv`: one row per compared frame.
pub fn write_csv(dir: &Path, outcome: &Outcome) -> anyhow::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    let mut csv = String::from(
        "chamber,width,height,denoise,frame,rel_mse,srgb_rmse,reference_spp,reference_rel_mse,reference_srgb_rmse,upscale\n",
    );
    for c in &outcome.compared {
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{},{},{},{}",
            c.chamber,
            c.config.width,
            c.config.height,
            c.config.denoise,
            c.frame,
            c.rel_mse,
            c.srgb_rmse,
            c.reference_spp,
            c.reference_rel_mse,
            c.reference_srgb_rmse,
            c.config.upscale
        );
    }
    let path = dir.join("picture.csv");
    std::fs::write(&path, csv)?;
    Ok(path)
}
