//! # Candela
//!
//! A game engine whose only renderer is a real-time path tracer (after Bikker & van Schijndel,
//! "The Brigade Renderer", 2013).
//!
//! Conventions for the whole engine: right-handed, +Y up, metres, seconds, radians; colours are
//! linear Rec.709 radiance until tonemapping. glTF axis conversion lives only in the glTF loader.
//!
//! Modules are listed in layers, lowest first: a module uses only modules above it in this
//! list (`engine/tests/engine/structure_layers.rs` checks every `crate::` path, so a cycle cannot
//! quietly come back). Keep the blank line between declarations: rustfmt sorts adjacent ones. The flow of a frame runs the same way: files become descriptions,
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
