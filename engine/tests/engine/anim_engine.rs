//! Skeletal animation in the engine's frame loop: CesiumMan (glTF sample, skinned) on an
//! entity with a [`SkinnedAnimator`] deforms its mesh every frame through the deforming-mesh
//! BVH path (one BLAS refit or rebuild per frame, reported by the frame's work), and the
//! vertices the engine commits are the skinned pose at the player's time. Paused, it costs no
//! BLAS work at all.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use candela::app::{Engine, Environment, Step};
use candela::assets::{CameraDesc, RenderSettings, SkyDesc, load_model_file};
use candela::ecs::{Deformable, Renderable, Transform};
use candela::render::RenderConfig;
use candela::sim::animation::{
    PlayMode, Playback, SkinnedAnimator, deform_mesh, load_animation_file,
};

fn external(relative: &str) -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/external/gltf"
    ))
    .join(relative)
}

#[test]
fn skinned_character_deforms_through_the_frame_loop() -> anyhow::Result<()> {
    let path = external("CesiumMan/glTF-Binary/CesiumMan.glb");
    let animated = Arc::new(load_animation_file(&path)?);
    let model = load_model_file(&path)?;
    let config = RenderConfig::cpu(8, 8);
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.5; 3]),
        render: RenderSettings {
            max_bounces: 1,
            roulette_start: 1,
            ..Default::default()
        },
        default_camera: CameraDesc {
            position: [0.0, 1.0, 3.0],
            look_at: [0.0, 0.8, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 45.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    };
    let mut engine = Engine::new(config, environment)?;
    let handle = engine.add_model(&model);
    let (mut animator, deformable) =
        SkinnedAnimator::single(animated.clone(), &model).expect("one skinned mesh");
    animator.player.play(Playback::new(0, PlayMode::Loop));
    let entity = engine.world_mut().spawn((
        Transform::IDENTITY,
        Renderable {
            model: handle,
            material_override: None,
        },
        animator,
        deformable,
    ));

    let mut blas_work = Vec::new();
    for _ in 0..12 {
        let report = engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        blas_work.push(report.work.blas_refits + report.work.blas_rebuilds);
        let _ = engine.wait_rendered();
    }
    assert!(blas_work.iter().all(|&w| w == 1), "{blas_work:?}");

    // The committed vertices are the pose at the player's time (12 steps of 1/60 s).
    let time = {
        let animator = engine.world().get::<&SkinnedAnimator>(entity)?;
        animator
            .player
            .current()
            .map(|p| p.time_seconds)
            .unwrap_or(-1.0)
    };
    assert!((time - 12.0 / 60.0).abs() < 1e-9, "{time}");
    let pose = animated.pose_at(0, time);
    let world = animated.world_matrices(&pose);
    let placement = &model.placements[0];
    let expected = deform_mesh(
        &animated,
        &pose,
        &world,
        find_node(&animated),
        placement.model_from_mesh,
    )
    .expect("deformed");
    let now = engine.world().get::<&Deformable>(entity)?.positions.clone();
    assert_eq!(now, expected.positions);

    // Paused: no BLAS work.
    if let Ok(mut animator) = engine.world_mut().get::<&mut SkinnedAnimator>(entity) {
        animator.player.set_paused(true);
    }
    let mut paused = Vec::new();
    for _ in 0..4 {
        let report = engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        paused.push(report.work.blas_refits + report.work.blas_rebuilds);
        let _ = engine.wait_rendered();
    }
    // The first paused frame may still carry the last step's pose.
    assert!(paused[1..].iter().all(|&w| w == 0), "{paused:?}");
    drop(engine.shutdown());
    Ok(())
}

fn find_node(animated: &candela::sim::animation::AnimatedModel) -> usize {
    animated
        .nodes
        .nodes
        .iter()
        .position(|n| n.mesh.is_some())
        .unwrap_or(0)
}

/// A rigidly animated glTF node (AnimatedCube: rotation keys on its one node) turns its mesh
/// through the same path: the committed vertices are the node's animated world matrix applied
/// to the mesh, in the space the renderer places it with.
#[test]
fn rigid_gltf_node_animation_moves_the_mesh() -> anyhow::Result<()> {
    let path = external("AnimatedCube/glTF/AnimatedCube.gltf");
    let animated = Arc::new(load_animation_file(&path)?);
    let model = load_model_file(&path)?;
    let (mut animator, mut deformable) =
        SkinnedAnimator::single(animated.clone(), &model).expect("one mesh node");
    animator.player.play(Playback::new(0, PlayMode::Loop));
    let mut world = hecs::World::new();
    let rest = deformable.positions.clone();
    deformable.positions.iter_mut().for_each(|p| *p *= 0.0);
    let entity = world.spawn((animator, deformable));
    for _ in 0..30 {
        candela::sim::animation::tick_skinned(&mut world, 1.0 / 60.0);
    }
    assert_eq!(candela::sim::animation::deform_skinned(&mut world), 1);
    let pose = animated.pose_at(0, 0.5);
    let node = find_node(&animated);
    let node_world = animated.world_matrices(&pose)[node];
    let m = model.placements[0].model_from_mesh.inverse() * node_world;
    let got = &world.get::<&Deformable>(entity)?.positions;
    let size = rest
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f32::max);
    for (g, r) in got.iter().zip(&rest) {
        let e = m.transform_point3(*r);
        assert!((*g - e).abs().max_element() <= 1e-5 * size, "{g} vs {e}");
    }
    assert!(
        got.iter()
            .zip(&rest)
            .any(|(g, r)| (*g - *r).length() > 0.05 * size),
        "half a second in, the cube has turned"
    );
    Ok(())
}
