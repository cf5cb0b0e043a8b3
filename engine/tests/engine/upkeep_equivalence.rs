//! After any sequence of scene changes, the render side's scene (built only from the commits'
//! writes) equals a fresh build of the game side's current scene: closest hits on random rays
//! name the same entity, triangle and distance, occlusion agrees, and the light tables carry
//! the same total power. Changes: spawning, moving, re-parenting-free restyling (material
//! override), despawning, deforming a mesh (refits and rebuilds), switching light groups.
//! Besides the random rays, every frame aims one ray at a point of every live entity's surface
//! (a triangle's centroid): each must hit on both sides, so a frame in which everything misses
//! (both scenes empty or untraceable) fails instead of comparing nothing.

use std::collections::HashMap;

use candela::accel::Upkeep;
use candela::assets::{Material, MaterialKind, Mesh, Model, Placement};
use candela::ecs::ModelHandle;
use candela::render::cpu::rng::Rng;
use candela::scene::RenderScene;
use candela::trace::Ray;
use glam::{Mat4, Quat, Vec3};

/// A `n × n` grid in the xz plane, heights from `wave`.
fn grid(n: u32, wave: f32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let mut p = Vec::new();
    let mut t = Vec::new();
    for z in 0..=n {
        for x in 0..=n {
            let (fx, fz) = (x as f32 / n as f32 - 0.5, z as f32 / n as f32 - 0.5);
            p.push(Vec3::new(
                fx,
                0.3 * (5.0 * fx + wave).sin() * (3.0 * fz + wave).cos(),
                fz,
            ));
        }
    }
    for z in 0..n {
        for x in 0..n {
            let i = z * (n + 1) + x;
            t.push([i, i + n + 1, i + 1]);
            t.push([i + 1, i + n + 1, i + n + 2]);
        }
    }
    (p, t)
}

fn model(
    positions: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    emission: f32,
    extra_placement: bool,
) -> Model {
    let count = triangles.len();
    let mut placements = vec![Placement {
        mesh: 0,
        model_from_mesh: Mat4::IDENTITY,
    }];
    if extra_placement {
        placements.push(Placement {
            mesh: 0,
            model_from_mesh: Mat4::from_translation(Vec3::Y * 0.7),
        });
    }
    Model {
        name: "grid".into(),
        meshes: vec![Mesh {
            name: "grid".into(),
            positions,
            triangles,
            triangle_materials: vec![0; count],
            ..Default::default()
        }],
        materials: vec![Material {
            kind: MaterialKind::Diffuse,
            emission: Vec3::splat(emission),
            ..Default::default()
        }],
        placements,
        ..Default::default()
    }
}

#[derive(Clone, Copy)]
struct Entity {
    model: usize,
    world: Mat4,
    material: Option<u32>,
    group: Option<u32>,
}

fn random_transform(u: &mut impl FnMut() -> f32) -> Mat4 {
    Mat4::from_scale_rotation_translation(
        Vec3::new(0.5 + u(), 0.5 + u(), 0.5 + u()),
        Quat::from_euler(glam::EulerRot::YXZ, 6.0 * u(), 6.0 * u(), 6.0 * u()),
        Vec3::new(8.0 * u() - 4.0, 8.0 * u() - 4.0, 8.0 * u() - 4.0),
    )
}

