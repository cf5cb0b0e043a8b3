//! The hero's clips, made of sines: `idle` (breathing, a slow look around), `walk`, `run`,
//! `jump` (tucked, arms up) and `fall` (arms and legs flailing), and the explorer's actions
//! (`actions`): `push`, `pick_up` and `celebrate`. Each is one cycle: keys every 1/30 s over
//! the clip's period, the last key equal to the first (a loop is seamless, a one-shot starts
//! and ends at rest). Every clip animates the hips' translation and all 21 joints' rotations.
//!
//! Conventions (`skeleton`): rest rotations are the identity and limbs hang down, so a
//! positive rotation about X swings a limb's end backwards (−Z) and a positive one about Z
//! swings a left (+X) limb outwards. The walk's cycle is one stride of each leg (2 m at the
//! 2 m/s reference speed of the third-person level's `walk` state). Values are computed in
//! f64 and rounded to 1e-6 so the bytes do not depend on the last bit of `sin`/`cos`.
//! Must not: build geometry.

use std::f64::consts::{PI, TAU};

use glam::{DQuat, DVec3};

use super::actions::{celebrate, pick_up, push};
use super::skeleton::{HIPS_Y, JOINT_COUNT, joint};
use crate::gltf_skin::{ChannelPath, ChannelSpec, ClipSpec};

/// Keys per second.
const KEY_RATE_HZ: f64 = 30.0;

/// One pose: the hips' translation (metres) and every joint's local rotation.
pub(super) struct Pose {
    pub(super) hips: DVec3,
    rotations: [DQuat; JOINT_COUNT],
}

impl Pose {
    pub(super) fn rest() -> Self {
        Self {
            hips: DVec3::new(0.0, f64::from(HIPS_Y), 0.0),
            rotations: [DQuat::IDENTITY; JOINT_COUNT],
        }
    }

    /// Sets joint `j` to yaw (about Y) · roll (about Z) · pitch (about X), radians.
    pub(super) fn set(&mut self, j: u16, pitch: f64, yaw: f64, roll: f64) {
        self.rotations[usize::from(j)] = DQuat::from_rotation_y(yaw)
            * DQuat::from_rotation_z(roll)
            * DQuat::from_rotation_x(pitch);
    }
}

/// How much of an arm's raise beyond [`SHRUG_FROM_RAD`] the clavicle takes (the shoulder
/// rises as the arm goes up), the rest being the shoulder joint's.
const SHRUG_SHARE: f64 = 0.25;
/// The raise (radians away from the body) below which the clavicle stays at rest.
const SHRUG_FROM_RAD: f64 = 0.3;

/// Sets both arms: `swing` about X for the left arm (the right one gets `-swing` when
/// `mirror_swing`), `out` radians away from the body (the clavicles take a share of a large
/// raise), elbows bent forward by `elbow`.
pub(super) fn arms(pose: &mut Pose, swing: f64, mirror_swing: bool, out: f64, elbow: f64) {
    use joint::*;
    let right_swing = if mirror_swing { -swing } else { swing };
    let shrug = SHRUG_SHARE * (out - SHRUG_FROM_RAD).max(0.0);
    pose.set(CLAVICLE_L, 0.0, 0.0, shrug);
    pose.set(CLAVICLE_R, 0.0, 0.0, -shrug);
    pose.set(UPPER_ARM_L, swing, 0.0, out - shrug);
    pose.set(UPPER_ARM_R, right_swing, 0.0, shrug - out);
    pose.set(LOWER_ARM_L, -elbow, 0.0, 0.0);
    pose.set(LOWER_ARM_R, -elbow, 0.0, 0.0);
}

/// A gait: legs swing `leg` radians each way, knees bend `knee_min + knee` during the swing
/// forward, arms swing `arm` opposite, elbows bent `elbow`, the body leans `lean` forward
/// and bobs `bob` metres twice per cycle; the toes bend up as a leg pushes off behind.
/// `a`: the cycle's angle, radians.
#[allow(clippy::too_many_arguments)]
pub(super) fn gait(
    a: f64,
    leg: f64,
    knee_min: f64,
    knee: f64,
    arm: f64,
    elbow: f64,
    lean: f64,
    bob: f64,
) -> Pose {
    use joint::*;
    let mut pose = Pose::rest();
    pose.hips.y += bob * ((2.0 * a).cos() - 1.0) * 0.5;
    let swing = a.sin();
    pose.set(HIPS, 0.0, 0.08 * swing, 0.0);
    pose.set(SPINE, lean * 0.6, 0.0, 0.0);
    pose.set(CHEST, lean * 0.4, -0.14 * swing, 0.0);
    pose.set(NECK, -lean * 0.5, 0.0, 0.0);
    pose.set(HEAD, -lean * 0.3, 0.06 * swing, 0.0);
    for (phase, [upper, lower, foot, toes]) in [
        (0.0, [UPPER_LEG_L, LOWER_LEG_L, FOOT_L, TOES_L]),
        (PI, [UPPER_LEG_R, LOWER_LEG_R, FOOT_R, TOES_R]),
    ] {
        let b = a + phase;
        let thigh = -leg * b.sin();
        let bend = knee_min + knee * (0.5 + 0.5 * b.cos()).powi(2);
        pose.set(upper, thigh, 0.0, 0.0);
        pose.set(lower, bend, 0.0, 0.0);
        pose.set(foot, -0.5 * (thigh + bend), 0.0, 0.0);
        pose.set(toes, -0.8 * thigh.max(0.0), 0.0, 0.0);
    }
    arms(&mut pose, arm * swing, true, 0.06, elbow);
    pose
}

