//! Dynamic workload scaling (Brigade §4.7): hold a frame time by trading samples per pixel, the
//! Russian-roulette survival scale and the render resolution.
//!
//! Owns: a small controller over the measured frame time (exponential average). Too slow by
//! more than 10 %: first fewer samples per pixel, then a lower roulette scale (shorter paths; no
//! bias, more noise), then a lower resolution (presented upscaled). Fast by more than 25 %: the
//! reverse order, except that the resolution rises only while the view moves: a resolution
//! change restarts the converging image, and a still view that stepped up, found itself too
//! slow and stepped back down restarted every few frames and never converged (issue 37). One
//! step per three frames, so that each step's effect is measured before the next; more than twice too slow, samples and roulette drop at once and then the resolution in
//! proportion, so a first frame of seconds is followed by a playable one within a few frames. Render thread. Must not: change anything but the workload numbers.

/// What to hold and within which bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalingTarget {
    /// Target seconds per frame (1/60 for 60 Hz).
    pub frame_seconds: f32,
    pub min_spp: u32,
    pub max_spp: u32,
    /// Lowest roulette scale (1 = default survival).
    pub min_roulette: f32,
    /// Lowest render resolution, as a fraction of the output size per axis.
    pub min_resolution: f32,
    /// The resolution the first frame is traced at, fraction of the output per axis (1: the
    /// output's, the default; benches that measure the steady state start at the floor
    /// instead of spending their first seconds on frames of the full size).
    pub start_resolution: f32,
}

impl ScalingTarget {
    /// Hold `frame_seconds` with the default bounds (1–64 spp, roulette ≥ 0.5, resolution ≥ ¼:
    /// 320×180 of a 1280×720 window, the games' floor on a 2-core machine with the CPU tracer).
    pub fn new(frame_seconds: f32) -> Self {
        Self {
            frame_seconds,
            min_spp: 1,
            max_spp: 64,
            min_roulette: 0.5,
            min_resolution: 0.25,
            start_resolution: 1.0,
        }
    }

    /// What a level declares it needs (`render: (target_fps, min_scale)`, defaults 30 fps and
    /// ¼): the target the harness holds while the level is played.
    pub fn of_level(render: &crate::assets::RenderSettings) -> Self {
        Self {
            min_resolution: render.min_resolution(),
            ..Self::new(render.frame_seconds())
        }
    }
}

/// A live change of what the controller holds (the player's settings: target frame rate and
/// resolution scale), sent with each present request.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalingGoal {
    /// The frame time to hold (`None`: a fixed workload).
    pub target: Option<ScalingTarget>,
    /// Highest render resolution, fraction of the output per axis, in [0.1, 1]; scaling goes
    /// below it to hold the target, never above.
    pub max_resolution: f32,
}

/// The workload of one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Workload {
    pub spp: u32,
    pub roulette_scale: f32,
    /// Fraction of the output resolution per axis.
    pub resolution: f32,
}

impl Workload {
    /// The film size for an output of `width × height`.
    pub fn film_size(&self, width: u32, height: u32) -> (u32, u32) {
        let scale = |n: u32| ((n as f32 * self.resolution).round() as u32).clamp(1, n.max(1));
        (scale(width), scale(height))
    }
}

/// The controller.
#[derive(Clone, Debug)]
pub struct Scaling {
    target: Option<ScalingTarget>,
    work: Workload,
    smoothed: Option<f32>,
    cooldown: u32,
    resized: bool,
    /// Highest resolution allowed (the player's resolution scale).
    max_resolution: f32,
    goal: Option<ScalingGoal>,
}

impl Scaling {
    /// Starts at `spp` samples per pixel, the target's start resolution (full resolution
    /// without a target), default roulette.
    pub fn new(spp: u32, target: Option<ScalingTarget>) -> Self {
        let resolution = target.map_or(1.0, |t| {
            if t.start_resolution.is_finite() {
                t.start_resolution.clamp(t.min_resolution.min(1.0), 1.0)
            } else {
                1.0
            }
        });
        Self {
            target,
            work: Workload {
                spp: spp.max(1),
                roulette_scale: 1.0,
                resolution,
            },
            smoothed: None,
            cooldown: 0,
            resized: false,
            max_resolution: 1.0,
            goal: None,
        }
    }

