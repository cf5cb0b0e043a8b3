//! Emitters that move rigidly refit the light table and tree (`scene::light_refit`) instead of
//! rebuilding them, and the refitted table is the one a rebuild would give where it matters:
//!
//! * every light of the render side's scene (built from the commits' writes) sits where a
//!   fresh build of the same scene puts it, with the same power;
//! * every node of the refitted tree bounds the lights below it (box, normal cone, summed
//!   power), and the PMF the tracers sample with is consistent: sampling reports the PMF of
//!   the light it picked, and the PMF sums to at most 1;
//! * a scaled emitter (area changed) rebuilds; placing an emitter where it already is, or
//!   moving a grouped entity that emits nothing, touches neither.

use candela::accel::Upkeep;
use candela::assets::Model;
use candela::layout::{GpuLight, INVALID, LIGHT_NODE_LEAF};
use candela::render::cpu::light_tree::{pmf, sample};
use candela::scene::RenderScene;
use candela::scene::light_tree::leaf_of;
use glam::{Mat4, Quat, Vec3};

/// A 4×4 quad grid (32 triangles) with a bump, so that its triangles' normals differ.
fn grid_model(emission: f32) -> Model {
    let mut model = crate::work_report::grid_model(4, 1.0, emission);
    for p in &mut model.meshes[0].positions {
        p.y = 0.2 * (4.0 * p.x).sin() * p.z;
    }
    model
}

fn points(l: &GpuLight) -> [Vec3; 3] {
    [l.p0, l.p1, l.p2].map(Vec3::from)
}

/// Every light's ancestors bound it (box, cone) and every interior node's power is its
/// children's sum; the PMF is consistent with sampling from a few points.
fn check_tree(scene: &RenderScene, what: &str) {
    let table = &scene.lights;
    let nodes = &table.tree.nodes;
    let lights = &table.lights[..table.count as usize];
    for (k, node) in nodes.iter().enumerate() {
        if node.flags & LIGHT_NODE_LEAF == 0 {
            let (a, b) = (&nodes[k + 1], &nodes[node.child as usize]);
            let sum = a.phi + b.phi;
            assert!(
                (node.phi - sum).abs() <= 1e-4 * sum,
                "{what}: node {k} has power {} but its children {sum}",
                node.phi
            );
        }
    }
    for (i, light) in lights.iter().enumerate() {
        let p = points(light);
        let normal = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
        let mut k = leaf_of(&table.tree.lookup, light.instance, light.triangle);
        assert_ne!(k, INVALID, "{what}: light {i} has no leaf");
        while k != INVALID {
            let node = &nodes[k as usize];
            let (lo, hi) = (Vec3::from(node.bounds_min), Vec3::from(node.bounds_max));
            for c in p {
                assert!(
                    c.cmpge(lo - 1e-5).all() && c.cmple(hi + 1e-5).all(),
                    "{what}: light {i}'s corner {c} lies outside node {k}'s box {lo}..{hi}"
                );
            }
            let cos = normal.dot(Vec3::from(node.axis));
            assert!(
                cos >= node.cos_theta_o - 1e-4,
                "{what}: light {i}'s normal is outside node {k}'s cone ({cos} < {})",
                node.cos_theta_o
            );
            k = node.parent;
        }
    }
    let leaves: Vec<u32> = lights
        .iter()
        .map(|l| leaf_of(&table.tree.lookup, l.instance, l.triangle))
        .collect();
    // Above the still emitter (which faces +Y), so that some light is always seen.
    for (j, p) in [Vec3::new(-1.0, 6.0, 0.0), Vec3::new(3.0, 5.0, -1.0)]
        .into_iter()
        .enumerate()
    {
        let n = Vec3::ZERO;
        let sum: f32 = leaves.iter().map(|&l| pmf(nodes, l, p, n)).sum();
        assert!(
            sum > 0.5 && sum <= 1.0 + 1e-4,
            "{what}: PMF sums to {sum} at point {j}"
        );
        for s in 0..64 {
            let u = (s as f32 + 0.5) / 64.0;
            if let Some((light, prob)) = sample(nodes, table.count, p, n, u) {
                let want = pmf(nodes, leaves[light as usize], p, n);
                assert!(
                    (prob - want).abs() <= 1e-4 * want,
                    "{what}: light {light} sampled with {prob}, PMF {want}"
                );
            }
        }
    }
}