fn idle(a: f64) -> Pose {
    use joint::*;
    let mut pose = Pose::rest();
    let breath = a.sin();
    pose.hips.y += 0.004 * breath;
    pose.set(SPINE, 0.015 * breath, 0.0, 0.0);
    pose.set(CHEST, -0.03 * breath, 0.0, 0.0);
    pose.set(NECK, 0.015 * (a + 0.5).sin(), 0.0, 0.0);
    pose.set(HEAD, 0.0, 0.12 * breath, 0.0);
    arms(&mut pose, 0.03 * breath, false, 0.08 + 0.02 * breath, 0.15);
    pose
}

fn walk(a: f64) -> Pose {
    gait(a, 0.45, 0.08, 0.6, 0.35, 0.25, 0.05, 0.025)
}

fn run(a: f64) -> Pose {
    gait(a, 0.8, 0.25, 1.25, 0.7, 1.3, 0.22, 0.05)
}

fn jump(a: f64) -> Pose {
    use joint::*;
    let mut pose = Pose::rest();
    let s = a.sin();
    pose.set(SPINE, 0.08, 0.0, 0.0);
    pose.set(HEAD, -0.1, 0.0, 0.0);
    for (upper, lower, foot, k) in [
        (UPPER_LEG_L, LOWER_LEG_L, FOOT_L, 1.0),
        (UPPER_LEG_R, LOWER_LEG_R, FOOT_R, -1.0),
    ] {
        pose.set(upper, -0.7 + 0.08 * k * s, 0.0, 0.0);
        pose.set(lower, 1.1 + 0.08 * s, 0.0, 0.0);
        pose.set(foot, -0.3, 0.0, 0.0);
    }
    arms(&mut pose, -0.5, false, 1.5 + 0.1 * s, 0.5);
    pose
}

fn fall(a: f64) -> Pose {
    use joint::*;
    let mut pose = Pose::rest();
    let s = a.sin();
    pose.set(SPINE, -0.1, 0.0, 0.0);
    pose.set(HEAD, 0.1, 0.0, 0.0);
    for (upper, lower, k) in [
        (UPPER_LEG_L, LOWER_LEG_L, 1.0),
        (UPPER_LEG_R, LOWER_LEG_R, -1.0),
    ] {
        pose.set(upper, -0.3 + 0.3 * k * s, 0.0, 0.0);
        pose.set(lower, 0.5 + 0.25 * k * (a + 1.0).cos(), 0.0, 0.0);
    }
    pose.set(CLAVICLE_L, 0.0, 0.0, 0.15);
    pose.set(CLAVICLE_R, 0.0, 0.0, -0.15);
    pose.set(UPPER_ARM_L, 0.35 * s, 0.0, 0.85 + 0.35 * s);
    pose.set(UPPER_ARM_R, -0.35 * s, 0.0, -0.85 + 0.35 * s);
    pose.set(LOWER_ARM_L, -0.4, 0.0, 0.0);
    pose.set(LOWER_ARM_R, -0.4, 0.0, 0.0);
    pose
}

fn round6(v: f64) -> f32 {
    ((v * 1e6).round() / 1e6) as f32
}

/// Samples `pose_at` (the cycle's angle, radians) over `period_s` seconds into a clip.
fn clip(name: &str, period_s: f64, pose_at: fn(f64) -> Pose) -> ClipSpec {
    let keys = (period_s * KEY_RATE_HZ).round().max(2.0) as usize;
    let poses: Vec<Pose> = (0..keys)
        .map(|i| pose_at(TAU * i as f64 / keys as f64))
        .collect();
    // The closing key repeats the first, so the loop is seamless.
    let at = |i: usize| &poses[i % keys];
    let times = (0..=keys)
        .map(|i| round6(period_s * i as f64 / keys as f64))
        .collect();
    let mut channels = vec![ChannelSpec {
        joint: usize::from(joint::HIPS),
        path: ChannelPath::Translation,
        values: (0..=keys)
            .flat_map(|i| at(i).hips.to_array().map(round6))
            .collect(),
    }];
    for j in 0..JOINT_COUNT {
        channels.push(ChannelSpec {
            joint: j,
            path: ChannelPath::Rotation,
            values: (0..=keys)
                .flat_map(|i| at(i).rotations[j].normalize().to_array().map(round6))
                .collect(),
        });
    }
    ClipSpec {
        name: name.to_string(),
        times,
        channels,
    }
}

/// The eight clips, in file order (`hero::CLIPS`).
pub fn clips() -> Vec<ClipSpec> {
    vec![
        clip("idle", 3.0, idle),
        clip("walk", 1.0, walk),
        clip("run", 0.7, run),
        clip("jump", 0.8, jump),
        clip("fall", 1.0, fall),
        clip("push", 1.2, push),
        clip("pick_up", 1.4, pick_up),
        clip("celebrate", 1.6, celebrate),
    ]
}
