//! The fixed-step simulation clock: game rules and physics advance in steps of `step_seconds`
//! (1/60 s by default), decoupled from how long frames take to render.
//!
//! Owns: the time accumulator and the clamp on catch-up steps after a long frame (so a hitch
//! does not snowball). Main thread. Must not: read the wall clock itself (callers pass frame
//! times in, so headless runs and tests are deterministic).

/// Fixed-step clock.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedClock {
    /// Seconds per simulation step.
    pub step_seconds: f64,
    /// At most this many steps per frame; longer frames drop the excess time.
    pub max_steps: u32,
    accumulator: f64,
    /// Steps taken since the start.
    pub steps: u64,
}

impl FixedClock {
    /// A clock of `hz` steps per second.
    pub fn new(hz: f64) -> Self {
        Self {
            step_seconds: 1.0 / hz,
            max_steps: 8,
            accumulator: 0.0,
            steps: 0,
        }
    }

    /// Adds `frame_seconds` of elapsed time and returns how many steps to run now.
    pub fn advance(&mut self, frame_seconds: f64) -> u32 {
        self.accumulator += frame_seconds.max(0.0);
        let mut n = (self.accumulator / self.step_seconds).floor() as u64;
        if n > self.max_steps as u64 {
            n = self.max_steps as u64;
            self.accumulator = 0.0;
        } else {
            self.accumulator -= n as f64 * self.step_seconds;
        }
        self.steps += n;
        n as u32
    }

    /// Fraction of a step left in the accumulator, in [0, 1): how far rendering should
    /// interpolate from the last step towards the next.
    pub fn alpha(&self) -> f64 {
        (self.accumulator / self.step_seconds).clamp(0.0, 1.0)
    }
}

impl Default for FixedClock {
    fn default() -> Self {
        Self::new(60.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_follow_time_and_clamp_hitches() {
        let mut c = FixedClock::new(60.0);
        let total: u32 = (0..60).map(|_| c.advance(1.0 / 30.0)).sum();
        assert_eq!(total, 120);
        assert_eq!(c.advance(1.0 / 120.0), 0);
        assert!((c.alpha() - 0.5).abs() < 1e-6);
        assert_eq!(c.advance(10.0), 8);
        assert_eq!(c.alpha(), 0.0);
    }
}
