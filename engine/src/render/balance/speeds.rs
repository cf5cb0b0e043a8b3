//! [`SpeedEstimate`]: the relative speed of each tracer, from per-unit times alone.
//!
//! A unit's time on tracer `w` is `cost / speed_w`. Two kinds of pairs tell speeds apart
//! without knowing costs: neighbouring units of one frame on different tracers (neighbouring
//! rows cost about the same) and one unit on different tracers in consecutive frames (a unit
//! costs about the same from one frame to the next). Each pair says
//! `ln t_a − ln t_b ≈ ln s_b − ln s_a`; the log speeds are the least-squares fit over all pairs,
//! with pairs far off the current fit down-weighted (a row at a sky edge) and old frames fading
//! by [`SpeedEstimate::FADE`] per frame. Speeds are normalised to a mean log speed of zero.
//! Owns: the estimate. Must not: decide splits.

use super::measure::FrameTimes;

/// Running least-squares estimate of the tracers' relative speeds.
#[derive(Clone, Debug)]
pub struct SpeedEstimate {
    /// ln speed per tracer, mean zero.
    log_speed: Vec<f64>,
    /// Faded normal equations: `normal · x = rhs` (graph Laplacian of the pairs).
    normal: Vec<Vec<f64>>,
    rhs: Vec<f64>,
    /// The previous frame's owners and unit times, for the pairs across frames.
    previous: Option<(Vec<u16>, Vec<f64>)>,
}

impl SpeedEstimate {
    /// Weight left to one frame's pairs after each later frame.
    pub const FADE: f64 = 0.9;
    /// Residual (in ln time) at which a pair's weight has halved.
    const ROBUST_SCALE: f64 = 0.25;

    /// Equal speeds for `tracers` tracers.
    pub fn new(tracers: usize) -> Self {
        Self {
            log_speed: vec![0.0; tracers],
            normal: vec![vec![0.0; tracers]; tracers],
            rhs: vec![0.0; tracers],
            previous: None,
        }
    }

    /// Relative speeds (geometric mean one).
    pub fn speeds(&self) -> Vec<f64> {
        self.log_speed.iter().map(|x| x.exp()).collect()
    }

    /// Adds one frame's pairs and refits. Frames without per-unit times change nothing.
    pub fn observe(&mut self, m: &FrameTimes) {
        let n = self.log_speed.len();
        let owners = m.split.owners();
        if m.split.tracers() != n || m.unit_seconds.len() != owners.len() {
            return;
        }
        for row in &mut self.normal {
            row.iter_mut().for_each(|v| *v *= Self::FADE);
        }
        self.rhs.iter_mut().for_each(|v| *v *= Self::FADE);
        let t = &m.unit_seconds;
        for u in 1..owners.len() {
            self.add_pair(owners[u - 1] as usize, t[u - 1], owners[u] as usize, t[u]);
        }
        if let Some((prev_owners, prev_t)) = &self.previous
            && prev_owners.len() == owners.len()
        {
            let pairs: Vec<(usize, f64, usize, f64)> = (0..owners.len())
                .map(|u| (prev_owners[u] as usize, prev_t[u], owners[u] as usize, t[u]))
                .collect();
            for (a, ta, b, tb) in pairs {
                self.add_pair(a, ta, b, tb);
            }
        }
        self.previous = Some((owners.to_vec(), t.clone()));
        self.solve();
    }

    /// One pair: unit time `ta` on tracer `a`, `tb` on tracer `b`, for about the same cost.
    fn add_pair(&mut self, a: usize, ta: f64, b: usize, tb: f64) {
        if a == b || !(ta > 0.0 && tb > 0.0 && ta.is_finite() && tb.is_finite()) {
            return;
        }
        // ln ta − ln tb = x_b − x_a (+ noise).
        let d = ta.ln() - tb.ln();
        let residual = d - (self.log_speed[b] - self.log_speed[a]);
        let w = 1.0 / (1.0 + (residual / Self::ROBUST_SCALE).powi(2));
        self.normal[a][a] += w;
        self.normal[b][b] += w;
        self.normal[a][b] -= w;
        self.normal[b][a] -= w;
        self.rhs[b] += w * d;
        self.rhs[a] -= w * d;
    }

    /// Solves `(normal + 1·1ᵀ) x = rhs` (the added term pins the mean to zero) when every tracer
    /// is tied to the others by some weight; otherwise keeps the previous estimate.
    fn solve(&mut self) {
        let n = self.log_speed.len();
        if n < 2 || (0..n).any(|w| self.normal[w][w] <= 1e-9) {
            return;
        }
        let mut a: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                let mut row: Vec<f64> = (0..n).map(|j| self.normal[i][j] + 1.0).collect();
                row.push(self.rhs[i]);
                row
            })
            .collect();
        // Gaussian elimination with partial pivoting on an n × (n + 1) system, n tiny.
        for col in 0..n {
            let Some(pivot) = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            else {
                return;
            };
            if a[pivot][col].abs() < 1e-12 {
                return;
            }
            a.swap(col, pivot);
            let pivot_row = a[col].clone();
            for (r, row) in a.iter_mut().enumerate() {
                if r != col {
                    let f = row[col] / pivot_row[col];
                    for (v, p) in row.iter_mut().zip(&pivot_row).skip(col) {
                        *v -= f * p;
                    }
                }
            }
        }
        let x: Vec<f64> = (0..n).map(|i| a[i][n] / a[i][i]).collect();
        if x.iter().all(|v| v.is_finite()) {
            let mean = x.iter().sum::<f64>() / n as f64;
            self.log_speed = x.iter().map(|v| v - mean).collect();
        }
    }
}
