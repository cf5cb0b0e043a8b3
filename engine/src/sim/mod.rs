//! Simulation on the main thread, run by the fixed-step clock: [`animation`] (rigid keyframe
//! clips, skeletal skinning, morph targets, blending). Physics and triggers join here.
//!
//! Must not: talk to the render thread (what moved reaches it through the extract and commit).

pub mod animation;
