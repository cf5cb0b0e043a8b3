//! The GPU tracer has no WGSL twin of the physical sky yet: given `SkyDesc::Physical` it answers
//! `RenderError::Unsupported`, and the render thread hands the run to the CPU tracer at once —
//! the first frame rendered again on the CPU, one message naming the reason, every frame back
//! and lit. Real GPU tracer (lavapipe without a GPU).

use candela::app::{Engine, Step};
use candela::assets::SkyDesc;
use candela::ecs::{Renderable, Static, Transform};
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{OpenTracer, Tracer};
use candela::sky::PhysicalSky;

use crate::pipeline_common::{config, environment, quad_model};

const FRAMES: u64 = 4;

#[test]
fn the_gpu_tracer_hands_a_physical_sky_to_the_cpu_tracer() {
    let open: OpenTracer = Box::new(|_, scene| {
        Ok(Box::new(GpuTracer::new(GpuContext::headless()?, scene)?) as Box<dyn Tracer>)
    });
    let mut env = environment();
    env.sky = SkyDesc::Physical(PhysicalSky {
        sun_elevation_deg: 40.0,
        sun_azimuth_deg: 120.0,
        time: None,
        haze: candela::sky::HAZE_TURBIDITY_3,
        ozone: 1.0,
        ground_albedo: [0.3; 3],
        sun_scale: 1.0,
    });
    let mut engine = Engine::with_tracer(config(2, 16), env, open).expect("engine");
    let floor = engine.add_model(&quad_model(20.0, 0.0));
    engine.world_mut().spawn((
        Transform::IDENTITY,
        Renderable {
            model: floor,
            material_override: None,
        },
        Static,
    ));
    for frame in 0..FRAMES {
        if frame == FRAMES - 1 {
            engine.capture_next();
        }
        engine
            .frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})
            .expect("the main thread's frame");
    }
    let rendered: Vec<_> = engine
        .shutdown()
        .into_iter()
        .map(|r| r.unwrap_or_else(|e| panic!("a render failed: {e}")))
        .collect();
    assert_eq!(rendered.len() as u64, FRAMES);
    assert!(
        rendered.iter().all(|r| r.tracer == "cpu"),
        "every frame on the CPU tracer"
    );
    let notices: Vec<&str> = rendered
        .iter()
        .filter_map(|r| r.notice.as_deref())
        .collect();
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(
        notices[0].contains("physical sky") && notices[0].contains("CPU tracer"),
        "{}",
        notices[0]
    );
    let film = rendered
        .last()
        .and_then(|r| r.film.as_ref())
        .expect("captured film");
    assert!(film.mean.iter().all(|p| p.is_finite()));
    let mean = film.mean.iter().map(|p| p.y).sum::<f32>() / film.mean.len() as f32;
    assert!(mean > 0.01, "the sunlit floor is dark: {mean}");
}
