//! The third-person follow camera: it orbits a pivot above the character (yaw and pitch from
//! the look input, pitch clamped) at a chosen distance, pulls in when geometry comes between
//! the pivot and where it wants to be, and eases back out when the way is clear — moving at
//! most a bounded distance per step either way, so it never pops.
//!
//! Owns: [`FollowCamera`] (tuning and state), [`CameraPose`], [`ease_distance`]. The way
//! out is probed with a few ray queries (the centre and four rays offset by the probe
//! radius, a thin sphere sweep) on the scene of the last commit, skipping the character's own
//! drawn mesh. Pulling in is fast (`pull_in_mps`), going out slow (`ease_out_mps`); a
//! wall that appears closer than the camera can move in one step is reached over a few
//! steps (at 20 m/s and 60 Hz, 0.33 m a step), the price of never jumping.
//! Main thread, in the game's fixed step. Must not: move the character or write the ECS
//! (the caller places its camera entity from the returned pose).
//! Units: metres, metres per second, radians; yaw 0 looks along −Z, positive turns right,
//! pitch positive looks up.

use glam::{Quat, Vec2, Vec3};
use hecs::Entity;

use crate::query::Queries;
use crate::trace::Ray;

/// Hits on ignored entities a probe ray looks past before giving up.
const MAX_SKIPS: usize = 8;

/// Where the camera is after a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraPose {
    /// Metres, world space.
    pub position: Vec3,
    /// Looks along its local −Z with +Y up.
    pub rotation: Quat,
    /// Metres from the pivot now.
    pub distance_m: f32,
    /// How far the way out is clear this step, metres (≤ the wanted distance).
    pub allowed_m: f32,
}

/// An orbit camera behind a character.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FollowCamera {
    pub yaw_rad: f32,
    pub pitch_rad: f32,
    /// Lowest and highest pitch, radians.
    pub pitch_limits_rad: (f32, f32),
    /// The wanted distance from the pivot, metres.
    pub distance_m: f32,
    /// The closest the camera comes when pulled in, metres.
    pub min_distance_m: f32,
    /// Pivot height above the body's centre, metres.
    pub pivot_height_m: f32,
    /// Radius of the probe around the camera and room kept to walls, metres.
    pub probe_radius_m: f32,
    /// Fastest pull-in, m/s.
    pub pull_in_mps: f32,
    /// Fastest ease back out, m/s.
    pub ease_out_mps: f32,
    /// Distance now, metres.
    pub current_m: f32,
}

impl Default for FollowCamera {
    fn default() -> Self {
        Self {
            yaw_rad: 0.0,
            pitch_rad: -0.35,
            pitch_limits_rad: (-1.2, 0.5),
            distance_m: 4.5,
            min_distance_m: 0.6,
            pivot_height_m: 0.45,
            probe_radius_m: 0.2,
            pull_in_mps: 20.0,
            ease_out_mps: 2.5,
            current_m: 4.5,
        }
    }
}

impl FollowCamera {
    /// The camera's rotation for its yaw and pitch.
    pub fn rotation(&self) -> Quat {
        Quat::from_rotation_y(-self.yaw_rad) * Quat::from_rotation_x(self.pitch_rad)
    }

    /// The most a step of `dt_seconds` moves the camera along its boom, metres.
    pub fn max_step_m(&self, dt_seconds: f32) -> f32 {
        self.pull_in_mps.max(self.ease_out_mps) * dt_seconds.max(0.0)
    }

    /// One fixed step of `dt_seconds`: turns by `look` (radians, as in
    /// [`super::PlayerInput::look`]: x positive turns left, y positive looks up),
    /// probes the way from the pivot above `body_centre` back to the wanted distance on
    /// `queries` (skipping hits on `ignore`), and eases the distance. Returns the new pose.
    pub fn update(
        &mut self,
        look: Vec2,
        body_centre: Vec3,
        queries: &Queries<'_>,
        ignore: &[Entity],
        dt_seconds: f32,
    ) -> CameraPose {
        if look.is_finite() {
            self.yaw_rad = (self.yaw_rad - look.x).rem_euclid(std::f32::consts::TAU);
            let (low, high) = self.pitch_limits_rad;
            self.pitch_rad = (self.pitch_rad + look.y).clamp(low, high);
        }
        let rotation = self.rotation();
        let pivot = body_centre + Vec3::Y * self.pivot_height_m;
        let back = rotation * Vec3::Z;
        let allowed = self.clear_distance(pivot, rotation, queries, ignore);
        self.current_m = ease_distance(
            self.current_m,
            allowed.max(self.min_distance_m),
            self.pull_in_mps,
            self.ease_out_mps,
            dt_seconds,
        );
        CameraPose {
            position: pivot + back * self.current_m,
            rotation,
            distance_m: self.current_m,
            allowed_m: allowed,
        }
    }

