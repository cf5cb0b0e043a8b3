//! The window runner: a winit 0.30 window driving the same `Engine::frame` loop as headless runs, with the stats overlay, the shell's screens and the editor
//! (F1); the render thread presents every frame.
//!
//! One file per job: `config` (what a run is given and what it gives back: [`WindowConfig`],
//! [`WindowReport`], [`WindowEnd`], [`WindowError`]), `run` (the entry points [`run_window`]
//! and [`run_game`]), `app` (the per-run work), `running` (the per-run state), `events`
//! (winit events), `edit` (the editor's hook), `stats_overlay`, `profiler_view` (F5) over
//! `profile_frames` (puffin's frames as nested bars). Main thread (or any thread on
//! X11). Must not: render or present (the render thread does), or hold game rules.

mod app;
mod config;
mod edit;
mod events;
mod profile_frames;
mod profiler_view;
mod run;
mod running;
mod stats_overlay;

pub use config::{WindowConfig, WindowEnd, WindowError, WindowReport};
pub use profile_frames::{FrameTime, ProfileFrame, ProfileRecorder, ScopeBar, ThreadScopes};
pub use profiler_view::{FRAME_BARS, ProfilerState, ProfilerView, profiler_window};
pub use run::{run_game, run_window};
pub use stats_overlay::stats_window;
