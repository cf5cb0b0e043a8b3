//! What the frame-pipeline tests share (`pipeline.rs`, `pipeline_denoise.rs`): a small lit
//! scene of emissive and diffuse quads on the CPU tracer, its engine with moving platforms, and
//! direct batch renders of a scene to compare against.
#![allow(dead_code)]

use candela::app::{Engine, Environment};
use candela::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SkyDesc,
};
use candela::ecs::{Renderable, Static, Transform};
use candela::render::film::ConvergePolicy;
use candela::render::{RenderConfig, TracerChoice};
use glam::{Mat4, Vec3};

pub fn quad_model(size: f32, emission: f32) -> Model {
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

pub fn environment() -> Environment {
    Environment {
        sun: None,
        sky: SkyDesc::Constant([0.2, 0.2, 0.25]),
        render: RenderSettings {
            max_bounces: 3,
            roulette_start: 2,
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
    }
}

pub fn config(spp: u32, size: u32) -> RenderConfig {
    RenderConfig {
        tracer: TracerChoice::Cpu,
        width: size,
        height: size,
        spp,
        seed: 1,
        converge: ConvergePolicy::default(),
        scaling: None,
        denoise: false,
        light_sampling: None,
        indirect_every: None,
        first_hit_guides: false,
        atrous_kernel: Default::default(),
        sky_rebuild: candela::scene::SkyRebuild::Blocking,
        temporal_upscale: None,
    }
}

/// A floor, a lamp above it and `movers` platforms; returns the engine and the platforms.
pub fn scene(spp: u32, size: u32, movers: usize) -> (Engine, Vec<hecs::Entity>) {
    scene_with(config(spp, size), movers)
}

/// [`scene`] with any render configuration.
pub fn scene_with(config: RenderConfig, movers: usize) -> (Engine, Vec<hecs::Entity>) {
    let mut engine = Engine::new(config, environment()).expect("engine starts");
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

pub fn direct_batches(desc: &candela::assets::SceneDesc, size: u32, spp: u32) -> Vec<Vec<Vec3>> {
    use candela::render::cpu::CpuTracer;
    use candela::render::{FrameSettings, Tracer, frame_uniforms};
    use candela::scene::RenderScene;
    let scene = RenderScene::build(desc);
    let mut tracer = CpuTracer::new();
    (0..8)
        .map(|b| {
            let mut s = FrameSettings::new(size, size, spp / 8, 1000 + b, &desc.render);
            s.film_blend = 1.0;
            let u = frame_uniforms(&desc.camera, None, &desc.sky, &s, &scene.header());
            tracer.render(&scene, &u).expect("render");
            tracer.film().expect("film").mean
        })
        .collect()
}
