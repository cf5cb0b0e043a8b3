//! # Candela
//!
//! A game engine whose only renderer is a real-time path tracer (after Bikker & van Schijndel,
//! "The Brigade Renderer", 2013): the game updates the world while a render thread
//! path-traces the previous frame, and scene changes reach it only through a sealed commit.
//!
//! ## Writing a game
//!
//! A game is a type that implements [`Game`]: [`Game::setup`] spawns its level into the
//! [`Engine`] (see [`level::load_level`] and [`Engine::spawn_level`]), [`Game::fixed_step`]
//! runs its rules at 60 Hz on a [`Step`] (the world, ray queries, physics, the step's
//! replayable [`ActionFrame`], [`Commands`]), [`Game::level_event`] hears the level's rules
//! fire ([`LevelEvent`]), and [`Game::frame`] moves cameras and menus once a frame
//! ([`FrameInput`]). The menus around a game ask it for [`ShellHooks`], the editor (F1) for
//! [`EditHooks`]. [`FirstPersonGame`] and [`ThirdPersonGame`] are whole games to wrap.
//!
//! A game binary plays in a window inside the shell ([`run_game`], or
//! [`app::harness::play_windowed`]) and runs every headless mode through the game harness
//! ([`app::harness`]: a recording replayed for a summary line and an exit code, bench, soak,
//! converged captures), configured by the game ([`app::harness::HarnessGame`]). Steps are
//! driven by the devices, a [`Recorder`] or a [`Replay`] ([`StepInput`]), and
//! [`Engine::state_hash`] fingerprints the simulation.
//!
//! The names a game needs are re-exported here, below; everything else lives in the module
//! that owns it (the modules are public for tools and tests, and their own docs say what
//! each owns).
//!
//! ## Conventions
//!
//! Right-handed, +Y up, metres, seconds, radians; colours are linear Rec.709 radiance until
//! tonemapping. glTF axis conversion lives only in the glTF loader.
//!
//! ## Modules
//!
//! Modules are listed in layers, lowest first: a module uses only modules above it in this
//! list (`engine/tests/engine/structure_layers.rs` checks every `crate::` path, so a cycle cannot
//! quietly come back; code inside the crate names the module an item lives in, never the
//! re-exports below). Keep the blank line between declarations: rustfmt sorts adjacent ones. The flow of a frame runs the same way: files become descriptions,
//! the flattened scene is kept up to date and sealed into a commit, the render thread renders
//! it, game code queries it and simulates, and the runner drives it all.

// GPU structs and constants both tracers share (WGSL twins in `shaders/shared/types.wgsl`).
pub mod layout;

// CPU ray traversal over `layout` buffers (scalar, AVX2, AVX-512).
pub mod trace;

// Sun and moon positions for a place and time; the physical sky's tables.
pub mod sky;

// Files in (models, textures, levels), descriptions out.
pub mod assets;

// Components and the transform hierarchy.
pub mod ecs;

// World → typed scene changes.
pub mod extract;

// The flattened scene both sides share: buffers, their writes, lights, materials.
pub mod scene;

// Main thread: BLAS/TLAS builds, refit/rebuild policy, the scene's upkeep.
pub mod accel;

// The commit sealed once per frame, and the hand-off.
pub mod commit;

// Render thread: apply, converge, scale, trace (GPU and CPU), present.
pub mod render;

// Ray queries for game code on the last commit's scene.
pub mod query;

// Sounds, music and spatial emitters.
pub mod audio;

// Physics, animation and triggers.
pub mod sim;

// A level to play: loading with bodies and gameplay.
pub mod level;

// Players: per-step input in game terms, the first-person controller, what is under the
// crosshair, using and carrying; the third-person character and its follow camera.
pub mod player;

// The level editor's core: level documents with their comments, edit commands with undo,
// selection and picking, snapping, checked atomic saves with backups, recovery files.
pub mod editor;

// The runner: the frame's phases, the game-facing API, windows, scripts.
pub mod app;

// The game-facing API, in one place: what a game crate names to run, spawn, play, record and
// be shown. Each is also reachable at its own module's path (`app::Engine`, …).

// Running a game: the engine, the hooks a game implements and what they are handed.
pub use app::{
    Commands, Engine, EngineError, Environment, FrameInput, FrameReport, Game, LevelEvent,
    SetupError, SpawnedLevel, Step,
};
// The shell's and the editor's hooks a game may offer.
pub use app::edit::{EditHooks, EditTarget};
pub use app::shell::{GameSummary, HudInfo, LevelStart, ShellHooks, ShellInfo};
// Games to wrap, and what they report.
pub use app::{FirstPersonGame, Happened, ThirdPersonGame};
// Input: named actions, bindings and the per-step frame of them.
pub use app::{ActionDef, ActionFrame, ActionKind, ActionSet, Binding, KeyCode, MouseButton};
// Recording and replaying the steps.
pub use app::{Recorder, Recording, Replay, ReplayError, StepInput};
// Playing in a window inside the shell.
pub use app::{WindowConfig, run_game};
// Levels and assets.
pub use assets::{AssetError, AssetRoot, Level};
pub use level::{PlayableLevel, load_composed, load_level};
// The world: transforms, the camera that crosses the commit, ray queries.
pub use ecs::Transform;
pub use extract::RenderCamera;
pub use query::Queries;
pub use render::{RenderConfig, TracerChoice};
pub use sim::triggers::Outcome;
