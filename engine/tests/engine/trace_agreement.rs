//! Every traversal kernel (scalar reference, AVX2, AVX-512 where the CPU has them) against brute
//! force: closest hit (`t` bit for bit, triangle, instance) and any hit, on 10,000 random rays
//! per case: procedural meshes, instanced scenes with rotation / non-uniform scale /
//! translation, and degenerate input.

use crate::common;

use candela::accel::{BlasParams, build_blas, build_blas_with_params};
use candela::layout::{INVALID, LEAF_BIT, LEAF_COUNT_SHIFT};
use candela::trace::Ray;
use common::*;
use glam::{Mat4, Vec3};

const RAYS: usize = 10_000;

/// The kernels this CPU can run, from the CPU's own feature flags (the requirements the
/// kernels' docs state), independent of `Kernel::supported`.
fn kernels_this_cpu_can_run() -> Vec<candela::trace::Kernel> {
    use candela::trace::Kernel;
    #[allow(unused_mut)]
    let mut expected = vec![Kernel::Scalar];
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        let avx2 = has!("avx2") && has!("fma") && has!("popcnt") && has!("bmi1");
        if avx2 {
            expected.push(Kernel::Avx2);
        }
        if avx2 && has!("avx512f") && has!("avx512vl") && has!("avx512bw") && has!("avx512dq") {
            expected.push(Kernel::Avx512);
        }
    }
    expected
}

#[test]
fn every_kernel_of_this_cpu_is_tested() {
    // On every CPU (AVX-512, AVX2 only, or scalar only): the kernels the other tests loop over
    // are exactly those the CPU can run, the scalar reference first, and the fastest is used.
    use candela::trace::Kernel;
    let expected = kernels_this_cpu_can_run();
    eprintln!("kernels on this CPU: {expected:?}");
    assert_eq!(Kernel::available(), expected);
    assert_eq!(Some(&Kernel::best()), expected.last());
    for kernel in [Kernel::Scalar, Kernel::Avx2, Kernel::Avx512] {
        assert_eq!(kernel.supported(), expected.contains(&kernel), "{kernel:?}");
    }
}

fn check_mesh(name: &str, mesh: &Mesh, seed: u64, zero_components: bool) -> usize {
    let blas = build_blas(&mesh.positions, &mesh.triangles);
    let mut rng = Rng::new(seed);
    let rays = rays(&mut rng, mesh.bounds(), RAYS, zero_components);
    match check_blas(&blas, mesh, &rays) {
        Ok(hits) => hits,
        Err(e) => panic!("{name}: {e}"),
    }
}

#[test]
fn procedural_meshes_agree_with_brute_force() {
    let mut rng = Rng::new(7);
    let cases = [
        ("sphere", sphere(Vec3::new(1.0, 2.0, -3.0), 2.0, 24, 48)),
        ("bumpy grid", grid(32, 10.0, false)),
        ("soup", soup(&mut rng, 2500, 5.0)),
    ];
    for (i, (name, mesh)) in cases.iter().enumerate() {
        let hits = check_mesh(name, mesh, 100 + i as u64, i == 1);
        assert!(
            hits > RAYS / 5,
            "{name}: only {hits} of {RAYS} rays hit; the test is too easy"
        );
    }
}

/// Leaves of one to four blocks (each kernel tests two blocks at a time where it can, so even and
/// odd block counts take different paths).
#[test]
fn every_leaf_size_agrees_with_brute_force() {
    let mut rng = Rng::new(21);
    let meshes = [
        ("sphere", sphere(Vec3::new(0.5, -1.0, 2.0), 1.5, 20, 40)),
        ("soup", soup(&mut rng, 2000, 4.0)),
    ];
    for (name, mesh) in &meshes {
        for (block_cost, max_leaf_blocks) in [(1.0, 1), (0.1, 2), (0.05, 3), (0.02, 4)] {
            let params = BlasParams {
                block_cost,
                max_leaf_blocks,
                ..BlasParams::default()
            };
            let blas = build_blas_with_params(&mesh.positions, &mesh.triangles, params);
            let rays = rays(&mut rng, mesh.bounds(), RAYS / 4, false);
            let hits = check_blas(&blas, mesh, &rays)
                .unwrap_or_else(|e| panic!("{name}, {params:?}: {e}"));
            assert!(hits > RAYS / 40, "{name}: only {hits} hits");
        }
    }
}

