//! Converging (Brigade §4.5): how much of each new frame enters the displayed image,
//! `C = (1 − f)·C_prev + f·C_new`.
//!
//! Owns: the one function that chooses `f` (and so resets accumulation): a full reset on cuts
//! and on camera motion above a threshold (there is no reprojection yet, so old pixels would
//! smear); an exact running mean (`f = 1/n` for the n-th still frame) while nothing moves; and a
//! floor on `f` while objects move so that they do not leave ghosts. Render thread.
//! Must not: look at pixels.

use crate::commit::Motion;

/// The knobs of the policy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergePolicy {
    /// Smallest `f` while any object moves: the previous frames' weight decays at least this
    /// fast, so a moving object's ghost fades within about 1/floor frames.
    pub moving_floor: f32,
    /// Camera motion (metres + radians per frame) above which the image restarts.
    pub camera_reset: f32,
}

impl Default for ConvergePolicy {
    fn default() -> Self {
        Self {
            moving_floor: 0.25,
            camera_reset: 1e-4,
        }
    }
}

/// The converging state: frames blended since the last reset.
#[derive(Clone, Debug, Default)]
pub struct Converge {
    pub policy: ConvergePolicy,
    frames: u32,
}

impl Converge {
    pub fn new(policy: ConvergePolicy) -> Self {
        Self { policy, frames: 0 }
    }

    /// Forgets the accumulated image (the next blend factor is 1).
    pub fn reset(&mut self) {
        self.frames = 0;
    }

    /// The blend factor `f` for the next frame.
    pub fn blend(&mut self, motion: &Motion) -> f32 {
        if motion.cut || motion.camera > self.policy.camera_reset {
            self.frames = 0;
        }
        self.frames += 1;
        let mut f = 1.0 / self.frames as f32;
        if motion.objects {
            f = f.max(self.policy.moving_floor);
        }
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn still_frames_average_moving_objects_floor_cuts_reset() {
        let mut c = Converge::default();
        let still = Motion::default();
        assert_eq!(c.blend(&still), 1.0);
        assert_eq!(c.blend(&still), 0.5);
        assert!((c.blend(&still) - 1.0 / 3.0).abs() < 1e-7);
        let moving = Motion {
            objects: true,
            ..still
        };
        for _ in 0..10 {
            assert!(c.blend(&moving) >= 0.25);
        }
        assert_eq!(c.blend(&Motion { cut: true, ..still }), 1.0);
        assert_eq!(
            c.blend(&Motion {
                camera: 0.1,
                ..still
            }),
            1.0
        );
        assert_eq!(c.blend(&still), 0.5);
    }
}
