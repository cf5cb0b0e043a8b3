//! The tracer pool as a `Tracer` (render/balance/pool_tracer.rs): a CPU-only pool's frames
//! equal a single `CpuTracer`'s bit for bit over converging frames, whatever the scheme moves;
//! a GPU + CPU pool (the GPU tracer on lavapipe here) gives the GPU's units the GPU tracer's
//! pixels and the CPU's units the CPU tracer's, every unit rendered by exactly one tracer; and
//! the render thread runs a pool like any other tracer.

use std::path::Path;

use candela::app::{Engine, Environment, Step};
use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::layout::GpuFrameUniforms;
use candela::level::load_level;
use candela::render::balance::{PoolSpec, PoolTracer, SchemeKind, unit_count, unit_rows};
use candela::render::cpu::CpuTracer;
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{FrameSettings, RenderConfig, Tracer, TracerChoice, frame_uniforms};
use candela::scene::RenderScene;

/// 38 rows: 10 units, the last of two rows.
const SIZE: (u32, u32) = (40, 38);

fn scene() -> anyhow::Result<(SceneDesc, RenderScene)> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/script");
    let desc = load_scene(&assets.join("small.ron"), &AssetRoot::new(&assets)?)?;
    let scene = RenderScene::build(&desc);
    Ok((desc, scene))
}

fn uniforms(desc: &SceneDesc, scene: &RenderScene, frame: u32) -> GpuFrameUniforms {
    let s = FrameSettings::new(SIZE.0, SIZE.1, 2, 5, &desc.render).continuing(frame * 2);
    frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &s,
        &scene.header(),
    )
}

#[test]
fn a_cpu_pool_converges_to_the_single_tracer_film_bit_for_bit() -> anyhow::Result<()> {
    let (desc, scene) = scene()?;
    let mut single = CpuTracer::new();
    for scheme in [SchemeKind::RobinHood, SchemeKind::Interleaved] {
        let spec = PoolSpec {
            gpu: false,
            cpu_tracers: 2,
            cpu_threads: 1,
            scheme,
        };
        let mut pool = PoolTracer::new(spec, None, &scene)?;
        single.clear();
        let mut splits = Vec::new();
        for frame in 0..4 {
            let u = uniforms(&desc, &scene, frame);
            single.render(&scene, &u)?;
            let stats = pool.render(&scene, &u)?;
            let (expected, got) = (single.film()?, pool.film()?);
            assert!(
                got.mean == expected.mean,
                "{scheme:?}, frame {frame}: the pool's film differs from the single tracer's"
            );
            assert_eq!(got.samples, expected.samples);
            assert!(stats.counts.camera >= (SIZE.0 * SIZE.1 * 2) as u64);
            let times = pool.last_times().expect("a frame was measured");
            assert_eq!(times.tracer_seconds.len(), 2);
            assert!(times.tracer_seconds.iter().all(|t| *t > 0.0));
            splits.push(times.split.owners().to_vec());
        }
        assert_eq!(pool.name(), "pool");
        // The check means something only if the work moved between tracers at least once:
        // Robin Hood moves a unit every frame whatever the times; the interleaved scheme may
        // keep its split when the two equal tracers' times are even (a quiet machine).
        if scheme == SchemeKind::RobinHood {
            assert!(
                splits.windows(2).any(|w| w[0] != w[1]),
                "{scheme:?} never moved a unit: {splits:?}"
            );
        }
    }
    Ok(())
}

#[test]
fn a_gpu_and_cpu_pool_renders_each_unit_on_exactly_one_tracer() -> anyhow::Result<()> {
    let (desc, scene) = scene()?;
    let context = GpuContext::headless()?;
    let mut gpu = GpuTracer::new(context.clone(), &scene)?;
    let mut cpu = CpuTracer::new();
    let spec = PoolSpec {
        gpu: true,
        cpu_tracers: 1,
        cpu_threads: 1,
        scheme: SchemeKind::Equal,
    };
    let mut pool = PoolTracer::new(spec, Some(context), &scene)?;
    let u = uniforms(&desc, &scene, 0);
    gpu.render(&scene, &u)?;
    cpu.render(&scene, &u)?;
    pool.render(&scene, &u)?;
    let (g, c, p) = (gpu.film()?, cpu.film()?, pool.film()?);
    let owners = pool.last_times().expect("measured").split.owners().to_vec();
    assert_eq!(owners.len(), unit_count(SIZE.1));
    assert!(owners.contains(&0) && owners.contains(&1), "{owners:?}");
    let width = SIZE.0 as usize;
    for (unit, &owner) in owners.iter().enumerate() {
        let rows = unit_rows(unit, SIZE.1);
        for i in rows.start as usize * width..rows.end as usize * width {
            let expected = if owner == 0 { g.mean[i] } else { c.mean[i] };
            // The GPU's units: the GPU tracer's own pixels (same shader, same seeds); the
            // pool blends them on the host with blend 1, which copies them exactly.
            assert!(
                p.mean[i] == expected,
                "unit {unit} (tracer {owner}) pixel {i}: pool {:?}, tracer {:?}",
                p.mean[i],
                expected
            );
        }
    }
    // And the two tracers do differ on this scene, so a unit taken from the wrong one fails.
    assert!(g.mean.iter().zip(&c.mean).any(|(a, b)| a != b));
    Ok(())
}

#[test]
fn the_render_thread_runs_a_pool_like_any_tracer() -> anyhow::Result<()> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets");
    let level = load_level(
        &assets.join("test_scenes/gameplay/plate_door.ron"),
        &AssetRoot::new(&assets)?,
    )?;
    let config = RenderConfig {
        tracer: TracerChoice::Pool(PoolSpec {
            gpu: false,
            cpu_tracers: 2,
            cpu_threads: 1,
            scheme: SchemeKind::CostModel,
        }),
        ..RenderConfig::cpu(SIZE.0, SIZE.1)
    };
    let mut engine = Engine::new(config, Environment::of(&level.scene))?;
    engine.spawn_level(&level);
    let mut films = Vec::new();
    for frame in 0..6 {
        if frame == 5 {
            engine.capture_next();
        }
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let rendered = engine.wait_rendered().expect("a result")?;
        assert_eq!(rendered.tracer, "pool", "frame {frame}");
        if let Some(film) = rendered.film {
            films.push(film);
        }
    }
    let film = films.pop().expect("the captured film came back");
    assert_eq!((film.width, film.height), SIZE);
    // Converged over the six frames (a still camera keeps blending), every pixel finite.
    assert!(film.samples >= 6, "{} samples", film.samples);
    assert!(film.mean.iter().all(|p| p.is_finite()));
    Ok(())
}
