//! The hero's skin (`assets/common/hero/hero.glb`, made by `tools/assetgen/src/hero/`): about
//! 20 joints (clavicles and toes beside the limbs), up to four weights per vertex where
//! shoulders and hips bend, every weight finite and each vertex's summing to 1 — and the
//! blend does its job: with an arm raised 90° or a thigh raised 90°, the skin near the
//! shoulder or hip stretches instead of tearing. Measured as the largest distance, in the
//! bent pose, between two vertices that lay within [`NEIGHBOUR_M`] of each other at rest
//! (near the joint); the same mesh with every vertex on its strongest joint alone (1-weight
//! skinning) tears there, and the test checks that too, so the measure can tell.

use std::f32::consts::FRAC_PI_2;
use std::path::Path;
use std::sync::Arc;

use candela::assets::AssetRoot;
use candela::sim::animation::{AnimatedModel, Influence, load_animation, world_positions};
use glam::Quat;

const MODEL: &str = "common/hero/hero.glb";
/// Vertices this close at rest count as neighbours on the skin, metres.
const NEIGHBOUR_M: f32 = 0.03;
/// Vertices this close to the bent joint at rest are the junction looked at, metres.
const NEAR_JOINT_M: f32 = 0.16;

fn load() -> anyhow::Result<AnimatedModel> {
    let root = AssetRoot::new(candela_tests::repo().join("assets"))?;
    Ok(load_animation(
        &root,
        Path::new("tests/cross/hero_skin.rs"),
        MODEL,
    )?)
}

fn influences(model: &AnimatedModel) -> Vec<Influence> {
    model
        .meshes
        .iter()
        .flat_map(|m| m.primitives.iter())
        .flat_map(|p| p.influences.iter().flatten().copied())
        .collect()
}

/// The model with every vertex bound to its strongest joint alone.
fn one_weight(model: &AnimatedModel) -> AnimatedModel {
    let mut rigid = model.clone();
    for primitive in rigid
        .meshes
        .iter_mut()
        .flat_map(|m| m.primitives.iter_mut())
    {
        for influence in primitive.influences.iter_mut().flatten() {
            let strongest = (0..4)
                .max_by(|&a, &b| influence.weights[a].total_cmp(&influence.weights[b]))
                .unwrap_or(0);
            *influence = Influence {
                joints: [influence.joints[strongest], 0, 0, 0],
                weights: [1.0, 0.0, 0.0, 0.0],
            };
        }
    }
    rigid
}

/// With joint `joint` turned by `turn` from rest: the largest posed distance between two
/// vertices that were neighbours at rest within [`NEAR_JOINT_M`] of the joint, metres.
fn widest_tear(model: &AnimatedModel, joint: &str, turn: Quat) -> anyhow::Result<f32> {
    let node = model.find_joint(joint)?;
    let rest = model.rest_pose();
    let centre = model.world_matrices(&rest)[node].w_axis.truncate();
    let mut bent = rest.clone();
    bent.rotation[node] = turn * bent.rotation[node];
    let (before, after) = (world_positions(model, &rest), world_positions(model, &bent));
    anyhow::ensure!(
        before.len() == after.len() && !before.is_empty(),
        "vertices"
    );
    let near: Vec<usize> = (0..before.len())
        .filter(|&i| before[i].distance(centre) < NEAR_JOINT_M)
        .collect();
    anyhow::ensure!(near.len() > 50, "{} vertices near {joint}", near.len());
    let mut widest = 0.0_f32;
    for (k, &i) in near.iter().enumerate() {
        for &j in &near[k + 1..] {
            if before[i].distance(before[j]) < NEIGHBOUR_M {
                widest = widest.max(after[i].distance(after[j]));
            }
        }
    }
    Ok(widest)
}

#[test]
fn the_hero_has_about_20_joints_and_four_weights_at_the_junctions() -> anyhow::Result<()> {
    let model = load()?;
    let joints = model.skins[0].joints.len();
    assert!(joints >= 20, "{joints} joints");
    for name in [
        "hips",
        "spine",
        "chest",
        "clavicle_l",
        "clavicle_r",
        "hand_r",
        "toes_l",
        "toes_r",
    ] {
        model.find_joint(name)?;
    }
    let all = influences(&model);
    assert!(all.len() > 1000, "{} skinned vertices", all.len());
    for (i, influence) in all.iter().enumerate() {
        let sum: f32 = influence.weights.iter().sum();
        assert!(
            influence.weights.iter().all(|w| w.is_finite() && *w >= 0.0)
                && (sum - 1.0).abs() < 1e-6,
            "vertex {i}: {influence:?}"
        );
    }
    let four = all
        .iter()
        .filter(|i| i.weights.iter().all(|&w| w > 0.0))
        .count();
    assert!(four >= 20, "{four} vertices with four weights");
    Ok(())
}

#[test]
fn a_raised_arm_or_thigh_stretches_the_skin_where_one_weight_tears_it() -> anyhow::Result<()> {
    let model = Arc::new(load()?);
    let rigid = one_weight(&model);
    // Left arm out to the side, up to horizontal; left thigh forward, up to horizontal.
    for (joint, turn, limit_m) in [
        ("upper_arm_l", Quat::from_rotation_z(FRAC_PI_2), 0.045),
        ("upper_leg_l", Quat::from_rotation_x(-FRAC_PI_2), 0.045),
    ] {
        let blended = widest_tear(&model, joint, turn)?;
        let torn = widest_tear(&rigid, joint, turn)?;
        println!("{joint}: widest gap {blended:.4} m blended, {torn:.4} m with one weight");
        assert!(
            blended < limit_m,
            "{joint} raised 90°: neighbours at rest end {blended} m apart"
        );
        assert!(
            torn > limit_m,
            "one-weight skinning should tear at {joint}: {torn} m"
        );
    }
    Ok(())
}

#[test]
fn a_raised_arm_keeps_the_shoulder_round() -> anyhow::Result<()> {
    // No collapse: the skin within reach of the shoulder keeps its distance from the joint
    // (linear blending pulls a vertex between two joints towards the bend).
    let model = load()?;
    let node = model.find_joint("upper_arm_l")?;
    let rest = model.rest_pose();
    let centre = model.world_matrices(&rest)[node].w_axis.truncate();
    let mut bent = rest.clone();
    bent.rotation[node] = Quat::from_rotation_z(FRAC_PI_2) * bent.rotation[node];
    let (before, after) = (
        world_positions(&model, &rest),
        world_positions(&model, &bent),
    );
    let mut worst = f32::INFINITY;
    for (b, a) in before.iter().zip(&after) {
        let d = b.distance(centre);
        if d > 0.04 && d < NEAR_JOINT_M {
            worst = worst.min(a.distance(centre) / d);
        }
    }
    println!("shoulder: the nearest skin keeps {worst:.3} of its distance");
    assert!(worst > 0.5, "the shoulder collapses: {worst}");
    Ok(())
}
