//! Determinism: the same input recording gives the same game state after 1,000 steps. The
//! state is hashed bit for bit (every `Transform`, every character's state); a run with one
//! input changed must hash differently, so the hash does see the recording.

use crate::physics_common;

use std::hash::{Hash, Hasher};

use candela::ecs::Transform;
use candela::sim::physics::{
    Carrier, CarryRequest, CharacterController, CharacterInput, CharacterState, ColliderShape,
    character_bundle,
};
use glam::{Quat, Vec3};
use physics_common::Sim;

/// One step of the recording: what the player does at step `k`.
#[derive(Clone, Copy)]
struct Recorded {
    move_direction: Vec3,
    run: bool,
    jump: bool,
    carry: Option<CarryRequest>,
}

fn recording(changed_step: Option<usize>) -> Vec<Recorded> {
    (0..1000)
        .map(|k| {
            let heading = (k / 100) as f32 * 0.9;
            let mut r = Recorded {
                move_direction: Vec3::new(heading.cos(), 0.0, heading.sin()),
                run: (k / 250) % 2 == 1,
                jump: k % 170 == 60,
                carry: match k {
                    300 => Some(CarryRequest::Pick),
                    520 => Some(CarryRequest::Drop),
                    _ => None,
                },
            };
            if Some(k) == changed_step {
                r.jump = !r.jump;
            }
            r
        })
        .collect()
}

fn play(inputs: &[Recorded]) -> u64 {
    let mut sim = Sim::new();
    sim.fixed_box(Vec3::new(6.0, 0.15, 3.0), Vec3::new(1.0, 0.15, 1.0));
    let shapes = [
        ColliderShape::cube(0.4),
        ColliderShape::Sphere { radius: 0.25 },
        ColliderShape::Capsule {
            half_height: 0.2,
            radius: 0.15,
        },
        ColliderShape::ConvexHull {
            points: vec![
                Vec3::new(-0.3, 0.0, -0.3),
                Vec3::new(0.3, 0.0, -0.3),
                Vec3::new(0.0, 0.0, 0.35),
                Vec3::new(0.0, 0.5, 0.0),
            ],
        },
    ];
    for i in 0..24 {
        let shape = shapes[i % shapes.len()].clone();
        let at = Vec3::new(
            1.5 + (i % 4) as f32 * 0.7,
            0.5 + (i / 4) as f32 * 0.6,
            -0.6 + (i % 3) as f32 * 0.6,
        );
        sim.dynamic(at, shape, 2.0 + i as f32 * 0.25);
    }
    let character = sim.world.spawn(
        character_bundle(
            Vec3::new(0.0, 0.92, 0.0),
            1.8,
            0.3,
            CharacterController::default(),
        )
        .expect("valid capsule"),
    );
    // A first-person carrier looking slightly down, carried along with the character by the
    // game rules below.
    let look = Quat::from_rotation_x(-0.5);
    let eye = sim.world.spawn((
        Transform {
            rotation: look,
            ..Transform::from_translation(Vec3::new(0.0, 1.6, 0.0))
        },
        Carrier {
            ignore: Some(character),
            ..Carrier::default()
        },
    ));
    for r in inputs {
        // Game rules: input into components, eye follows the character's head.
        let head = sim.position(character) + Vec3::Y * 0.7;
        let yaw = f32::atan2(-r.move_direction.x, -r.move_direction.z);
        if let Ok(t) = sim.world.query_one_mut::<&mut Transform>(eye) {
            t.translation = head;
            t.rotation = Quat::from_rotation_y(yaw) * look;
        }
        if let Ok(c) = sim.world.query_one_mut::<&mut Carrier>(eye) {
            c.request = r.carry;
        }
        if let Ok(input) = sim.world.query_one_mut::<&mut CharacterInput>(character) {
            input.move_direction = r.move_direction;
            input.run = r.run;
            input.jump = r.jump;
        }
        sim.step();
    }
    let mut hasher = std::collections::hash_map::DefaultHasher::new();
    let mut state: Vec<(u64, [u32; 7])> = sim
        .world
        .query::<(hecs::Entity, &Transform)>()
        .iter()
        .map(|(e, t)| {
            let [x, y, z] = t.translation.to_array().map(f32::to_bits);
            let [a, b, c, d] = t.rotation.to_array().map(f32::to_bits);
            (e.to_bits().get(), [x, y, z, a, b, c, d])
        })
        .collect();
    state.sort();
    state.hash(&mut hasher);
    if let Ok(s) = sim.world.get::<&CharacterState>(character) {
        (s.vertical_speed.to_bits(), s.grounded).hash(&mut hasher);
    }
    hasher.finish()
}

#[test]
fn same_recording_same_state_after_1000_steps() {
    let inputs = recording(None);
    let started = std::time::Instant::now();
    let first = play(&inputs);
    // Printed for the record only (no timed assertion): 24 bodies, a character, a carrier.
    println!(
        "1000 steps in {:.1} ms",
        started.elapsed().as_secs_f64() * 1000.0
    );
    let second = play(&inputs);
    println!("state hash after 1000 steps: {first:016x}");
    assert_eq!(first, second, "two runs of one recording diverged");
    let changed = play(&recording(Some(60)));
    assert_ne!(first, changed, "a different recording gave the same hash");
}
