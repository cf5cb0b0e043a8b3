//! The water's height field (issue 35 item 1, `engine/src/sim/water/`): a bump spreads and its
//! energy never grows under damping, nothing blows up in 10,000 steps at the largest speed the
//! level check allows; without damping the scheme keeps its energy; a body walked through the
//! water leaves ripples along its path, and one at rest makes none once the water settles.

use candela::assets::{VALIDATED_STEP_SECONDS, WaterSimDesc};
use candela::ecs::Transform;
use candela::sim::physics::{Collider, ColliderShape, PhysicsPose, RigidBody};
use candela::sim::water::{GridLayout, HeightField, WaterSim, water_system};
use glam::{Quat, Vec3};

const DT: f32 = 1.0 / 60.0;

/// Rest positions of a flat grid `size` metres wide, `divisions` quads per axis, centred on
/// the origin (as the engine's grid models are laid out).
fn grid(size: f32, divisions: usize) -> Vec<Vec3> {
    let mut positions = Vec::new();
    for z in 0..=divisions {
        for x in 0..=divisions {
            let (u, v) = (x as f32 / divisions as f32, z as f32 / divisions as f32);
            positions.push(Vec3::new((u - 0.5) * size, 0.0, (v - 0.5) * size));
        }
    }
    positions
}

fn sim(wave_speed: f32, damping: f32) -> WaterSimDesc {
    WaterSimDesc {
        wave_speed,
        damping,
        substeps: 1,
        push: 0.5,
        start_at_rest: false,
    }
}

/// A Gaussian bump of `metres` at the centre of `field`, 0.3 m wide.
fn bump(field: &mut HeightField, metres: f32) {
    let l = field.layout;
    let centre = l.rest(l.columns / 2, l.rows / 2);
    for iz in 0..l.rows {
        for ix in 0..l.columns {
            let d2 = (l.rest(ix, iz) - centre).length_squared();
            field.raise(ix, iz, metres * (-d2 / (0.3f32 * 0.3)).exp());
        }
    }
}

/// The largest speed the level check lets through on `layout` at one substep: 0.99 of the CFL
/// limit `c·dt·√(1/dx² + 1/dz²) < 1`.
fn largest_allowed_speed(layout: &GridLayout) -> f32 {
    let limit = 1.0 / (DT * (1.0 / layout.dx.powi(2) + 1.0 / layout.dz.powi(2)).sqrt());
    let speed = 0.99 * limit;
    let courant = sim(speed, 0.0).courant(VALIDATED_STEP_SECONDS, layout.dx, layout.dz);
    assert!(courant < 1.0 && courant > 0.98, "courant {courant}");
    speed
}

#[test]
fn a_bump_spreads_and_its_energy_decays_for_10000_steps_at_the_largest_speed() {
    let layout = GridLayout::infer(&grid(8.0, 64)).expect("a grid");
    let speed = largest_allowed_speed(&layout);
    let mut field = HeightField::new(layout, sim(speed, 0.5));
    bump(&mut field, 0.1);
    let centre = (layout.columns / 2) + (layout.rows / 2) * layout.columns;
    let start = field.energy(DT);
    assert!(start > 0.0);
    let mut energy = vec![start];
    // The step at which a ring at the wave speed is 1 m out.
    let ring_step = (1.0 / (speed * DT)).round() as usize;
    for step in 1..=10_000 {
        field.step(DT, &[]);
        energy.push(field.energy(DT));
        if step == ring_step {
            // The bump has fallen and a ring has gone out 1 m from the centre.
            let h = field.heights();
            assert!(h[centre].abs() < 0.05, "centre still at {} m", h[centre]);
            let ring = centre + (1.0 / layout.dx).round() as usize;
            let near: f32 = (ring - 3..ring + 3).map(|i| h[i].abs()).fold(0.0, f32::max);
            assert!(near > 1e-3, "no ring 1 m out ({near} m)");
        }
    }
    assert!(field.heights().iter().all(|h| h.is_finite()), "NaN or inf");
    for (step, pair) in energy.windows(2).enumerate() {
        // Rounding (f32 state, f64 sums) is far below a millionth of the energy.
        assert!(
            pair[1] <= pair[0] + 1e-6 * start,
            "step {step}: the energy grew from {} to {}",
            pair[0],
            pair[1]
        );
    }
    let end = energy[energy.len() - 1];
    assert!(end < 1e-6 * start, "energy {end} of {start} left");
}

#[test]
fn without_damping_the_scheme_keeps_its_energy() {
    let layout = GridLayout::infer(&grid(8.0, 64)).expect("a grid");
    let mut field = HeightField::new(layout, sim(largest_allowed_speed(&layout), 0.0));
    bump(&mut field, 0.1);
    let start = field.energy(DT);
    for _ in 0..2_000 {
        field.step(DT, &[]);
    }
    let end = field.energy(DT);
    assert!(
        ((end - start) / start).abs() < 1e-3,
        "energy {start} became {end}"
    );
    assert!(
        field.heights().iter().any(|h| h.abs() > 1e-3),
        "the waves died"
    );
}

