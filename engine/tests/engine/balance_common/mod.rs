//! Shared helpers of the workload balancing tests: a deterministic number stream, what a pool
//! of simulated tracers reports for a split, a scheme run over frames, a sky-over-city cost
//! field, and the time of contiguous bands.
#![allow(dead_code)]

use candela::render::balance::{Balancer, FrameTimes, Split};

/// A deterministic stream of numbers in [0, 1) (xorshift).
pub struct Noise(pub u64);

impl Noise {
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// What a pool of tracers of `speeds` reports after rendering `costs` (seconds on a speed-one
/// tracer per unit) with `split`.
pub fn measure(split: &Split, costs: &[f64], speeds: &[f64]) -> FrameTimes {
    let unit_seconds: Vec<f64> = (0..split.units())
        .map(|u| costs[u] / speeds[split.owner(u)])
        .collect();
    let mut tracer_seconds = vec![0.0; speeds.len()];
    for (u, t) in unit_seconds.iter().enumerate() {
        tracer_seconds[split.owner(u)] += t;
    }
    FrameTimes {
        split: split.clone(),
        tracer_seconds,
        unit_seconds,
    }
}

/// Runs `scheme` for `frames` frames over cost fields from `field(frame)`, checking every split
/// with `check`, and returns the frame times.
pub fn run(
    scheme: &mut dyn Balancer,
    speeds: &[f64],
    frames: usize,
    mut field: impl FnMut(usize) -> Vec<f64>,
    mut check: impl FnMut(&Split),
) -> Vec<FrameTimes> {
    let mut last: Option<FrameTimes> = None;
    let mut out = Vec::new();
    for f in 0..frames {
        let split = scheme.next(last.as_ref());
        check(&split);
        let m = measure(&split, &field(f), speeds);
        out.push(m.clone());
        last = Some(m);
    }
    out
}

/// A sky-over-city field: cheap top rows, expensive bottom rows, a bright band that drifts.
pub fn city_field(units: usize, frame: usize) -> Vec<f64> {
    (0..units)
        .map(|u| {
            let y = u as f64 / units as f64;
            let drift = ((y * 9.0 + frame as f64 * 0.3).sin() + 1.0) * 0.5;
            if y < 0.4 {
                0.05 + 0.02 * drift
            } else {
                1.0 + 2.0 * drift * y
            }
        })
        .collect()
}

/// The frame time of contiguous bands `counts` over `costs` on tracers of `speeds`.
pub fn band_time(counts: &[usize], costs: &[f64], speeds: &[f64]) -> f64 {
    let mut start = 0;
    let mut worst: f64 = 0.0;
    for (w, n) in counts.iter().enumerate() {
        worst = worst.max(costs[start..start + n].iter().sum::<f64>() / speeds[w]);
        start += n;
    }
    worst
}
