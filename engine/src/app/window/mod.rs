//! The window runner: a winit 0.30 window driving the same `Engine::frame` loop as headless runs, with the stats overlay, the shell's screens and the editor
//! (F1); the render thread presents every frame.
//!
//! One file per job: `config` (what a run is given and what it gives back: [`WindowConfig`],
//! [`WindowReport`], [`WindowEnd`], [`WindowError`]), `run` (the entry points [`run_window`]
//! and [`run_game`]), `app` (the per-run work), `running` (the per-run state), `events`
//! (winit events), `edit` (the editor's hook), `stats_overlay`. Main thread (or any thread on
//! X11). Must not: render or present (the render thread does), or hold game rules.

mod app;
mod config;
mod edit;
mod events;
mod run;
mod running;
mod stats_overlay;

pub use config::{WindowConfig, WindowEnd, WindowError, WindowReport};
pub use run::{run_game, run_window};
pub use stats_overlay::stats_window;
