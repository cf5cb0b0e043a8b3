//! `reflect --soak FRAMES [--seed N] [--soak-chamber ID]`: each chamber played headless for
//! `FRAMES` frames by the engine's soak over a game's levels (`candela::app::harness::soak_levels`,
//! `candela::app::soak`: the seeded monkey walks, looks,
//! jumps, carries, fires and reverts the mirror gun; every frame is checked for non-finite
//! transforms and bodies out of the world, the film every 500 frames, memory after the warm-up
//! and at the end), one chamber after another, each from its own start.
//!
//! `reflect --soak-shell FRAMES [--seed N]`: the whole game inside its shell ([`soak_shell`]:
//! the same checks, and the pause menu, settings, editor, saves and chamber changes too).
//!
//! Owns: [`soak_chambers`], [`table`], [`soak_shell`] and [`shell_table`]. Main thread. Must not: open windows or devices.

use candela::app::UserDirs;
use candela::app::harness::{Episode, ShellSoak, ShellSoakReport, soak_levels};
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

/// `reflect --soak-shell FRAMES [--seed N]`: the whole game played headless inside its shell
/// for `frames` frames (`candela::app::harness::soak_shell`): the monkey plays, and around it
/// pauses, opens the settings, the editor (select, drag, undo), saves and loads, and changes
/// chambers, with the soak's checks on every frame. The player's files go to a scratch folder
/// under the system's temporary folder, removed afterwards. `every`: mean frames of play between
/// episodes ([`SHELL_EVERY`] on the command line); `disabled`: episodes never started.
pub fn soak_shell(
    world: &ReflectWorld,
    frames: u64,
    seed: u64,
    every: u32,
    disabled: Vec<Episode>,
) -> anyhow::Result<ShellSoakReport> {
    let scratch = std::env::temp_dir().join(format!(
        "reflect-soak-shell-{}-{seed}-{frames}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&scratch);
    let dirs = UserDirs::under(&scratch, "reflect")?;
    let mut game = ReflectGame::new(world.clone(), 0);
    let environment = game.inner().environment();
    let how = ShellSoak {
        frames,
        seed,
        every,
        disabled,
        dirs,
    };
    let report = candela::app::harness::soak_shell(&mut game, environment, how);
    let _ = std::fs::remove_dir_all(&scratch);
    Ok(report?)
}

/// Mean frames of play between the menu monkey's episodes in Reflect's shell soak (10 s).
pub const SHELL_EVERY: u32 = 600;

/// The shell soak's result as Markdown (as `docs/RELIABILITY.md` shows it).
pub fn shell_table(r: &ShellSoakReport, seed: u64) -> String {
    let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
    let c = &r.counts;
    let (median, p99, max) = r.frame_times();
    let checked: Vec<String> = r.checked.iter().map(|(s, n)| format!("{s} {n}")).collect();
    format!(
        "| frames | seed | film checks | memory after warm-up → end | frame ms median / p99 / max |\n\
         |---:|---:|---:|---|---|\n\
         | {} | {seed} | {} | {:.1} MiB → {:.1} MiB | {median:.2} / {p99:.2} / {max:.2} |\n\n\
         | pause | resume | settings opened / changed / closed | editor opened / closed | select | drag | undo | save | load | chamber changed |\n\
         |---:|---:|---|---|---:|---:|---:|---:|---:|---:|\n\
         | {} | {} | {} / {} / {} | {} / {} | {} | {} | {} | {} | {} | {} |\n\n\
         Frames checked per screen: {}.\n",
        r.soak.frames,
        r.soak.film_checks,
        mib(r.soak.rss_warm),
        mib(r.soak.rss_end),
        c.paused,
        c.resumed,
        c.settings_opened,
        c.settings_changed,
        c.settings_closed,
        c.editor_opened,
        c.editor_closed,
        c.selected,
        c.dragged,
        c.undone,
        c.saved,
        c.loaded,
        c.levels_changed,
        checked.join(", ")
    )
}
