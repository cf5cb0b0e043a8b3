//! The upper-body layer (`sim::animation::upper_body`) on the generated hero
//! (`assets/common/hero/hero.glb`): with `walk` playing and `push` layered on the upper body
//! at full weight, every node of the `spine` subtree (chest, neck, head, arms) takes the push
//! pose and every other node (hips, legs) keeps the walk's; at half weight an arm sits between
//! the two; the slot fades the layer in while asked for and drops it after it fades out, and a
//! character that never asks hashes no extra words.

use std::path::{Path, PathBuf};

use candela::sim::animation::{
    AnimatedModel, AnimationPlayer, PlayMode, Playback, UPPER_FADE_SECONDS, UpperBodySlot,
    UpperLayer, load_animation_file, subtree_mask,
};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn hero() -> anyhow::Result<AnimatedModel> {
    Ok(load_animation_file(
        &repo().join("assets/common/hero/hero.glb"),
    )?)
}

/// The walk at 0.3 s, with `push` at 0.5 s over the upper body at `weight` (none at 0).
fn posed(model: &AnimatedModel, weight: f32) -> anyhow::Result<candela::sim::animation::Pose> {
    let walk = model.find_clip("walk")?;
    let push = model.find_clip("push")?;
    let mut player = AnimationPlayer::new();
    let mut playback = Playback::new(walk, PlayMode::Loop);
    playback.time_seconds = 0.3;
    player.play(playback);
    if weight > 0.0 {
        let mut layer = Playback::new(push, PlayMode::Loop);
        layer.time_seconds = 0.5;
        player.set_layer(Some(UpperLayer {
            playback: layer,
            mask: subtree_mask(model, model.find_joint("spine")?),
            weight,
        }));
    }
    Ok(player.pose(&model.clips, &model.rest_pose()))
}

#[test]
fn the_layer_moves_the_upper_body_and_leaves_the_legs_walking() -> anyhow::Result<()> {
    let model = hero()?;
    let walking = posed(&model, 0.0)?;
    let layered = posed(&model, 1.0)?;
    let half = posed(&model, 0.5)?;
    let pushing = model.pose_at(model.find_clip("push")?, 0.5);
    let joint = |name: &str| model.find_joint(name);
    let mut arm_moved = false;
    for name in ["chest", "head", "upper_arm_l", "lower_arm_r", "hand_r"] {
        let j = joint(name)?;
        // Rotations are used as stored (not unit): compare directions.
        let d = layered.rotation[j]
            .normalize()
            .angle_between(pushing.rotation[j].normalize());
        assert!(d < 1e-4, "{name} is {d} rad from the push pose");
        arm_moved |= walking.rotation[j]
            .normalize()
            .angle_between(pushing.rotation[j].normalize())
            > 0.05;
    }
    assert!(
        arm_moved,
        "the push pose differs from the walk on the upper body"
    );
    for name in ["hips", "upper_leg_l", "lower_leg_r", "foot_l"] {
        let j = joint(name)?;
        assert_eq!(
            layered.rotation[j], walking.rotation[j],
            "{name} keeps walking"
        );
        assert_eq!(layered.translation[j], walking.translation[j], "{name}");
    }
    let arm = joint("upper_arm_r")?;
    let unit = |p: &candela::sim::animation::Pose| p.rotation[arm].normalize();
    let (a, b) = (
        unit(&walking).angle_between(unit(&half)),
        unit(&half).angle_between(unit(&pushing)),
    );
    assert!(
        a > 0.0 && (a - b).abs() < 0.1 * (a + b),
        "half weight sits halfway: {a} and {b} rad"
    );
    Ok(())
}

#[test]
fn the_slot_fades_the_layer_in_while_asked_and_out_after() -> anyhow::Result<()> {
    let model = hero()?;
    let push = model.find_clip("push")?;
    let mut player = AnimationPlayer::new();
    player.play(Playback::new(model.find_clip("walk")?, PlayMode::Loop));
    let mut slot = UpperBodySlot::default();
    assert!(
        slot.state_words(&player).is_empty(),
        "nothing hashed before use"
    );
    let dt = 1.0 / 60.0;
    let fade_steps = (UPPER_FADE_SECONDS / dt).round() as usize;
    for step in 0..fade_steps * 2 {
        slot.request(&model, push)?;
        slot.update(&mut player, dt);
        player.tick(&model.clips, dt);
        let weight = player.layer().map_or(0.0, |l| l.weight);
        let expected = ((step + 1) as f32 / fade_steps as f32).min(1.0);
        assert!((weight - expected).abs() < 1e-3, "step {step}: {weight}");
    }
    assert_eq!(slot.playing(), Some(push));
    assert_eq!(slot.state_words(&player).len(), 3);
    for _ in 0..fade_steps + 1 {
        slot.update(&mut player, dt);
    }
    assert!(
        player.layer().is_none() && slot.playing().is_none(),
        "faded out"
    );
    Ok(())
}
