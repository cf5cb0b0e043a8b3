//! The stability suite, watertightness: rays from all around a closed mesh aimed exactly at its
//! vertices and at points on its shared edges (midpoints and random points) never slip through
//! between the triangles, by both tracers, closest-hit and any-hit queries alike.
//!
//! The mesh (an icosphere of 1,280 triangles, edges about 0.1 m) is placed at the origin and as a
//! rotated, non-uniformly scaled, translated instance; ray origins lie 20 m from their targets,
//! so the rounding of the ray–triangle test is about 200 times that of a ray starting at the
//! triangle. Only rays that enter the mesh at the target count: a ray that merely touches the
//! convex mesh at a silhouette vertex or edge grazes it, and whether that hits is moot.

use candela::assets::{Material, SceneDesc};
use candela::layout::{GpuRay, INVALID};
use candela::render::cpu::rng::Rng;
use candela::scene::RenderScene;
use candela::trace::{Kernel, Ray};
use candela_tests::{camera, icosphere, single_mesh_model};
use glam::{Mat4, Vec3};

/// Distance from each ray's origin to its target, metres.
const ORIGIN_DISTANCE: f32 = 20.0;

/// Rays into `sphere` (object space, placed by `world_from_object`) at every vertex and at three
/// points of every edge, from random directions, entering rays only.
fn rays_at_edges(
    sphere: &candela::assets::Mesh,
    world_from_object: Mat4,
    rng: &mut Rng,
) -> Vec<Ray> {
    let mut u = || rng.next_f32();
    let mut targets = Vec::new();
    for t in &sphere.triangles {
        for k in 0..3 {
            let a = sphere.positions[t[k] as usize];
            let b = sphere.positions[t[(k + 1) % 3] as usize];
            targets.push(a);
            targets.push((a + b) * 0.5);
            targets.push(a.lerp(b, u()));
        }
    }
    let normal_matrix = world_from_object.inverse().transpose();
    let mut rays = Vec::new();
    for target in targets {
        // The sphere is centred on the object origin: the outward normal is along the position.
        let normal = normal_matrix.transform_vector3(target).normalize();
        let target = world_from_object.transform_point3(target);
        let dir = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5).normalize();
        let origin = target + dir * ORIGIN_DISTANCE;
        if (target - origin).normalize().dot(normal) > -0.05 {
            continue;
        }
        rays.push(Ray::new(origin, target - origin));
    }
    rays
}

#[test]
fn rays_at_shared_edges_and_vertices_never_slip_through() {
    let sphere = icosphere(Vec3::ZERO, 1.0, 3, false);
    let transforms = [
        Mat4::IDENTITY,
        Mat4::from_scale_rotation_translation(
            Vec3::new(1.3, 0.7, 2.1),
            glam::Quat::from_euler(glam::EulerRot::YXZ, 0.7, -1.1, 0.3),
            Vec3::new(3.0, -2.0, 5.0),
        ),
    ];
    let mut rng = Rng::new(9, 9, 9, 9);
    let context = candela::render::gpu::GpuContext::headless().expect("GPU adapter");
    for (placement, world_from_object) in transforms.into_iter().enumerate() {
        let mut desc = SceneDesc::single(
            single_mesh_model(sphere.clone(), Material::default()),
            camera(Vec3::Z * 5.0, Vec3::ZERO, 40.0),
        );
        desc.instances[0].world_from_model = world_from_object;
        let scene = RenderScene::build(&desc);
        let tracer = scene.trace_scene();
        let rays = rays_at_edges(&sphere, world_from_object, &mut rng);
        // About 7,700 targets; a little over half of the random directions enter the sphere.
        assert!(
            rays.len() > 3000,
            "placement {placement}: only {} rays",
            rays.len()
        );

        for kernel in Kernel::available() {
            let closest_missed: Vec<&Ray> = rays
                .iter()
                .filter(|r| tracer.closest_with(kernel, r).is_none())
                .collect();
            let any_missed = rays
                .iter()
                .filter(|r| !tracer.occluded_with(kernel, r))
                .count();
            assert!(
                closest_missed.is_empty() && any_missed == 0,
                "placement {placement}, CPU {kernel:?}: {} of {} rays slipped through (closest \
                 hit), {any_missed} (any hit); first: {:?}",
                closest_missed.len(),
                rays.len(),
                closest_missed.first()
            );
        }

        let mut gpu =
            candela::render::gpu::GpuTracer::new(context.clone(), &scene).expect("GPU tracer");
        let gpu_rays: Vec<GpuRay> = rays
            .iter()
            .map(|r| GpuRay {
                origin: r.origin.to_array(),
                t_min: r.t_min,
                direction: r.direction.to_array(),
                t_max: r.t_max,
            })
            .collect();
        for any_hit in [false, true] {
            let (hits, _) = gpu
                .trace_rays(&gpu_rays, any_hit, scene.tlas_root)
                .expect("trace");
            let missed = hits.iter().filter(|h| h.instance == INVALID).count();
            assert_eq!(
                missed,
                0,
                "placement {placement}, GPU (any hit: {any_hit}): {missed} of {} rays slipped through",
                rays.len()
            );
        }
    }
}
