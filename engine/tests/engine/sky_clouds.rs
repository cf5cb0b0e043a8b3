//! The cloud layer (`sky/clouds.rs`, `render/cpu/clouds.rs`, `scene/discs.rs`):
//! * one Gaussian cloud carried by the wind: its shadow's centroid on the ground, measured from
//!   the tracers' transmittance towards the sun over a 400 × 400 grid covering the whole tile,
//!   sits at h · tan(zenith) from the cloud (measured the same way straight up) away from the
//!   sun's azimuth, and both move by wind × Δt between two times of day a minute apart, each
//!   to a texel;
//! * a diffuse floor under the sun alone (the sky and the cloud's in-scatter switched off in
//!   the uniforms): inside the shadow the CPU tracer's radiance is the unshadowed one × exp(−τ)
//!   (averaged over the sun's disc by quadrature) within 4.5 standard errors, next-event and
//!   escaping rays alike;
//! * bad layers (a texture of 0 texels, a tile of 0 metres, a negative height, a non-finite
//!   wind) are refused naming the level file and the field.

use std::path::PathBuf;

use candela::assets::{
    AssetRoot, CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings,
    SceneDesc, SkyDesc, load_scene,
};
use candela::layout::{GpuFrameUniforms, SKY_CONSTANT};
use candela::render::cpu::{CpuTracer, clouds};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::{RenderScene, SkyTable};
use candela::sky::{CloudLayer, CloudShape, PhysicalSky, SkyTime};
use glam::{DVec2, DVec3, Mat4, Vec2, Vec3};

const SIZE: f32 = 4000.0;
const TEXELS: u32 = 256;
const HEIGHT: f32 = 1500.0;
const WIND: [f32; 2] = [12.0, -7.0];

fn blob(centre: Vec2, radius: f32, tau: f32) -> CloudLayer {
    CloudLayer {
        height_m: HEIGHT,
        wind_m_s: WIND,
        texels: TEXELS,
        size_m: SIZE,
        shape: CloudShape::Gaussian {
            centre_m: centre.to_array(),
            radius_m: radius,
            optical_depth: tau,
        },
    }
}

/// The uniforms (world space) and the cloud texels the render side holds for `sky`.
fn uniforms(sky: &PhysicalSky) -> (GpuFrameUniforms, Vec<f32>) {
    let desc = SkyDesc::Physical(*sky);
    let mut u: GpuFrameUniforms = bytemuck::Zeroable::zeroed();
    candela::scene::lights::fill_sun_and_sky(&mut u, None, &desc);
    let mut table = SkyTable::default();
    table.update(&desc);
    (u, table.clouds.to_vec())
}

/// The weighted circular mean over the tile (per axis, so a blob across the tile's edge is
/// found whole), on a 400 × 400 grid of ground points; metres in 0..SIZE.
fn centroid(weight: impl Fn(Vec3) -> f64) -> DVec2 {
    let n = 400;
    let s = f64::from(SIZE);
    let (mut cx, mut sx, mut cz, mut sz) = (0.0, 0.0, 0.0, 0.0);
    for j in 0..n {
        for i in 0..n {
            let x = (i as f64 + 0.5) * s / n as f64;
            let z = (j as f64 + 0.5) * s / n as f64;
            let w = weight(Vec3::new(x as f32, 0.0, z as f32));
            let (ax, az) = (x / s * std::f64::consts::TAU, z / s * std::f64::consts::TAU);
            cx += w * ax.cos();
            sx += w * ax.sin();
            cz += w * az.cos();
            sz += w * az.sin();
        }
    }
    let at = |c: f64, s_: f64| (s_.atan2(c) / std::f64::consts::TAU).rem_euclid(1.0) * s;
    DVec2::new(at(cx, sx), at(cz, sz))
}

/// `d` wrapped into −SIZE/2..SIZE/2.
fn wrapped(d: DVec2) -> DVec2 {
    let s = f64::from(SIZE);
    d - (d / s).round() * s
}

