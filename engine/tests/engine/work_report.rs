//! "Model no more than a scene needs" (DESIGN.md), checked on what the engine reports it
//! computed each frame ([`FrameWork`]) and on the render side's own scene:
//! * a static scene does no BVH work after its first frame: no refits, rebuilds or TLAS builds,
//!   no instance rows written, zero geometry bytes in the commit;
//! * a switched-off light group is absent from the render side's light distribution: none of
//!   the alias table's entries belongs to it and its probability mass is zero (checked on a
//!   render-side `RenderScene` built only from commits, as the render thread builds its own,
//!   and on the count the render thread reports);
//! * a moving rigid body costs a TLAS build per frame and no BLAS work;
//! * a deforming mesh costs a BLAS refit (or rebuild) per frame.
//!
//! * sleeping physics bodies produce no commits: a crate dropped on a floor writes its instance
//!   row and rebuilds the TLAS every frame while it falls and settles, and once it sleeps the
//!   frames report no awake body, no instance row, no TLAS build and zero geometry bytes.
//! Also: a level's declared `needs` refuses content that uses an undeclared feature.

use std::path::Path;

use candela::accel::Upkeep;
use candela::app::{Engine, Environment, FrameWork, Step, Waves, waves_system};
use candela::assets::{
    AssetError, AssetRoot, CameraDesc, Level, Material, MaterialKind, Mesh, Model, Needs,
    Placement, RenderSettings, SkyDesc, WaveDesc, scene_from_level,
};
use candela::ecs::{Deformable, LightGroup, Renderable, Static, Transform};
use candela::level::playable_from_level;
use candela::render::RenderConfig;
use candela::scene::RenderScene;
use glam::{Mat4, Vec3};

/// A `n × n` grid of quads, `size` metres wide, in the xz plane, facing +Y; two-sided
/// emission `emission` (also used by `upkeep_light_refit`).
pub(crate) fn grid_model(n: u32, size: f32, emission: f32) -> Model {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for z in 0..=n {
        for x in 0..=n {
            positions.push(Vec3::new(
                size * (x as f32 / n as f32 - 0.5),
                0.0,
                size * (z as f32 / n as f32 - 0.5),
            ));
        }
    }
    for z in 0..n {
        for x in 0..n {
            let i = z * (n + 1) + x;
            triangles.push([i, i + n + 1, i + 1]);
            triangles.push([i + 1, i + n + 1, i + n + 2]);
        }
    }
    let count = triangles.len();
    Model {
        name: "grid".into(),
        meshes: vec![Mesh {
            name: "grid".into(),
            positions,
            triangles,
            triangle_materials: vec![0; count],
            ..Default::default()
        }],
        materials: vec![Material {
            kind: MaterialKind::Diffuse,
            emission: Vec3::splat(emission),
            two_sided_emission: true,
            ..Default::default()
        }],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

fn engine() -> Engine {
    let config = RenderConfig::cpu(8, 8);
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.1; 3]),
        render: RenderSettings {
            max_bounces: 2,
            roulette_start: 1,
            ..Default::default()
        },
        default_camera: CameraDesc {
            position: [0.0, 3.0, 6.0],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 45.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    };
    Engine::new(config, environment).expect("engine starts")
}

fn renderable(model: candela::ecs::ModelHandle) -> Renderable {
    Renderable {
        model,
        material_override: None,
    }
}

/// Runs `frames` frames (calling `before(engine, frame)` first) and returns their work; every
/// frame is rendered (results checked) before the next.
fn run(
    engine: &mut Engine,
    frames: u32,
    mut before: impl FnMut(&mut Engine, u32),
) -> Vec<FrameWork> {
    (0..frames)
        .map(|frame| {
            before(engine, frame);
            let report = engine
                .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
                .expect("frame");
            let rendered = engine.wait_rendered().expect("a result").expect("renders");
            assert_eq!(rendered.lights, report.work.lights, "frame {frame}");
            assert_eq!(report.work.awake_bodies, 0, "no bodies in these scenes");
            assert_eq!(report.work.max_bounces, 2);
            report.work
        })
        .collect()
}

#[test]
fn static_scene_does_no_bvh_work_after_its_first_frame() {
    let mut engine = engine();
    let floor = engine.add_model(&grid_model(8, 10.0, 0.0));
    let lamp = engine.add_model(&grid_model(1, 1.0, 5.0));
    engine
        .world_mut()
        .spawn((Transform::IDENTITY, renderable(floor), Static));
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::Y * 3.0),
        renderable(lamp),
        Static,
    ));
    let work = run(&mut engine, 6, |_, _| {});
    assert!(work[0].tlas_builds == 1 && work[0].geometry_bytes > 0);
    for (frame, w) in work.iter().enumerate().skip(1) {
        let expected = FrameWork {
            static_instances: 2,
            dynamic_instances: 0,
            lights: 2,
            max_bounces: 2,
            ..Default::default()
        };
        assert_eq!(*w, expected, "frame {frame}");
    }
    let _ = engine.shutdown();
}

