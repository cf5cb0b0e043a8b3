//! `reflect --soak FRAMES [--seed N] [--soak-chamber ID]`: each chamber played headless for
//! `FRAMES` frames by the engine's soak over a game's levels (`candela::app::harness::soak_levels`,
//! `candela::app::soak`: the seeded monkey walks, looks,
//! jumps, carries, fires and reverts the mirror gun; every frame is checked for non-finite
//! transforms and bodies out of the world, the film every 500 frames, memory after the warm-up
//! and at the end), one chamber after another, each from its own start.
//!
//! Owns: [`soak_chambers`] and [`table`]. Main thread. Must not: open windows or devices.

use candela::app::harness::soak_levels;
use candela::app::soak::SoakReport;

use crate::game::ReflectGame;
use crate::world::ReflectWorld;

/// What one chamber's soak saw.
#[derive(Clone, Debug)]
pub struct ChamberSoak {
    /// The chamber's id (`chamber_1` …).
    pub id: String,
    /// The engine's checks and memory.
    pub report: SoakReport,
    /// Mirrors the monkey's mirror gun made.
    pub mirrors: u32,
    /// Times a laser sent the monkey back to the checkpoint.
    pub sent_back: u32,
    /// Game events (doors, plates, receivers, chambers finished) during the soak.
    pub events: usize,
}

/// Soaks the chambers `chambers` (indices into `world.chambers`) in order; what each soak saw,
/// or the first failure naming the chamber.
pub fn soak_chambers(
    world: &ReflectWorld,
    chambers: &[usize],
    frames: u64,
    seed: u64,
) -> anyhow::Result<Vec<ChamberSoak>> {
    let soaks = soak_levels(world, chambers, frames, seed, |game: &ReflectGame| {
        (game.gun().made, game.sent_back(), game.log().len())
    })?;
    Ok(soaks
        .into_iter()
        .map(|s| ChamberSoak {
            id: s.id,
            report: s.report,
            mirrors: s.note.0,
            sent_back: s.note.1,
            events: s.note.2,
        })
        .collect())
}

/// The soak's results as a Markdown table (as `docs/RELIABILITY.md` shows them).
pub fn table(results: &[ChamberSoak], seed: u64) -> String {
    let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
    let mut s = String::from(
        "| chamber | frames | seed | film checks | mirrors made | sent back | game events \
         | memory after warm-up → end |\n|---|---:|---:|---:|---:|---:|---:|---|\n",
    );
    for c in results {
        let r = &c.report;
        s.push_str(&format!(
            "| {} | {} | {seed} | {} | {} | {} | {} | {:.1} MiB → {:.1} MiB |\n",
            c.id,
            r.frames,
            r.film_checks,
            c.mirrors,
            c.sent_back,
            c.events,
            mib(r.rss_warm),
            mib(r.rss_end)
        ));
    }
    s
}
