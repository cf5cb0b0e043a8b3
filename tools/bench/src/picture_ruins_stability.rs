//! The still-view stability figure of `bench picture-ruins` (`--still`), as `bench picture`'s
//! "still" row (`picture_stability.rs`): the explorer stands at the spawn, nothing pressed, the
//! day flowing at the level's rate; after `--settle-frames` frames, `--pairs` consecutive frame
//! pairs are compared: the mean absolute change of the exposed sRGB picture (0–1) of the
//! displayed frames, and of references of each of those frames (a quarter of the compared
//! frames' samples, render areas off, on the same seeds every frame, so that their change is
//! the picture's — the sun moving — rather than their noise's).
//!
//! Owns: [`still`] and its table. Main thread. Must not: draw.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::sync::{Arc, Mutex};

use candela::render::RenderConfig;
use candela::scene::SkyRebuild;
use its_about_time::world::RuinsWorld;

use super::picture::progress_bar;
use super::picture_metrics::{mean_change, srgb_at};
use super::picture_ruins_run::{RuinsRun, play_ruins};
use super::picture_run::Config;
use super::picture_tracer::References;

/// One configuration, standing still.
#[derive(Clone, Debug)]
pub struct Still {
    pub config: Config,
    /// Mean frame-to-frame change of the displayed picture.
    pub displayed: f64,
    /// The same of the references of those frames.
    pub reference: f64,
    /// Samples per pixel of the references at this size.
    pub reference_spp: u32,
}

/// Measures every configuration standing still at the spawn: `settle` frames, then `pairs`
/// frame pairs; references of `spp` samples at `large` (the largest configuration's size).
pub fn still(
    world: &RuinsWorld,
    configs: &[Config],
    large: (u32, u32),
    spp: u32,
    (settle, pairs): (u64, u64),
) -> anyhow::Result<Vec<Still>> {
    let frames: BTreeSet<u64> = (settle..=settle + pairs).collect();
    let last = settle + pairs + 1;
    let bar = progress_bar(frames.len() as u64 * u64::from(large.0 * large.1) * u64::from(spp));
    bar.set_message("still view, references");
    let refs = Arc::new(Mutex::new(References {
        wanted: frames.clone(),
        spp,
        ..Default::default()
    }));
    let mut full = world.clone();
    full.level.render_areas.clear();
    let reference = RuinsRun {
        world: &full,
        replay: None,
        render: RenderConfig::cpu(large.0, large.1),
        frames: last,
        live: frames.clone(),
        cuts: BTreeSet::new(),
        keep: frames.clone(),
    };
    let reference = play_ruins(&reference, refs.clone(), bar.clone())?;
    let rendered = {
        let mut r = refs.lock().expect("references lock");
        r.spp = 2;
        r.rendered
    };
    let mut out = Vec::new();
    for config in configs {
        bar.set_message(format!("still view, {}", config.label()));
        let run = RuinsRun {
            world,
            replay: None,
            render: RenderConfig {
                denoise: config.denoise,
                sky_rebuild: SkyRebuild::Background,
                ..RenderConfig::cpu(config.width, config.height)
            },
            frames: last,
            live: (0..last).collect(),
            cuts: BTreeSet::new(),
            keep: frames.clone(),
        };
        let played = play_ruins(&run, refs.clone(), bar.clone())?;
        let refs = refs.lock().expect("references lock");
        anyhow::ensure!(
            refs.rendered == rendered && played.cameras == reference.cameras,
            "still view, {}: the camera is not the reference run's",
            config.label()
        );
        let list: Vec<u64> = frames.iter().copied().collect();
        let (mut shown, mut converged) = (Vec::new(), Vec::new());
        for pair in list.windows(2) {
            let pick = |f: u64| {
                let d = played.displayed.get(&f);
                let r = refs.done.get(&f).map(|r| r.at_width(config.width).mean());
                let ev = played.exposure_ev.get(&f).copied().unwrap_or(0.0);
                let ev_ref = reference.exposure_ev.get(&f).copied().unwrap_or(0.0);
                d.zip(r)
                    .map(|(d, r)| (srgb_at(d, ev), srgb_at(&r, ev_ref)))
                    .ok_or_else(|| anyhow::anyhow!("still view: frame {f} missing"))
            };
            let (d0, r0) = pick(pair[0])?;
            let (d1, r1) = pick(pair[1])?;
            shown.push(mean_change(&d0, &d1));
            converged.push(mean_change(&r0, &r1));
        }
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
        out.push(Still {
            config: *config,
            displayed: mean(&shown),
            reference: mean(&converged),
            reference_spp: (refs.done.values().next()).map_or(0, |r| r.at_width(config.width).spp),
        });
    }
    bar.finish_with_message("still view done");
    Ok(out)
}

/// The still-view table (Markdown).
pub fn table(rows: &[Still]) -> String {
    let mut out = String::from(
        "| view | configuration | displayed change | reference spp | reference's change |\n|---|---|---:|---:|---:|\n",
    );
    for r in rows {
        let _ = writeln!(
            out,
            "| still at the spawn | {} | {:.4} | {} | {:.4} |",
            r.config.label(),
            r.displayed,
            r.reference_spp,
            r.reference
        );
    }
    out
}
