//! The paper's four schemes (Brigade §4.3): [`Equal`] ("do not balance"), [`RobinHood`],
//! [`Perfect`] (equation 1) and [`PerfectSmooth`] (equation 2). All hand out contiguous bands
//! of units, tracer 0 at the top, and read only each tracer's total time, as in the paper.
//!
//! Owns: these four rules. Must not: look at per-unit times (that is what ours add).

use super::apportion::apportion;
use super::measure::FrameTimes;
use super::scheme::Balancer;
use super::split::Split;

/// An equal split. Schemes are built for `units >= tracers >= 1` (the simulator and the pool
/// check it); anything less is a broken invariant.
fn equal(units: usize, tracers: usize) -> Split {
    Split::equal(units.max(tracers), tracers.max(1))
        .unwrap_or_else(|e| panic!("an equal split of {units} units over {tracers} tracers: {e}"))
}

/// Whether `last` is a usable measurement of a split of `units` units over `tracers`
/// tracers: every tracer timed, every time positive and finite.
fn usable(last: &FrameTimes, units: usize, tracers: usize) -> bool {
    last.split.units() == units
        && last.split.tracers() == tracers
        && last.tracer_seconds.len() == tracers
        && last
            .tracer_seconds
            .iter()
            .all(|t| t.is_finite() && *t > 0.0)
}

/// Paper §4.3.1, "Do Not Balance": every tracer an equal share of the rows, always.
#[derive(Clone, Debug)]
pub struct Equal {
    split: Split,
}

impl Equal {
    pub fn new(units: usize, tracers: usize) -> Self {
        Self {
            split: equal(units, tracers),
        }
    }
}

impl Balancer for Equal {
    fn name(&self) -> String {
        "none".into()
    }

    fn next(&mut self, _last: Option<&FrameTimes>) -> Split {
        self.split.clone()
    }
}

/// Paper §4.3.2: starts equal; after each frame the tracer that finished last passes one work
/// unit to the tracer that finished first (never its last unit). Moves exactly one unit per
/// frame while the times differ.
#[derive(Clone, Debug)]
pub struct RobinHood {
    units: usize,
    tracers: usize,
}

impl RobinHood {
    pub fn new(units: usize, tracers: usize) -> Self {
        Self { units, tracers }
    }
}

impl Balancer for RobinHood {
    fn name(&self) -> String {
        "Robin Hood".into()
    }

    fn next(&mut self, last: Option<&FrameTimes>) -> Split {
        let Some(last) = last.filter(|l| usable(l, self.units, self.tracers)) else {
            return equal(self.units, self.tracers);
        };
        let mut counts = last.split.counts();
        let t = &last.tracer_seconds;
        let slowest = (0..self.tracers).max_by(|&a, &b| t[a].total_cmp(&t[b]));
        let fastest = (0..self.tracers).min_by(|&a, &b| t[a].total_cmp(&t[b]));
        if let (Some(s), Some(f)) = (slowest, fastest)
            && t[s] > t[f]
            && counts[s] > 1
        {
            counts[s] -= 1;
            counts[f] += 1;
        }
        Split::contiguous(&counts).unwrap_or_else(|_| equal(self.units, self.tracers))
    }
}

/// Perfect's shares, equation (1): `P_w = (units_w / time_w) / Σ_v (units_v / time_v)`, the
/// share of the frame tracer `w` would finish in equal time if every unit cost the same.
pub fn perfect_shares(last: &FrameTimes) -> Vec<f64> {
    let counts = last.split.counts();
    let rates: Vec<f64> = counts
        .iter()
        .zip(&last.tracer_seconds)
        .map(|(&n, &t)| n as f64 / t)
        .collect();
    let total: f64 = rates.iter().sum();
    rates.iter().map(|r| r / total).collect()
}

/// Paper §4.3.3, "Perfect": each frame's shares from the previous frame's units per second
/// (equation 1), ignoring that rows differ in cost, so it overcompensates when expensive rows
/// change hands.
#[derive(Clone, Debug)]
pub struct Perfect {
    units: usize,
    tracers: usize,
}

impl Perfect {
    pub fn new(units: usize, tracers: usize) -> Self {
        Self { units, tracers }
    }
}

impl Balancer for Perfect {
    fn name(&self) -> String {
        "Perfect".into()
    }

    fn next(&mut self, last: Option<&FrameTimes>) -> Split {
        let Some(last) = last.filter(|l| usable(l, self.units, self.tracers)) else {
            return equal(self.units, self.tracers);
        };
        Split::contiguous(&apportion(&perfect_shares(last), self.units))
            .unwrap_or_else(|_| equal(self.units, self.tracers))
    }
}

/// Paper §4.3.3, "Perfect Smooth": Perfect's shares smoothed over frames, equation (2):
/// `S_{w,i+1} = α P_{w,i+1} + (1 − α) S_{w,i}`, starting from equal shares. The paper gives
/// no α; [`PerfectSmooth::DEFAULT_ALPHA`] is ours (`bench balance --alphas` sweeps it).
#[derive(Clone, Debug)]
pub struct PerfectSmooth {
    units: usize,
    tracers: usize,
    alpha: f64,
    shares: Vec<f64>,
}

impl PerfectSmooth {
    /// The smoothing weight of the newest Perfect shares when none is given.
    pub const DEFAULT_ALPHA: f64 = 0.5;

    /// `alpha` in (0, 1]: the weight of the newest Perfect shares (1 is Perfect).
    pub fn new(units: usize, tracers: usize, alpha: f64) -> Self {
        Self {
            units,
            tracers,
            alpha: alpha.clamp(1e-3, 1.0),
            shares: vec![1.0 / tracers.max(1) as f64; tracers.max(1)],
        }
    }
}

impl Balancer for PerfectSmooth {
    fn name(&self) -> String {
        if self.alpha == Self::DEFAULT_ALPHA {
            "Perfect Smooth".into()
        } else {
            format!("Perfect Smooth α={}", self.alpha)
        }
    }

    fn next(&mut self, last: Option<&FrameTimes>) -> Split {
        let Some(last) = last.filter(|l| usable(l, self.units, self.tracers)) else {
            return Split::contiguous(&apportion(&self.shares, self.units))
                .unwrap_or_else(|_| equal(self.units, self.tracers));
        };
        let p = perfect_shares(last);
        for (s, p) in self.shares.iter_mut().zip(&p) {
            *s = self.alpha * p + (1.0 - self.alpha) * *s;
        }
        Split::contiguous(&apportion(&self.shares, self.units))
            .unwrap_or_else(|_| equal(self.units, self.tracers))
    }
}
