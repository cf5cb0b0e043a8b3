//! The per-step settle (`Engine::settle_every_step`, `app/runner/step_scene.rs`; issue 36): a
//! frame of several fixed steps, or one that ends between steps, settles the world and the
//! query scene again before each step (pose, the deformed meshes refitted, the TLAS), and
//! every step's ray queries must see exactly what they would see had each step had a frame of
//! its own (a full upkeep and commit). A swelling water (deformed every step, its BLAS
//! refitted) and a tile the game moves every step, under a fan of 64 rays from above: run once
//! at one step per frame (no settle: each step reads the last frame's upkeep) and once at four
//! and a half steps per frame (every step settled), the closest hits of every step (entity,
//! instance, triangle, distance to the bit, normal) and the state hashes agree.

use std::collections::BTreeMap;

use candela::app::{Engine, Environment, Step, Waves};
use candela::assets::{
    CameraDesc, Material, MaterialKind, Mesh, Model, Placement, RenderSettings, SkyDesc, WaveDesc,
};
use candela::ecs::{Deformable, Renderable, Transform};
use candela::render::RenderConfig;
use candela::trace::Ray;
use glam::{Mat4, Vec3};

/// What one ray saw: entity bits, instance, triangle, and the distance and geometric normal
/// as f32 bits.
type Seen = Option<(Option<u64>, u32, u32, u32, [u32; 3])>;

/// A `n × n` grid of quads, `size` metres wide, in the xz plane.
fn grid_model(n: u32, size: f32) -> Model {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for z in 0..=n {
        for x in 0..=n {
            positions.push(Vec3::new(
                size * (x as f32 / n as f32 - 0.5),
                0.0,
                size * (z as f32 / n as f32 - 0.5),
            ));
        }
    }
    for z in 0..n {
        for x in 0..n {
            let i = z * (n + 1) + x;
            triangles.push([i, i + n + 1, i + 1]);
            triangles.push([i + 1, i + n + 1, i + n + 2]);
        }
    }
    let count = triangles.len();
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
            ..Default::default()
        }],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        ..Default::default()
    }
}

fn engine() -> Engine {
    let environment = Environment {
        sun: None,
        sky: SkyDesc::Constant([0.1; 3]),
        render: RenderSettings {
            max_bounces: 1,
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
    };
    Engine::new(RenderConfig::cpu(8, 8), environment).expect("engine starts")
}

/// 64 rays from 3 m above the water's centre, fanned over the water and the tile's path.
fn fan() -> Vec<Ray> {
    let origin = Vec3::new(0.0, 3.0, 0.0);
    (0..64)
        .map(|i| {
            let (x, z) = ((i % 8) as f32 - 3.5, (i / 8) as f32 - 3.5);
            Ray::new(origin, Vec3::new(0.17 * x, -1.0, 0.17 * z).normalize())
        })
        .collect()
}

/// What every step saw (by step index) and the state hash after every step count a frame
/// ended on, for `steps` fixed steps at frames of `steps_per_frame` steps.
struct Run {
    seen: BTreeMap<u64, Vec<Seen>>,
    hashes: BTreeMap<u64, u64>,
}

fn run(steps_per_frame: f64, steps: u64) -> Run {
    let mut engine = engine();
    engine.settle_every_step(true);
    // 24 × 24 quads over 4 m: 1,152 triangles swelling by 0.15 m.
    let water_model = grid_model(24, 4.0);
    let base = water_model.meshes[0].positions.clone();
    let water = engine.add_model(&water_model);
    let waves = Waves::new(
        WaveDesc {
            amplitude: 0.15,
            wavelength: 1.3,
            speed: 0.9,
            simulate: None,
        },
        base.clone(),
    );
    let deformable = Deformable {
        mesh: 0,
        positions: base,
        normals: None,
        dirty: false,
    };
    let renderable = |model| Renderable {
        model,
        material_override: None,
    };
    engine
        .world_mut()
        .spawn((Transform::IDENTITY, renderable(water), waves, deformable));
    let tile = engine.add_model(&grid_model(2, 0.8));
    let tile = engine.world_mut().spawn((
        Transform::from_translation(Vec3::new(-1.5, 0.6, 0.0)),
        renderable(tile),
    ));
    let rays = fan();
    let mut out = Run {
        seen: BTreeMap::new(),
        hashes: BTreeMap::new(),
    };
    let step_seconds = 1.0 / 60.0;
    let mut done = 0;
    let mut frame = 0;
    while done < steps {
        let seen = &mut out.seen;
        let mut game = |step: &mut Step<'_>| {
            let hits = rays
                .iter()
                .map(|ray| {
                    step.queries.closest(ray).map(|h| {
                        let n = h.geometric_normal.to_array().map(f32::to_bits);
                        (
                            h.entity.map(|e| e.to_bits().get()),
                            h.instance,
                            h.triangle,
                            h.t.to_bits(),
                            n,
                        )
                    })
                })
                .collect();
            seen.insert(step.index, hits);
            // The tile slides along x and turns a little every step.
            let t = (step.index + 1) as f32 * step.step_seconds as f32;
            if let Ok(mut transform) = step.world.get::<&mut Transform>(tile) {
                transform.translation = Vec3::new(-1.5 + 0.9 * t, 0.6, 0.2 * t);
                transform.rotation = glam::Quat::from_rotation_y(0.7 * t);
            }
        };
        // At 4.5 steps a frame the first frame leaves half a step in the clock, so that every
        // frame ends between steps and every later step is settled first.
        let seconds = if frame == 0 {
            steps_per_frame * step_seconds
        } else {
            steps_per_frame.floor() * step_seconds
        };
        let report = engine.frame(seconds, &mut game).expect("frame");
        let _ = engine.rendered();
        done += u64::from(report.steps);
        out.hashes.insert(done, engine.state_hash());
        frame += 1;
    }
    drop(engine.shutdown());
    out
}

#[test]
fn settled_steps_see_what_steps_of_their_own_frames_see() {
    let steps = 90;
    let own = run(1.0, steps);
    let settled = run(4.5, steps);
    let mut compared = 0;
    let mut water_hits = 0;
    for (index, hits) in &settled.seen {
        let Some(reference) = own.seen.get(index) else {
            continue;
        };
        for (ray, (a, b)) in hits.iter().zip(reference).enumerate() {
            assert_eq!(
                a, b,
                "step {index}, ray {ray}: settled {a:?}, own frame {b:?}"
            );
        }
        water_hits += hits.iter().filter(|h| h.is_some()).count();
        compared += 1;
    }
    assert!(compared >= 80, "only {compared} steps compared");
    assert!(
        water_hits > 60 * compared,
        "the fan missed: {water_hits} hits"
    );
    // The scene moved under the fan: the hits of the first and the last step differ.
    assert_ne!(
        settled.seen.first_key_value().map(|(_, h)| h),
        settled.seen.last_key_value().map(|(_, h)| h)
    );
    let mut hashed = 0;
    for (done, hash) in &settled.hashes {
        if let Some(reference) = own.hashes.get(done) {
            assert_eq!(hash, reference, "state hash after {done} steps");
            hashed += 1;
        }
    }
    assert!(hashed >= 15, "only {hashed} hashes compared");
}