#[test]
fn a_cloud_shadow_moves_with_the_wind_and_falls_away_from_the_sun() -> anyhow::Result<()> {
    let at = |hours: f64| PhysicalSky {
        time: Some(SkyTime {
            latitude_deg: 48.1,
            longitude_deg: 11.6,
            year: 2026,
            month: 6,
            day: 21,
            utc_hours: hours,
            time_rate: 0.0,
        }),
        clouds: Some(blob(Vec2::new(1000.0, 2500.0), 150.0, 2.0)),
        ..PhysicalSky::default()
    };
    let texel = f64::from(SIZE / TEXELS as f32);
    let mut seen = Vec::new();
    for hours in [10.0, 10.0 + 1.0 / 60.0] {
        let (u, tau) = uniforms(&at(hours));
        let sun = Vec3::from(u.sun_direction);
        anyhow::ensure!(sun.y > 0.3, "the sun must stand high: {sun}");
        let cloud = centroid(|p| 1.0 - f64::from(clouds::transmittance(&u, &tau, p, Vec3::Y)));
        let shadow = centroid(|p| 1.0 - f64::from(clouds::transmittance(&u, &tau, p, sun)));
        // Away from the sun: −(d.x, d.z) / d.y · h = h · tan(zenith) against its azimuth.
        let expected =
            -DVec2::new(f64::from(sun.x), f64::from(sun.z)) / f64::from(sun.y) * f64::from(HEIGHT);
        let offset = wrapped(shadow - cloud);
        println!(
            "{hours:.4} h: cloud {cloud:.1}, shadow {shadow:.1}, shadow − cloud {offset:.2} \
             m, expected {expected:.2} m (texel {texel:.1} m)"
        );
        assert!(
            (offset - expected).abs().max_element() < texel,
            "shadow − cloud {offset} vs h·tan(zenith) away from the sun {expected}"
        );
        seen.push((cloud, shadow, expected));
    }
    let wind = DVec2::new(f64::from(WIND[0]), f64::from(WIND[1])) * 60.0;
    let cloud_moved = wrapped(seen[1].0 - seen[0].0);
    // The shadow moves with the cloud, plus the little the sun turned in that minute.
    let shadow_moved = wrapped(seen[1].1 - seen[0].1);
    let shadow_expected = wind + seen[1].2 - seen[0].2;
    println!(
        "in 60 s the cloud moved {cloud_moved:.2} m, its shadow {shadow_moved:.2} m; wind × Δt \
         {wind:.2} m, with the sun's turn {shadow_expected:.2} m"
    );
    assert!(
        (cloud_moved - wind).abs().max_element() < texel,
        "cloud moved {cloud_moved}, wind × Δt {wind}"
    );
    assert!(
        (shadow_moved - shadow_expected).abs().max_element() < texel,
        "shadow moved {shadow_moved}, expected {shadow_expected}"
    );
    Ok(())
}

/// A square floor of side `size` metres in the y = 0 plane, facing +Y, reflectance 0.5.
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

/// Mean and standard error (of the spread of the pixel means) of a CPU render with `u`.
fn render(scene: &RenderScene, u: &GpuFrameUniforms) -> anyhow::Result<(DVec3, DVec3)> {
    let mut tracer = CpuTracer::new();
    tracer.render(scene, u)?;
    let pixels: Vec<DVec3> = tracer.film()?.mean.iter().map(|p| p.as_dvec3()).collect();
    let n = pixels.len() as f64;
    let mean = pixels.iter().copied().sum::<DVec3>() / n;
    let variance = pixels
        .iter()
        .map(|p| (*p - mean) * (*p - mean))
        .sum::<DVec3>()
        / (n - 1.0);
    Ok((mean, (variance / n).powf(0.5)))
}