    /// Holds `goal` from now on (the same goal again changes nothing). A lower resolution cap
    /// applies at once; without a target the resolution is the cap.
    pub fn set_goal(&mut self, goal: ScalingGoal) {
        if self.goal == Some(goal) {
            return;
        }
        self.goal = Some(goal);
        let max = if goal.max_resolution.is_finite() {
            goal.max_resolution.clamp(0.1, 1.0)
        } else {
            1.0
        };
        self.max_resolution = max;
        self.target = goal.target.map(|mut t| {
            t.min_resolution = t.min_resolution.min(max);
            t
        });
        let before = self.work.resolution;
        if self.work.resolution > max || self.target.is_none() {
            self.work.resolution = max;
        }
        if self.work.resolution != before {
            self.resized = true;
        }
    }

    /// The workload for the next frame.
    pub fn current(&self) -> Workload {
        self.work
    }

    /// Whether the last adjustment changed the resolution (reported once).
    pub fn resized(&mut self) -> bool {
        std::mem::take(&mut self.resized)
    }

    /// Feeds the measured seconds of the frame just rendered; `view_moving`: the camera moved
    /// or cut in that frame (its image restarted or reprojects anyway). While the view is still
    /// the resolution only goes down, so a still view restarts a bounded number of times.
    pub fn observe(&mut self, seconds: f64, view_moving: bool) {
        let Some(t) = self.target else {
            return;
        };
        let s = self
            .smoothed
            .map_or(seconds as f32, |s| 0.7 * s + 0.3 * seconds as f32);
        self.smoothed = Some(s);
        if self.cooldown > 0 {
            self.cooldown -= 1;
            return;
        }
        let before = self.work;
        let w = &mut self.work;
        if s > 2.0 * t.frame_seconds {
            // Far too slow (the first frames, a heavy view): samples and path length go at
            // once, then the resolution in proportion (the cost follows the pixel count),
            // instead of one small step per three frames (seconds each at full resolution).
            if w.spp > t.min_spp || w.roulette_scale > t.min_roulette + 1e-6 {
                w.spp = t.min_spp;
                w.roulette_scale = t.min_roulette;
            } else if w.resolution > t.min_resolution + 1e-6 {
                let ratio = (t.frame_seconds / s).sqrt();
                w.resolution = (w.resolution * ratio).max(t.min_resolution);
            }
        } else if s > 1.1 * t.frame_seconds {
            if w.spp > t.min_spp {
                w.spp = (w.spp * 3 / 4).max(t.min_spp).min(w.spp - 1);
            } else if w.roulette_scale > t.min_roulette + 1e-6 {
                w.roulette_scale = (w.roulette_scale - 0.1).max(t.min_roulette);
            } else if w.resolution > t.min_resolution + 1e-6 {
                w.resolution = (w.resolution - 0.125).max(t.min_resolution);
            }
        } else if s < 0.75 * t.frame_seconds {
            if w.resolution < self.max_resolution - 1e-6 && view_moving {
                w.resolution = (w.resolution + 0.125).min(self.max_resolution);
            } else if w.roulette_scale < 1.0 {
                w.roulette_scale = (w.roulette_scale + 0.1).min(1.0);
            } else if w.spp < t.max_spp {
                w.spp = (w.spp + w.spp.div_ceil(4)).min(t.max_spp);
            }
        }
        if self.work != before {
            self.cooldown = 3;
            self.resized |= self.work.resolution != before.resolution;
            if s > 2.0 * t.frame_seconds {
                // Measure the new workload afresh, after the frame already under way.
                self.smoothed = None;
                self.cooldown = 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A synthetic renderer whose frame time is proportional to the work.
    fn cost(w: &Workload) -> f64 {
        0.002
            * w.spp as f64
            * (0.5 + 0.5 * w.roulette_scale as f64)
            * (w.resolution * w.resolution) as f64
    }

    #[test]
    fn converges_to_the_target_from_both_sides() {
        for start in [1, 64] {
            let mut s = Scaling::new(start, Some(ScalingTarget::new(0.02)));
            for _ in 0..400 {
                let w = s.current();
                s.observe(cost(&w), true);
            }
            let t = cost(&s.current());
            assert!(
                t <= 0.022 && t >= 0.75 * 0.02 * 0.7,
                "start {start}: {:?} costs {t}",
                s.current()
            );
        }
    }

    #[test]
    fn far_too_slow_reaches_the_target_within_a_few_frames() {
        // Full resolution costs 40× the target: steps of 1/8 would take some 30 frames.
        let target = 0.001;
        let mut s = Scaling::new(1, Some(ScalingTarget::new(target as f32)));
        let full = |w: &Workload| {
            0.04 * (w.resolution * w.resolution) as f64 * (0.5 + 0.5 * w.roulette_scale as f64)
        };
        let mut frames = 0;
        while full(&s.current()) > 2.0 * target {
            let w = s.current();
            s.observe(full(&w), true);
            frames += 1;
            assert!(frames < 12, "still {:?} after {frames} frames", s.current());
        }
        assert!(s.current().resolution >= 0.25);
    }

    #[test]
    fn a_goal_caps_the_resolution_and_retargets() {
        let mut s = Scaling::new(4, None);
        s.set_goal(ScalingGoal {
            target: None,
            max_resolution: 0.5,
        });
        assert_eq!(s.current().resolution, 0.5);
        assert!(s.resized());
        s.set_goal(ScalingGoal {
            target: None,
            max_resolution: 0.5,
        });
        assert!(!s.resized(), "the same goal again changes nothing");
        // With a target far above the cost, scaling climbs back only up to the cap.
        s.set_goal(ScalingGoal {
            target: Some(ScalingTarget::new(1.0)),
            max_resolution: 0.75,
        });
        for _ in 0..100 {
            s.observe(0.0001, true);
        }
        assert_eq!(s.current().resolution, 0.75);
    }

    #[test]
    fn gives_up_resolution_only_after_samples_and_roulette() {
        let mut s = Scaling::new(4, Some(ScalingTarget::new(0.001)));
        let mut seen_low_res_with_spp = false;
        for _ in 0..200 {
            let w = s.current();
            if w.resolution < 1.0 && (w.spp > 1 || w.roulette_scale > 0.5 + 1e-6) {
                seen_low_res_with_spp = true;
            }
            s.observe(1.0, true);
        }
        assert!(!seen_low_res_with_spp);
        assert_eq!(
            s.current(),
            Workload {
                spp: 1,
                roulette_scale: 0.5,
                resolution: 0.25
            }
        );
    }

    #[test]
    fn the_first_frame_is_traced_at_the_start_resolution_within_the_bounds() {
        let at = |start: f32| {
            let target = ScalingTarget {
                start_resolution: start,
                ..ScalingTarget::new(0.02)
            };
            Scaling::new(1, Some(target)).current().resolution
        };
        assert_eq!(at(1.0), 1.0);
        assert_eq!(at(0.25), 0.25);
        assert_eq!(at(0.5), 0.5);
        // Below the floor, above the output or not a number: clamped, or the output's.
        assert_eq!(at(0.1), 0.25);
        assert_eq!(at(3.0), 1.0);
        assert_eq!(at(f32::NAN), 1.0);
        assert_eq!(Scaling::new(1, None).current().resolution, 1.0);
    }

    #[test]
    fn a_still_view_never_raises_the_resolution_so_it_stops_restarting() {
        // A cost that sits between two resolution steps: stepping up is too slow, stepping
        // down is fast enough. Moving, the controller may swing; still, it must settle.
        let swinging = |w: &Workload| 0.2 * (w.resolution * w.resolution) as f64;
        let mut s = Scaling::new(1, Some(ScalingTarget::new(0.02)));
        let mut restarts = 0;
        for _ in 0..300 {
            let w = s.current();
            s.observe(swinging(&w), false);
            if s.resized() {
                restarts += 1;
            }
        }
        assert!(restarts <= 8, "{restarts} restarts of a still view");
        let settled = s.current();
        for _ in 0..100 {
            let w = s.current();
            s.observe(swinging(&w), false);
            assert!(
                !s.resized(),
                "the resolution changed on a still view: {:?}",
                s.current()
            );
        }
        assert_eq!(s.current(), settled);
        // Moving, it climbs again when fast.
        let mut climbed = false;
        for _ in 0..20 {
            s.observe(0.001, true);
            climbed |= s.current().resolution > settled.resolution;
        }
        assert!(climbed);
    }
}
