//! The hero's skeleton: 21 joints, their names and rest positions (metres; the hero stands
//! with feet at y = 0, faces +Z, its left is +X). Every rest rotation is the identity, so a
//! clip's rotation keys are the joints' whole local rotations and the limbs hang straight
//! down at rest. A clavicle on each side carries the arm from the chest (the shoulder shrugs
//! and reaches), and a toe joint at each ball of the foot bends the boot's front as the heel
//! lifts. Must not: build geometry or clips.

use crate::gltf_skin::JointSpec;

/// Joint indices (into [`joints`]): parents first.
pub mod joint {
    pub const HIPS: u16 = 0;
    pub const SPINE: u16 = 1;
    pub const CHEST: u16 = 2;
    pub const NECK: u16 = 3;
    pub const HEAD: u16 = 4;
    pub const CLAVICLE_L: u16 = 5;
    pub const UPPER_ARM_L: u16 = 6;
    pub const LOWER_ARM_L: u16 = 7;
    pub const HAND_L: u16 = 8;
    pub const CLAVICLE_R: u16 = 9;
    pub const UPPER_ARM_R: u16 = 10;
    pub const LOWER_ARM_R: u16 = 11;
    pub const HAND_R: u16 = 12;
    pub const UPPER_LEG_L: u16 = 13;
    pub const LOWER_LEG_L: u16 = 14;
    pub const FOOT_L: u16 = 15;
    pub const TOES_L: u16 = 16;
    pub const UPPER_LEG_R: u16 = 17;
    pub const LOWER_LEG_R: u16 = 18;
    pub const FOOT_R: u16 = 19;
    pub const TOES_R: u16 = 20;
}

/// How many joints the skin has.
pub const JOINT_COUNT: usize = 21;

/// Height of the hips joint at rest, metres.
pub const HIPS_Y: f32 = 0.95;
/// Height of the chest joint at rest, metres.
pub const CHEST_Y: f32 = 1.25;
/// Clavicle joints (where each clavicle leaves the chest): ±x, height (metres).
pub const CLAVICLE: (f32, f32) = (0.05, 1.42);
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
/// Toe joints (the ball of each foot): height and distance in front of the ankle, metres.
pub const TOES: (f32, f32) = (0.03, 0.10);

/// Name, parent and rest translation (relative to the parent, metres) of every joint.
const TABLE: [(&str, Option<usize>, [f32; 3]); JOINT_COUNT] = [
    ("hips", None, [0.0, HIPS_Y, 0.0]),
    ("spine", Some(0), [0.0, 0.10, 0.0]),
    ("chest", Some(1), [0.0, 0.20, 0.0]),
    ("neck", Some(2), [0.0, 0.24, 0.0]),
    ("head", Some(3), [0.0, 0.08, 0.0]),
    (
        "clavicle_l",
        Some(2),
        [CLAVICLE.0, CLAVICLE.1 - CHEST_Y, 0.0],
    ),
    (
        "upper_arm_l",
        Some(5),
        [SHOULDER.0 - CLAVICLE.0, SHOULDER.1 - CLAVICLE.1, 0.0],
    ),
    ("lower_arm_l", Some(6), [0.0, ELBOW_Y - SHOULDER.1, 0.0]),
    ("hand_l", Some(7), [0.0, WRIST_Y - ELBOW_Y, 0.0]),
    (
        "clavicle_r",
        Some(2),
        [-CLAVICLE.0, CLAVICLE.1 - CHEST_Y, 0.0],
    ),
    (
        "upper_arm_r",
        Some(9),
        [CLAVICLE.0 - SHOULDER.0, SHOULDER.1 - CLAVICLE.1, 0.0],
    ),
    ("lower_arm_r", Some(10), [0.0, ELBOW_Y - SHOULDER.1, 0.0]),
    ("hand_r", Some(11), [0.0, WRIST_Y - ELBOW_Y, 0.0]),
    ("upper_leg_l", Some(0), [HIP.0, HIP.1 - HIPS_Y, 0.0]),
    ("lower_leg_l", Some(13), [0.0, KNEE_Y - HIP.1, 0.0]),
    ("foot_l", Some(14), [0.0, ANKLE_Y - KNEE_Y, 0.0]),
    ("toes_l", Some(15), [0.0, TOES.0 - ANKLE_Y, TOES.1]),
    ("upper_leg_r", Some(0), [-HIP.0, HIP.1 - HIPS_Y, 0.0]),
    ("lower_leg_r", Some(17), [0.0, KNEE_Y - HIP.1, 0.0]),
    ("foot_r", Some(18), [0.0, ANKLE_Y - KNEE_Y, 0.0]),
    ("toes_r", Some(19), [0.0, TOES.0 - ANKLE_Y, TOES.1]),
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
