//! The hero's skeleton: 17 joints, their names and rest positions (metres; the hero stands
//! with feet at y = 0, faces +Z, its left is +X). Every rest rotation is the identity, so a
//! clip's rotation keys are the joints' whole local rotations and the limbs hang straight
//! down at rest. Must not: build geometry or clips.

use crate::gltf_skin::JointSpec;

/// Joint indices (into [`joints`]).
pub mod joint {
    pub const HIPS: u16 = 0;
    pub const SPINE: u16 = 1;
    pub const CHEST: u16 = 2;
    pub const NECK: u16 = 3;
    pub const HEAD: u16 = 4;
    pub const UPPER_ARM_L: u16 = 5;
    pub const LOWER_ARM_L: u16 = 6;
    pub const HAND_L: u16 = 7;
    pub const UPPER_ARM_R: u16 = 8;
    pub const LOWER_ARM_R: u16 = 9;
    pub const HAND_R: u16 = 10;
    pub const UPPER_LEG_L: u16 = 11;
    pub const LOWER_LEG_L: u16 = 12;
    pub const FOOT_L: u16 = 13;
    pub const UPPER_LEG_R: u16 = 14;
    pub const LOWER_LEG_R: u16 = 15;
    pub const FOOT_R: u16 = 16;
}

/// How many joints the skin has.
pub const JOINT_COUNT: usize = 17;

/// Height of the hips joint at rest, metres.
pub const HIPS_Y: f32 = 0.95;
/// Shoulder joints: ±x, height (metres).
pub const SHOULDER: (f32, f32) = (0.255, 1.45);
/// Elbow and wrist heights, metres.
pub const ELBOW_Y: f32 = 1.17;
pub const WRIST_Y: f32 = 0.92;
/// Hip joints: ±x, height (metres).
pub const HIP: (f32, f32) = (0.095, 0.90);
/// Knee and ankle heights, metres.
pub const KNEE_Y: f32 = 0.48;
pub const ANKLE_Y: f32 = 0.08;

/// Name, parent and rest translation (relative to the parent, metres) of every joint.
const TABLE: [(&str, Option<usize>, [f32; 3]); JOINT_COUNT] = [
    ("hips", None, [0.0, HIPS_Y, 0.0]),
    ("spine", Some(0), [0.0, 0.10, 0.0]),
    ("chest", Some(1), [0.0, 0.20, 0.0]),
    ("neck", Some(2), [0.0, 0.24, 0.0]),
    ("head", Some(3), [0.0, 0.08, 0.0]),
    ("upper_arm_l", Some(2), [SHOULDER.0, SHOULDER.1 - 1.25, 0.0]),
    ("lower_arm_l", Some(5), [0.0, ELBOW_Y - SHOULDER.1, 0.0]),
    ("hand_l", Some(6), [0.0, WRIST_Y - ELBOW_Y, 0.0]),
    (
        "upper_arm_r",
        Some(2),
        [-SHOULDER.0, SHOULDER.1 - 1.25, 0.0],
    ),
    ("lower_arm_r", Some(8), [0.0, ELBOW_Y - SHOULDER.1, 0.0]),
    ("hand_r", Some(9), [0.0, WRIST_Y - ELBOW_Y, 0.0]),
    ("upper_leg_l", Some(0), [HIP.0, HIP.1 - HIPS_Y, 0.0]),
    ("lower_leg_l", Some(11), [0.0, KNEE_Y - HIP.1, 0.0]),
    ("foot_l", Some(12), [0.0, ANKLE_Y - KNEE_Y, 0.0]),
    ("upper_leg_r", Some(0), [-HIP.0, HIP.1 - HIPS_Y, 0.0]),
    ("lower_leg_r", Some(14), [0.0, KNEE_Y - HIP.1, 0.0]),
    ("foot_r", Some(15), [0.0, ANKLE_Y - KNEE_Y, 0.0]),
];

/// The joints, parents first.
pub fn joints() -> Vec<JointSpec> {
    TABLE
        .iter()
        .map(|&(name, parent, translation)| JointSpec {
            name: name.to_string(),
            parent,
            translation,
            rotation: [0.0, 0.0, 0.0, 1.0],
        })
        .collect()
}