#[test]
fn rigid_mover_costs_a_tlas_build_and_no_blas_work() {
    let mut engine = engine();
    let floor = engine.add_model(&grid_model(8, 10.0, 0.0));
    let crate_model = engine.add_model(&grid_model(2, 0.5, 0.0));
    engine
        .world_mut()
        .spawn((Transform::IDENTITY, renderable(floor), Static));
    let mover = engine.world_mut().spawn((
        Transform::from_translation(Vec3::Y),
        renderable(crate_model),
    ));
    let work = run(&mut engine, 6, |engine, frame| {
        if let Ok(mut t) = engine.world_mut().get::<&mut Transform>(mover) {
            t.translation.x = 0.1 * frame as f32;
        }
    });
    for (frame, w) in work.iter().enumerate().skip(1) {
        assert_eq!((w.static_instances, w.dynamic_instances), (1, 1));
        assert_eq!(w.tlas_builds, 1, "frame {frame}");
        assert_eq!(w.instances_written, 1, "frame {frame}");
        assert_eq!((w.blas_refits, w.blas_rebuilds), (0, 0), "frame {frame}");
    }
    let _ = engine.shutdown();
}

#[test]
fn deforming_mesh_costs_a_refit_per_frame() {
    let mut engine = engine();
    let model = grid_model(16, 4.0, 0.0);
    let positions = model.meshes[0].positions.clone();
    let water = engine.add_model(&model);
    let waves = Waves::new(
        WaveDesc {
            amplitude: 0.1,
            wavelength: 1.0,
            speed: 1.0,
            simulate: None,
        },
        positions.clone(),
    );
    let deformable = Deformable {
        mesh: 0,
        positions,
        normals: None,
        dirty: false,
    };
    engine
        .world_mut()
        .spawn((Transform::IDENTITY, renderable(water), waves, deformable));
    let work = run(&mut engine, 6, |engine, frame| {
        waves_system(engine.world_mut(), frame as f64 / 60.0);
    });
    for (frame, w) in work.iter().enumerate().skip(1) {
        assert_eq!(w.blas_refits + w.blas_rebuilds, 1, "frame {frame}");
        assert_eq!(w.tlas_builds, 1, "frame {frame}: its bounds moved");
        assert!(w.geometry_bytes > 0, "frame {frame}");
        assert_eq!(w.dynamic_instances, 1);
    }
    let _ = engine.shutdown();
}

/// Probability of each alias-table entry among the first `count`: its own threshold plus the
/// spill of every entry aliased to it, over `count`.
fn alias_probabilities(scene: &RenderScene) -> Vec<f64> {
    let lights = &scene.lights.lights[..scene.lights.count as usize];
    let n = lights.len() as f64;
    let mut p = vec![0.0; lights.len()];
    for (i, l) in lights.iter().enumerate() {
        p[i] += l.alias_threshold as f64 / n;
        p[l.alias_index as usize] += (1.0 - l.alias_threshold as f64) / n;
    }
    p
}

#[test]
fn switched_off_light_group_leaves_the_render_side_distribution() {
    // Render side built only from commits, exactly as the render thread applies them.
    let mut game = Upkeep::new();
    let mut render = RenderScene::empty();
    let commit = |game: &mut Upkeep, render: &mut RenderScene| {
        let (writes, header, _) = game.finish_frame();
        render.apply(&writes, &header);
    };
    let lamp = game.add_model(&grid_model(2, 1.0, 5.0));
    let mut ids = hecs::World::new();
    let (a, b) = (ids.spawn(()), ids.spawn(()));
    game.set_instance(
        a,
        lamp,
        Mat4::from_translation(Vec3::X * -2.0),
        None,
        Some(1),
    );
    game.set_instance(
        b,
        lamp,
        Mat4::from_translation(Vec3::X * 2.0),
        None,
        Some(2),
    );
    commit(&mut game, &mut render);
    assert_eq!(render.lights.count, 16, "two lamps of 8 emissive triangles");
    game.set_light_group(2, false);
    commit(&mut game, &mut render);
    // Rows: `a` was placed first, so it is row 0 and `b` row 1.
    let lights = &render.lights.lights[..render.lights.count as usize];
    assert_eq!(lights.len(), 8, "only group 1's lamp");
    assert!(lights.iter().all(|l| l.instance == 0), "{lights:?}");
    let p = alias_probabilities(&render);
    assert!((p.iter().sum::<f64>() - 1.0).abs() < 1e-6);
    assert!(
        lights
            .iter()
            .all(|l| (l.alias_index as usize) < lights.len())
    );
    game.set_light_group(2, true);
    commit(&mut game, &mut render);
    assert_eq!(render.lights.count, 16);
    let p = alias_probabilities(&render);
    let mass_b: f64 = render.lights.lights[..16]
        .iter()
        .zip(&p)
        .filter(|(l, _)| l.instance == 1)
        .map(|(_, p)| p)
        .sum();
    // Equal lamps: each group holds half the probability (alias tables are exact to f32).
    assert!((mass_b - 0.5).abs() < 1e-5, "{mass_b}");

    // The same through the engine: the render thread reports its own table's size.
    let mut engine = engine();
    let lamp = engine.add_model(&grid_model(2, 1.0, 5.0));
    for (x, group) in [(-2.0, 1), (2.0, 2), (0.0, 2)] {
        engine.world_mut().spawn((
            Transform::from_translation(Vec3::new(x, 2.0, 0.0)),
            renderable(lamp),
            Static,
            LightGroup(group),
        ));
    }
    let work = run(&mut engine, 3, |engine, frame| {
        if frame == 1 {
            engine.set_light_group(2, false);
        }
    });
    assert_eq!(work[0].lights, 24);
    assert_eq!(
        work[1].lights, 8,
        "group 2's two lamps left the distribution"
    );
    assert_eq!((work[2].lights, work[2].light_table_builds), (8, 0));
    let _ = engine.shutdown();
}

