//! Capture scripts (RON) that drive the engine for a fixed number of frames: the script's
//! description ([`Script`]: level, tracer, render settings, camera and object motion, light
//! switches, screenshots) and its [`ScriptError`]s, binding it to a level ([`BoundScript`]),
//! checking it, the motion it describes ([`motion::apply_motion`], [`camera_at`]) and running it
//! ([`run_script`], a [`ScriptReport`]).
//!
//! One file per job: `error`, `desc`, `check`, `bind`, `motion`, `run`. Main thread (the
//! engine's render thread renders). Must not: open a window or read input (a script is the
//! whole input), or know a particular game.

mod bind;
mod check;
mod desc;
mod error;
mod motion;
mod run;

pub use bind::{BoundScript, matches};
pub use desc::{
    CameraKey, Interpolation, LightSwitch, Motion, MotionEntry, ObjectKey, Screenshot, Script,
    ScriptError, ScriptLevel, ScriptRender, ScriptTracer, TimeKey,
};
pub use motion::camera_at;
pub use run::{FrameTiming, RunOptions, ScriptReport, ShotResult, run_script};
