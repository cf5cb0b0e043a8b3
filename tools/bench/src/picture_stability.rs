//! The temporal-stability figures of `bench picture`: how much the displayed picture changes
//! from one frame to the next, against how much a converged picture of the same views changes.
//! The player stands at the stability chamber's own camera (`--stability-chamber`), nothing
//! pressed, or turning right at a constant mouse rate (`--turn-counts`); after
//! `--settle-frames` frames, `--pairs` consecutive frame pairs are compared: the mean absolute
//! change of the tonemapped sRGB picture (0–1) of the displayed frames, and of references of
//! each of those frames (a quarter of the samples of `bench picture`'s references, on the same
//! seeds for every frame, so that their change is the picture's rather than their noise's). Whatever the displayed picture changes beyond the
//! reference's change is shimmer, noise and lag.
//!
//! Owns: [`stability`] and its table. Main thread. Must not: draw.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::sync::{Arc, Mutex};

use reflect::world::ReflectWorld;

use super::picture::{PictureArgs, progress_bar, reference_plan, run_order};
use super::picture_metrics::{mean_change, srgb};
use super::picture_run::{Config, Drive, play};
use super::picture_tracer::References;

/// One configuration on one drive.
#[derive(Clone, Debug)]
pub struct Stability {
    /// "still" or "turn".
    pub drive: &'static str,
    pub config: Config,
    /// Mean frame-to-frame change of the displayed picture.
    pub displayed: f64,
    /// The same of the references of those frames.
    pub reference: f64,
    /// Samples per pixel of the references at this size.
    pub reference_spp: u32,
    /// How far the view turned per frame, degrees (from the references' cameras).
    pub degrees_per_frame: f64,
}

/// Measures every configuration still and turning.
pub fn stability(
    args: &PictureArgs,
    world: &ReflectWorld,
    configs: &[Config],
) -> anyhow::Result<Vec<Stability>> {
    let chamber = world
        .chamber_index(&args.stability_chamber)
        .ok_or_else(|| anyhow::anyhow!("no chamber {:?}", args.stability_chamber))?;
    let frames: BTreeSet<u64> = (args.settle_frames..=args.settle_frames + args.pairs).collect();
    let (spp, largest) = reference_plan(args, configs);
    let spp = (spp / 4).max(16);
    let bar =
        progress_bar(2 * frames.len() as u64 * u64::from(largest.0 * largest.1) * u64::from(spp));
    let mut out = Vec::new();
    for (name, drive) in [
        ("still", Drive::Still),
        ("turn", Drive::Turn(args.turn_counts)),
    ] {
        // One set of references per view, rendered by the first (largest) run.
        let refs = Arc::new(Mutex::new(References {
            wanted: frames.clone(),
            spp,
            ..Default::default()
        }));
        for k in run_order(configs) {
            let config = &configs[k];
            bar.set_message(format!("{name}, {}", config.label()));
            let last = frames.last().copied().unwrap_or(0) + 1;
            let played = play(
                world,
                chamber,
                drive,
                *config,
                last,
                &frames,
                refs.clone(),
                bar.clone(),
            )?;
            let refs = refs.lock().expect("references lock");
            let (mut shown, mut reference, mut degrees) = (Vec::new(), Vec::new(), Vec::new());
            let list: Vec<u64> = frames.iter().copied().collect();
            for pair in list.windows(2) {
                let pick = |f: u64| {
                    let d = played.displayed.get(&f);
                    let r = refs.done.get(&f);
                    d.zip(r)
                        .ok_or_else(|| anyhow::anyhow!("{name}: frame {f} missing"))
                };
                let (d0, r0) = pick(pair[0])?;
                let (d1, r1) = pick(pair[1])?;
                let (r0, r1) = (r0.at_width(config.width), r1.at_width(config.width));
                shown.push(mean_change(&srgb(d0), &srgb(d1)));
                if let Some(dir) = &args.dump_dir {
                    let tag = format!("{name}_{}_{}", config.label(), pair[0]);
                    dump_change(dir, &tag, d0, d1, config.width)?;
                }
                reference.push(mean_change(&srgb(&r0.mean()), &srgb(&r1.mean())));
                let forward = |c: &[f32; 12]| glam::Vec3::new(c[9], c[10], c[11]).normalize();
                let cos = forward(&r0.camera)
                    .dot(forward(&r1.camera))
                    .clamp(-1.0, 1.0);
                degrees.push(f64::from(cos.acos().to_degrees()));
            }
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
            out.push(Stability {
                drive: name,
                config: *config,
                reference_spp: refs
                    .done
                    .values()
                    .next()
                    .map_or(0, |r| r.at_width(config.width).spp),
                displayed: mean(&shown),
                reference: mean(&reference),
                degrees_per_frame: mean(&degrees),
            });
        }
    }
    bar.finish_with_message("stability done");
    let index = |c: &Config| configs.iter().position(|k| k == c);
    out.sort_by_key(|s| (s.drive != "still", index(&s.config)));
    Ok(out)
}

/// The stability table (Markdown).
pub fn table(rows: &[Stability]) -> String {
    let mut out = String::from(
        "| view | configuration | turn, °/frame | displayed change | reference spp | reference's change | displayed / reference |\n|---|---|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let _ = writeln!(
            out,
            "| {} | {} | {:.2} | {:.4} | {} | {:.4} | {:.1}× |",
            r.drive,
            r.config.label(),
            r.degrees_per_frame,
            r.displayed,
            r.reference_spp,
            r.reference,
            r.displayed / r.reference
        );
    }
    out
}

/// Writes the displayed frame `d0` and the map of its change to `d1` (the absolute sRGB change
/// summed over the channels, ×4, as grey) as zoomed PNGs named after `tag`.
fn dump_change(
    dir: &std::path::Path,
    tag: &str,
    d0: &[glam::Vec3],
    d1: &[glam::Vec3],
    width: u32,
) -> anyhow::Result<()> {
    use super::picture_outliers::dump;
    let change: Vec<glam::Vec3> = srgb(d0)
        .iter()
        .zip(srgb(d1))
        .map(|(a, b)| glam::Vec3::splat((0..3).map(|c| (a[c] - b[c]).abs()).sum::<f32>() * 4.0))
        .collect();
    dump(dir, &format!("{tag}_change"), &change, width)?;
    dump(dir, &format!("{tag}_shown"), d0, width)?;
    Ok(())
}
