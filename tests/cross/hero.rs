//! The hero (`assets/common/hero/hero.glb`): the committed file is exactly what
//! `tools/assetgen` makes, and it loads through the engine's glTF loader and animation as a
//! character: one skinned mesh on a 21-joint skin, the eight clips (the third-person level's
//! states and the explorer's actions), about 1.8 m tall with its feet at y = 0, and a walk that moves its feet.

use std::path::{Path, PathBuf};

use candela::assets::{AssetRoot, Model, load_model};
use candela::sim::animation::{AnimatedModel, SkinnedAnimator, deform_mesh, load_animation};
use glam::Vec3;

const REGENERATE: &str = "cargo run --release -p assetgen -- hero";
const MODEL: &str = "common/hero/hero.glb";

fn assets() -> PathBuf {
    candela_tests::repo().join("assets")
}

fn load() -> anyhow::Result<(Model, AnimatedModel)> {
    let root = AssetRoot::new(assets())?;
    let referrer = Path::new("tests/cross/hero.rs");
    let model = load_model(&root, referrer, MODEL)?;
    let animated = load_animation(&root, referrer, MODEL)?;
    Ok((model, animated))
}

fn bounds(points: &[Vec3]) -> (Vec3, Vec3) {
    points
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(min, max), &p| {
            (min.min(p), max.max(p))
        })
}

#[test]
fn committed_hero_is_what_assetgen_makes() -> anyhow::Result<()> {
    let dir = assets().join("common/hero");
    let made = assetgen::hero::hero_files()?;
    let mut committed: Vec<String> = std::fs::read_dir(&dir)
        .map(|entries| {
            entries
                .flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    committed.sort();
    let names: Vec<String> = made.iter().map(|(name, _)| name.clone()).collect();
    assert_eq!(
        committed, names,
        "files of assets/common/hero; run `{REGENERATE}`"
    );
    for (name, bytes) in &made {
        assert!(
            std::fs::read(dir.join(name))? == *bytes,
            "assets/common/hero/{name} is stale; run `{REGENERATE}`"
        );
    }
    Ok(())
}

#[test]
fn the_hero_loads_as_a_skinned_character() -> anyhow::Result<()> {
    let (model, animated) = load()?;
    assert_eq!(animated.skins.len(), 1);
    assert_eq!(animated.skins[0].joints.len(), 21, "joints");
    let clips: Vec<&str> = animated.clips.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(
        clips,
        [
            "idle",
            "walk",
            "run",
            "jump",
            "fall",
            "push",
            "pick_up",
            "celebrate"
        ]
    );
    assert_eq!(clips, assetgen::hero::CLIPS);
    assert!(
        SkinnedAnimator::single(std::sync::Arc::new(animated.clone()), &model).is_some(),
        "one mesh node, drawn once"
    );
    let names: Vec<&str> = model.materials.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["jacket", "cloth", "skin", "leather"]);
    let jacket = model.materials[0].base_color;
    assert!(
        jacket[0] > 2.0 * jacket[2],
        "the jacket is coloured: {jacket:?}"
    );
    assert_eq!(model.placements.len(), 1);
    let mesh = &model.meshes[model.placements[0].mesh];
    let (min, max) = bounds(&mesh.positions);
    assert!(min.y.abs() < 1e-3, "feet at y = 0: {min}");
    assert!(
        (max.y - assetgen::hero::HEIGHT_M).abs() < 0.02,
        "about 1.8 m tall: {max}"
    );
    assert!(max.x - min.x < 0.8 && max.z - min.z < 0.5, "{min}..{max}");
    // Facing +Z: the nose and toes reach further forward than the back goes.
    assert!(max.z > -min.z, "{min}..{max}");
    let triangles: usize = model.meshes.iter().map(|m| m.triangles.len()).sum();
    assert!(triangles < 5_000, "low poly: {triangles} triangles");
    Ok(())
}

#[test]
fn every_clip_keeps_the_feet_near_the_ground_and_walk_moves_a_foot() -> anyhow::Result<()> {
    let (model, animated) = load()?;
    let foot = animated
        .nodes
        .nodes
        .iter()
        .position(|n| n.name.as_deref() == Some("foot_l"))
        .ok_or_else(|| anyhow::anyhow!("no foot_l joint"))?;
    let walk = animated.find_clip("walk")?;
    let foot_at = |time: f64| {
        let pose = animated.pose_at(walk, time);
        animated.world_matrices(&pose)[foot].w_axis.truncate()
    };
    let (a, b) = (foot_at(0.0), foot_at(0.25));
    assert!(
        (a - b).length() > 0.1,
        "the left foot moves over a quarter walk cycle: {a} → {b}"
    );
    // The skinned mesh follows: the lowest vertex stays near the ground in every clip, and
    // the walk's deformed mesh differs from the rest pose.
    let node = SkinnedAnimator::single(std::sync::Arc::new(animated.clone()), &model)
        .map(|(animator, _)| animator.node)
        .ok_or_else(|| anyhow::anyhow!("not a character"))?;
    let placement = model.placements[0].model_from_mesh;
    for (clip, c) in animated.clips.iter().enumerate() {
        for step in 0..8 {
            let time = c.duration_seconds * f64::from(step) / 8.0;
            let pose = animated.pose_at(clip, time);
            let world = animated.world_matrices(&pose);
            let deformed = deform_mesh(&animated, &pose, &world, node, placement)
                .ok_or_else(|| anyhow::anyhow!("no mesh"))?;
            let (min, max) = bounds(&deformed.positions);
            assert!(
                min.y > -0.1 && max.y < 2.3,
                "{} at {time} s: {min}..{max}",
                c.name
            );
        }
    }
    Ok(())
}
