//! Riding kinematic platforms and carrying into walls (issue 10, §3): a character and a cube
//! standing on a game-driven kinematic lift (moved the way level clips move doors and lifts:
//! its `Transform` set before each step) follow it 3 m up, 3 m down and 2 m sideways; the
//! character at every step, the cube once it has settled after each start. A carried cube
//! pushed against a wall stays on the near side; a thrown cube leaves along the view.

use crate::physics_common;

use candela::ecs::Transform;
use candela::sim::physics::{
    Carrier, CarryRequest, CharacterController, Collider, ColliderShape, RigidBody,
    character_bundle,
};
use glam::Vec3;
use physics_common::Sim;

/// Half extents of the lift's deck, metres; its top starts at y = 0.3.
const DECK: Vec3 = Vec3::new(1.0, 0.1, 1.0);
const DECK_START: Vec3 = Vec3::new(0.0, 0.2, 0.0);

/// Smoothstep from 0 to 1 over [0, 1] (peak acceleration 6·distance/duration², below g for
/// the moves here so that a resting cube is never left behind by gravity).
fn ease(x: f32) -> f32 {
    let x = x.clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// The lift's centre at step `i`: rest 0.5 s, up 3 m in 3 s, rest 1 s, down 3 m in 3 s, rest
/// 1 s, 2 m along +X in 2 s, rest 1 s.
fn lift_at(i: usize) -> Vec3 {
    let t = i as f32 / 60.0;
    let up = 3.0 * (ease((t - 0.5) / 3.0) - ease((t - 4.5) / 3.0));
    let side = 2.0 * ease((t - 8.5) / 2.0);
    DECK_START + Vec3::new(side, up, 0.0)
}
const STEPS: usize = 60 * 12;

#[test]
fn a_character_and_a_cube_ride_a_lift_up_down_and_sideways() {
    let mut sim = Sim::new();
    let lift = sim.world.spawn((
        Transform::from_translation(DECK_START),
        RigidBody::kinematic(),
        Collider::new(&ColliderShape::Box { half_extents: DECK }).expect("box"),
    ));
    // A 1.8 m capsule standing on the deck (top 0.3) near one side, a 0.4 m cube on the other.
    let bundle = character_bundle(
        Vec3::new(-0.5, 0.3 + 0.9 + 0.02, 0.0),
        1.8,
        0.3,
        CharacterController::default(),
    )
    .expect("capsule");
    let player = sim.world.spawn(bundle);
    let cube = sim.dynamic(Vec3::new(0.5, 0.5, 0.0), ColliderShape::cube(0.4), 5.0);
    // Settle: both rest on the deck.
    sim.steps(20);
    let offset = |sim: &Sim, e| sim.position(e) - sim.position(lift);
    let (player_rest, cube_rest) = (offset(&sim, player), offset(&sim, cube));
    let (mut worst_player, mut worst_cube) = (Vec3::ZERO, Vec3::ZERO);
    for i in 0..STEPS {
        sim.world
            .get::<&mut Transform>(lift)
            .expect("lift")
            .translation = lift_at(i);
        sim.step();
        let dp = (offset(&sim, player) - player_rest).abs();
        let dc = (offset(&sim, cube) - cube_rest).abs();
        worst_player = worst_player.max(dp);
        worst_cube = worst_cube.max(dc);
        // The character is carried exactly by the deck's motion; 5 mm leaves room for the
        // controller's own ground snapping and skin handling, far below one step of lift
        // motion (up to 25 mm at 1.5 m/s), so lagging a step or sinking would fail.
        assert!(
            dp.y < 0.005 && dp.x < 0.005 && dp.z < 0.005,
            "step {i}: character off its place on the lift by {dp} (lift at {})",
            lift_at(i)
        );
        // The cube rides on contacts and friction; 2 cm covers contact compliance and the
        // slip of starting sideways (friction 0.5 against a peak 3 m/s² acceleration).
        assert!(
            dc.y < 0.02 && dc.x < 0.02 && dc.z < 0.02,
            "step {i}: cube off its place on the lift by {dc} (lift at {})",
            lift_at(i)
        );
    }
    println!(
        "ride: worst character offset {worst_player} m, worst cube offset {worst_cube} m over {STEPS} steps"
    );
    // The lift really went up 3 m and 2 m sideways: the ride was not trivial.
    assert!((sim.position(lift) - (DECK_START + Vec3::new(2.0, 0.0, 0.0))).length() < 1e-4);
}

/// A cube carried towards a wall by a carrier walking into it stays on the near side.
#[test]
fn a_carried_cube_is_stopped_by_a_wall() {
    let mut sim = Sim::new();
    // Wall: its near face at z = -2.0, 20 cm thick, 4 m wide and tall.
    sim.fixed_box(Vec3::new(0.0, 2.0, -2.1), Vec3::new(2.0, 2.0, 0.1));
    let eye = Vec3::new(0.0, 1.6, 0.0);
    let cube = sim.dynamic(Vec3::new(0.0, 1.6, -1.0), ColliderShape::cube(0.3), 2.0);
    let carrier = sim
        .world
        .spawn((Transform::from_translation(eye), Carrier::default()));
    // The pick ray sees bodies from the step after they were added.
    sim.step();
    sim.world
        .get::<&mut Carrier>(carrier)
        .expect("carrier")
        .request = Some(CarryRequest::Pick);
    sim.steps(30);
    assert_eq!(
        sim.world.get::<&Carrier>(carrier).expect("carrier").held,
        Some(cube),
        "picked"
    );
    // Walk 1.4 m towards the wall in 1 s: the hold point (1.5 m ahead) ends 0.9 m inside it.
    let mut nearest = f32::MAX;
    for i in 0..120 {
        let z = -1.4 * ((i + 1) as f32 / 60.0).min(1.0);
        sim.world
            .get::<&mut Transform>(carrier)
            .expect("carrier")
            .translation = eye + Vec3::new(0.0, 0.0, z);
        sim.step();
        // The cube's far face (centre − 0.15) may touch the wall face at −2.0; 1 cm of contact
        // compliance at most.
        let far_face = sim.position(cube).z - 0.15;
        nearest = nearest.min(far_face);
        assert!(
            far_face > -2.01,
            "step {i}: the cube went into the wall (far face at z = {far_face})"
        );
    }
    println!("carry into a wall: far face reached z = {nearest} (wall face at -2.0)");
    assert!(nearest < -1.95, "the cube was pushed up to the wall");
    assert_eq!(
        sim.world.get::<&Carrier>(carrier).expect("carrier").held,
        Some(cube),
        "still held: the gap stays under the break distance"
    );
}

/// Throwing lets go and sends the cube along the view at the given speed.
#[test]
fn a_thrown_cube_flies_along_the_view() {
    let mut sim = Sim::new();
    let eye = Vec3::new(0.0, 1.6, 0.0);
    let cube = sim.dynamic(Vec3::new(0.0, 1.6, -1.0), ColliderShape::cube(0.3), 2.0);
    let carrier = sim
        .world
        .spawn((Transform::from_translation(eye), Carrier::default()));
    // The pick ray sees bodies from the step after they were added.
    sim.step();
    sim.world
        .get::<&mut Carrier>(carrier)
        .expect("carrier")
        .request = Some(CarryRequest::Pick);
    sim.steps(30);
    sim.world
        .get::<&mut Carrier>(carrier)
        .expect("carrier")
        .request = Some(CarryRequest::Throw { speed: 6.0 });
    sim.step();
    assert_eq!(sim.world.get::<&Carrier>(carrier).expect("c").held, None);
    let v = sim.physics.linear_velocity(cube).expect("cube velocity");
    // 6 m/s along −Z, less one step of gravity on Y (0.16 m/s).
    assert!((v.z + 6.0).abs() < 0.05, "thrown at {v}");
    sim.steps(120);
    let z = sim.position(cube).z;
    // Falling 1.45 m takes 0.54 s: at 6 m/s it lands more than 3 m from the hold point.
    assert!(z < -4.5, "the cube landed at z = {z}");
}

/// A character walks on a lift at rest after it rose, and off its edge onto a floor at the
/// same height.
#[test]
fn a_character_walks_on_and_off_a_lift_that_rose() {
    use candela::sim::physics::{CharacterInput, CharacterState};
    let mut sim = Sim::new();
    // The upper floor: top at y = 3.3, from z = -1 to -5.
    sim.fixed_box(Vec3::new(0.0, 3.2, -3.0), Vec3::new(3.0, 0.1, 2.0));
    let lift = sim.world.spawn((
        Transform::from_translation(DECK_START),
        RigidBody::kinematic(),
        Collider::new(&ColliderShape::Box { half_extents: DECK }).expect("box"),
    ));
    let bundle = character_bundle(
        Vec3::new(0.0, 0.3 + 0.9 + 0.02, 0.0),
        1.8,
        0.3,
        CharacterController::default(),
    )
    .expect("capsule");
    let player = sim.world.spawn(bundle);
    sim.steps(20);
    for i in 0..240 {
        let y = 3.0 * ((i + 1) as f32 / 180.0).min(1.0);
        sim.world
            .get::<&mut Transform>(lift)
            .expect("lift")
            .translation = DECK_START + Vec3::Y * y;
        sim.step();
    }
    let start = sim.position(player);
    sim.world
        .get::<&mut CharacterInput>(player)
        .expect("input")
        .move_direction = Vec3::NEG_Z;
    for _ in 0..90 {
        sim.step();
    }
    let end = sim.position(player);
    let state = *sim.world.get::<&CharacterState>(player).expect("state");
    println!("walk off the lift: from {start} to {end}, {state:?}");
    assert!(end.z < start.z - 2.5, "walked from {start} to {end}");
    // The deck and the floor are flush: the character neither climbs nor drops.
    assert!((end.y - start.y).abs() < 0.01, "from {start} to {end}");
}
