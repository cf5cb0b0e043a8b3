//! The hero's skin weights: which joints move each vertex of the mesh (`body`), and how much.
//!
//! Most shapes follow one joint, or blend by height across an elbow, knee or ankle. Where the
//! body bends most — shoulders and hips — a vertex follows up to four joints, blended smoothly
//! over the junction so the armpit and groin stretch instead of tearing or creasing: the chest's
//! outer top follows the clavicle and upper arm a little (and its bottom the spine), the top of
//! the arm follows the clavicle and chest a little; the seat's bottom follows both thighs (and
//! its top the spine), the top of each thigh follows the hips. The boot's front follows the toes.
//!
//! Weights are computed from the vertex's rest position (metres, `skeleton`'s frame), the four
//! largest kept and rounded to multiples of 1/64 (exact in binary: they sum to exactly 1, and
//! the bytes do not depend on the last bit of a smoothstep). Must not: build geometry.

use glam::Vec3;

use super::skeleton::{HIP, SHOULDER, TOES, joint};

/// Half the height over which a limb blends between two joints, metres.
const BLEND_HALF_M: f32 = 0.05;
/// Weights are multiples of this.
const WEIGHT_STEP: f32 = 1.0 / 64.0;

/// The joints of one side's arm or leg (left or right).
#[derive(Clone, Copy)]
pub(super) struct Limb {
    /// Upper, middle and lower joint of the chain (upper arm, lower arm, hand).
    pub(super) chain: [u16; 3],
    /// Heights where the middle and lower joints start, metres.
    pub(super) joint_y: [f32; 2],
    /// The joint the limb hangs from (the clavicle for an arm, the hips for a leg).
    pub(super) root: u16,
    /// +1 on the left (+X), −1 on the right.
    pub(super) side: f32,
}

/// How a shape's vertices are bound.
#[derive(Clone, Copy)]
pub(super) enum Bind {
    /// Wholly to one joint.
    Rigid(u16),
    /// An arm: its chain, and near the shoulder its clavicle and the chest.
    Arm(Limb),
    /// A leg: its chain, and near the hip the hips.
    Leg(Limb),
    /// The chest: its outer top towards each clavicle and upper arm, its bottom the spine.
    Chest,
    /// The seat of the trousers (hips): its bottom towards both thighs, its top the spine.
    Seat,
    /// A boot's foot `(foot, toes)`: its front follows the toes.
    Boot(u16, u16),
}

/// 0 below `e0`, 1 above `e1` (or the other way round when `e0 > e1`), smooth between.
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The weights of `limb`'s chain at height `y` (metres), linear across each joint.
fn chain(limb: Limb, y: f32) -> Vec<(u16, f32)> {
    let [upper, middle, lower] = limb.chain;
    let [y_middle, y_lower] = limb.joint_y;
    let mid = 0.5 * (y_middle + y_lower);
    let (above, below, y_joint) = if y > mid {
        (upper, middle, y_middle)
    } else {
        (middle, lower, y_lower)
    };
    let t = ((y_joint + BLEND_HALF_M - y) / (2.0 * BLEND_HALF_M)).clamp(0.0, 1.0);
    vec![(above, 1.0 - t), (below, t)]
}

/// Moves `share` of every weight in `weights` to the `(joint, fraction)` pairs of `to`.
fn give(weights: &mut Vec<(u16, f32)>, share: f32, to: &[(u16, f32)]) {
    for w in weights.iter_mut() {
        w.1 *= 1.0 - share;
    }
    weights.extend(to.iter().map(|&(j, f)| (j, share * f)));
}

/// The (clavicle, upper arm) joints of the side of `x`.
fn shoulder_joints(x: f32) -> (u16, u16) {
    if x >= 0.0 {
        (joint::CLAVICLE_L, joint::UPPER_ARM_L)
    } else {
        (joint::CLAVICLE_R, joint::UPPER_ARM_R)
    }
}

