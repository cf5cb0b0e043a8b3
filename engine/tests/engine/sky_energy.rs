//! Energy of the physical sky in both tracers: a diffuse floor (reflectance ρ = 0.5) under
//! the sky alone (`sun_scale: 0`, no night sky) has radiance ρ/π · E_h, where E_h is the
//! horizontal irradiance of the very sky-view lookup the tracer reads, integrated by fine
//! quadrature (`sky_reference::horizontal_irradiance`), at sun elevations 60°, 30°, 10° and −6°
//! (twilight). The tracer's estimate is the mean over 32 × 32 pixels of 64 samples each (one
//! bounce: camera → floor → sky, reached by cosine sampling); its standard error comes from the
//! spread of the pixel means, and the test allows 4.5 of them per channel (a wrong table frame,
//! a missing cosine or a factor π fails by far more). The GPU tracer runs on lavapipe here.

use candela::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SceneDesc, SkyDesc,
};
use candela::render::cpu::CpuTracer;
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use candela::sky::{HAZE_TURBIDITY_3, PhysicalSky, SkyTables};
use glam::{DVec3, Mat4, Vec3};

/// A square floor of side `size` metres in the y = 0 plane, facing +Y.
fn floor(size: f32) -> Model {
    let h = size / 2.0;
    Model {
        name: "floor".into(),
        meshes: vec![Mesh {
            name: "floor".into(),
            positions: vec![
                Vec3::new(-h, 0.0, h),
                Vec3::new(h, 0.0, h),
                Vec3::new(h, 0.0, -h),
                Vec3::new(-h, 0.0, -h),
            ],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            triangle_materials: vec![0, 0],
            ..Default::default()
        }],
        materials: vec![Material {
            kind: MaterialKind::Diffuse,
            base_color: Vec3::splat(0.5),
            ..Default::default()
        }],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

/// Which tracer renders the floor.
#[derive(Clone, Copy, Debug)]
enum Which {
    Cpu,
    Gpu,
}

#[test]
fn diffuse_floor_under_the_physical_sky_conserves_energy() -> anyhow::Result<()> {
    for elevation in [60.0, 30.0, 10.0, -6.0] {
        floor_under_the_sky(Which::Cpu, elevation)?;
    }
    Ok(())
}

#[test]
fn the_gpu_floor_under_the_physical_sky_conserves_energy() -> anyhow::Result<()> {
    for elevation in [60.0, 10.0, -6.0] {
        floor_under_the_sky(Which::Gpu, elevation)?;
    }
    Ok(())
}

/// Renders the floor under the sky alone with the sun at `elevation_deg` with `which` and
/// checks its radiance against ρ/π · E_h.
fn floor_under_the_sky(which: Which, elevation_deg: f32) -> anyhow::Result<()> {
    let sky = PhysicalSky {
        sun_elevation_deg: elevation_deg,
        sun_azimuth_deg: 40.0,
        time: None,
        haze: HAZE_TURBIDITY_3,
        aerosol: candela::sky::Aerosol::TURBIDITY_3,
        ozone: 1.0,
        ground_albedo: [0.3; 3],
        sun_scale: 0.0,
        night_sky: 0.0,
        clouds: None,
    };
    let camera = CameraDesc {
        position: [0.0, 1.0, 0.0],
        look_at: [0.0, 0.0, 0.0],
        up: [0.0, 0.0, -1.0],
        vertical_fov_deg: 20.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let mut desc = SceneDesc::single(floor(10_000.0), camera);
    desc.sky = SkyDesc::Physical(sky);
    desc.render = RenderSettings {
        max_bounces: 1,
        roulette_start: 4,
        ..Default::default()
    };
    let scene = RenderScene::build(&desc);
    anyhow::ensure!(!scene.sky.texels.is_empty(), "the scene holds no sky table");
    let settings = FrameSettings::new(32, 32, 64, 7, &desc.render);
    let u = frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &settings,
        &scene.header(),
    );
    anyhow::ensure!(u.sun_solid_angle < 0.0, "sun_scale 0 must leave no sun");
    let mut tracer: Box<dyn Tracer> = match which {
        Which::Cpu => Box::new(CpuTracer::new()),
        Which::Gpu => Box::new(GpuTracer::new(GpuContext::headless()?, &scene)?),
    };
    tracer.render(&scene, &u)?;
    let pixels: Vec<DVec3> = tracer.film()?.mean.iter().map(|p| p.as_dvec3()).collect();
    let n = pixels.len() as f64;
    let mean = pixels.iter().copied().sum::<DVec3>() / n;
    let variance = pixels
        .iter()
        .map(|p| (*p - mean) * (*p - mean))
        .sum::<DVec3>()
        / (n - 1.0);
    let standard_error = (variance / n).powf(0.5);
    let expected = crate::sky_reference::horizontal_irradiance(&SkyTables::build(&sky)?)
        * (0.5 / std::f64::consts::PI);
    let z = (mean - expected).abs() / standard_error;
    println!(
        "{which:?} tracer, sun at {elevation_deg}°: floor radiance {mean:.6} expected \
         {expected:.6} (ρ/π·E_h), standard error {standard_error:.7}, deviation {z:.2} \
         standard errors"
    );
    anyhow::ensure!(
        expected.min_element() > 0.0,
        "sun at {elevation_deg}°: the sky gives no light"
    );
    assert!(
        z.max_element() < 4.5,
        "{which:?} tracer, sun at {elevation_deg}°: floor {mean} vs {expected}: {z} standard \
         errors"
    );
    Ok(())
}
