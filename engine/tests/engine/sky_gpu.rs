//! The GPU tracer renders the physical sky itself (its sky-view table on binding 16, the WGSL
//! twin of the lookup in `shaders/shared/sky_view.wgsl`): given `SkyDesc::Physical` through the
//! engine, every frame comes back from the GPU tracer, with no fallback notice, finite and with
//! the floor sunlit. That the GPU's sky equals the CPU's is `tests/cross/gpu_matches_cpu.rs`.
//! Real GPU tracer (lavapipe without a GPU).

use candela::app::{Engine, Step};
use candela::assets::SkyDesc;
use candela::ecs::{Renderable, Static, Transform};
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{OpenTracer, Tracer};
use candela::sky::PhysicalSky;

use crate::pipeline_common::{config, environment, quad_model};

const FRAMES: u64 = 4;

#[test]
fn the_gpu_tracer_renders_a_physical_sky_itself() {
    let open: OpenTracer = Box::new(|_, scene| {
        Ok(Box::new(GpuTracer::new(GpuContext::headless()?, scene)?) as Box<dyn Tracer>)
    });
    let mut env = environment();
    env.sky = SkyDesc::Physical(PhysicalSky {
        sun_elevation_deg: 40.0,
        sun_azimuth_deg: 120.0,
        time: None,
        haze: candela::sky::HAZE_TURBIDITY_3,
        aerosol: candela::sky::Aerosol::TURBIDITY_3,
        ozone: 1.0,
        ground_albedo: [0.3; 3],
        sun_scale: 1.0,
        night_sky: 1.0,
        clouds: None,
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
    let tracers: Vec<&str> = rendered.iter().map(|r| r.tracer).collect();
    assert!(
        tracers.iter().all(|t| *t == "gpu"),
        "every frame on the GPU tracer: {tracers:?}"
    );
    let notices: Vec<&str> = rendered
        .iter()
        .filter_map(|r| r.notice.as_deref())
        .collect();
    assert!(notices.is_empty(), "no fallback: {notices:?}");
    let film = rendered
        .last()
        .and_then(|r| r.film.as_ref())
        .expect("captured film");
    assert!(film.mean.iter().all(|p| p.is_finite()));
    let mean = film.mean.iter().map(|p| p.y).sum::<f32>() / film.mean.len() as f32;
    assert!(mean > 0.01, "the sunlit floor is dark: {mean}");
}
