//! The hero's mesh: a stylised low-poly body of bevelled boxes and cylinders, one shape per
//! body part, each bound to its joint — rigidly, or blended (`weights`: across elbows, knees
//! and ankles by height, over shoulders and hips with up to four joints). Metres, bind pose = rest pose
//! (`skeleton`): feet at y = 0, head top at 1.8 m, facing +Z, left = +X.
//!
//! Shapes come from the Reflect kit's `Builder` (positions and normals rounded to 10 µm, so
//! the bytes do not depend on the last bit of `sin`/`cos`). Must not: write files.

use glam::{Affine3A, Vec3};

use super::skeleton::{ANKLE_Y, ELBOW_Y, HIP, KNEE_Y, SHOULDER, WRIST_Y, joint};
use super::weights::{Bind, Limb};
use crate::gltf_skin::SkinnedPart;
use crate::reflect_kit::mesh::{Builder, Uv};

/// Material indices (see `hero::materials`).
pub mod material {
    pub const JACKET: usize = 0;
    pub const CLOTH: usize = 1;
    pub const SKIN: usize = 2;
    pub const LEATHER: usize = 3;
    pub const COUNT: usize = 4;
}

/// Sides of every cylinder.
const SEGMENTS: u32 = 12;

/// Collects the parts, one per material.
struct Body {
    parts: Vec<SkinnedPart>,
}

impl Body {
    /// Adds what `build` makes (one material) at `offset`, bound by `bind`.
    fn add(&mut self, material: usize, offset: Vec3, bind: Bind, build: impl FnOnce(&mut Builder)) {
        let mut builder = Builder::new(1);
        builder.with(Affine3A::from_translation(offset), build);
        let data = builder.finish();
        let part = &mut self.parts[material];
        let base = part.positions.len() as u32;
        for (p, (n, uv)) in data
            .positions
            .iter()
            .zip(data.normals.iter().zip(&data.uvs))
        {
            let (joints, weights) = bind.influence(Vec3::from(*p));
            part.positions.push(*p);
            part.normals.push(*n);
            part.uvs.push(*uv);
            part.joints.push(joints);
            part.weights.push(weights);
        }
        part.indices
            .extend(data.indices.iter().flatten().map(|i| i + base));
    }

    /// A bevelled box from `min` to `max` (metres) on one joint.
    fn block(&mut self, material: usize, min: [f32; 3], max: [f32; 3], radius: f32, j: u16) {
        self.bound_block(material, min, max, radius, Bind::Rigid(j));
    }

    /// A bevelled box from `min` to `max` (metres), bound by `bind`.
    fn bound_block(
        &mut self,
        material: usize,
        min: [f32; 3],
        max: [f32; 3],
        radius: f32,
        bind: Bind,
    ) {
        self.add(material, Vec3::ZERO, bind, |b| {
            b.bevel_box(0, Vec3::from(min), Vec3::from(max), radius, Uv::Unit);
        });
    }

    /// A capped vertical cylinder at `(x, ·, 0)` from `y0` to `y1`, radius `r` (metres).
    fn limb(&mut self, material: usize, x: f32, r: f32, y: [f32; 2], bind: Bind) {
        self.add(material, Vec3::new(x, 0.0, 0.0), bind, |b| {
            b.tube(0, r, 0.0, y[0], y[1], SEGMENTS, true, 1.0);
        });
    }
}

/// The hero's mesh, one part per material (`material::*` order).
pub fn parts() -> Vec<SkinnedPart> {
    use joint::*;
    let mut body = Body {
        parts: (0..material::COUNT)
            .map(|material| SkinnedPart {
                material,
                ..SkinnedPart::default()
            })
            .collect(),
    };
    let (jacket, cloth, skin, leather) = (
        material::JACKET,
        material::CLOTH,
        material::SKIN,
        material::LEATHER,
    );
    // Head: face, hair cap (top at 1.8 m), nose (shows the facing, +Z).
    body.block(skin, [-0.095, 1.57, -0.10], [0.095, 1.77, 0.11], 0.04, HEAD);
    body.block(
        leather,
        [-0.105, 1.71, -0.115],
        [0.105, 1.80, 0.06],
        0.04,
        HEAD,
    );
    body.block(skin, [-0.018, 1.63, 0.10], [0.018, 1.67, 0.135], 0.01, HEAD);
    body.limb(skin, 0.0, 0.045, [1.47, 1.60], Bind::Rigid(NECK));
    // Torso: jacket over chest and belly, belt, trousers' seat.
    body.bound_block(
        jacket,
        [-0.20, 1.22, -0.12],
        [0.20, 1.50, 0.12],
        0.05,
        Bind::Chest,
    );
    body.block(
        jacket,
        [-0.175, 1.02, -0.105],
        [0.175, 1.24, 0.11],
        0.04,
        SPINE,
    );
    body.block(
        leather,
        [-0.18, 0.96, -0.11],
        [0.18, 1.02, 0.115],
        0.015,
        HIPS,
    );
    body.bound_block(
        cloth,
        [-0.17, 0.84, -0.10],
        [0.17, 0.98, 0.10],
        0.04,
        Bind::Seat,
    );
    for (side, [clavicle, upper_arm, lower_arm, hand], [upper_leg, lower_leg, foot, toes]) in [
        (
            1.0,
            [CLAVICLE_L, UPPER_ARM_L, LOWER_ARM_L, HAND_L],
            [UPPER_LEG_L, LOWER_LEG_L, FOOT_L, TOES_L],
        ),
        (
            -1.0,
            [CLAVICLE_R, UPPER_ARM_R, LOWER_ARM_R, HAND_R],
            [UPPER_LEG_R, LOWER_LEG_R, FOOT_R, TOES_R],
        ),
    ] {
        let x = side * SHOULDER.0;
        let arm = Bind::Arm(Limb {
            chain: [upper_arm, lower_arm, hand],
            joint_y: [ELBOW_Y, WRIST_Y],
            root: clavicle,
            side,
        });
        let (x0, x1) = sorted(x - side * 0.055, x + side * 0.055);
        body.bound_block(jacket, [x0, 1.36, -0.065], [x1, 1.50, 0.065], 0.05, arm);
        body.limb(jacket, x, 0.055, [ELBOW_Y - 0.02, 1.42], arm);
        body.limb(jacket, x, 0.047, [WRIST_Y + 0.02, ELBOW_Y + 0.02], arm);
        body.block(
            skin,
            [x - 0.035, 0.78, -0.045],
            [x + 0.035, 0.95, 0.045],
            0.025,
            hand,
        );
        let x = side * HIP.0;
        let leg = Bind::Leg(Limb {
            chain: [upper_leg, lower_leg, foot],
            joint_y: [KNEE_Y, ANKLE_Y],
            root: HIPS,
            side,
        });
        body.limb(cloth, x, 0.075, [KNEE_Y - 0.02, 0.92], leg);
        body.limb(cloth, x, 0.062, [ANKLE_Y + 0.02, KNEE_Y + 0.02], leg);
        body.limb(leather, x, 0.068, [ANKLE_Y, 0.26], leg);
        body.bound_block(
            leather,
            [x - 0.062, 0.0, -0.075],
            [x + 0.062, 0.13, 0.17],
            0.03,
            Bind::Boot(foot, toes),
        );
    }
    body.parts
}

fn sorted(a: f32, b: f32) -> (f32, f32) {
    if a <= b { (a, b) } else { (b, a) }
}