#[test]
fn instanced_scene_agrees_with_brute_force() {
    let mut rng = Rng::new(11);
    let meshes = vec![
        sphere(Vec3::ZERO, 1.0, 12, 24),
        grid(12, 3.0, false),
        soup(&mut rng, 300, 1.0),
        Mesh::default(), // empty: its instances can never be hit
    ];
    let mut placements = vec![(0, None), (1, None)];
    for i in 0..60 {
        placements.push((i % meshes.len(), Some(messy_transform(&mut rng))));
    }
    let scene = assemble(&meshes, &placements);
    // Aim at the instances (most of the world box is empty space).
    let mut rays = rays(&mut rng, scene.world_bounds, RAYS, true);
    for ray in &mut rays {
        let target = scene.instance_bounds[rng.next_u32() as usize % placements.len()];
        let p = rng.vec3(target.min, target.max);
        ray.direction = (p - ray.origin) * rng.range(0.2, 2.0);
    }
    let hits = check_scene(&scene, &meshes, &rays).unwrap_or_else(|e| panic!("{e}"));
    assert!(hits > RAYS / 5, "only {hits} hits");
}

#[test]
fn degenerate_input_agrees_with_brute_force() {
    let mut rng = Rng::new(3);
    // Zero-area (collinear, point) and duplicate triangles among ordinary ones.
    let mut dupes = sphere(Vec3::ZERO, 1.0, 8, 16);
    let base = dupes.triangles.clone();
    dupes.triangles.extend_from_slice(&base);
    dupes.triangles.extend_from_slice(&base[..20]);
    dupes.push_tri(Vec3::ZERO, Vec3::X, Vec3::X * 2.0);
    dupes.push_tri(Vec3::ONE, Vec3::ONE, Vec3::ONE);
    for _ in 0..50 {
        let p = rng.vec3(Vec3::splat(-1.0), Vec3::ONE);
        dupes.push_tri(p, p, p + Vec3::Y);
    }
    check_mesh("zero-area and duplicates", &dupes, 1, true);
    // Far from the origin.
    let far = sphere(Vec3::new(1e5, -1e5, 1e5), 3.0, 16, 32);
    assert!(check_mesh("near 1e5", &far, 2, true) > RAYS / 5);
    // A single triangle.
    let mut single = Mesh::default();
    single.push_tri(
        Vec3::ZERO,
        Vec3::new(1.0, 0.0, 0.5),
        Vec3::new(0.0, 1.0, 0.2),
    );
    assert!(check_mesh("single triangle", &single, 3, true) > RAYS / 10);
    // Axis-aligned flat meshes (a floor and a wall) traced with zero direction components.
    let mut flat = grid(16, 4.0, true);
    let wall = grid(8, 2.0, true);
    let offset = flat.positions.len() as u32;
    flat.positions.extend(
        wall.positions
            .iter()
            .map(|p| Vec3::new(1.0, p.x + 1.0, p.z)),
    );
    flat.triangles
        .extend(wall.triangles.iter().map(|t| t.map(|i| i + offset)));
    assert!(check_mesh("flat", &flat, 4, true) > RAYS / 10);
    // Out-of-range indices and non-finite positions are left out, never hit, never panic.
    let mut bad = sphere(Vec3::ZERO, 1.0, 6, 12);
    bad.triangles.push([0, 1, 10_000]);
    bad.positions.push(Vec3::new(f32::NAN, 0.0, 0.0));
    bad.positions.push(Vec3::new(0.0, f32::INFINITY, 0.0));
    let n = bad.positions.len() as u32;
    bad.triangles.push([0, n - 2, 1]);
    bad.triangles.push([n - 1, 2, 3]);
    check_mesh("out of range and non-finite", &bad, 5, false);
}

#[test]
fn empty_mesh_and_empty_scene_never_hit() {
    let blas = build_blas(&[], &[]);
    assert_eq!(blas.nodes.len(), 1);
    assert!(blas.blocks.is_empty());
    let mut rng = Rng::new(9);
    let scene = assemble(
        &[Mesh::default()],
        &[(0, None), (0, Some(messy_transform(&mut rng)))],
    );
    let empty_scene = assemble(&[], &[]);
    for ray in rays(
        &mut rng,
        candela::accel::Aabb::new(Vec3::splat(-1.0), Vec3::ONE),
        1000,
        true,
    ) {
        for kernel in candela::trace::Kernel::available() {
            assert!(
                candela::trace::closest_blas_with(kernel, &blas.nodes, &blas.blocks, &ray)
                    .is_none()
            );
            assert!(scene.trace().closest_with(kernel, &ray).is_none());
            assert!(!scene.trace().occluded_with(kernel, &ray));
            assert!(!empty_scene.trace().occluded_with(kernel, &ray));
        }
    }
}

#[test]
fn zero_direction_and_axis_rays_hit_flat_floor() {
    // Straight down onto y = 0 from random points above: every ray inside the floor hits.
    let floor = grid(20, 4.0, true);
    let blas = build_blas(&floor.positions, &floor.triangles);
    let mut rng = Rng::new(21);
    for _ in 0..2000 {
        let o = rng.vec3(Vec3::new(-1.9, 0.5, -1.9), Vec3::new(1.9, 3.0, 1.9));
        let d = Vec3::new(0.0, -rng.range(0.5, 2.0), -0.0);
        let ray = Ray::new(o, d);
        for kernel in candela::trace::Kernel::available() {
            let hit = candela::trace::closest_blas_with(kernel, &blas.nodes, &blas.blocks, &ray)
                .unwrap_or_else(|| panic!("{kernel:?}: {ray:?} missed the floor"));
            assert!((o.y + hit.t * d.y).abs() < 1e-5);
        }
    }
}