/// A water (12 m, 96 × 96 quads, c = 1.5 m/s) and a wading capsule (radius 0.3 m, 1.8 m tall)
/// standing with its feet `depth` metres below the surface at `x`, 0 in z.
fn pool_and_wader(depth: f32, x: f32) -> (hecs::World, hecs::Entity, hecs::Entity) {
    let mut world = hecs::World::new();
    let water = WaterSim::on_grid(&grid(12.0, 96), sim(1.5, 0.4)).expect("a grid");
    let water = world.spawn((Transform::IDENTITY, water));
    let capsule = ColliderShape::Capsule {
        half_height: 0.6,
        radius: 0.3,
    };
    let centre = Vec3::new(x, 0.9 - depth, 0.0);
    let wader = world.spawn((
        PhysicsPose {
            previous: (centre, Quat::IDENTITY),
            current: (centre, Quat::IDENTITY),
        },
        RigidBody::kinematic(),
        Collider::new(&capsule).expect("a capsule"),
    ));
    (world, water, wader)
}

fn move_to(world: &mut hecs::World, wader: hecs::Entity, centre: Vec3) {
    let mut pose = world.get::<&mut PhysicsPose>(wader).expect("pose");
    pose.previous = pose.current;
    pose.current = (centre, Quat::IDENTITY);
}

/// Mean square height (m²) of the vertices within 0.5 m of z = 0 with `x` in `xs`.
fn mean_square(world: &hecs::World, water: hecs::Entity, xs: std::ops::Range<f32>) -> f32 {
    let sim = world.get::<&WaterSim>(water).expect("water");
    let l = sim.field.layout;
    let (mut sum, mut n) = (0.0, 0);
    for iz in 0..l.rows {
        for ix in 0..l.columns {
            let p = l.rest(ix, iz);
            if p.z.abs() <= 0.5 && xs.contains(&p.x) {
                sum += sim.field.heights()[ix + iz * l.columns].powi(2);
                n += 1;
            }
        }
    }
    sum / n.max(1) as f32
}

fn energy(world: &hecs::World, water: hecs::Entity) -> f64 {
    world
        .get::<&WaterSim>(water)
        .expect("water")
        .field
        .energy(DT)
}

#[test]
fn a_body_walked_through_the_water_leaves_ripples_along_its_path() {
    // Knee deep (0.5 m): stands at x = −4 until the water settles (20 s), then walks to
    // x = +2 at 1.2 m/s (5 s).
    let (mut world, water, wader) = pool_and_wader(0.5, -4.0);
    for _ in 0..1200 {
        water_system(&mut world, f64::from(DT));
    }
    let settled = mean_square(&world, water, -4.0..-1.0);
    let mut along = Vec::new();
    // Printed for docs/PERFORMANCE.md, never asserted.
    let mut stepping = std::time::Duration::ZERO;
    for step in 1..=300 {
        let x = -4.0 + 1.2 * step as f32 * DT;
        move_to(&mut world, wader, Vec3::new(x, 0.4, 0.0));
        let started = std::time::Instant::now();
        water_system(&mut world, f64::from(DT));
        stepping += started.elapsed();
        if step % 75 == 0 {
            // The stretch walked so far, up to 0.5 m behind the body.
            along.push(mean_square(&world, water, -4.0..x - 0.5));
        }
    }
    println!("mean square heights along the path: start {settled}, then {along:?} m²");
    println!(
        "water_system, 96 x 96 quads, one wader: {:.1} µs per fixed step",
        stepping.as_secs_f64() * 1e6 / 300.0
    );
    assert!(along[0] > 1e-6, "no ripples behind the body: {along:?}");
    assert!(
        along.iter().all(|&m| m > 100.0 * settled.max(1e-12)),
        "the path is no rougher than where it stood: {settled} vs {along:?}"
    );
    let far = mean_square(&world, water, 4.5..5.5);
    let path = mean_square(&world, water, -2.0..1.0);
    assert!(path > 2.0 * far, "path {path} m² vs. ahead {far} m²");
}

#[test]
fn a_body_at_rest_makes_no_ripples_once_settled() {
    // Stepping into the water makes a ring; standing still then adds nothing.
    let (mut world, water, _) = pool_and_wader(0.5, 0.0);
    for _ in 0..600 {
        water_system(&mut world, f64::from(DT));
    }
    let settled = energy(&world, water);
    let mut last = settled;
    for step in 0..1200 {
        water_system(&mut world, f64::from(DT));
        let now = energy(&world, water);
        assert!(
            now <= last + 1e-9 * settled.max(1e-12),
            "step {step}: energy grew"
        );
        last = now;
    }
    assert!(last < 1e-3 * settled, "energy {last} of {settled} left");
    let worst = (world
        .get::<&WaterSim>(water)
        .expect("water")
        .field
        .heights())
    .iter()
    .fold(0.0f32, |m, h| m.max(h.abs()));
    assert!(worst < 1e-4, "still rippling: {worst} m");

    // Out of the water (its feet above the surface): no push at all.
    let (mut world, water, _) = pool_and_wader(-0.1, 0.0);
    for _ in 0..60 {
        water_system(&mut world, f64::from(DT));
    }
    assert_eq!(energy(&world, water), 0.0);
}
