//! Test harnesses over the headless engine: the soak (`soak`: any game played by the seeded
//! monkey for many frames, watched for what must never happen) and the ghosting measurement
//! ([`measure_ghosting`]: a converging policy's error on a fast-moving object and its trail).
//!
//! Main thread (the engine's render thread renders). Must not: change the game, its level or
//! any policy; they drive and measure.

mod ghosting;
pub mod soak;

pub use ghosting::{GhostError, GhostSetup, measure_ghosting};
