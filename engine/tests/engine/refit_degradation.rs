//! Refit degradation over a long animation (DESIGN.md, "stability where methods fail"): a
//! 5,000-triangle grid swirls and waves for 10,000 frames through the real upkeep path
//! (`Upkeep::deform` every frame, then `finish_frame`), so its BLAS is refitted every frame and
//! rebuilt whenever the policy says so. Checks that
//! * every frame, the tree's SAH cost stays within the policy's bound, which is at most
//!   [`REBUILD_RATIO`] × its cost right after its last build;
//! * every 100 frames and at the end, against a fresh build of the same shape, the cost is at
//!   most [`REBUILD_RATIO`] × the fresh cost × the measured error of the policy's fresh-cost
//!   estimate (itself bounded by 1.25);
//! * at several checkpoints, the flattened scene (what both tracers and ray queries read) agrees
//!   with brute force on random rays: same triangle, same distance bit for bit;
//! * the animation really degrades refits (the policy rebuilds at least twice), so the bound
//!   above is exercised rather than trivially met.
//!
//! No rendering; CPU BVH only.

use candela::accel::{REBUILD_RATIO, Upkeep, build_blas, sah_cost};
use candela::assets::{Material, Mesh, Model, Placement};
use candela::render::cpu::rng::Rng;
use candela::trace::Ray;
use candela::trace::brute::{BruteInstance, BruteMesh, closest_brute};
use glam::{Mat4, Quat, Vec3};

/// Quads per side: 2 · 50² = 5,000 triangles.
const N: u32 = 50;
const FRAMES: u32 = 10_000;
/// Frames of one swirl cycle (twist up, untwist, twist the other way).
const SWIRL_PERIOD: f32 = 1_500.0;

/// The rest grid: `N × N` quads over [-1, 1]² in the xz plane (metres), facing +Y.
fn grid() -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let mut p = Vec::new();
    let mut t = Vec::new();
    for z in 0..=N {
        for x in 0..=N {
            p.push(Vec3::new(
                2.0 * x as f32 / N as f32 - 1.0,
                0.0,
                2.0 * z as f32 / N as f32 - 1.0,
            ));
        }
    }
    for z in 0..N {
        for x in 0..N {
            let i = z * (N + 1) + x;
            t.push([i, i + N + 1, i + 1]);
            t.push([i + 1, i + N + 1, i + N + 2]);
        }
    }
    (p, t)
}

/// The shape at `frame`: a swirl about +Y whose twist (radians, strongest at the centre)
/// swings between ±6 over a [`SWIRL_PERIOD`], plus a travelling wave 0.15 m high. Triangles that
/// were neighbours end up far apart and back, which is what makes refitted boxes grow.
fn deformed(rest: &[Vec3], frame: u32) -> Vec<Vec3> {
    let t = frame as f32;
    let twist = 6.0 * (std::f32::consts::TAU * t / SWIRL_PERIOD).sin();
    rest.iter()
        .map(|p| {
            let r = (p.x * p.x + p.z * p.z).sqrt();
            let angle = twist * (1.0 - r / std::f32::consts::SQRT_2).max(0.0).powi(2);
            let q = Quat::from_rotation_y(angle) * Vec3::new(p.x, 0.0, p.z);
            let height = 0.15 * (4.0 * p.x - 0.05 * t).sin() * (3.0 * p.z + 0.03 * t).cos();
            Vec3::new(q.x, height, q.z)
        })
        .collect()
}

