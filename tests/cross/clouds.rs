//! Both tracers agree under a cloud layer (`sky/clouds.rs`, `render/cpu/clouds.rs`, WGSL twin
//! `shaders/shared/clouds.wgsl` reading the optical depths after the sky view in binding 16):
//! a diffuse floor and a sphere in afternoon sun under a noise cloud layer 60 m up that the
//! wind has carried (the sky's time sets the drift), so the floor holds cloud shadows, the sky
//! above the horizon shows the clouds, and both estimators of the sun disc (next-event and
//! escaping rays) are dimmed. Judged by `gpu_matches_cpu::compare_method`: region means within
//! 4.5 σ + rounding, and the same paths (RMS difference below half the noise).

use candela::assets::{Material, MaterialKind, Mesh, SceneDesc, SceneInstance, SkyDesc};
use candela::layout::METHOD_DEFAULT;
use candela::sky::{CloudLayer, CloudShape, HAZE_TURBIDITY_3, PhysicalSky, SkyTime};
use candela_tests::{camera, icosphere, single_mesh_model};
use glam::Vec3;

/// The scene: a 40 m floor, a sphere, noise clouds 60 m up drifting with a 7 m/s wind.
pub(crate) fn cloudy_scene() -> SceneDesc {
    let h = 20.0;
    let floor = Mesh {
        name: "floor".into(),
        positions: vec![
            Vec3::new(-h, 0.0, -h),
            Vec3::new(-h, 0.0, h),
            Vec3::new(h, 0.0, h),
            Vec3::new(h, 0.0, -h),
        ],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0, 0],
        ..Default::default()
    };
    let diffuse = |albedo: f32| Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        ..Material::default()
    };
    let mut desc = SceneDesc::single(
        single_mesh_model(floor, diffuse(0.5)),
        camera(Vec3::new(0.0, 1.5, 6.0), Vec3::new(0.0, 3.0, 0.0), 80.0),
    );
    desc.models.push(single_mesh_model(
        icosphere(Vec3::new(0.0, 1.0, 0.0), 1.0, 3, false),
        diffuse(0.7),
    ));
    desc.instances
        .push(SceneInstance::placed(1, glam::Mat4::IDENTITY));
    desc.sun = None;
    desc.sky = SkyDesc::Physical(PhysicalSky {
        time: Some(SkyTime {
            latitude_deg: 48.1,
            longitude_deg: 11.6,
            year: 2026,
            month: 6,
            day: 21,
            utc_hours: 14.2,
            time_rate: 0.0,
        }),
        haze: HAZE_TURBIDITY_3,
        aerosol: candela::sky::Aerosol::TURBIDITY_3,
        clouds: Some(CloudLayer {
            height_m: 60.0,
            wind_m_s: [7.0, -3.0],
            texels: 64,
            size_m: 160.0,
            shape: CloudShape::Noise {
                coverage: 0.6,
                optical_depth: 8.0,
                cells: 4,
                seed: 11,
            },
        }),
        ..PhysicalSky::default()
    });
    desc
}

#[test]
fn cloud_shadowed_scene_agrees() {
    let _ =
        crate::gpu_matches_cpu::compare_method("clouds", &cloudy_scene(), 32, 4, METHOD_DEFAULT);
}