/// The render side's lights equal a fresh build's, matched by (entity, triangle).
fn check_lights(game: &Upkeep, render: &RenderScene, fresh: &Upkeep, what: &str) {
    let want = &fresh.scene().lights;
    assert_eq!(render.lights.count, want.count, "{what}: light count");
    let total = (render.lights.weight_total, want.weight_total);
    assert!(
        (total.0 - total.1).abs() <= 1e-4 * total.1,
        "{what}: power {total:?}"
    );
    for light in &render.lights.lights[..render.lights.count as usize] {
        let entity = game.entity_of_instance(light.instance);
        let twin = want.lights[..want.count as usize]
            .iter()
            .find(|l| {
                fresh.entity_of_instance(l.instance) == entity && l.triangle == light.triangle
            })
            .unwrap_or_else(|| panic!("{what}: no fresh light for {entity:?}"));
        for (a, b) in points(light).into_iter().zip(points(twin)) {
            assert!(
                a.distance(b) <= 1e-4,
                "{what}: light of {entity:?} triangle {} at {a}, fresh build {b}",
                light.triangle
            );
        }
        assert!((light.weight - twin.weight).abs() <= 1e-4 * twin.weight);
    }
}

#[test]
fn a_rigidly_moved_emitter_refits_and_matches_a_fresh_build() {
    let mut game = Upkeep::new();
    let (lamp, plain) = (grid_model(2.0), grid_model(0.0));
    let (h_lamp, h_plain) = (game.add_model(&lamp), game.add_model(&plain));
    let mut world = hecs::World::new();
    let (still, moving, grouped) = (world.spawn(()), world.spawn(()), world.spawn(()));
    let still_at = Mat4::from_translation(Vec3::new(-2.0, 3.0, 0.0));
    let place = |game: &mut Upkeep, t: f32, scale: f32| {
        let at = Mat4::from_scale_rotation_translation(
            Vec3::splat(scale),
            Quat::from_euler(glam::EulerRot::YXZ, 0.7 * t, 0.3 * t, 0.2),
            Vec3::new(1.5 * t, 2.0, -0.5 * t),
        );
        game.set_instance(moving, h_lamp, at, None, Some(1));
        game.set_instance(grouped, h_plain, at, None, Some(1));
        at
    };
    game.set_instance(still, h_lamp, still_at, None, None);
    place(&mut game, 0.0, 1.0);
    let mut render = RenderScene::empty();
    let (writes, header, first) = game.finish_frame();
    render.apply(&writes, &header);
    assert_eq!((first.light_table_builds, first.light_refits), (1, 0));
    let fresh_of = |at: Mat4| {
        let mut fresh = Upkeep::new();
        let (a, b) = (fresh.add_model(&lamp), fresh.add_model(&plain));
        fresh.set_instance(still, a, still_at, None, None);
        fresh.set_instance(moving, a, at, None, Some(1));
        fresh.set_instance(grouped, b, at, None, Some(1));
        fresh.finish_frame();
        fresh
    };
    for frame in 1..=12 {
        let t = frame as f32 * 0.4;
        let at = place(&mut game, t, 1.0);
        let (writes, header, stats) = game.finish_frame();
        render.apply(&writes, &header);
        let what = format!("frame {frame}");
        assert_eq!(
            (stats.light_table_builds, stats.light_refits),
            (0, 1),
            "{what}: a rigid move refits"
        );
        check_lights(&game, &render, &fresh_of(at), &what);
        check_tree(&render, &what);
    }
    // Placed where it already is: nothing to do for the lights.
    place(&mut game, 12.0 * 0.4, 1.0);
    let (writes, header, stats) = game.finish_frame();
    render.apply(&writes, &header);
    assert_eq!((stats.light_table_builds, stats.light_refits), (0, 0));
    // The grouped entity that emits nothing moves alone: nothing either.
    game.set_instance(
        grouped,
        h_plain,
        Mat4::from_translation(Vec3::X),
        None,
        Some(1),
    );
    let (writes, header, stats) = game.finish_frame();
    render.apply(&writes, &header);
    assert_eq!((stats.light_table_builds, stats.light_refits), (0, 0));
    // A scale changes the triangles' areas, so their power: the table is rebuilt.
    let at = place(&mut game, 5.0, 1.5);
    let (writes, header, stats) = game.finish_frame();
    render.apply(&writes, &header);
    assert_eq!((stats.light_table_builds, stats.light_refits), (1, 0));
    check_lights(&game, &render, &fresh_of(at), "scaled");
    check_tree(&render, "scaled");
}
