//! The runner's core: the headless [`Engine`] and its frame loop ([`Engine::frame`], phase by
//! phase, [`Phase`]), the game-facing API ([`Game`], [`Step`], [`FrameInput`],
//! [`LevelEvent`], [`Commands`], [`ProgressEvent`]), the shell's and the editor's hook traits a
//! game may offer ([`ShellHooks`] with its plain data in `shell_hooks`, [`EditHooks`] and
//! [`EditTarget`] in `edit_target`), the fixed-step clock, the frame limiter, level
//! spawning, the wave deformer, the per-step settle of the query scene, the frame's work counts
//! and timers, the stats the overlay shows, the simulation's fingerprint
//! ([`Engine::state_hash`]), the time of day in play ([`Engine::sky_now`]) and the exposure
//! the sky calls for ([`Engine::sky_exposure_ev`]).
//!
//! One file per job: `clock`, `frame_limiter`, `work`, `phase`, `stats`, `waves`, `commands`,
//! `shell_hooks`, `edit_target`, `spawned`, `game`, `environment`, `engine`, `level`, `frame`, `step_scene`,
//! `state_hash`, `time_of_day`, `sky_exposure`. Main thread (the render thread is reached only through the commit hand-off).
//! Must not: name the shell, the editor, the window, scripts or a particular game: those are
//! the layers above it and build on it.

mod clock;
mod commands;
mod edit_target;
mod engine;
mod environment;
mod frame;
mod frame_limiter;
mod game;
mod level;
mod phase;
mod shell_hooks;
mod sky_exposure;
mod spawned;
mod state_hash;
mod stats;
mod step_scene;
mod time_of_day;
mod waves;
mod work;

pub use clock::FixedClock;
pub use commands::{Command, Commands, ProgressEvent, TimeChange};
pub use edit_target::{BuildWorld, CheckWorld, EditHooks, EditTarget};
pub use engine::{Engine, EngineError};
pub use environment::Environment;
pub use frame_limiter::FrameLimiter;
pub use game::{FrameInput, Game, LevelEvent, SetupError, Step};
pub use phase::{FrameReport, Phase, PhaseTimes};
pub use shell_hooks::{GameSummary, HudInfo, LevelEntry, LevelStart, ShellHooks, ShellInfo};
pub use spawned::{SpawnedCharacter, SpawnedLevel};
pub use stats::FrameStats;
pub use time_of_day::{TimeError, lighting_change};
pub use waves::{Waves, waves_system};
pub use work::{FrameWork, WorkTotals};