impl Bind {
    /// The vertex at rest position `p`'s joints and weights, before rounding.
    fn raw(self, p: Vec3) -> Vec<(u16, f32)> {
        use joint::*;
        match self {
            Bind::Rigid(j) => vec![(j, 1.0)],
            Bind::Arm(limb) => {
                let mut w = chain(limb, p.y);
                // Top of the arm, on the side towards the torso: stretches to the chest.
                let inner = smoothstep(SHOULDER.0 + 0.055, SHOULDER.0 - 0.055, p.x * limb.side);
                let near = inner * smoothstep(SHOULDER.1 - 0.17, SHOULDER.1 + 0.01, p.y);
                give(&mut w, 0.5 * near, &[(limb.root, 0.6), (CHEST, 0.4)]);
                w
            }
            Bind::Leg(limb) => {
                let mut w = chain(limb, p.y);
                let near = smoothstep(HIP.1 - 0.14, HIP.1 + 0.02, p.y);
                give(&mut w, 0.4 * near, &[(limb.root, 1.0)]);
                w
            }
            Bind::Chest => {
                let mut w = vec![(CHEST, 1.0)];
                let (clavicle, upper_arm) = shoulder_joints(p.x);
                let outer = smoothstep(0.08, 0.20, p.x.abs()) * smoothstep(1.22, 1.44, p.y);
                give(&mut w, 0.65 * outer, &[(clavicle, 0.6), (upper_arm, 0.4)]);
                let low = smoothstep(1.34, 1.22, p.y);
                give(&mut w, 0.5 * low, &[(SPINE, 1.0)]);
                w
            }
            Bind::Seat => {
                let mut w = vec![(HIPS, 1.0)];
                let low = smoothstep(0.97, 0.85, p.y);
                let left = smoothstep(-0.08, 0.08, p.x);
                give(
                    &mut w,
                    0.5 * low,
                    &[(UPPER_LEG_L, left), (UPPER_LEG_R, 1.0 - left)],
                );
                let high = smoothstep(0.88, 0.98, p.y);
                give(&mut w, 0.3 * high, &[(SPINE, 1.0)]);
                w
            }
            Bind::Boot(foot, toes) => {
                let front = smoothstep(TOES.1 - 0.04, TOES.1 + 0.04, p.z);
                vec![(foot, 1.0 - front), (toes, front)]
            }
        }
    }

    /// The vertex at rest position `p`'s four joints and weights: the largest four, each a
    /// multiple of [`WEIGHT_STEP`], summing to exactly 1, largest first; unused slots are
    /// joint 0 with weight 0.
    pub(super) fn influence(self, p: Vec3) -> ([u16; 4], [f32; 4]) {
        let mut merged: Vec<(u16, f32)> = Vec::new();
        for (j, w) in self.raw(p) {
            match merged.iter_mut().find(|m| m.0 == j) {
                Some(m) => m.1 += w,
                None => merged.push((j, w)),
            }
        }
        merged.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
        merged.truncate(4);
        let total: f32 = merged.iter().map(|m| m.1).sum();
        let steps = (1.0 / WEIGHT_STEP) as i32;
        let mut quantized: Vec<(u16, i32)> = merged
            .iter()
            .map(|&(j, w)| (j, (w / total * steps as f32).round() as i32))
            .collect();
        // The largest takes what rounding left over, so the steps add up to one.
        let rest: i32 = quantized.iter().skip(1).map(|q| q.1).sum();
        quantized[0].1 = steps - rest;
        quantized.retain(|q| q.1 > 0);
        let mut joints = [0_u16; 4];
        let mut weights = [0.0_f32; 4];
        for (slot, (j, q)) in quantized.into_iter().enumerate() {
            joints[slot] = j;
            weights[slot] = q as f32 * WEIGHT_STEP;
        }
        (joints, weights)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one_and_the_junctions_have_four() {
        let chest = Bind::Chest.influence(Vec3::new(0.19, 1.30, 0.0));
        assert_eq!(chest.1.iter().sum::<f32>(), 1.0);
        assert!(chest.1.iter().all(|&w| w > 0.0), "{chest:?}");
        let seat = Bind::Seat.influence(Vec3::new(0.0, 0.92, 0.1));
        assert_eq!(seat.1.iter().sum::<f32>(), 1.0);
        assert!(seat.1.iter().all(|&w| w > 0.0), "{seat:?}");
        assert_eq!(
            Bind::Rigid(joint::HEAD).influence(Vec3::ZERO),
            ([joint::HEAD, 0, 0, 0], [1.0, 0.0, 0.0, 0.0])
        );
    }
}
