//! The kinematic character controller: stairs of 30 cm, a 45° ramp, a ramp too steep to walk,
//! jumping, pushing a box.

use crate::physics_common;

use candela::sim::physics::{
    CharacterController, CharacterInput, CharacterState, ColliderShape, character_bundle,
};
use glam::{Quat, Vec3};
use hecs::Entity;
use physics_common::Sim;

const HEIGHT: f32 = 1.8;
const RADIUS: f32 = 0.3;
/// Capsule centre above the floor when standing.
const STAND: f32 = HEIGHT * 0.5;

fn spawn_character(sim: &mut Sim, x: f32) -> Entity {
    let controller = CharacterController::default();
    let bundle = character_bundle(
        Vec3::new(x, STAND + controller.skin, 0.0),
        HEIGHT,
        RADIUS,
        controller,
    )
    .expect("valid capsule");
    sim.world.spawn(bundle)
}

/// Walks along +X for `steps` fixed steps; returns the highest centre height reached.
fn walk(sim: &mut Sim, character: Entity, steps: usize) -> f32 {
    let mut highest = f32::MIN;
    for _ in 0..steps {
        if let Ok(input) = sim.world.query_one_mut::<&mut CharacterInput>(character) {
            input.move_direction = Vec3::X;
        }
        sim.step();
        highest = highest.max(sim.position(character).y);
    }
    highest
}

/// A ramp surface (two triangles) rising from x = 2 at `angle_deg` up to `rise` metres, then a
/// plateau on top.
fn ramp(sim: &mut Sim, angle_deg: f32, rise: f32) {
    let run = rise / angle_deg.to_radians().tan();
    let (x0, x1) = (2.0, 2.0 + run);
    let vertices = vec![
        Vec3::new(x0, 0.0, -5.0),
        Vec3::new(x0, 0.0, 5.0),
        Vec3::new(x1, rise, 5.0),
        Vec3::new(x1, rise, -5.0),
    ];
    // Counter-clockwise seen from above: the normal points up and back towards −X.
    let triangles = vec![[0, 1, 2], [0, 2, 3]];
    sim.fixed(
        Vec3::ZERO,
        Quat::IDENTITY,
        ColliderShape::Trimesh {
            vertices,
            triangles,
        },
    );
    sim.fixed_box(
        Vec3::new(x1 + 10.0, rise * 0.5, 0.0),
        Vec3::new(10.0, rise * 0.5, 5.0),
    );
}

#[test]
fn climbs_stairs_of_thirty_centimetres() {
    const RISE: f32 = 0.3;
    const TREAD: f32 = 0.4;
    const STEPS: usize = 5;
    let mut sim = Sim::new();
    // Step i covers x ≥ 2 + i·TREAD up to a long landing, its top at (i + 1)·RISE.
    for i in 0..STEPS {
        let top = RISE * (i + 1) as f32;
        let start = 2.0 + TREAD * i as f32;
        let end = 20.0;
        sim.fixed_box(
            Vec3::new((start + end) * 0.5, top * 0.5, 0.0),
            Vec3::new((end - start) * 0.5, top * 0.5, 5.0),
        );
    }
    let character = spawn_character(&mut sim, 0.0);
    walk(&mut sim, character, 240);
    let p = sim.position(character);
    let landing = RISE * STEPS as f32 + STAND;
    println!("stairs: centre at {p} (landing stand height {landing})");
    assert!(
        p.x > 2.0 + TREAD * STEPS as f32,
        "stuck on the stairs at {p}"
    );
    // Within 5 cm of standing on the landing: the skin gap and snapping tolerance.
    assert!(
        (p.y - landing).abs() < 0.05,
        "not standing on the landing: {p}"
    );
}

#[test]
fn walks_up_a_45_degree_ramp() {
    let mut sim = Sim::new();
    ramp(&mut sim, 45.0, 2.0);
    let character = spawn_character(&mut sim, 0.0);
    walk(&mut sim, character, 300);
    let p = sim.position(character);
    println!("45° ramp: centre at {p}");
    assert!(p.x > 4.5, "did not reach the plateau: {p}");
    assert!(
        (p.y - (2.0 + STAND)).abs() < 0.05,
        "not on the plateau: {p}"
    );
}

#[test]
fn stops_at_ramps_steeper_than_the_limit() {
    for angle in [55.0, 60.0] {
        let mut sim = Sim::new();
        ramp(&mut sim, angle, 2.0);
        let character = spawn_character(&mut sim, 0.0);
        let highest = walk(&mut sim, character, 300);
        let p = sim.position(character);
        println!("{angle}° ramp: highest centre {highest}, ends at {p}");
        // It may climb the first few centimetres (the step-up and the capsule's round bottom
        // touching the ramp) but never far up: 0.4 m over 2 m of ramp.
        assert!(highest < STAND + 0.4, "{angle}°: climbed to {highest}");
        assert!(p.y < STAND + 0.4, "{angle}°: ended at {p}");
    }
}

#[test]
fn jumps_to_the_height_its_speed_gives() {
    let mut sim = Sim::new();
    let character = spawn_character(&mut sim, 0.0);
    sim.steps(10);
    let grounded = sim
        .world
        .get::<&CharacterState>(character)
        .map(|s| s.grounded)
        .unwrap_or(false);
    assert!(grounded, "should stand on the ground");
    let start = sim.position(character).y;
    if let Ok(input) = sim.world.query_one_mut::<&mut CharacterInput>(character) {
        input.jump = true;
    }
    let mut highest = start;
    for k in 0..90 {
        sim.step();
        if k == 0
            && let Ok(input) = sim.world.query_one_mut::<&mut CharacterInput>(character)
        {
            // Released after one step (held, it would jump again on landing).
            input.jump = false;
        }
        highest = highest.max(sim.position(character).y);
    }
    let expected = 5.0f32.powi(2) / (2.0 * 9.81);
    println!("jump: {:.3} m (ballistic {expected:.3} m)", highest - start);
    // Explicit Euler at 60 Hz undershoots the ballistic height by v·dt/2 ≈ 4 cm.
    assert!(
        (highest - start - expected).abs() < 0.08,
        "jumped {}",
        highest - start
    );
    assert!(
        (sim.position(character).y - start).abs() < 0.05,
        "did not land"
    );
}

#[test]
fn pushes_a_box_it_walks_into() {
    let mut sim = Sim::new();
    let cube = sim.dynamic(Vec3::new(1.5, 0.25, 0.0), ColliderShape::cube(0.5), 10.0);
    let character = spawn_character(&mut sim, 0.0);
    walk(&mut sim, character, 120);
    let moved = sim.position(cube).x - 1.5;
    println!("push: box moved {moved:.3} m");
    assert!(moved > 0.5, "the box moved only {moved} m");
}
