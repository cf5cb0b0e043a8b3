//! The runner: the frame loop that drives the world, the upkeep and the render thread, headless
//! ([`Engine`]) or in a window ([`run_window`]); the fixed-step clock; input mapped to actions;
//! the fly camera; the stats overlay; capture scripts (RON) that drive the loop for a fixed
//! number of frames.

mod clock;
mod engine;
mod fly_camera;
mod frame;
mod frame_limiter;
mod game;
mod ghosting;
mod input;
mod level;
mod phase;
mod script;
mod script_bind;
mod script_check;
mod script_error;
mod script_motion;
mod script_run;
mod stats;
mod stats_overlay;
mod waves;
mod window;
mod window_app;
mod work;

pub use clock::FixedClock;
pub use engine::{Engine, EngineError, Environment};
pub use fly_camera::{FlyCamera, fly_camera_system};
pub use frame_limiter::FrameLimiter;
pub use game::{Command, Commands, FrameInput, Game, LevelEvent, SetupError, Step};
pub use ghosting::{GhostError, GhostSetup, measure_ghosting};
pub use input::{Binding, InputMap, InputMapError, InputState, KeyCode, MouseButton, actions};
pub use level::SpawnedLevel;
pub use phase::{FrameReport, Phase, PhaseTimes};
pub use script::{
    CameraKey, Interpolation, LightSwitch, Motion, MotionEntry, ObjectKey, Screenshot, Script,
    ScriptError, ScriptLevel, ScriptRender, ScriptTracer,
};
pub use script_bind::{BoundScript, matches};
pub use script_motion::{apply_motion, camera_at, camera_transform, cut_at};
pub use script_run::{FrameTiming, RunOptions, ScriptReport, ShotResult, run_script};
pub use stats::FrameStats;
pub use stats_overlay::StatsOverlay;
pub use waves::{Waves, waves_system};
pub use window::{WindowConfig, WindowEnd, WindowError, WindowReport, display_problem, run_window};
pub use work::{FrameWork, WorkTotals};

/// Action names of the fly camera.
pub mod fly_actions {
    pub use super::fly_camera::actions::*;
}
