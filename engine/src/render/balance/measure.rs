//! [`FrameTimes`]: what one frame measured, the only input of every scheme.
//!
//! Owns: the measurement record. Must not: decide.

use super::split::Split;

/// What the tracers reported after rendering one frame with `split`.
#[derive(Clone, Debug)]
pub struct FrameTimes {
    /// The split the frame was rendered with.
    pub split: Split,
    /// Render time of each tracer, seconds (from its start signal to its done signal).
    pub tracer_seconds: Vec<f64>,
    /// Render time of each unit on the tracer that rendered it, seconds; empty when the
    /// tracers report only their totals (the paper's schemes need nothing more).
    pub unit_seconds: Vec<f64>,
}

impl FrameTimes {
    /// The time the frame took: its slowest tracer, seconds.
    pub fn frame_seconds(&self) -> f64 {
        self.tracer_seconds.iter().copied().fold(0.0, f64::max)
    }
}
