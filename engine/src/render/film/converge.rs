//! Converging (Brigade §4.5): how much of each new frame enters the displayed image,
//! `C = (1 − f)·C_prev + f·C_new`.
//!
//! Owns: the one function that chooses `f` (and so resets accumulation): a full reset on cuts
//! and on camera motion above a threshold (the film has no reprojection, so old pixels would
//! smear; the denoiser reprojects per pixel and uses [`Converge::blend_reprojected`]); an exact running mean (`f = 1/n` for the n-th still frame) while nothing moves; and a
//! floor on `f` while objects move so that they do not leave ghosts. After a floored blend the
//! frame count drops to the film's effective count, so that once motion stops new frames get
//! the weight the film's real noise calls for (see [`Converge::blend`]). The light is treated
//! like motion: a sun that jumps (a time set, a new sky) restarts the image, a sun that moves
//! slowly (the day flowing) keeps a floor of its own. Render thread.
//! Must not: look at pixels.

use crate::commit::Motion;

/// The knobs of the policy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergePolicy {
    /// Smallest `f` while any object moves: the previous frames' weight decays at least this
    /// fast, so a moving object's ghost fades within about 1/floor frames. 1 resets the image
    /// on every frame in which an object moves. Measured in `docs/ACCURACY.md` ("Ghosting").
    pub moving_floor: f32,
    /// Camera motion (metres + radians per frame) above which the image restarts.
    pub camera_reset: f32,
    /// Smallest `f` while the sun moves slowly (`Motion::lighting` above 0, at most
    /// `lighting_reset`): a shadow's old place fades within about 1/floor frames. Lower than
    /// `moving_floor`: a flowing day moves the sun by thousandths of a degree a frame.
    pub lighting_floor: f32,
    /// Sun motion (degrees per commit) above which the image restarts (any other change of
    /// the sky or sun is infinite and restarts it too).
    pub lighting_reset_deg: f32,
}

impl Default for ConvergePolicy {
    fn default() -> Self {
        Self {
            moving_floor: 0.25,
            camera_reset: 1e-4,
            lighting_floor: 0.1,
            lighting_reset_deg: 0.5,
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
    ///
    /// A floored blend keeps an exponential moving average whose noise is that of
    /// `(2 − f) / f` frames (Σ wᵢ² = f / (2 − f) in steady state), not of every frame since the
    /// last reset; the count is capped there, so the first still frame after motion gets
    /// `f = f_floor / 2` (1/8 for the default floor) instead of 1/(frames since the reset).
    /// Without the cap, 100 moving frames left the film after 50 further still frames 1.9×
    /// noisier (in standard deviation) than an exact mean of its effective frames for the
    /// default floor, 4.8× for a floor of 1 (see the test below).
    pub fn blend(&mut self, motion: &Motion) -> f32 {
        if motion.cut
            || motion.camera > self.policy.camera_reset
            || motion.lighting > self.policy.lighting_reset_deg
        {
            self.frames = 0;
        }
        self.frames += 1;
        let mut f = 1.0 / self.frames as f32;
        let mut floor = if motion.objects {
            self.policy.moving_floor
        } else {
            0.0
        };
        if motion.lighting > 0.0 {
            floor = floor.max(self.policy.lighting_floor);
        }
        if floor > f {
            f = floor.min(1.0);
            let effective = ((2.0 - f) / f).round().max(1.0) as u32;
            self.frames = self.frames.min(effective);
        }
        f
    }

    /// The blend factor `f` for the next frame when the consumer reprojects its history per
    /// pixel (the denoiser, `denoise::reproject`): camera motion no longer restarts the image,
    /// it is floored as moving objects are (old pixels that survive reprojection still fade
    /// within about 1/floor frames); only cuts restart.
    pub fn blend_reprojected(&mut self, motion: &Motion) -> f32 {
        let moving = motion.objects || motion.camera > self.policy.camera_reset;
        self.blend(&Motion {
            cut: motion.cut,
            camera: 0.0,
            objects: moving,
            lighting: motion.lighting,
        })
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

    #[test]
    fn a_jumping_sun_restarts_a_slow_sun_floors_no_change_averages() {
        let mut c = Converge::default();
        let still = Motion::default();
        for _ in 0..20 {
            c.blend(&still);
        }
        // An unchanged sky keeps averaging: the 21st still frame gets 1/21.
        assert!((c.blend(&still) - 1.0 / 21.0).abs() < 1e-7);
        // The day flowing: a thousandth of a degree a frame keeps the lighting floor.
        let slow = Motion {
            lighting: 1e-3,
            ..still
        };
        for _ in 0..10 {
            assert_eq!(c.blend(&slow), c.policy.lighting_floor);
        }
        // A time set hours away (or a new sky): the film restarts.
        let jump = Motion {
            lighting: 30.0,
            ..still
        };
        assert_eq!(c.blend(&jump), 1.0);
        assert_eq!(c.blend(&still), 0.5);
        let other = Motion {
            lighting: f32::INFINITY,
            ..still
        };
        assert_eq!(c.blend(&other), 1.0);
        assert_eq!(c.blend_reprojected(&jump), 1.0);
    }

    /// √Σ wᵢ² of the film after the blend factors `fs` (each frame's noise weight).
    fn noise_factor(fs: &[f32]) -> f64 {
        let (mut sum, mut later) = (0.0f64, 1.0f64);
        for &f in fs.iter().rev() {
            sum += (f as f64 * later).powi(2);
            later *= 1.0 - f as f64;
        }
        sum.sqrt()
    }

    #[test]
    fn after_motion_stops_the_film_converges_like_an_exact_mean_of_its_effective_frames() {
        for floor in [0.1f32, 0.25, 0.5, 1.0] {
            let mut c = Converge::new(ConvergePolicy {
                moving_floor: floor,
                ..Default::default()
            });
            let moving = Motion {
                objects: true,
                ..Default::default()
            };
            let mut fs: Vec<f32> = (0..100).map(|_| c.blend(&moving)).collect();
            let effective_moving = 1.0 / noise_factor(&fs).powi(2);
            fs.extend((0..50).map(|_| c.blend(&Motion::default())));
            // An exact mean over the effective frames and the 50 still ones.
            let ideal = 1.0 / (effective_moving + 50.0).sqrt();
            let ours = noise_factor(&fs);
            // Rounding the effective count to whole frames costs at most a few per cent.
            assert!(
                ours <= 1.03 * ideal,
                "floor {floor}: {ours} vs ideal {ideal}"
            );
        }
    }
}
