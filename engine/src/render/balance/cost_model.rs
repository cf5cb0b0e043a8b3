//! Our schemes: [`CostModel`] (contiguous bands) and [`Interleaved`] (dealt units), both
//! placed on a per-unit cost field predicted from the previous frame.
//!
//! The paper's schemes see one number per tracer and so assume every row costs the same; its
//! Figure 10 shows they do not (sky against geometry). Ours keep the previous frame's time of
//! every unit, turn it into a device-independent cost with the tracers' estimated relative
//! speeds ([`SpeedEstimate`]), and split the next frame on that field: [`CostModel`] into the
//! best contiguous bands, [`Interleaved`] by dealing units out so each tracer's units come
//! from every part of the image and a change anywhere in the picture is shared by all.
//! Owns: the prediction and the two schemes. Must not: measure.

use super::deal::{deal_interleaved, fill_contiguous};
use super::measure::FrameTimes;
use super::scheme::Balancer;
use super::speeds::SpeedEstimate;
use super::split::Split;

/// Weight of the newest frame in the predicted cost field. Measured unit times carry noise
/// that the next frame does not repeat (on this shared VM 8 % per unit from frame to frame,
/// against 1–2 % in what the rows really cost, judged by their ray counts), so the field is
/// an exponential average; `bench balance --blends` sweeps it.
pub const COST_BLEND: f64 = 0.5;

/// The next frame's cost per unit (seconds on a speed-one tracer) and the tracers' speeds.
#[derive(Clone, Debug)]
struct Predictor {
    units: usize,
    tracers: usize,
    speeds: SpeedEstimate,
    /// Weight of the newest frame in the smoothed cost field (1: the last frame only).
    blend: f64,
    costs: Option<Vec<f64>>,
}

impl Predictor {
    fn new(units: usize, tracers: usize, blend: f64) -> Self {
        Self {
            units,
            tracers,
            speeds: SpeedEstimate::new(tracers),
            blend: blend.clamp(1e-3, 1.0),
            costs: None,
        }
    }

    /// Takes in one frame, blended into the running cost field with weight `blend`: per-unit
    /// times when there are, else each tracer's time spread
    /// evenly over its units (then the schemes act like a smoothed Perfect).
    fn observe(&mut self, m: &FrameTimes) {
        if m.split.units() != self.units
            || m.split.tracers() != self.tracers
            || m.tracer_seconds.len() != self.tracers
        {
            return;
        }
        self.speeds.observe(m);
        let speeds = self.speeds.speeds();
        let owners = m.split.owners();
        let costs: Vec<f64> = if m.unit_seconds.len() == self.units {
            (0..self.units)
                .map(|u| m.unit_seconds[u] * speeds[owners[u] as usize])
                .collect()
        } else {
            let counts = m.split.counts();
            (0..self.units)
                .map(|u| {
                    let w = owners[u] as usize;
                    m.tracer_seconds[w] * speeds[w] / counts[w].max(1) as f64
                })
                .collect()
        };
        if costs.iter().all(|c| c.is_finite() && *c >= 0.0) && costs.iter().any(|c| *c > 0.0) {
            self.costs = Some(match self.costs.take() {
                Some(old) => old
                    .iter()
                    .zip(&costs)
                    .map(|(o, c)| self.blend * c + (1.0 - self.blend) * o)
                    .collect(),
                None => costs,
            });
        }
    }
}

/// `base`, with the blend when it is not the default.
fn blend_name(base: &str, blend: f64) -> String {
    if blend == COST_BLEND {
        base.into()
    } else {
        format!("{base} β={blend}")
    }
}

/// Ours, contiguous: the bands that equalise the predicted times exactly on the previous
/// frame's per-unit cost field (what Perfect would do if it knew what each row costs).
#[derive(Clone, Debug)]
pub struct CostModel {
    predictor: Predictor,
}

impl CostModel {
    /// With the default cost blend, [`COST_BLEND`].
    pub fn new(units: usize, tracers: usize) -> Self {
        Self::with_blend(units, tracers, COST_BLEND)
    }

    /// `blend` in (0, 1]: the weight of the newest frame in the cost field.
    pub fn with_blend(units: usize, tracers: usize, blend: f64) -> Self {
        Self {
            predictor: Predictor::new(units, tracers, blend),
        }
    }
}

impl Balancer for CostModel {
    fn name(&self) -> String {
        blend_name("cost model", self.predictor.blend)
    }

    fn next(&mut self, last: Option<&FrameTimes>) -> Split {
        let p = &mut self.predictor;
        if let Some(last) = last {
            p.observe(last);
        }
        let counts = match &p.costs {
            Some(costs) => fill_contiguous(costs, &p.speeds.speeds()),
            None => fill_contiguous(&vec![1.0; p.units], &vec![1.0; p.tracers]),
        };
        Split::contiguous(&counts).unwrap_or_else(|e| {
            panic!(
                "contiguous bands of {} units over {} tracers: {e}",
                p.units, p.tracers
            )
        })
    }
}

/// Ours, interleaved: units dealt out on the previous frame's per-unit cost field, so every
/// tracer renders rows from the whole image, then evened up unit by unit.
#[derive(Clone, Debug)]
pub struct Interleaved {
    predictor: Predictor,
}

impl Interleaved {
    /// With the default cost blend, [`COST_BLEND`].
    pub fn new(units: usize, tracers: usize) -> Self {
        Self::with_blend(units, tracers, COST_BLEND)
    }

    /// `blend` in (0, 1]: the weight of the newest frame in the cost field.
    pub fn with_blend(units: usize, tracers: usize, blend: f64) -> Self {
        Self {
            predictor: Predictor::new(units, tracers, blend),
        }
    }
}

impl Balancer for Interleaved {
    fn name(&self) -> String {
        blend_name("interleaved", self.predictor.blend)
    }

    fn next(&mut self, last: Option<&FrameTimes>) -> Split {
        let p = &mut self.predictor;
        if let Some(last) = last {
            p.observe(last);
        }
        let owners = match &p.costs {
            Some(costs) => deal_interleaved(costs, &p.speeds.speeds()),
            None => deal_interleaved(&vec![1.0; p.units], &vec![1.0; p.tracers]),
        };
        Split::from_owners(owners, p.tracers).unwrap_or_else(|e| {
            panic!(
                "dealt units of {} units over {} tracers: {e}",
                p.units, p.tracers
            )
        })
    }
}
