//! The frame pipeline end to end, headless, on the CPU tracer: world → extract → upkeep →
//! commit → render thread. Checks that
//! * every submitted frame is rendered and shutdown is clean (all results returned, the thread
//!   joined, no deadlock) — also when the engine is dropped mid-run;
//! * ray queries made by game code during a frame see the scene of the previous commit while the
//!   render thread renders, and are exact;
//! * the overlap is real: with game update and rendering both loaded, a frame takes about
//!   max(update, render), not their sum (generous bound here; `bench pipeline` gives the ratio);
//! * once everything stops moving, the converged image equals a direct render of the final
//!   scene within noise.

use std::time::{Duration, Instant};

use candela::app::{Engine, Environment, Step};
use candela::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SkyDesc,
};
use candela::ecs::{GlobalTransform, Renderable, Static, Transform};
use candela::render::film::ConvergePolicy;
use candela::render::{RenderConfig, TracerChoice};
use candela::trace::Ray;
use glam::{Mat4, Vec3};

fn quad_model(size: f32, emission: f32) -> Model {
    let h = size / 2.0;
    Model {
        name: "quad".into(),
        meshes: vec![Mesh {
            name: "quad".into(),
            positions: vec![
                Vec3::new(-h, 0.0, -h),
                Vec3::new(-h, 0.0, h),
                Vec3::new(h, 0.0, h),
                Vec3::new(h, 0.0, -h),
            ],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            triangle_materials: vec![0, 0],
            ..Default::default()
        }],
        materials: vec![Material {
            kind: MaterialKind::Diffuse,
            base_color: Vec3::splat(0.7),
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

fn environment() -> Environment {
    Environment {
        sun: None,
        sky: SkyDesc::Constant([0.2, 0.2, 0.25]),
        render: RenderSettings {
            max_bounces: 3,
            roulette_start: 2,
        },
        default_camera: CameraDesc {
            position: [0.0, 3.0, 6.0],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 45.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    }
}

fn config(spp: u32, size: u32) -> RenderConfig {
    RenderConfig {
        tracer: TracerChoice::Cpu,
        width: size,
        height: size,
        spp,
        seed: 1,
        converge: ConvergePolicy::default(),
        scaling: None,
    }
}

/// A floor, a lamp above it and `movers` platforms; returns the engine and the platforms.
fn scene(spp: u32, size: u32, movers: usize) -> (Engine, Vec<hecs::Entity>) {
    let mut engine = Engine::new(config(spp, size), environment()).expect("engine starts");
    let floor = engine.add_model(&quad_model(20.0, 0.0));
    let lamp = engine.add_model(&quad_model(2.0, 5.0));
    let platform = engine.add_model(&quad_model(0.5, 0.0));
    engine.world_mut().spawn((
        Transform::IDENTITY,
        Renderable {
            model: floor,
            material_override: None,
        },
        Static,
    ));
    engine.world_mut().spawn((
        Transform::from_translation(Vec3::Y * 4.0),
        Renderable {
            model: lamp,
            material_override: None,
        },
    ));
    let platforms = (0..movers)
        .map(|i| {
            engine.world_mut().spawn((
                Transform::from_translation(Vec3::new(i as f32 - movers as f32 / 2.0, 1.0, 0.0)),
                Renderable {
                    model: platform,
                    material_override: None,
                },
            ))
        })
        .collect();
    (engine, platforms)
}

#[test]
fn every_frame_renders_and_shutdown_is_clean() {
    let (mut engine, platforms) = scene(1, 16, 5);
    for frame in 0..30 {
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                let dt = step.step_seconds;
                for (i, &p) in platforms.iter().enumerate() {
                    if let Ok(mut t) = world.get::<&mut Transform>(p) {
                        t.translation.y = 1.0 + (frame as f32 * dt as f32 + i as f32).sin();
                    }
                }
            })
            .expect("frame");
    }
    let results = engine.shutdown();
    let mut frames: Vec<u64> = Vec::new();
    for r in results {
        frames.push(r.expect("render ok").frame);
    }
    // Results that the main thread had not collected yet come back at shutdown; together
    // every frame is there exactly once, in order.
    assert_eq!(frames.last(), Some(&29));
    assert!(frames.windows(2).all(|w| w[1] == w[0] + 1));

    // Dropping a running engine joins its render thread (no deadlock, no panic).
    let (mut engine, _) = scene(1, 16, 3);
    for _ in 0..5 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("frame");
    }
    drop(engine);
}

#[test]
fn queries_see_the_last_commit_while_the_render_thread_renders() {
    let (mut engine, platforms) = scene(4, 48, 3);
    let probe = platforms[1];
    let x = engine
        .world()
        .get::<&Transform>(probe)
        .expect("probe")
        .translation
        .x;
    let mut heights = Vec::new();
    for frame in 0..20 {
        let target = 0.5 + 0.1 * frame as f32;
        let mut seen = None;
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                let queries = step.queries;
                // The ray down onto the probe platform sees last frame's height.
                let ray = Ray::new(Vec3::new(x, 3.5, 0.0), Vec3::NEG_Y); // below the lamp
                if let Some(hit) = queries.closest(&ray) {
                    seen = Some((hit.entity, hit.position.y, hit.geometric_normal));
                }
                if let Ok(mut t) = world.get::<&mut Transform>(probe) {
                    t.translation.y = target;
                }
            })
            .expect("frame");
        heights.push((seen, target));
    }
    for (frame, window) in heights.windows(2).enumerate() {
        let (seen, _) = window[1];
        let (_, previous_target) = window[0];
        let (entity, y, normal) = seen.expect("the probe is always below the ray");
        assert_eq!(entity, Some(probe), "frame {}", frame + 1);
        assert!(
            (y - previous_target).abs() < 1e-5,
            "frame {}: {y} vs {previous_target}",
            frame + 1
        );
        assert!((normal.abs() - Vec3::Y).length() < 1e-5);
    }
    engine.shutdown();
}