#[test]
fn the_floor_in_a_cloud_shadow_gets_the_sun_times_exp_minus_tau() -> anyhow::Result<()> {
    let tau0 = 1.5;
    let mut sky = PhysicalSky {
        sun_elevation_deg: 55.0,
        sun_azimuth_deg: 30.0,
        ..PhysicalSky::default()
    };
    let sun = sky.sun_horizontal()?.direction();
    // The cloud straight towards the sun from the floor's origin, so its shadow is centred
    // there (the sky has no time: the wind has not moved it).
    let centre = Vec2::new(sun.x, sun.z) / sun.y * HEIGHT;
    sky.clouds = Some(blob(centre, 300.0, tau0));
    let camera = CameraDesc {
        position: [0.0, 1.0, 0.0],
        look_at: [0.0, 0.0, 0.0],
        up: [0.0, 0.0, -1.0],
        vertical_fov_deg: 2.0,
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
    let settings = FrameSettings::new(16, 16, 64, 3, &desc.render);
    let mut cloudy = frame_uniforms(
        &desc.camera,
        desc.sun.as_ref(),
        &desc.sky,
        &settings,
        &scene.header(),
    );
    anyhow::ensure!(cloudy.sun_solid_angle > 0.0, "the sun must be a disc");
    anyhow::ensure!(
        cloudy.cloud_texels == TEXELS,
        "no cloud layer in the uniforms"
    );
    // The sun alone: a black sky, and no in-scatter from the cloud.
    cloudy.sky_kind = SKY_CONSTANT;
    cloudy.sky_zenith = [0.0; 4];
    cloudy.cloud_light = [0.0; 3];
    let clear = GpuFrameUniforms {
        cloud_plane: [0.0; 4],
        ..cloudy
    };
    // The floor's origin in render space.
    let seen = -scene.header().origin;
    let t = clouds::transmittance(&cloudy, &scene.sky.clouds, seen, sun);
    anyhow::ensure!(
        (t - (-tau0).exp()).abs() < 0.01,
        "T at the shadow's centre {t} vs exp(−τ) {}",
        (-tau0).exp()
    );
    // exp(−τ) along each direction of the sun's disc (the cone the tracer samples; τ falls
    // by ~4·10⁻⁴ of itself over the ~10 m the disc spans on the cloud plane), by a 64 × 64
    // quadrature uniform in solid angle.
    let sun_disc = Vec3::from(cloudy.sun_direction);
    let (a, b) = sun_disc.any_orthonormal_pair();
    let n = 64;
    let mut sum = 0.0f64;
    for i in 0..n {
        let c = 1.0 - (i as f32 + 0.5) / n as f32 * (1.0 - cloudy.sun_cos_radius);
        let s_ = (1.0 - c * c).max(0.0).sqrt();
        for j in 0..n {
            let phi = std::f32::consts::TAU * (j as f32 + 0.5) / n as f32;
            let w = sun_disc * c + (a * phi.cos() + b * phi.sin()) * s_;
            sum += f64::from(clouds::transmittance(&cloudy, &scene.sky.clouds, seen, w));
        }
    }
    let t_disc = sum / (n * n) as f64;
    let (shaded, shaded_error) = render(&scene, &cloudy)?;
    let (lit, lit_error) = render(&scene, &clear)?;
    let expected = lit * t_disc;
    let sigma = (shaded_error * shaded_error + lit_error * lit_error * t_disc * t_disc).powf(0.5);
    let z = (shaded - expected).abs() / sigma.max(DVec3::splat(1e-12));
    println!(
        "floor in the shadow {shaded:.6}, unshadowed {lit:.6} × T {t_disc:.5} (centre {t:.5}) \
         = {expected:.6}; \
         σ {sigma:.7}, deviation {z:.2} σ"
    );
    assert!(
        z.max_element() < 4.5,
        "shadowed {shaded} vs unshadowed × exp(−τ) {expected}: {z} σ"
    );
    Ok(())
}

struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn refused(name: &str, clouds: &str, field: &str) {
    let dir = std::env::temp_dir().join(format!("candela_clouds_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let d = Dir(dir);
    let text = format!(
        "Level(models: [], instances: [], camera: (position: (0, 1, 3), look_at: (0, 0, 0), \
         vertical_fov_deg: 40), sky: Physical((clouds: Some(({clouds})))))"
    );
    let path = d.0.join(format!("{name}.ron"));
    std::fs::write(&path, text).expect("write");
    let message = match load_scene(&path, &AssetRoot::new(&d.0).expect("root")) {
        Ok(_) => panic!("{name} should be refused"),
        Err(e) => e.to_string(),
    };
    println!("{name}: {message}");
    assert!(
        message.contains(&format!("{name}.ron")),
        "does not name the file: {message}"
    );
    assert!(message.contains(field), "does not name {field}: {message}");
}

const BLOB: &str = "shape: Gaussian(centre_m: (0.0, 0.0), radius_m: 50.0, optical_depth: 1.0)";

#[test]
fn bad_cloud_layers_name_the_file_and_the_field() {
    refused(
        "zero_texels",
        &format!("height_m: 1000.0, texels: 0, size_m: 800.0, {BLOB}"),
        "clouds.texels",
    );
    refused(
        "zero_size",
        &format!("height_m: 1000.0, texels: 64, size_m: 0.0, {BLOB}"),
        "clouds.size_m",
    );
    refused(
        "below_ground",
        &format!("height_m: -5.0, texels: 64, size_m: 800.0, {BLOB}"),
        "clouds.height_m",
    );
    refused(
        "stormy",
        &format!("height_m: 1000.0, wind_m_s: (inf, 0.0), texels: 64, size_m: 800.0, {BLOB}"),
        "clouds.wind_m_s",
    );
    // The same layer with good values loads.
    let dir = std::env::temp_dir().join(format!("candela_clouds_good_{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let d = Dir(dir);
    let path = d.0.join("good.ron");
    std::fs::write(
        &path,
        format!(
            "Level(models: [], instances: [], camera: (position: (0, 1, 3), look_at: (0, 0, 0), \
             vertical_fov_deg: 40), sky: Physical((clouds: Some((height_m: 1000.0, \
             wind_m_s: (3.0, 1.0), texels: 64, size_m: 800.0, {BLOB})))))"
        ),
    )
    .expect("write");
    let desc = load_scene(&path, &AssetRoot::new(&d.0).expect("root")).expect("a good layer loads");
    let SkyDesc::Physical(sky) = desc.sky else {
        panic!("not physical")
    };
    assert_eq!(sky.clouds.map(|c| c.texels), Some(64));
}
