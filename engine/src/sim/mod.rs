//! Simulation on the main thread, run by the fixed-step clock: [`animation`] (rigid keyframe
//! clips, skeletal skinning, morph targets, blending) and [`physics`] (rapier3d: bodies,
//! colliders, the character controller, carrying, sensors) and [`triggers`] (volumes, lasers,
//! rules and their actions) and [`water`] (ripples on grid waters, pushed by what wades).
//!
//! Must not: talk to the render thread (what moved reaches it through the extract and commit).

pub mod animation;
pub mod physics;
pub mod triggers;
pub mod water;