#[test]
fn declared_needs_refuse_undeclared_features() -> Result<(), Box<dyn std::error::Error>> {
    let text = |needs: &str| {
        format!(
            r#"Level(
            materials: [(name: "glass", kind: Dielectric), (name: "lamp", kind: Diffuse,
                         emission: (4, 4, 4))],
            grids: [(name: "pane", size: (1, 1), divisions: (1, 1), material: "glass"),
                    (name: "panel", size: (1, 1), divisions: (1, 1), material: "lamp")],
            instances: [(model: "pane"), (model: "panel", transform: (translation: (0, 2, 0)))],
            camera: (position: (0, 1, 3), look_at: (0, 0, 0), vertical_fov_deg: 40),
            {needs}
        )"#
        )
    };
    let path = Path::new("needs.ron");
    let root = AssetRoot::new(std::env::temp_dir())?;
    let derived = scene_from_level(path, &Level::parse(path, &text(""))?, &root)?;
    let used = Needs::of_scene(&derived);
    assert_eq!(
        used,
        Needs {
            glass: true,
            emitters: true,
            ..Default::default()
        }
    );
    let ok = text("needs: (glass: true, emitters: true, sun: true),");
    playable_from_level(path, &Level::parse(path, &ok)?, &root)?;
    let bad = text("needs: (emitters: true),");
    match playable_from_level(path, &Level::parse(path, &bad)?, &root) {
        Err(AssetError::Level { message, .. }) => {
            assert!(message.contains("uses glass"), "{message}")
        }
        other => panic!("expected a level error, got {other:?}"),
    }
    Ok(())
}

#[test]
fn sleeping_bodies_produce_no_commits() {
    use candela::sim::physics::{Collider, ColliderShape, RigidBody};
    let mut engine = engine();
    let floor = engine.add_model(&grid_model(4, 10.0, 0.0));
    let lamp = engine.add_model(&grid_model(1, 1.0, 5.0));
    let crate_model = engine.add_model(&grid_model(1, 0.5, 0.0));
    let ground = Collider::new(&ColliderShape::Box {
        half_extents: Vec3::new(5.0, 0.5, 5.0),
    })
    .expect("floor collider");
    engine
        .world_mut()
        .spawn((Transform::IDENTITY, renderable(floor), Static));
    // The floor's collider: a box whose top face is the grid's surface (y = 0).
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::new(0.0, -0.5, 0.0)),
        RigidBody::fixed(),
        ground,
    ));
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::Y * 3.0),
        renderable(lamp),
        Static,
    ));
    let crate_collider = Collider::new(&ColliderShape::Box {
        half_extents: Vec3::splat(0.25),
    })
    .expect("crate collider");
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::new(0.0, 1.5, 0.0)),
        renderable(crate_model),
        RigidBody::dynamic(),
        crate_collider,
    ));
    let work: Vec<FrameWork> = (0..360)
        .map(|_| {
            let report = engine
                .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
                .expect("frame");
            let _ = engine.wait_rendered().expect("a result").expect("renders");
            report.work
        })
        .collect();
    // Falling: the crate is awake and its row is written every frame.
    for (frame, w) in work.iter().enumerate().take(20).skip(1) {
        assert_eq!(w.awake_bodies, 1, "frame {frame}");
        assert!(
            w.instances_written >= 1 && w.tlas_builds == 1,
            "frame {frame}: {w:?}"
        );
    }
    // Asleep by the end of 6 s; from the first sleeping frame on, nothing is committed.
    let asleep = work
        .iter()
        .position(|w| w.awake_bodies == 0)
        .expect("the crate falls asleep within 6 s");
    let after = &work[asleep + 1..];
    assert!(after.len() > 60, "asleep only at frame {asleep}");
    for (i, w) in after.iter().enumerate() {
        let frame = asleep + 1 + i;
        assert_eq!(w.awake_bodies, 0, "frame {frame}");
        assert_eq!(
            w.instances_written, 0,
            "frame {frame}: a sleeping body wrote its row"
        );
        assert_eq!(w.tlas_builds, 0, "frame {frame}");
        assert_eq!(w.geometry_bytes, 0, "frame {frame}");
    }
    let _ = engine.shutdown();
}
