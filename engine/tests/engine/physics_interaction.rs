//! Carrying bodies and sensors.

use crate::physics_common;

use candela::ecs::Transform;
use candela::sim::physics::{
    Carrier, CarryRequest, Collider, ColliderShape, RigidBody, SensorContacts,
};
use glam::{Quat, Vec3};
use physics_common::Sim;

const EYE: Vec3 = Vec3::new(0.0, 1.6, 0.0);

/// A carrier looking along −Z picks up a cube resting on a pillar in front of it; the cube
/// follows the hold point as the carrier moves and turns, and falls when dropped.
#[test]
fn picked_body_follows_the_hold_point_and_falls_when_dropped() {
    let mut sim = Sim::new();
    // Pillar top at y = 1.45; a 0.3 m cube resting on it, its centre at eye height, 2 m ahead.
    sim.fixed_box(Vec3::new(0.0, 0.725, -2.0), Vec3::new(0.3, 0.725, 0.3));
    let cube = sim.dynamic(Vec3::new(0.0, 1.6, -2.0), ColliderShape::cube(0.3), 2.0);
    let carrier = sim
        .world
        .spawn((Transform::from_translation(EYE), Carrier::default()));
    sim.steps(5);
    let set = |sim: &mut Sim, request, translation: Vec3, rotation: Quat| {
        if let Ok((c, t)) = sim
            .world
            .query_one_mut::<(&mut Carrier, &mut Transform)>(carrier)
        {
            c.request = request;
            t.translation = translation;
            t.rotation = rotation;
        }
    };
    set(&mut sim, Some(CarryRequest::Pick), EYE, Quat::IDENTITY);
    sim.steps(60);
    let held = sim
        .world
        .get::<&Carrier>(carrier)
        .map(|c| c.held)
        .ok()
        .flatten();
    assert_eq!(held, Some(cube), "the cube was not picked");
    // Hold point 1.5 m ahead; 2 cm covers the spring's residual against gravity-free drift.
    let hold = EYE + Vec3::NEG_Z * 1.5;
    let gap = (sim.position(cube) - hold).length();
    assert!(gap < 0.02, "cube {gap} m from the hold point");

    // Walk 1 m to the side and turn 90° left (now looking along −X).
    let moved_eye = EYE + Vec3::new(1.0, 0.0, 0.0);
    let turned = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
    set(&mut sim, None, moved_eye, turned);
    sim.steps(60);
    let hold = moved_eye + Vec3::NEG_X * 1.5;
    let gap = (sim.position(cube) - hold).length();
    println!(
        "carry: cube {:.1} mm from the moved hold point",
        gap * 1000.0
    );
    assert!(gap < 0.02, "cube {gap} m from the moved hold point");

    set(&mut sim, Some(CarryRequest::Drop), moved_eye, turned);
    sim.steps(90);
    let held = sim
        .world
        .get::<&Carrier>(carrier)
        .map(|c| c.held)
        .ok()
        .flatten();
    assert_eq!(held, None);
    let y = sim.position(cube).y;
    assert!(
        (y - 0.15).abs() < 0.01,
        "dropped cube should rest on the ground, at y = {y}"
    );
}

/// A sensor box reports a falling sphere and a game-moved kinematic box entering and leaving,
/// once each, and never blocks them.
#[test]
fn sensor_reports_enter_and_exit() {
    let mut sim = Sim::new();
    let sensor = sim.world.spawn((
        Transform::from_translation(Vec3::new(0.0, 2.0, 0.0)),
        RigidBody::fixed(),
        Collider::new(&ColliderShape::Box {
            half_extents: Vec3::new(1.0, 0.5, 1.0),
        })
        .expect("valid box")
        .as_sensor(),
        SensorContacts::default(),
    ));
    let ball = sim.dynamic(
        Vec3::new(0.0, 5.0, 0.0),
        ColliderShape::Sphere { radius: 0.2 },
        1.0,
    );
    let mover = sim.world.spawn((
        Transform::from_translation(Vec3::new(-4.0, 2.0, 0.5)),
        RigidBody::kinematic(),
        Collider::new(&ColliderShape::cube(0.4)).expect("valid box"),
    ));
    let (mut entered, mut exited) = (Vec::new(), Vec::new());
    for k in 0..240 {
        if let Ok(t) = sim.world.query_one_mut::<&mut Transform>(mover) {
            t.translation.x = -4.0 + 0.05 * k as f32;
        }
        sim.step();
        let contacts = sim
            .world
            .get::<&SensorContacts>(sensor)
            .expect("sensor has contacts");
        entered.extend(contacts.entered.iter().map(|&e| (k, e)));
        exited.extend(contacts.exited.iter().map(|&e| (k, e)));
    }
    let of = |list: &[(usize, hecs::Entity)], e| list.iter().filter(|(_, x)| *x == e).count();
    println!("sensor: entered {entered:?}, exited {exited:?}");
    assert_eq!((of(&entered, ball), of(&exited, ball)), (1, 1), "ball");
    assert_eq!(
        (of(&entered, mover), of(&exited, mover)),
        (1, 1),
        "kinematic box"
    );
    // The ball fell through the sensor onto the ground.
    assert!((sim.position(ball).y - 0.2).abs() < 0.01);
}
