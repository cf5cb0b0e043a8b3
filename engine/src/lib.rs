//! # Candela
//!
//! A game engine whose only renderer is a real-time path tracer (after Bikker & van Schijndel,
//! "The Brigade Renderer", 2013). Modules are listed in frame order: assets are loaded, the
//! acceleration structures are built, the scene is flattened into [`layout`] buffers, and a
//! tracer (GPU or CPU, the same algorithm) renders it into a film.
//!
//! Conventions for the whole engine: right-handed, +Y up, metres, seconds, radians; colours are
//! linear Rec.709 radiance until tonemapping. glTF axis conversion lives only in the glTF loader.

pub mod layout;

pub mod assets;

pub mod ecs;

pub mod sim;

pub mod audio;

pub mod extract;

pub mod accel;
pub mod trace;

pub mod commit;

pub mod render;

pub mod query;

pub mod app;
