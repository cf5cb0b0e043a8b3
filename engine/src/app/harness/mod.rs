//! The game harness: every headless mode a game binary offers, configured by the game
//! ([`HarnessGame`]: its levels, a fresh game for one, its recordings) so that Reflect, the
//! playground and the next game run the same loops — a recording replayed headless for the
//! game's one-line summary and exit code ([`play_replay`]), a set number of fixed steps
//! several a frame, with or without a recording ([`run_fixed_steps`]), timed in real time
//! ([`bench_replay`]), the soak over the game's levels ([`soak_levels`], over `soak`: any game
//! played by the seeded monkey, watched for what must never happen) and inside its shell
//! ([`soak_shell`]), converged captures
//! ([`capture_converged`]), the windowed screenshot runs' cues ([`play_shots`],
//! [`tour_shots`]), play in a window inside the shell ([`play_windowed`]); [`FirstPersonLevel`], the configuration of one level played in
//! first person (the playground's); and the ghosting measurement ([`measure_ghosting`]: a converging
//! policy's error on a fast-moving object and its trail).
//!
//! One file per job: `config` (the trait and the errors), `replay_run` (and the start every headless
//! mode shares), `fixed_steps`, `bench`, `soak`,
//! `soak_levels`, `soak_shell` (the soak inside the game's shell: menus, settings, the editor,
//! saves, level changes, driven by `menu_monkey`, its report `soak_shell_report`, the editor's gestures
//! `soak_gestures`), `capture`, `shots` (the screenshot runs' cues), `windowed`, `first_person`, `ghosting`. Main thread (the engine's render thread renders).
//! Must not: change the game, its level or any policy (they drive and measure), or name a
//! particular game (its summaries and tables are the game's).

mod bench;
mod capture;
mod config;
mod first_person;
mod fixed_steps;
mod ghosting;
mod menu_monkey;
mod replay_run;
mod shots;
pub mod soak;
mod soak_gestures;
mod soak_levels;
mod soak_shell;
mod soak_shell_report;
mod windowed;

pub use bench::{BenchFigures, bench_replay, median, table_head, table_row};
pub use capture::{SETTLE_FRAMES, capture_converged};
pub use config::{HarnessError, HarnessGame};
pub use first_person::FirstPersonLevel;
pub use fixed_steps::{FixedSteps, StepsEnd, run_fixed_steps};
pub use ghosting::{GhostError, GhostSetup, measure_ghosting};
pub use menu_monkey::{Episode, MenuMonkey, MenuStep};
pub use replay_run::{ReplayEnd, ReplayPace, play_replay, play_replay_watching};
pub use shots::{play_shots, start_cue, tour_shots};
pub use soak_levels::{LevelSoak, soak_levels};
pub use soak_shell::{ShellSoak, soak_shell};
pub use soak_shell_report::{ActionCounts, ShellSoakReport};
pub use windowed::{WindowedPlay, play_windowed, windowed_render};
