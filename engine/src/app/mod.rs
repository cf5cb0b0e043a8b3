//! The runner: the frame loop that drives the world, the upkeep and the render thread, headless
//! ([`Engine`]) or in a window ([`run_window`]), phase by phase ([`Phase`]); the game-facing API
//! ([`Game`]); the fixed-step clock; input mapped to actions;
//! the fly camera; the stats overlay; capture scripts (RON) that drive the loop for a fixed
//! number of frames. The game platform's pieces: named game actions and the player's
//! bindings, gamepads, per-step action frames with recording and replay, settings and
//! progress saves in the user's folders, written atomically; the shell around a game
//! (`shell`: title, HUD, pause, settings, ending; [`run_game`]).

mod action_frame;
mod action_set;
mod bindings;
mod clock;
pub mod edit;
mod engine;
mod first_person_game;
mod fly_camera;
mod frame;
mod frame_limiter;
mod game;
mod gamepad;
mod ghosting;
mod input;
mod level;
mod monkey;
mod pad;
mod phase;
mod player_input;
mod replay;
mod replay_error;
mod replay_format;
mod saves;
mod script;
mod script_bind;
mod script_check;
mod script_error;
mod script_motion;
mod script_run;
mod settings;
pub mod shell;
pub mod soak;
mod state_hash;
mod stats;
mod stats_overlay;
pub mod steer;
mod step_input;
mod step_scene;
mod stored;
mod user_dirs;
mod waves;
mod window;
mod window_app;
mod window_edit;
mod window_events;
mod window_running;
mod work;

// Atomic writes live in `assets` (the editor, below `app`, saves levels with them too).
use crate::assets::atomic_file;

pub use action_frame::{AXIS_ONE, ActionFrame, MOTION_PER_COUNT, quantise_axis, quantise_motion};
pub use action_set::{
    ActionDef, ActionId, ActionKind, ActionSet, ActionSetError, MAX_ACTIONS, game_actions,
};
pub use atomic_file::{AtomicFileError, keep_aside, write_atomic};
pub use bindings::{BindingProblem, Bindings, BindingsError};
pub use clock::FixedClock;
pub use engine::{Engine, EngineError, Environment};
pub use first_person_game::{
    CARRY_PROMPT, FIRST_PERSON_GAME, FirstPersonGame, Happened, MESSAGE_STEPS, TOO_FAR,
};
pub use fly_camera::{FlyCamera, fly_camera_system};
pub use frame_limiter::FrameLimiter;
pub use game::{Command, Commands, FrameInput, Game, LevelEvent, SetupError, Step};
pub use gamepad::{DEFAULT_DEAD_ZONE, Gamepads, apply_dead_zone, pad_button};
pub use ghosting::{GhostError, GhostSetup, measure_ghosting};
pub use input::{Binding, InputMap, InputMapError, InputState, KeyCode, MouseButton, actions};
pub use level::{SpawnedCharacter, SpawnedLevel};
pub use monkey::Monkey;
pub use pad::{PadAxis, PadButton};
pub use phase::{FrameReport, Phase, PhaseTimes};
pub use player_input::{MOUSE_RADIANS_PER_COUNT, PAD_RADIANS_PER_SECOND, player_input};
pub use replay::{Recorder, Replay, ReplayTarget};
pub use replay_error::ReplayError;
pub use replay_format::{
    FORMAT_VERSION, OLDEST_VERSION, RecordedAction, RecordedLook, Recording, RecordingHeader, Run,
    fnv1a64, level_hash,
};
pub use saves::Progress;
pub use script::{
    CameraKey, Interpolation, LightSwitch, Motion, MotionEntry, ObjectKey, Screenshot, Script,
    ScriptError, ScriptLevel, ScriptRender, ScriptTracer,
};
pub use script_bind::{BoundScript, matches};
pub use script_motion::{apply_motion, camera_at, camera_transform, cut_at};
pub use script_run::{FrameTiming, RunOptions, ScriptReport, ShotResult, run_script};
pub use settings::Settings;
pub use stats::FrameStats;
pub use stats_overlay::StatsOverlay;
pub use step_input::StepInput;
pub use stored::{
    LoadWarning, Loaded, StoreError, describe_ron_error, load_or_default, parse_checked, save_ron,
};
pub use user_dirs::{UserDirs, UserDirsError};
pub use waves::{Waves, waves_system};
pub use window::{
    WindowConfig, WindowEnd, WindowError, WindowReport, display_problem, run_game, run_window,
};
pub use work::{FrameWork, WorkTotals};

/// Action names of the fly camera.
pub mod fly_actions {
    pub use super::fly_camera::actions::*;
}
