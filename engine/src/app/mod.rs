//! The runner: the frame loop that drives the world, the upkeep and the render thread, headless
//! or (later) in a window, and the fixed-step clock.

mod clock;
mod engine;

pub use clock::FixedClock;
pub use engine::{Engine, EngineError, Environment, FrameReport};
