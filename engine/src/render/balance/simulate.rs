//! The device simulator: replays recorded per-unit costs ([`CostTrace`]) on simulated tracers
//! of given relative speeds under any [`Balancer`], frame by frame, as a real pool would run it.
//!
//! A simulated tracer of speed `s` renders a unit of recorded cost `c` in `c / s` seconds and a
//! set of units in the sum of their times (no per-frame overhead, no noise beyond what the
//! recording holds). After each frame the scheme gets what a real pool would report: each
//! tracer's time and each unit's time on the tracer that rendered it.
//!
//! Idle share of a frame (the paper's Table 1 measure, "percentage of summed rendering time for
//! all GPUs spent idling due to early completion"): `Σ_w (T_max − T_w) / (n · T_max)`, the time
//! the tracers wait for the slowest over the time all `n` of them are held by the frame.
//! Owns: the replay and the measure. Must not: decide splits (the schemes do).

use super::costs::CostTrace;
use super::measure::FrameTimes;
use super::scheme::Balancer;
use super::split::Split;

/// Idle share of one frame from each tracer's time, in [0, 1); 0 for no time at all.
pub fn idle_share(tracer_seconds: &[f64]) -> f64 {
    let n = tracer_seconds.len();
    let slowest = tracer_seconds.iter().copied().fold(0.0, f64::max);
    if n == 0 || slowest <= 0.0 {
        return 0.0;
    }
    let waiting: f64 = tracer_seconds.iter().map(|t| slowest - t).sum();
    waiting / (n as f64 * slowest)
}

/// One simulated frame.
#[derive(Clone, Debug)]
pub struct FrameOutcome {
    /// Units per tracer this frame.
    pub counts: Vec<usize>,
    /// Each tracer's render time, seconds.
    pub tracer_seconds: Vec<f64>,
    /// [`idle_share`] of the frame.
    pub idle_share: f64,
}

/// A whole replay.
#[derive(Clone, Debug)]
pub struct SimReport {
    pub scheme: String,
    pub speeds: Vec<f64>,
    pub frames: Vec<FrameOutcome>,
}

impl SimReport {
    /// Mean idle share over the frames (the paper's Table 1 figure).
    pub fn mean_idle(&self) -> f64 {
        self.frames.iter().map(|f| f.idle_share).sum::<f64>() / self.frames.len().max(1) as f64
    }

    /// The worst frame after the first: its index and idle share (the spikes Table 1 hides;
    /// the first frame, rendered before anything was measured, is every contiguous scheme's
    /// equal split and would hide them again).
    pub fn worst(&self) -> (usize, f64) {
        self.frames
            .iter()
            .enumerate()
            .skip(usize::from(self.frames.len() > 1))
            .map(|(i, f)| (i, f.idle_share))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0))
    }

    /// Summed frame times (the slowest tracer's), seconds: what the frames took.
    pub fn total_seconds(&self) -> f64 {
        self.frames
            .iter()
            .map(|f| f.tracer_seconds.iter().copied().fold(0.0, f64::max))
            .sum()
    }
}

/// Replays every frame of `trace` on tracers of relative `speeds` (one per tracer, positive)
/// under `balancer`. Needs at least as many units per frame as tracers.
pub fn simulate(trace: &CostTrace, speeds: &[f64], balancer: &mut dyn Balancer) -> SimReport {
    let tracers = speeds.len();
    assert!(
        tracers >= 1 && trace.units() >= tracers && speeds.iter().all(|s| *s > 0.0),
        "simulate: {} units over speeds {speeds:?} (need units >= tracers >= 1, speeds > 0)",
        trace.units()
    );
    let mut last: Option<FrameTimes> = None;
    let mut frames = Vec::with_capacity(trace.frames());
    for costs in &trace.unit_seconds {
        let split: Split = balancer.next(last.as_ref());
        assert_eq!(
            split.units(),
            costs.len(),
            "{}: split of the wrong size",
            balancer.name()
        );
        let unit_seconds: Vec<f64> = costs
            .iter()
            .enumerate()
            .map(|(u, c)| c / speeds[split.owner(u)])
            .collect();
        let mut tracer_seconds = vec![0.0; tracers];
        for (u, t) in unit_seconds.iter().enumerate() {
            tracer_seconds[split.owner(u)] += t;
        }
        frames.push(FrameOutcome {
            counts: split.counts(),
            idle_share: idle_share(&tracer_seconds),
            tracer_seconds: tracer_seconds.clone(),
        });
        last = Some(FrameTimes {
            split,
            tracer_seconds,
            unit_seconds,
        });
    }
    SimReport {
        scheme: balancer.name(),
        speeds: speeds.to_vec(),
        frames,
    }
}
