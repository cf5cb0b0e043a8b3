//! The two-level BVH (one BLAS per mesh, a TLAS over instances, as the renderer builds them)
//! returns exactly the closest hit brute force finds, on 10,000 random rays per model, for
//! glTF sample models from `shared/external/gltf/` (single meshes, multi-mesh node hierarchies,
//! 125 instances, mirrored transforms) and OBJ meshes. Brute force uses the same triangle test
//! and ray transform, so `t` must agree bit for bit; where two triangles tie in `t` either may
//! be reported. Occlusion (any hit) must agree on every ray too.
//! (The degenerate set — zero-area and duplicate triangles, coordinates near 1e5, empty and
//! single-triangle meshes — is covered by the unit tests of `engine/src/trace/`.)

use std::path::Path;

use candela::assets::{Model, SceneDesc, load_model_file};
use candela::render::cpu::rng::Rng;
use candela::scene::RenderScene;
use candela::trace::Ray;
use candela::trace::brute::{BruteInstance, BruteMesh, closest_brute, occluded_brute};
use candela_tests::{camera, external};
use glam::Vec3;

fn check_model(path: &Path) {
    let model: Model = load_model_file(path).unwrap_or_else(|e| panic!("{e}"));
    let desc = SceneDesc::single(model.clone(), camera(Vec3::Z, Vec3::ZERO, 40.0));
    let scene = RenderScene::build(&desc);
    let meshes: Vec<BruteMesh> = model
        .meshes
        .iter()
        .map(|m| BruteMesh {
            positions: &m.positions,
            triangles: &m.triangles,
        })
        .collect();
    let instances: Vec<BruteInstance> = model
        .placements
        .iter()
        .zip(&scene.instances)
        .map(|(p, i)| BruteInstance {
            instance: *i,
            mesh: p.mesh,
        })
        .collect();
    assert_eq!(instances.len(), scene.instances.len());
    let bounds = scene.bounds;
    let center = (bounds.min + bounds.max) * 0.5;
    let radius = (bounds.max - bounds.min).length().max(1e-3);
    let tracer = scene.trace_scene();
    let mut rng = Rng::new(0, 0, 0, 1234);
    let mut u = || rng.next_f32();
    let mut hits = 0;
    for i in 0..10_000 {
        let inside = bounds.min + (bounds.max - bounds.min) * Vec3::new(u(), u(), u());
        let (origin, direction) = if i % 5 == 4 {
            // From inside the model in any direction.
            let d = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5);
            (inside, d)
        } else {
            // From a sphere around it, towards a point inside its bounds.
            let z = 2.0 * u() - 1.0;
            let phi = std::f32::consts::TAU * u();
            let r = (1.0 - z * z).max(0.0).sqrt();
            let o = center + Vec3::new(r * phi.cos(), r * phi.sin(), z) * radius;
            (o, inside - o)
        };
        let ray = Ray::with_range(origin, direction, 0.0, f32::INFINITY);
        let fast = tracer.closest(&ray);
        let slow = closest_brute(&meshes, &instances, &ray);
        match (fast, slow) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                hits += 1;
                assert_eq!(
                    a.t.to_bits(),
                    b.t.to_bits(),
                    "{}: ray {i}: t {} vs brute {}",
                    path.display(),
                    a.t,
                    b.t
                );
                if (a.instance, a.triangle) != (b.instance, b.triangle) {
                    // A tie in t: both triangles must really be hit at that distance.
                    let mut tie = ray;
                    tie.t_max = a.t.next_up();
                    assert!(
                        closest_brute(&meshes, &instances, &tie).is_some(),
                        "{}: ray {i}",
                        path.display()
                    );
                } else {
                    assert_eq!(
                        (a.u.to_bits(), a.v.to_bits()),
                        (b.u.to_bits(), b.v.to_bits()),
                        "{}: ray {i}",
                        path.display()
                    );
                }
            }
            (a, b) => panic!(
                "{}: ray {i}: BVH {a:?} vs brute force {b:?}",
                path.display()
            ),
        }
        assert_eq!(
            tracer.occluded(&ray),
            occluded_brute(&meshes, &instances, &ray),
            "{}: ray {i} occlusion",
            path.display()
        );
    }
    eprintln!("{}: {hits} of 10000 rays hit, all agree", path.display());
    assert!(
        hits > 1000,
        "{}: too few rays hit ({hits}) for the check to mean much",
        path.display()
    );
}

#[test]
fn gltf_models_match_brute_force() {
    for model in [
        "Box/glTF/Box.gltf",
        "Duck/glTF-Binary/Duck.glb",
        "DamagedHelmet/glTF-Binary/DamagedHelmet.glb",
        "SimpleInstancing/glTF-Binary/SimpleInstancing.glb",
        "NegativeScaleTest/glTF-Binary/NegativeScaleTest.glb",
        "Fox/glTF-Binary/Fox.glb",
        "OrientationTest/glTF-Binary/OrientationTest.glb",
    ] {
        let path = external().join("gltf").join(model);
        assert!(path.exists(), "{} is missing", path.display());
        check_model(&path);
    }
}

#[test]
fn obj_meshes_match_brute_force() {
    for model in [
        "obj/stanford_bunny_npm/bunny.obj",
        "reference/cornell_mirror_glass/meshes/mirror_sphere.obj",
        "obj/mcguire_cornell_box/CornellBox-Water.obj",
    ] {
        check_model(&external().join(model));
    }
}