#[test]
fn incremental_commits_equal_a_fresh_build() {
    let mut rng = Rng::new(1, 2, 3, 4);
    let mut u = move || rng.next_f32();
    let level_materials = vec![Material {
        kind: MaterialKind::Conductor,
        ..Default::default()
    }];
    // Models: plain, emissive with two placements, and a deforming one.
    let mut shapes: Vec<(Vec<Vec3>, Vec<[u32; 3]>, f32, bool)> = vec![
        (grid(6, 0.0).0, grid(6, 0.0).1, 0.0, false),
        (grid(4, 1.0).0, grid(4, 1.0).1, 2.0, true),
        (grid(20, 0.0).0, grid(20, 0.0).1, 0.5, false),
    ];
    let mut game = Upkeep::new();
    game.add_level_materials(&level_materials);
    let handles: Vec<ModelHandle> = shapes
        .iter()
        .map(|(p, t, e, two)| game.add_model(&model(p.clone(), t.clone(), *e, *two)))
        .collect();
    let mut render = RenderScene::empty();
    let mut world = hecs::World::new();
    let mut alive: HashMap<hecs::Entity, Entity> = HashMap::new();
    let mut groups_off: Vec<u32> = Vec::new();
    let mut rebuilds = 0;
    for frame in 0..60 {
        let ops = 1 + (u() * 6.0) as usize;
        for _ in 0..ops {
            let pick = u();
            let existing: Vec<hecs::Entity> = alive.keys().copied().collect();
            if pick < 0.3 || existing.is_empty() {
                let e = world.spawn(());
                let m = (u() * 3.0) as usize % 3;
                let entity = Entity {
                    model: m,
                    world: random_transform(&mut u),
                    material: (u() < 0.3).then_some(0),
                    group: (u() < 0.5).then_some((u() * 2.0) as u32),
                };
                game.set_instance(e, handles[m], entity.world, entity.material, entity.group);
                alive.insert(e, entity);
            } else if pick < 0.55 {
                let e = existing[(u() * existing.len() as f32) as usize % existing.len()];
                let entity = alive.get_mut(&e).expect("alive");
                entity.world = random_transform(&mut u);
                entity.material = if u() < 0.5 { None } else { Some(0) };
                game.set_instance(
                    e,
                    handles[entity.model],
                    entity.world,
                    entity.material,
                    entity.group,
                );
            } else if pick < 0.7 {
                let e = existing[(u() * existing.len() as f32) as usize % existing.len()];
                game.remove_instance(e);
                alive.remove(&e);
            } else if pick < 0.9 {
                // Deform the big grid: a wave (refit), or now and then a scramble of its
                // vertices, whose long sliver triangles degrade the refit tree (rebuild).
                let (mut p, t) = grid(20, frame as f32 * 0.3);
                if u() < 0.25 {
                    for i in (1..p.len()).rev() {
                        let j = (u() * (i + 1) as f32) as usize % (i + 1);
                        p.swap(i, j);
                    }
                }
                game.deform(handles[2], 0, &p, None);
                shapes[2] = (p, t, 0.5, false);
            } else {
                let group = (u() * 2.0) as u32;
                let on = groups_off.contains(&group);
                game.set_light_group(group, on);
                if on {
                    groups_off.retain(|&g| g != group);
                } else {
                    groups_off.push(group);
                }
            }
        }
        let (writes, header, stats) = game.finish_frame();
        rebuilds += stats.blas_rebuilds;
        render.apply(&writes, &header);

        // A fresh build of the same logical scene.
        let mut fresh = Upkeep::new();
        fresh.add_level_materials(&level_materials);
        let fresh_handles: Vec<ModelHandle> = shapes
            .iter()
            .map(|(p, t, e, two)| fresh.add_model(&model(p.clone(), t.clone(), *e, *two)))
            .collect();
        for &g in &groups_off {
            fresh.set_light_group(g, false);
        }
        for (e, entity) in &alive {
            fresh.set_instance(
                *e,
                fresh_handles[entity.model],
                entity.world,
                entity.material,
                entity.group,
            );
        }
        fresh.finish_frame();
        let fresh_scene = fresh.scene();
        assert_eq!(
            render.instances.len(),
            fresh_scene.instances.len(),
            "frame {frame}"
        );
        assert_eq!(
            render.lights.count, fresh_scene.lights.count,
            "frame {frame}: lights"
        );
        let (a, b) = (render.lights.weight_total, fresh_scene.lights.weight_total);
        assert!(
            (a - b).abs() <= 1e-4 * a.max(b),
            "frame {frame}: light power {a} vs {b}"
        );
        // Aimed rays first (index 0..alive), then 300 random ones.
        let mut live: Vec<(hecs::Entity, Entity)> = alive.iter().map(|(e, v)| (*e, *v)).collect();
        live.sort_by_key(|(e, _)| e.to_bits());
        let aimed: Vec<Ray> = live
            .iter()
            .map(|(_, entity)| {
                let (p, t) = (&shapes[entity.model].0, &shapes[entity.model].1[0]);
                let centroid = (p[t[0] as usize] + p[t[1] as usize] + p[t[2] as usize]) / 3.0;
                let target = entity.world.transform_point3(centroid);
                let from = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5).normalize_or(Vec3::Y);
                let o = target + 3.0 * from;
                Ray::new(o, target - o)
            })
            .collect();
        let mut aimed_hits = 0;
        for i in 0..aimed.len() + 300 {
            let ray = match aimed.get(i) {
                Some(ray) => *ray,
                None => {
                    let o = Vec3::new(16.0 * u() - 8.0, 16.0 * u() - 8.0, 16.0 * u() - 8.0);
                    let d = Vec3::new(u() - 0.5, u() - 0.5, u() - 0.5);
                    Ray::new(o, d)
                }
            };
            let got = render.trace_scene().closest(&ray);
            let want = fresh_scene.trace_scene().closest(&ray);
            match (got, want) {
                (None, None) => {}
                (Some(g), Some(w)) => {
                    aimed_hits += usize::from(i < aimed.len());
                    assert_eq!(g.t, w.t, "frame {frame} ray {i}");
                    assert_eq!(g.triangle, w.triangle, "frame {frame} ray {i}");
                    assert_eq!(
                        game.entity_of_instance(g.instance),
                        fresh.entity_of_instance(w.instance),
                        "frame {frame} ray {i}: different entity"
                    );
                    assert_eq!(
                        render.instances[g.instance as usize].material_override,
                        fresh_scene.instances[w.instance as usize].material_override
                    );
                    assert_eq!(
                        render.instances[g.instance as usize].flags,
                        fresh_scene.instances[w.instance as usize].flags
                    );
                }
                (g, w) => panic!("frame {frame} ray {i}: incremental {g:?} vs fresh {w:?}"),
            }
            assert_eq!(
                render.trace_scene().occluded(&ray),
                fresh_scene.trace_scene().occluded(&ray)
            );
        }
        assert_eq!(
            aimed_hits,
            alive.len(),
            "frame {frame}: of {} rays aimed at live entities, {aimed_hits} hit on both sides",
            alive.len()
        );
    }
    assert!(
        rebuilds > 0,
        "the sequence should exercise BLAS rebuilds too"
    );
}
