//! [`FrameLimiter`]: holds the window loop to at most a given frame rate by sleeping.
//!
//! Vsync (FIFO presentation) paces frames on a real display, but not everywhere: Xvfb presents
//! FIFO at once, and with vsync off nothing paces at all. The limiter gives each frame a slot
//! of `1 / max_fps` seconds; a late frame starts the next slot from now (no burst to catch
//! up). Main thread. Must not: measure or change anything but the sleeping.

use std::time::{Duration, Instant};

/// Sleeps so that frames start at most `max_fps` times per second.
#[derive(Clone, Debug, Default)]
pub struct FrameLimiter {
    period: Option<Duration>,
    next: Option<Instant>,
}

impl FrameLimiter {
    /// `None` (or a rate that is not positive and finite): no limit.
    pub fn new(max_fps: Option<f64>) -> Self {
        let period = max_fps
            .filter(|f| f.is_finite() && *f > 0.0)
            .map(|f| Duration::from_secs_f64(1.0 / f));
        Self { period, next: None }
    }

    /// The frame period, if limited (what the tests read).
    #[cfg(test)]
    pub fn period(&self) -> Option<Duration> {
        self.period
    }

    /// Sleeps until this frame's slot begins; returns how long it slept.
    pub fn wait(&mut self) -> Duration {
        let Some(period) = self.period else {
            return Duration::ZERO;
        };
        let now = Instant::now();
        let slot = self.next.unwrap_or(now);
        let slept = if slot > now {
            std::thread::sleep(slot - now);
            slot - now
        } else {
            Duration::ZERO
        };
        self.next = Some(slot.max(now) + period);
        slept
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_the_rate_and_does_not_burst_after_a_stall() {
        let mut limiter = FrameLimiter::new(Some(200.0));
        let started = Instant::now();
        for _ in 0..11 {
            limiter.wait();
        }
        let elapsed = started.elapsed().as_secs_f64();
        assert!(elapsed >= 0.049, "10 periods of 5 ms took {elapsed} s");
        std::thread::sleep(Duration::from_millis(30));
        // After a stall the next frame starts at once, the one after a full period later.
        let started = Instant::now();
        assert_eq!(limiter.wait(), Duration::ZERO);
        limiter.wait();
        assert!(started.elapsed() >= Duration::from_millis(4));
        assert_eq!(FrameLimiter::new(None).wait(), Duration::ZERO);
        assert_eq!(FrameLimiter::new(Some(0.0)).period(), None);
    }
}
