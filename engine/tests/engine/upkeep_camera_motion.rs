//! What a moving camera costs the commit, on the demo city (headless, CPU tracer at 32×18):
//! flying the camera through the city must not commit more per frame than what moves with it.
//!
//! The demo's pool deforms every frame (its waves run in the engine's frame) and is refitted:
//! that is the still camera's commit. A moving camera adds the origin shift (every instance row,
//! the TLAS and the light table, at most once per `REBASE_DISTANCE` of travel) and nothing else.

use std::path::PathBuf;

use candela::accel::origin::REBASE_DISTANCE;
use candela::app::{Engine, Environment, FrameReport, Step};
use candela::assets::AssetRoot;
use candela::ecs::{CameraRig, Transform};
use candela::layout::{GpuInstance, GpuLight};
use candela::level::load_level;
use candela::render::RenderConfig;
use glam::{Quat, Vec3};

fn demo() -> anyhow::Result<(Engine, hecs::Entity)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/demo");
    let level = load_level(&dir.join("demo.ron"), &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(RenderConfig::cpu(32, 18), Environment::of(&level.scene))?;
    engine.spawn_level(&level);
    let camera = engine.world_mut().spawn((
        Transform::from_translation(Vec3::new(-150.0, 3.0, -66.0)),
        CameraRig::default(),
    ));
    Ok((engine, camera))
}

fn frame(engine: &mut Engine, seconds: f64) -> anyhow::Result<FrameReport> {
    let report = engine.frame(seconds, &mut |_: &mut Step<'_>| {})?;
    let _ = engine.wait_rendered();
    Ok(report)
}

fn line(label: &str, r: &FrameReport) {
    let u = &r.upkeep;
    eprintln!(
        "{label}: frame {} steps {} commit {} B (geometry {} B), instances {}, refits {}, \
         rebuilds {}, tlas {}, light tables {}, lights {}",
        r.frame,
        r.steps,
        r.commit_bytes,
        u.geometry_bytes,
        u.instances_written,
        u.blas_refits,
        u.blas_rebuilds,
        u.tlas_builds,
        u.light_table_builds,
        r.work.lights,
    );
}

#[test]
fn flying_through_the_city_commits_only_what_moves() -> anyhow::Result<()> {
    let (mut engine, camera) = demo()?;
    for _ in 0..3 {
        frame(&mut engine, 1.0 / 30.0)?;
    }
    // A still camera: the pool's refit and the TLAS over it, nothing else.
    let mut still_geometry = 0;
    for _ in 0..5 {
        let r = frame(&mut engine, 0.5)?;
        line("still", &r);
        assert_eq!(
            r.commit_bytes, r.upkeep.geometry_bytes,
            "a still frame writes only geometry"
        );
        still_geometry = still_geometry.max(r.upkeep.geometry_bytes);
    }
    let mut position = Vec3::new(-150.0, 3.0, -66.0);
    let (mut travelled, mut shifts) = (0.0f32, 0u32);
    for i in 0..20 {
        // 2 frames per second holding W at the view tool's default speed (the level crossed
        // in about 10 s: 60 m/s), turning with the mouse.
        let step = Vec3::new(30.0, 0.0, 2.0);
        position += step;
        travelled += step.length();
        {
            let mut t = engine.world_mut().get::<&mut Transform>(camera)?;
            t.translation = position;
            t.rotation = Quat::from_rotation_y(-1.3 + 0.05 * i as f32);
        }
        let r = frame(&mut engine, 0.5)?;
        line("moving", &r);
        let rows = (r.work.static_instances + r.work.dynamic_instances) as usize;
        // Geometry: what the still camera writes (the camera moves no mesh).
        assert!(
            r.upkeep.geometry_bytes <= still_geometry,
            "frame {}: {} B of geometry, {still_geometry} B still",
            r.frame,
            r.upkeep.geometry_bytes
        );
        // The rest: nothing, or one origin shift (every instance row, the light table and the
        // light tree's nodes and hit lookup, which the shift rebuilds with the table).
        let other = r.commit_bytes - r.upkeep.geometry_bytes;
        if r.upkeep.instances_written == 0 {
            assert_eq!(
                other, 0,
                "frame {}: {other} B without an origin shift",
                r.frame
            );
        } else {
            shifts += 1;
            let tree = &engine.scene().lights.tree;
            let bound = rows * size_of::<GpuInstance>()
                + r.work.lights as usize * size_of::<GpuLight>()
                + tree.nodes.len() * size_of::<candela::layout::GpuLightNode>()
                + tree.lookup.len() * size_of::<u32>();
            assert!(
                other <= bound,
                "frame {}: {other} B, an origin shift is {bound} B",
                r.frame
            );
        }
    }
    // At most one shift per REBASE_DISTANCE of travel along an axis (and the first one).
    let most = (travelled / REBASE_DISTANCE).ceil() as u32 + 1;
    assert!(
        shifts >= 1 && shifts <= most,
        "{shifts} origin shifts over {travelled} m"
    );
    drop(engine.shutdown());
    Ok(())
}

/// A slow frame runs several fixed steps; with `settle_every_step` each step after the first
/// settles the scene (the pool refitted, the TLAS rebuilt), but the commit carries only the
/// last write of each range: a frame of six steps commits what a frame of one does, not six
/// times as much (`SceneWrite::supersedes`).
#[test]
fn a_frame_of_several_settled_steps_commits_one_steps_writes() -> anyhow::Result<()> {
    let (mut engine, _camera) = demo()?;
    engine.settle_every_step(true);
    for _ in 0..3 {
        frame(&mut engine, 1.0 / 60.0)?;
    }
    let one = frame(&mut engine, 1.0 / 60.0)?;
    line("one step", &one);
    let six = frame(&mut engine, 6.0 / 60.0)?;
    line("six steps", &six);
    assert_eq!((one.steps, six.steps), (1, 6));
    assert!(
        six.upkeep.blas_refits >= 5 * one.upkeep.blas_refits.max(1),
        "the six steps settled: {} refits against {}",
        six.upkeep.blas_refits,
        one.upkeep.blas_refits
    );
    assert_eq!(
        six.commit_bytes, one.commit_bytes,
        "the six-step frame commits each range once"
    );
    Ok(())
}