/// The agreement check must notice a broken tree: shrink every child box of the root to a point
/// far away and expect disagreements.
#[test]
fn agreement_check_detects_a_broken_tree() {
    let mesh = sphere(Vec3::ZERO, 1.0, 16, 32);
    let mut blas = build_blas(&mesh.positions, &mesh.triangles);
    let mut rng = Rng::new(1);
    let rays = rays(&mut rng, mesh.bounds(), 1000, false);
    assert!(check_blas(&blas, &mesh, &rays).is_ok());
    let root = &mut blas.nodes[0];
    for s in 0..8 {
        if root.child[s] != candela::layout::INVALID {
            root.min_x[s] = 50.0;
            root.max_x[s] = 50.0;
        }
    }
    assert!(check_blas(&blas, &mesh, &rays).is_err());
}

/// The kernels must test every block a leaf names: cutting each multi-block leaf down to its
/// first block loses hits.
#[test]
fn agreement_check_detects_ignored_leaf_blocks() {
    let mesh = sphere(Vec3::ZERO, 1.0, 16, 32);
    let params = BlasParams {
        block_cost: 0.05,
        ..BlasParams::default()
    };
    let mut blas = build_blas_with_params(&mesh.positions, &mesh.triangles, params);
    let mut rng = Rng::new(2);
    let rays = rays(&mut rng, mesh.bounds(), 2000, false);
    assert!(check_blas(&blas, &mesh, &rays).is_ok());
    let mut cut = 0;
    for node in &mut blas.nodes {
        for child in &mut node.child {
            if *child != INVALID && *child & LEAF_BIT != 0 && (*child >> LEAF_COUNT_SHIFT) & 3 != 0
            {
                *child &= !(3 << LEAF_COUNT_SHIFT);
                cut += 1;
            }
        }
    }
    assert!(cut > 10, "only {cut} multi-block leaves");
    assert!(check_blas(&blas, &mesh, &rays).is_err());
}

#[test]
fn instance_transform_keeps_world_t() {
    // A unit quad scaled ×3 in x and moved: the world t of the hit equals the analytic one.
    let mut quad = Mesh::default();
    quad.push_tri(
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(1.0, 1.0, 0.0),
    );
    quad.push_tri(
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(-1.0, 1.0, 0.0),
    );
    let m = Mat4::from_translation(Vec3::new(0.0, 0.0, -5.0))
        * Mat4::from_scale(Vec3::new(3.0, 1.0, 1.0));
    let scene = assemble(&[quad], &[(0, Some(m))]);
    let ray = Ray::new(Vec3::new(2.5, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
    for kernel in candela::trace::Kernel::available() {
        let hit = scene.trace().closest_with(kernel, &ray).expect("hit");
        assert_eq!(hit.t, 2.5);
        assert_eq!(hit.instance, 0);
    }
}

/// Rays exactly through the shared diagonal of a quad must hit one of its two triangles (the
/// cracks that the slack of `triangle.rs` closes). Tilted quads at a distance, so the rounding
/// is not trivial. `tests/cross/watertight.rs` does the same on a closed mesh with both tracers.
#[test]
fn shared_edges_have_no_cracks() {
    let mut rng = Rng::new(77);
    let mut misses = 0;
    for _ in 0..20 {
        let m = messy_transform(&mut rng);
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
            .map(|[x, y]| m.transform_point3(Vec3::new(x, y, 0.0)));
        let mut quad = Mesh::default();
        quad.push_tri(corners[0], corners[1], corners[2]);
        quad.push_tri(corners[0], corners[2], corners[3]);
        let blas = build_blas(&quad.positions, &quad.triangles);
        let normal = (corners[1] - corners[0])
            .cross(corners[3] - corners[0])
            .normalize();
        for _ in 0..500 {
            let s = rng.f32();
            let on_edge = corners[0] + (corners[2] - corners[0]) * s;
            let origin = on_edge + normal * rng.range(0.5, 30.0) + rng.unit() * 2.0;
            let ray = Ray::new(origin, on_edge - origin);
            for kernel in candela::trace::Kernel::available() {
                let hit =
                    candela::trace::closest_blas_with(kernel, &blas.nodes, &blas.blocks, &ray);
                misses += usize::from(hit.is_none());
            }
        }
    }
    assert_eq!(misses, 0, "rays through a shared edge slipped through");
}
