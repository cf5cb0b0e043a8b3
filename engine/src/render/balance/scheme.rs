//! The [`Balancer`] trait every scheme implements, and [`SchemeKind`], the list of schemes
//! by name for tools.
//!
//! Owns: the scheme interface and construction by name. Must not: hold scheme logic.

use super::cost_model::{CostModel, Interleaved};
use super::measure::FrameTimes;
use super::paper::{Equal, Perfect, PerfectSmooth, RobinHood};
use super::split::Split;

/// A workload balancing scheme: before each frame, the split from what the previous frame
/// measured (`None` before the first frame). Schemes are deterministic state machines over
/// their inputs; they never look at a clock.
pub trait Balancer {
    /// Short name for tables and charts.
    fn name(&self) -> String;
    /// The split for the next frame.
    fn next(&mut self, last: Option<&FrameTimes>) -> Split;
}

/// Every scheme, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SchemeKind {
    /// Paper §4.3.1: equal contiguous bands, never balanced.
    Equal,
    /// Paper §4.3.2: the last tracer to finish passes one unit to the first.
    RobinHood,
    /// Paper §4.3.3, equation (1): shares from the previous frame's units per second.
    Perfect,
    /// Paper §4.3.3, equation (2): Perfect's shares smoothed over frames.
    PerfectSmooth,
    /// Ours: contiguous bands placed on the previous frame's per-unit cost field.
    CostModel,
    /// Ours: units dealt out interleaved on the previous frame's per-unit cost field.
    Interleaved,
}

impl SchemeKind {
    /// Every scheme, paper's first.
    pub const ALL: [SchemeKind; 6] = [
        SchemeKind::Equal,
        SchemeKind::RobinHood,
        SchemeKind::Perfect,
        SchemeKind::PerfectSmooth,
        SchemeKind::CostModel,
        SchemeKind::Interleaved,
    ];

    /// Whether the paper describes it (otherwise it is ours).
    pub fn from_paper(self) -> bool {
        !matches!(self, SchemeKind::CostModel | SchemeKind::Interleaved)
    }

    /// The scheme for `units` units on `tracers` tracers, in its starting state.
    pub fn build(self, units: usize, tracers: usize) -> Box<dyn Balancer> {
        match self {
            SchemeKind::Equal => Box::new(Equal::new(units, tracers)),
            SchemeKind::RobinHood => Box::new(RobinHood::new(units, tracers)),
            SchemeKind::Perfect => Box::new(Perfect::new(units, tracers)),
            SchemeKind::PerfectSmooth => Box::new(PerfectSmooth::new(
                units,
                tracers,
                PerfectSmooth::DEFAULT_ALPHA,
            )),
            SchemeKind::CostModel => Box::new(CostModel::new(units, tracers)),
            SchemeKind::Interleaved => Box::new(Interleaved::new(units, tracers)),
        }
    }
}
