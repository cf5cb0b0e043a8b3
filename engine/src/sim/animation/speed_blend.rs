//! The walk/run blend by speed: a locomotion state that plays two cycles at once (walk and
//! run), phase-synchronised — both sampled at the same normalised time (the fraction of their
//! cycle) — and mixed by a weight that rises linearly with the ground speed, instead of a
//! crossfade from one to the other at a threshold.
//!
//! Owns: [`SpeedBlend`] (on an `AnimState`, from a level's `blend: (...)`) and
//! [`BlendPartner`] (on a `Playback`: what the player mixes in when it makes the pose).
//! The playback rate of a blended state follows the blended stride, so the shared phase
//! advances at `speed / stride(weight)` cycles per second and the feet do not slide in between.
//! Main thread, once per fixed step (by `state_machine`). Must not: touch the ECS or deform
//! vertices. Units: metres per second, seconds; the weight is in [0, 1] (0: the state's own
//! clip alone, 1: the partner alone).

/// A second clip mixed into a state's clip by ground speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedBlend {
    /// Index into the model's clips (the run, for a walk state).
    pub clip: usize,
    /// The ground speed at which the partner clip plays at rate 1, m/s.
    pub reference_speed_mps: f32,
    /// At or below this speed the weight is 0 (the state's clip alone), m/s.
    pub from_speed_mps: f32,
    /// At or above this speed the weight is 1 (the partner alone), m/s; above `from`.
    pub to_speed_mps: f32,
    /// The partner's cycle over the state clip's cycle (run 0.7 s / walk 1.0 s = 0.7).
    pub cycle_ratio: f32,
}

/// The clip a [`Playback`](super::Playback) mixes in, sampled at the same fraction of its
/// duration as the playback's own clip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlendPartner {
    pub clip: usize,
    /// In [0, 1]: 0 the playback's clip alone, 1 the partner alone.
    pub weight: f32,
}

impl SpeedBlend {
    /// The partner's weight at `speed_mps`: 0 up to `from_speed_mps`, rising linearly to 1 at
    /// `to_speed_mps` (monotone non-decreasing in speed; NaN counts as 0).
    pub fn weight(&self, speed_mps: f32) -> f32 {
        let span = self.to_speed_mps - self.from_speed_mps;
        let w = (speed_mps - self.from_speed_mps) / span;
        if w.is_nan() { 0.0 } else { w.clamp(0.0, 1.0) }
    }

    /// The playback rate of the state's clip (cycle length 1 in its own units) at
    /// `speed_mps`, given the state's own reference speed: the clip advances so that the
    /// blended stride, `(1 − w)·ref + w·ref_partner·cycle_ratio` metres per state cycle, keeps
    /// up with the ground.
    pub fn rate(&self, own_reference_mps: f32, speed_mps: f32) -> f32 {
        let w = self.weight(speed_mps);
        let stride =
            (1.0 - w) * own_reference_mps + w * self.reference_speed_mps * self.cycle_ratio;
        speed_mps.max(0.0) / stride
    }

    /// What is wrong with the numbers, if anything.
    pub fn check(&self) -> Result<(), String> {
        let finite_positive = |v: f32| v.is_finite() && v > 0.0;
        if !finite_positive(self.reference_speed_mps) {
            return Err(format!(
                "blend.reference_speed_mps must be finite and above 0, not {}",
                self.reference_speed_mps
            ));
        }
        if !finite_positive(self.cycle_ratio) {
            return Err(format!(
                "the blend's clip must have a duration above 0 (cycle ratio {})",
                self.cycle_ratio
            ));
        }
        let (from, to) = (self.from_speed_mps, self.to_speed_mps);
        if !(from.is_finite() && to.is_finite() && from >= 0.0 && to > from) {
            return Err(format!(
                "blend needs 0 ≤ from_speed_mps ({from}) < to_speed_mps ({to}), both finite"
            ));
        }
        Ok(())
    }
}