fn model(positions: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Model {
    let count = triangles.len();
    Model {
        name: "swirl".into(),
        meshes: vec![Mesh {
            name: "swirl".into(),
            positions,
            triangles,
            triangle_materials: vec![0; count],
            ..Default::default()
        }],
        materials: vec![Material::default()],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

/// Random rays from above and from the sides at the grid; every hit and miss must match brute
/// force exactly (same traversal transform and triangle test, so the same bits; ties on a
/// shared edge may name either neighbour).
fn check_against_brute_force(
    upkeep: &Upkeep,
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    frame: u32,
) {
    let scene = upkeep.scene();
    let meshes = [BruteMesh {
        positions,
        triangles,
    }];
    let instances = [BruteInstance {
        instance: scene.instances[0],
        mesh: 0,
    }];
    let mut rng = Rng::new(frame, 0, 0, 11);
    let mut u = || rng.next_f32();
    let mut hits = 0;
    for i in 0..400 {
        let origin = Vec3::new(1.8 * u() - 0.9, 0.5 + u(), 1.8 * u() - 0.9);
        let direction = Vec3::new(0.6 * u() - 0.3, -1.0, 0.6 * u() - 0.3);
        let ray = Ray::new(origin, direction);
        let fast = scene.trace_scene().closest(&ray);
        let slow = closest_brute(&meshes, &instances, &ray);
        // Same distance to the bit; the triangle too, except on a shared edge, where the
        // watertight test lets both neighbours report the same distance and which one wins
        // depends on visiting order.
        assert_eq!(
            fast.map(|h| h.t.to_bits()),
            slow.map(|h| h.t.to_bits()),
            "frame {frame}, ray {i}"
        );
        if let (Some(f), Some(s)) = (fast, slow)
            && f.triangle != s.triangle
        {
            let shared = triangles[f.triangle as usize]
                .iter()
                .filter(|v| triangles[s.triangle as usize].contains(v))
                .count();
            assert!(
                shared == 2,
                "frame {frame}, ray {i}: triangles {} and {} tie but share no edge",
                f.triangle,
                s.triangle
            );
        }
        hits += fast.is_some() as u32;
    }
    // The rays aim at the grid: most must hit, or the check says nothing.
    assert!(hits > 300, "frame {frame}: only {hits} of 400 rays hit");
}

#[test]
fn long_deformation_stays_within_the_rebuild_policy_and_exact() {
    let (rest, triangles) = grid();
    assert_eq!(triangles.len(), 5_000);
    let mut upkeep = Upkeep::new();
    let handle = upkeep.add_model(&model(rest.clone(), triangles.clone()));
    let mut ids = hecs::World::new();
    upkeep.set_instance(ids.spawn(()), handle, Mat4::IDENTITY, None, None);
    upkeep.finish_frame();

    let (mut refits, mut rebuilds) = (0u32, 0u32);
    let mut worst_to_fresh = 0.0f32;
    let mut fresh_costs = Vec::new();
    // How far the policy's estimate of a fresh build's cost (`rebuild_bound` / ratio) overshoots
    // the real one, worst over the checkpoints.
    let mut estimate_error = 0.0f32;
    for frame in 1..=FRAMES {
        let positions = deformed(&rest, frame);
        upkeep.deform(handle, 0, &positions, None);
        let (_, _, stats) = upkeep.finish_frame();
        refits += stats.blas_refits;
        rebuilds += stats.blas_rebuilds;
        assert_eq!(stats.blas_refits + stats.blas_rebuilds, 1, "frame {frame}");
        let cost = upkeep.mesh_cost(handle, 0).expect("mesh 0 exists");
        // The policy's own invariant: rebuilt as soon as the refit cost passes its bound,
        // which is never above the ratio times the cost at the last build.
        assert!(
            cost.current <= cost.bound && cost.bound <= REBUILD_RATIO * cost.built,
            "frame {frame}: cost {}, bound {}, {REBUILD_RATIO} × built {}",
            cost.current,
            cost.bound,
            cost.built
        );
        if frame % 100 == 0 || frame == FRAMES {
            let fresh = build_blas(&positions, &triangles);
            let fresh_cost = sah_cost(&fresh.nodes, &fresh.blocks);
            fresh_costs.push(fresh_cost);
            worst_to_fresh = worst_to_fresh.max(cost.current / fresh_cost);
            estimate_error = estimate_error.max(cost.bound / (REBUILD_RATIO * fresh_cost));
        }
        if frame % 2_500 == 0 || frame == 1 || frame == 777 {
            check_against_brute_force(&upkeep, &positions, &triangles, frame);
        }
    }
    // Fresh builds of different shapes of this animation differ in cost by `spread` (max / min
    // over the checkpoints, about 1.65): against the last build's cost alone, a refitted tree of
    // a simpler shape reached 2.1× a fresh build here. The policy scales its bound by an
    // estimate of the fresh cost, which can overshoot by `estimate_error` (≤ 1.25 allowed,
    // about 1.17 measured: the √area estimate is good to ±6 %, counted at the last build and
    // now). The animation is deterministic, so the check against the ratio itself is exact.
    let spread = fresh_costs.iter().copied().fold(0.0f32, f32::max)
        / fresh_costs.iter().copied().fold(f32::INFINITY, f32::min);
    eprintln!(
        "{FRAMES} frames: {refits} refits, {rebuilds} rebuilds; worst cost / fresh cost \
         {worst_to_fresh:.3}; fresh cost spread {spread:.3}; estimate error {estimate_error:.3}"
    );
    assert!(
        spread > 1.2,
        "the animation should change the fresh cost, spread {spread}"
    );
    assert!(
        estimate_error <= 1.25,
        "fresh-cost estimate off by {estimate_error}"
    );
    // cost ≤ bound ≤ ratio × estimate ≤ ratio × estimate_error × fresh: the policy's promise
    // against a real fresh build, measured (about 1.57 with the block-count SAH builder, whose
    // fresh trees are cheaper than the √area estimate expects).
    assert!(
        worst_to_fresh <= REBUILD_RATIO * estimate_error.max(1.0),
        "worst cost {worst_to_fresh} × a fresh build's, policy ratio {REBUILD_RATIO}, estimate \
         error {estimate_error}"
    );
    assert!(
        rebuilds >= 2,
        "the swirl never degraded the tree enough to rebuild"
    );
    assert!(
        refits > 10 * rebuilds,
        "refits {refits}, rebuilds {rebuilds}"
    );
}
