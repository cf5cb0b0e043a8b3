//! The runner: the frame loop that drives the world, the upkeep and the render thread, headless
//! or (later) in a window, and the fixed-step clock.

mod clock;
mod engine;
mod level;
mod waves;

pub use clock::FixedClock;
pub use engine::{Engine, EngineError, Environment, FrameReport};
pub use level::SpawnedLevel;
pub use waves::{Waves, waves_system};
