//! The moon in the CPU tracer: a narrow-field render (0.0125° a pixel) centred on a nearly full
//! moon shows a disc whose radius, from its area, is 0.259° to a pixel; and a diffuse floor
//! (ρ = 0.5) under the moon alone (night_sky 0: no stars nor airglow; the sun 18° below the
//! horizon) has radiance ρ/π (E_moon T cos θ + E_sky), E_moon T the moon's irradiance after
//! the air and E_sky the night sky-view table's horizontal irradiance (fine quadrature, the
//! moonlit sky included), within 4.5 standard errors of the pixel means, in both tracers (the GPU
//! one on lavapipe or a GPU).

use candela::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SceneDesc, SkyDesc,
};
use candela::render::cpu::CpuTracer;
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use candela::sky::{MOON_ANGULAR_RADIUS_DEG, PhysicalSky, SkyTables};
use glam::{DVec3, Mat4, Vec3};

use crate::sky_night::find;

/// A square floor of side `size` metres in the y = `y` plane, facing +Y.
fn floor(size: f32, y: f32) -> Model {
    let h = size / 2.0;
    Model {
        name: "floor".into(),
        meshes: vec![Mesh {
            name: "floor".into(),
            positions: vec![
                Vec3::new(-h, y, h),
                Vec3::new(h, y, h),
                Vec3::new(h, y, -h),
                Vec3::new(-h, y, -h),
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

/// A night with a nearly full moon more than 35° high and the sun below −18°.
fn full_moon_night() -> PhysicalSky {
    let sky = find(
        |now| {
            now.sun.elevation_deg < -18.0
                && now.moon.is_some_and(|m| m.horizontal.elevation_deg > 35.0)
        },
        |now| now.moon.map_or(f64::MAX, |m| m.phase_angle_deg),
    );
    PhysicalSky {
        night_sky: 0.0,
        ..sky
    }
}

fn render(
    desc: &SceneDesc,
    size: u32,
    spp: u32,
    gpu: bool,
) -> anyhow::Result<(Vec<DVec3>, candela::layout::GpuFrameUniforms)> {
    let scene = RenderScene::build(desc);
    let settings = FrameSettings::new(size, size, spp, 11, &desc.render);
    let u = frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &settings,
        &scene.header(),
    );
    let mut tracer: Box<dyn Tracer> = if gpu {
        Box::new(GpuTracer::new(GpuContext::headless()?, &scene)?)
    } else {
        Box::new(CpuTracer::new())
    };
    tracer.render(&scene, &u)?;
    Ok((
        tracer.film()?.mean.iter().map(|p| p.as_dvec3()).collect(),
        u,
    ))
}

#[test]
fn the_moon_disc_is_its_angular_size_to_a_pixel() -> anyhow::Result<()> {
    let sky = full_moon_night();
    let moon = sky.moon_light()?.expect("a moon").direction;
    const SIZE: u32 = 96;
    let fov_deg = 1.2f32;
    let camera = CameraDesc {
        position: [0.0, 0.0, 0.0],
        look_at: moon.to_array(),
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: fov_deg,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let mut desc = SceneDesc::single(floor(10.0, -100.0), camera);
    desc.sky = SkyDesc::Physical(sky);
    let (pixels, u) = render(&desc, SIZE, 16, false)?;
    let inside = Vec3::from(u.sun_radiance).y as f64;
    anyhow::ensure!(inside > 0.0, "the moon is not the primary disc");
    // Pixels more than half covered by the lit disc.
    let lit = pixels.iter().filter(|p| p.y > 0.5 * inside).count() as f64;
    let pixel_deg = fov_deg as f64 / SIZE as f64;
    let phase = sky.now()?.moon.expect("a moon");
    // The lit share is nearly 1 near full; the area of the lit part over it is the disc's.
    let radius_deg = (lit / phase.illuminated_fraction / std::f64::consts::PI).sqrt() * pixel_deg;
    println!(
        "moon radius {radius_deg:.4}° (declared {MOON_ANGULAR_RADIUS_DEG}°, pixel {pixel_deg:.4}°, \
         lit {:.4})",
        phase.illuminated_fraction
    );
    assert!(
        (radius_deg - MOON_ANGULAR_RADIUS_DEG as f64).abs() < pixel_deg,
        "radius {radius_deg}°"
    );
    Ok(())
}

#[test]
fn a_diffuse_floor_under_the_moon_alone_has_the_moons_irradiance() -> anyhow::Result<()> {
    floor_under_the_moon(false)
}

/// The same floor on the GPU tracer: the moon disc's next-event estimate and the moonlit sky's
/// WGSL lookup against the same quadrature.
#[test]
fn the_gpu_floor_under_the_moon_alone_has_the_moons_irradiance() -> anyhow::Result<()> {
    floor_under_the_moon(true)
}

fn floor_under_the_moon(gpu: bool) -> anyhow::Result<()> {
    let sky = full_moon_night();
    let light = sky.moon_light()?.expect("a moon");
    let camera = CameraDesc {
        position: [0.0, 1.0, 0.0],
        look_at: [0.0, 0.0, 0.0],
        up: [0.0, 0.0, -1.0],
        vertical_fov_deg: 20.0,
        aperture_radius: 0.0,
        focus_distance: None,
    };
    let mut desc = SceneDesc::single(floor(10_000.0, 0.0), camera);
    desc.sky = SkyDesc::Physical(sky);
    desc.render = RenderSettings {
        max_bounces: 1,
        roulette_start: 4,
        ..Default::default()
    };
    let (pixels, u) = render(&desc, 32, 64, gpu)?;
    anyhow::ensure!(u.sun_solid_angle > 0.0, "the moon must be the primary disc");
    let n = pixels.len() as f64;
    let mean = pixels.iter().copied().sum::<DVec3>() / n;
    let variance = pixels
        .iter()
        .map(|p| (*p - mean) * (*p - mean))
        .sum::<DVec3>()
        / (n - 1.0);
    let standard_error = (variance / n).powf(0.5);
    let moon = light.irradiance.as_dvec3() * light.direction.y as f64;
    let sky_part = crate::sky_reference::horizontal_irradiance(&SkyTables::build(&sky)?);
    let expected = (moon + sky_part) * (0.5 / std::f64::consts::PI);
    let z = (mean - expected).abs() / standard_error;
    println!(
        "{} tracer: floor G {:.4e} expected G {:.4e} (moon {:.4e}, sky {:.4e}), standard \
         error G {:.3e}, {z:.2} standard errors",
        if gpu { "GPU" } else { "CPU" },
        mean.y,
        expected.y,
        moon.y * 0.5 / std::f64::consts::PI,
        sky_part.y * 0.5 / std::f64::consts::PI,
        standard_error.y
    );
    assert!(z.max_element() < 4.5, "floor {mean} vs {expected}: {z}");
    Ok(())
}
