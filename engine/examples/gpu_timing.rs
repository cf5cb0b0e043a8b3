//! Times GPU pipeline creation and one dispatch on a tiny scene (development aid).
use candela::assets::*;
use candela::render::*;
use glam::*;
use std::sync::Arc;
use std::time::Instant;
fn main() -> anyhow::Result<()> {
    let mesh = Mesh {
        name: "tri".into(),
        positions: vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ],
        normals: None,
        uvs: None,
        tangents: None,
        triangles: vec![[0, 1, 2]],
        triangle_materials: vec![0],
    };
    let model = Model {
        name: "m".into(),
        meshes: vec![mesh],
        materials: vec![Material {
            emission: Vec3::ONE,
            ..Default::default()
        }],
        textures: vec![],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: vec![],
    };
    let desc = SceneDesc::single(
        model,
        CameraDesc {
            position: [0.0, 0.0, 3.0],
            look_at: [0.0; 3],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 40.0,
            aperture_radius: 0.0,
            focus_distance: None,
        },
    );
    let scene = Arc::new(RenderScene::build(&desc));
    let t = Instant::now();
    let ctx = gpu::GpuContext::headless()?;
    println!("context {:?}", t.elapsed());
    let t = Instant::now();
    let mut tracer = gpu::GpuTracer::new(ctx, &scene)?;
    println!("pipeline {:?}", t.elapsed());
    for spp in [1, 1, 8] {
        let u = frame_uniforms(
            &desc.camera,
            None,
            &desc.sky,
            &FrameSettings::new(64, 64, spp, 0, &desc.render),
            scene.lights.count,
            scene.lights.weight_total,
            scene.tlas_root,
        );
        let t = Instant::now();
        let s = tracer.render(&u)?;
        println!("render {spp} spp {:?} rays {}", t.elapsed(), s.rays());
    }
    Ok(())
}
