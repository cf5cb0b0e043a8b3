//! The runner: the frame loop that drives the world, the upkeep and the render thread, headless
//! or (later) in a window, the fixed-step clock, and capture scripts (RON) that drive it for a
//! fixed number of frames.

mod clock;
mod engine;
mod level;
mod script;
mod script_bind;
mod script_check;
mod script_error;
mod script_motion;
mod script_run;
mod waves;

pub use clock::FixedClock;
pub use engine::{Engine, EngineError, Environment, FrameReport};
pub use level::SpawnedLevel;
pub use script::{
    CameraKey, Interpolation, LightSwitch, Motion, MotionEntry, ObjectKey, Screenshot, Script,
    ScriptError, ScriptLevel, ScriptRender, ScriptTracer,
};
pub use script_bind::{BoundScript, matches};
pub use script_motion::{apply_motion, camera_at, camera_transform, cut_at};
pub use script_run::{FrameTiming, RunOptions, ScriptReport, ShotResult, run_script};
pub use waves::{Waves, waves_system};