    /// How far back from `pivot` the camera may go (at most the wanted distance): the nearest
    /// hit of five rays (centre, and offset by the probe radius right, left, up and down at
    /// the far end), less the probe radius.
    pub fn clear_distance(
        &self,
        pivot: Vec3,
        rotation: Quat,
        queries: &Queries<'_>,
        ignore: &[Entity],
    ) -> f32 {
        let wanted = self.distance_m.max(0.0);
        let reach = wanted + self.probe_radius_m;
        let back = rotation * Vec3::Z;
        let (right, up) = (rotation * Vec3::X, rotation * Vec3::Y);
        let r = self.probe_radius_m;
        let ends = [Vec3::ZERO, right * r, -right * r, up * r, -up * r];
        let mut allowed = wanted;
        for offset in ends {
            let to = back * reach + offset;
            let length = to.length();
            let Some(direction) = to.try_normalize() else {
                continue;
            };
            if let Some(t) = first_hit(queries, pivot, direction, length, ignore) {
                // Along the boom, the hit is this far back.
                let along = t * direction.dot(back);
                allowed = allowed.min(along - r);
            }
        }
        allowed.max(0.0)
    }
}

/// The distance `current` moved towards `target` in a step of `dt_seconds`: in at most
/// `pull_in_mps`, out at most `ease_out_mps` (metres per second).
pub fn ease_distance(
    current: f32,
    target: f32,
    pull_in_mps: f32,
    ease_out_mps: f32,
    dt_seconds: f32,
) -> f32 {
    let dt = dt_seconds.max(0.0);
    if !target.is_finite() {
        return current;
    }
    if target < current {
        current - (current - target).min(pull_in_mps * dt)
    } else {
        current + (target - current).min(ease_out_mps * dt)
    }
}

/// The distance to the first hit along `direction` (unit) from `origin` within `max_t`
/// metres that is not on an `ignore`d entity.
fn first_hit(
    queries: &Queries<'_>,
    origin: Vec3,
    direction: Vec3,
    max_t: f32,
    ignore: &[Entity],
) -> Option<f32> {
    let mut t_min = 0.0;
    for _ in 0..MAX_SKIPS {
        let ray = Ray {
            origin,
            t_min,
            direction,
            t_max: max_t,
        };
        let hit = queries.closest(&ray)?;
        match hit.entity {
            Some(e) if ignore.contains(&e) => t_min = hit.t + 1e-3,
            _ => return Some(hit.t),
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f32 = 1.0 / 60.0;

    #[test]
    fn pulls_in_fast_and_eases_out_slowly_in_bounded_steps() {
        let camera = FollowCamera::default();
        let (fast, slow) = (camera.pull_in_mps * DT, camera.ease_out_mps * DT);
        let mut d = 4.5;
        let mut steps_in = 0;
        while d > 1.0 {
            let next = ease_distance(d, 1.0, camera.pull_in_mps, camera.ease_out_mps, DT);
            assert!(d - next <= fast + 1e-6 && next < d, "{d} → {next}");
            d = next;
            steps_in += 1;
        }
        assert_eq!(d, 1.0, "lands on the target, no overshoot");
        // 3.5 m at 20 m/s: 0.175 s, 11 steps of a third of a metre at most.
        assert_eq!(steps_in, (3.5 / fast).ceil() as usize);
        let mut steps_out = 0;
        while d < 4.5 {
            let next = ease_distance(d, 4.5, camera.pull_in_mps, camera.ease_out_mps, DT);
            assert!(next - d <= slow + 1e-6 && next > d, "{d} → {next}");
            d = next;
            steps_out += 1;
        }
        assert_eq!(d, 4.5);
        assert!(
            steps_out > 5 * steps_in,
            "{steps_out} steps out, {steps_in} in"
        );
        assert_eq!(ease_distance(2.0, f32::NAN, 20.0, 2.5, DT), 2.0);
    }

    #[test]
    fn the_boom_points_behind_and_above_for_a_downward_pitch() {
        let camera = FollowCamera {
            yaw_rad: std::f32::consts::FRAC_PI_2,
            pitch_rad: -0.5,
            ..FollowCamera::default()
        };
        let rotation = camera.rotation();
        let forward = rotation * Vec3::NEG_Z;
        // Yawed a quarter turn right, the camera looks along +X and down.
        assert!(
            forward.x > 0.8 && forward.y < -0.4 && forward.z.abs() < 1e-5,
            "{forward}"
        );
        let back = rotation * Vec3::Z;
        assert!(back.y > 0.4 && back.x < -0.8, "{back}");
    }
}
