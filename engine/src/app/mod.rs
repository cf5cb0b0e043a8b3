//! The game platform over the engine: the runner that drives the world, the upkeep and the
//! render thread, headless ([`Engine`]) or in a window
//! ([`run_window`]), phase by phase ([`Phase`]); the
//! game-facing API ([`Game`]); and the pieces games are built from.
//!
//! The sub-modules form layers, like the crate's top-level modules: each uses only the ones
//! declared before it here (`engine/tests/engine/structure_layers.rs` checks every
//! `crate::app::<sub>` path and every `super::` chain that climbs into `app`):
//!
//! ```text
//! input → persist → replay → runner → script → play → edit → shell → window → harness
//! ```
//! - `input`: devices, bindings maps, named actions, per-step action frames, gamepads.
//! - `persist`: the player's folders, settings with their rebinding, progress saves.
//! - `replay`: recording and replaying each step's input, the soak's monkey, `StepInput`.
//! - `runner`: the `Engine`, its frame loop and phases, the `Game` trait, clock, spawning.
//! - `script`: capture scripts (RON) run for a fixed number of frames.
//! - `play`: what consumes actions, next to `crate::player`: `player_input`, the
//!   first-person game, the fly camera, the bots' steering.
//! - `edit`: the editor in a running game (F1).
//! - `shell`: the screens around a game (title, HUD, pause, settings, ending).
//! - `window`: the winit window runner, the stats overlay.
//! - `harness`: the game harness, configured by a game (`HarnessGame`): headless replay,
//!   bench, soak, converged captures; and the ghosting measurement.
//!
//! Everything games, tools and tests use is re-exported here, so `candela::app::X` paths do
//! not depend on the folders.

// Devices, input maps, named actions, action frames, gamepads.
mod input;

// The player's folders: settings with their rebinding, progress saves, stored RON.
mod persist;

// Each step's input recorded and replayed; the monkey; `StepInput`.
mod replay;

// The `Engine`, its frame loop and phases, the `Game` trait, clock, level spawning.
mod runner;

// Capture scripts (RON) run for a fixed number of frames.
mod script;

// What consumes actions: player input, the first-person game, the fly camera, steering.
mod play;

// The editor in a running game (F1).
pub mod edit;

// The screens around a game: title, HUD, pause, settings, ending.
pub mod shell;

// The winit window runner and the stats overlay.
mod window;

// The game harness (headless replay, bench, soak, captures, configured by a game) and the
// ghosting measurement.
pub mod harness;

// Atomic writes live in `assets` (the editor, below `app`, saves levels with them too).
pub use crate::assets::atomic_file::{AtomicFileError, write_atomic};

pub use harness::soak;
pub use harness::{GhostError, GhostSetup, measure_ghosting};
pub use input::fly_actions;
pub use input::{
    AXIS_ONE, ActionDef, ActionFrame, ActionId, ActionKind, ActionSet, ActionSetError,
    DEFAULT_DEAD_ZONE, Gamepads, MAX_ACTIONS, MOTION_PER_COUNT, PadAxis, PadButton,
    apply_dead_zone, game_actions, pad_button, quantise_axis, quantise_motion,
};
pub use input::{Binding, InputMap, InputMapError, InputState, KeyCode, MouseButton, actions};
pub use persist::{
    BindingProblem, Bindings, BindingsError, LoadWarning, Loaded, Progress, Settings, StoreError,
    UserDirs, UserDirsError, load_or_default, parse_checked, save_ron,
};
pub use play::steer;
pub use play::{
    CARRY_PROMPT, FIRST_PERSON_GAME, FirstPersonGame, FlyCamera, Happened, MESSAGE_STEPS,
    MOUSE_RADIANS_PER_COUNT, PAD_RADIANS_PER_SECOND, THIRD_PERSON_GAME, TOO_FAR, ThirdPersonGame,
    fly_camera_system, player_input,
};
pub use replay::{
    FORMAT_VERSION, Monkey, OLDEST_VERSION, RecordedAction, RecordedLook, Recorder, Recording,
    RecordingHeader, Replay, ReplayError, ReplayTarget, Run, StepInput, fnv1a64, level_hash,
};
pub use runner::{
    Command, Commands, Engine, EngineError, Environment, FixedClock, FrameInput, FrameReport,
    FrameStats, FrameWork, Game, LevelEvent, Phase, PhaseTimes, SetupError, SpawnedCharacter,
    SpawnedLevel, Step, TimeChange, TimeError, Waves, WorkTotals, lighting_change, waves_system,
};
pub use script::{
    BoundScript, CameraKey, FrameTiming, Interpolation, LightSwitch, Motion, MotionEntry,
    ObjectKey, RunOptions, Screenshot, Script, ScriptError, ScriptLevel, ScriptRender,
    ScriptReport, ScriptTracer, ShotResult, TimeKey, camera_at, matches, run_script,
};
pub use window::{
    FRAME_BARS, FrameTime, ProfileFrame, ProfileRecorder, ProfilerState, ProfilerView, ScopeBar,
    ThreadScopes, WindowConfig, WindowEnd, WindowError, WindowReport, profiler_window, run_game,
    run_window, stats_window,
};
