//! The explorer's action clips, made of sines like the locomotion in `clips`: `push` (a
//! looping push walk: leaning in, arms forward at shoulder height, short steps), `pick_up`
//! (one-shot: crouch with the feet kept flat where they stand, reach down, stand up) and
//! `celebrate` (one-shot: arms thrown up in a V, fists pumping, a small bounce).
//!
//! Conventions as in `clips` and `skeleton`: rest rotations are the identity, a positive pitch
//! swings a hanging limb's end backwards (−Z) and leans the spine forward (+Z), a positive
//! roll swings a left limb outwards. `a` is the cycle's angle, radians in [0, 2π); a one-shot's
//! envelope is 0 at both ends, so it starts and ends at the rest pose (and blends into
//! locomotion cleanly). Must not: build geometry.

use std::f64::consts::FRAC_PI_2;

use super::clips::{Pose, arms, gait};
use super::skeleton::{ANKLE_Y, HIP, KNEE_Y, joint};

/// Thigh and shin lengths, metres.
const THIGH_M: f64 = (HIP.1 - KNEE_Y) as f64;
const SHIN_M: f64 = (KNEE_Y - ANKLE_Y) as f64;

/// Bends both legs so the thighs swing `thigh` radians forward while the ankles stay under
/// the hips and the feet flat, and lowers the hips to keep the feet on the ground.
fn crouch(pose: &mut Pose, thigh: f64) {
    use joint::*;
    // The shin leans back by `shin` so the ankle is straight below the hip joint.
    let shin = (THIGH_M * thigh.sin() / SHIN_M).clamp(-1.0, 1.0).asin();
    let drop = THIGH_M + SHIN_M - (THIGH_M * thigh.cos() + SHIN_M * shin.cos());
    pose.hips.y -= drop;
    for [upper, lower, foot] in [
        [UPPER_LEG_L, LOWER_LEG_L, FOOT_L],
        [UPPER_LEG_R, LOWER_LEG_R, FOOT_R],
    ] {
        pose.set(upper, -thigh, 0.0, 0.0);
        pose.set(lower, thigh + shin, 0.0, 0.0);
        pose.set(foot, -shin, 0.0, 0.0);
    }
}

/// 0 at the start and end of a one-shot, rising to 1 and holding there for the middle
/// (`hold` > 1 holds longer).
fn envelope(a: f64, hold: f64) -> f64 {
    (hold * 0.5 * (1.0 - a.cos())).min(1.0)
}

/// Pushing a block: short steps, the body leaning in, both arms forward at shoulder height
/// with the elbows a little bent, giving a little with each step.
pub(super) fn push(a: f64) -> Pose {
    use joint::*;
    let lean = 0.45;
    let mut pose = gait(a, 0.3, 0.18, 0.45, 0.0, 0.0, lean, 0.02);
    // The arms hang from the leaning chest: `lean` already swings them back.
    let give = 0.06 * (2.0 * a).sin();
    let reach = -FRAC_PI_2 - lean + 0.08 + give;
    // The shoulders reach forward with the arms (the clavicles turn about +Y).
    pose.set(CLAVICLE_L, 0.0, -0.15, 0.0);
    pose.set(CLAVICLE_R, 0.0, 0.15, 0.0);
    pose.set(UPPER_ARM_L, reach, 0.0, -0.12);
    pose.set(UPPER_ARM_R, reach, 0.0, 0.12);
    pose.set(LOWER_ARM_L, -0.3 - give, 0.0, 0.0);
    pose.set(LOWER_ARM_R, -0.3 - give, 0.0, 0.0);
    pose.set(HAND_L, -0.9, 0.0, 0.0);
    pose.set(HAND_R, -0.9, 0.0, 0.0);
    pose
}

/// Picking something up: crouch, lean in and reach down in front of the feet, stand up.
pub(super) fn pick_up(a: f64) -> Pose {
    use joint::*;
    let e = envelope(a, 1.3);
    let mut pose = Pose::rest();
    crouch(&mut pose, 1.1 * e);
    let (spine, chest) = (0.45 * e, 0.35 * e);
    pose.set(SPINE, spine, 0.0, 0.0);
    pose.set(CHEST, chest, 0.0, 0.0);
    pose.set(NECK, -0.25 * e, 0.0, 0.0);
    pose.set(HEAD, 0.25 * e, 0.0, 0.0);
    // Arms 0.55 rad forward of straight down in the world, reaching between the knees.
    arms(
        &mut pose,
        -(0.55 * e + spine + chest),
        false,
        0.12 * e,
        0.2 * e,
    );
    pose
}

/// Celebrating: arms thrown up in a V, fists pumping, head up, a small bounce of the knees.
pub(super) fn celebrate(a: f64) -> Pose {
    use joint::*;
    let e = envelope(a, 2.0);
    let mut pose = Pose::rest();
    let bounce = e * (2.0 * a).sin().powi(2);
    crouch(&mut pose, 0.35 * bounce);
    pose.set(SPINE, -0.08 * e, 0.0, 0.0);
    pose.set(CHEST, -0.06 * e, 0.0, 0.0);
    pose.set(HEAD, -0.3 * e, 0.0, 0.0);
    let pump = e * (3.0 * a).sin().powi(2);
    arms(&mut pose, -0.2 * e, false, 2.6 * e, 0.3 * e + 0.5 * pump);
    pose
}