#[test]
fn update_and_render_overlap() {
    // Calibrate: spp such that one frame renders in about 80 ms.
    let (mut engine, _) = scene(1, 96, 20);
    let mut render = 0.0;
    for _ in 0..4 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("frame");
        render = engine
            .wait_rendered()
            .expect("result")
            .expect("ok")
            .render_seconds;
    }
    engine.shutdown();
    let spp = ((0.08 / render.max(1e-4)).round() as u32).clamp(1, 512);
    let (mut engine, _) = scene(spp, 96, 20);
    let update = Duration::from_millis(80);
    let mut render_total = 0.0;
    let mut rendered = 0;
    // Warm up, then time 12 frames.
    for _ in 0..3 {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {
                std::thread::sleep(update)
            })
            .expect("frame");
    }
    let started = Instant::now();
    let frames = 12;
    for _ in 0..frames {
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {
                std::thread::sleep(update)
            })
            .expect("frame");
        for r in engine.rendered() {
            render_total += r.expect("ok").render_seconds;
            rendered += 1;
        }
    }
    let per_frame = started.elapsed().as_secs_f64() / frames as f64;
    let render_mean = render_total / rendered.max(1) as f64;
    let update_s = update.as_secs_f64();
    eprintln!(
        "update {update_s:.3} s, render {render_mean:.3} s, frame {per_frame:.3} s: {:.2} × max, {:.2} × sum",
        per_frame / update_s.max(render_mean),
        per_frame / (update_s + render_mean)
    );
    // Serial execution would take update + render; overlapped, about the larger of the two.
    assert!(
        per_frame < 0.8 * (update_s + render_mean),
        "frame {per_frame:.3} s is not overlapped (update {update_s:.3} s, render {render_mean:.3} s)"
    );
    engine.shutdown();
}

#[test]
fn still_scene_converges_to_a_direct_render() {
    use candela::assets::{SceneDesc, SceneInstance};
    let (mut engine, platforms) = scene(2, 24, 2);
    // Move for a while, then stop and let the image converge for 40 frames.
    for frame in 0..50 {
        let moving = frame < 10;
        if frame == 49 {
            engine.capture_next();
        }
        engine
            .frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                let world = &mut *step.world;
                if moving {
                    for &p in &platforms {
                        if let Ok(mut t) = world.get::<&mut Transform>(p) {
                            t.translation.z += 0.05;
                        }
                    }
                }
            })
            .expect("frame");
    }
    let positions: Vec<Mat4> = platforms
        .iter()
        .map(|&p| engine.world().get::<&GlobalTransform>(p).expect("global").0)
        .collect();
    let results = engine.shutdown();
    let film = results
        .into_iter()
        .filter_map(|r| r.expect("ok").film)
        .next_back()
        .expect("captured film");
    // The same final scene, rendered directly with the same total samples (40 still frames × 2).
    let mut desc = SceneDesc::single(quad_model(20.0, 0.0), environment().default_camera);
    desc.models = vec![
        quad_model(20.0, 0.0),
        quad_model(2.0, 5.0),
        quad_model(0.5, 0.0),
    ];
    desc.sky = environment().sky;
    desc.render = environment().render;
    desc.instances = vec![
        SceneInstance::placed(0, Mat4::IDENTITY),
        SceneInstance::placed(1, Mat4::from_translation(Vec3::Y * 4.0)),
    ];
    for m in positions {
        desc.instances.push(SceneInstance::placed(2, m));
    }
    let direct = candela_direct_mean(&desc, 24, 80);
    let ours: f64 = film.mean.iter().map(|p| p.x as f64).sum::<f64>() / film.mean.len() as f64;
    // Two estimates of the same mean, each from 80 spp per pixel over 576 pixels; their
    // difference's standard error, from the direct render's pixel spread, bounds the gap.
    let (mean, std_error) = direct;
    assert!(
        (ours - mean).abs() <= 4.5 * std_error * std::f64::consts::SQRT_2,
        "converged {ours} vs direct {mean} ± {std_error}"
    );
}

/// Mean red radiance of a direct render (`spp` per pixel in 8 independent batches) and its
/// standard error.
fn candela_direct_mean(desc: &candela::assets::SceneDesc, size: u32, spp: u32) -> (f64, f64) {
    use candela::render::cpu::CpuTracer;
    use candela::render::{FrameSettings, Tracer, frame_uniforms};
    use candela::scene::RenderScene;
    let scene = RenderScene::build(desc);
    let mut tracer = CpuTracer::new();
    let mut means = Vec::new();
    for b in 0..8 {
        let mut s = FrameSettings::new(size, size, spp / 8, 1000 + b, &desc.render);
        s.film_blend = 1.0;
        let u = frame_uniforms(&desc.camera, None, &desc.sky, &s, &scene.header());
        tracer.render(&scene, &u).expect("render");
        let film = tracer.film().expect("film");
        means.push(film.mean.iter().map(|p| p.x as f64).sum::<f64>() / film.mean.len() as f64);
    }
    let m = means.iter().sum::<f64>() / 8.0;
    let var = means.iter().map(|x| (x - m).powi(2)).sum::<f64>() / 7.0;
    (m, (var / 8.0).sqrt())
}
