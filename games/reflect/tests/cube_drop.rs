//! Carrying chamber 1's cube as a new player does (issue 37): a drop lands where the crosshair
//! points, the cube rests upright on the plate and presses it, from 1, 2 and 3 m; the drop's
//! preview shows that spot before the key is pressed; and walking with the cube held while
//! looking down at the plate never stops the player. Driven through the keys (E) and the
//! player's view, on the game's own frame loop (headless, CPU tracer, one step a frame).

use candela::app::{Engine, Game, KeyCode};
use candela::assets::CameraDesc;
use candela::extract::RenderCamera;
use candela::render::RenderConfig;
use glam::{Vec3, Vec3Swizzles};
use reflect::game::{ReflectEvent, ReflectGame};
use reflect::world::ReflectWorld;

/// Chamber 1's plate: its centre on the floor, and the top of it a player aims at (metres).
const PLATE: Vec3 = Vec3::new(3.0, 0.0, -11.0);
const PLATE_TOP: Vec3 = Vec3::new(3.0, 0.08, -11.0);

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

fn frames(engine: &mut Engine, game: &mut ReflectGame, n: usize) {
    for _ in 0..n {
        engine.frame(1.0 / 60.0, game).expect("a frame");
        let _ = engine.rendered();
    }
}

/// Chamber 1 started headless (CPU tracer at 16×9), with its cube.
fn chamber_1(world: &ReflectWorld) -> (Engine, ReflectGame, hecs::Entity) {
    let mut game = ReflectGame::new(world.clone(), 0);
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 9), game.inner().environment()).expect("engine");
    game.setup(&mut engine).expect("setup");
    let cube = *game
        .inner()
        .spawned()
        .by_name
        .get("cube_1")
        .expect("chamber 1 has cube_1");
    (engine, game, cube)
}

/// Presses E for one frame and lets it go.
fn press_e(engine: &mut Engine, game: &mut ReflectGame) {
    engine.input_mut().key(KeyCode::KeyE, true);
    frames(engine, game, 1);
    engine.input_mut().key(KeyCode::KeyE, false);
    frames(engine, game, 1);
}

/// Chamber 1 with the player standing `distance` metres south of the plate, facing it, the
/// cube picked up with E.
fn holding_the_cube(world: &ReflectWorld, distance: f32) -> (Engine, ReflectGame, hecs::Entity) {
    let (mut engine, mut game, cube) = chamber_1(world);
    let eye = PLATE + Vec3::new(0.0, 1.65, distance);
    game.start_at_view(&RenderCamera::from_desc(&CameraDesc {
        position: eye.to_array(),
        look_at: (eye - Vec3::Z).to_array(),
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: 70.0,
        aperture_radius: 0.0,
        focus_distance: None,
    }));
    frames(&mut engine, &mut game, 5);
    // The cube on the floor a metre ahead (south of the plate, so it does not press it), the
    // player looking at it, as one who walked up to it.
    let player = game.inner().player().expect("a player");
    let (feet, view) = (player.feet(engine.world()), player.view());
    let spot = feet + view.with_y(0.0).normalize() * 1.0 + Vec3::Y * 0.26;
    engine
        .physics_mut()
        .set_pose(cube, spot, glam::Quat::IDENTITY);
    aim_at(&mut engine, &mut game, spot);
    frames(&mut engine, &mut game, 10);
    press_e(&mut engine, &mut game);
    let held = game.inner().player().and_then(|p| p.held(engine.world()));
    assert_eq!(held, Some(cube), "E picks up the cube in front of the eye");
    (engine, game, cube)
}

/// Turns the player's view to put the crosshair on `at`.
fn aim_at(engine: &mut Engine, game: &mut ReflectGame, at: Vec3) {
    let eye = game
        .inner()
        .player()
        .map(|p| p.eye(engine.world()))
        .expect("a player");
    let d = at - eye;
    if let Some(player) = game.inner_mut().player_mut() {
        player.yaw = (-d.x).atan2(-d.z);
        player.pitch = d.y.atan2(d.xz().length());
    }
}

/// Whether chamber 1's door rule is up now (its last change rose).
fn door_open(game: &ReflectGame) -> bool {
    game.log()
        .iter()
        .rev()
        .find_map(|(_, e)| match e {
            ReflectEvent::Rule { name, rising } if name == "door_1" => Some(*rising),
            _ => None,
        })
        .unwrap_or(false)
}

#[test]
fn a_cube_dropped_while_aiming_at_the_plate_lands_on_it_and_presses_it() {
    let world = world();
    for distance in [1.0f32, 2.0, 3.0] {
        let (mut engine, mut game, cube) = holding_the_cube(&world, distance);
        aim_at(&mut engine, &mut game, PLATE_TOP);
        frames(&mut engine, &mut game, 30);
        let camera = game.inner().player().expect("player").camera;
        let preview = engine
            .physics()
            .placement(engine.world(), camera)
            .unwrap_or_else(|| panic!("{distance} m: no drop preview on the plate"));
        assert!(
            (preview.position - PLATE).xz().length() < 0.1,
            "{distance} m: the preview is at {:?}, not on the plate",
            preview.position
        );
        press_e(&mut engine, &mut game);
        frames(&mut engine, &mut game, 90);
        let (at, rotation) = engine.physics().pose(cube).expect("the cube's pose");
        assert!(
            (at - PLATE).xz().length() < 0.2,
            "{distance} m: the cube landed at {at:?}, {:.2} m off the plate's centre",
            (at - PLATE).xz().length()
        );
        assert!(
            (rotation * Vec3::Y).y > 0.99,
            "{distance} m: the cube rests tilted"
        );
        let held = game.inner().player().and_then(|p| p.held(engine.world()));
        assert_eq!(held, None, "{distance} m: E did not drop the cube");
        assert!(
            door_open(&game),
            "{distance} m: the plate does not hold the door open"
        );
        let _ = engine.shutdown();
    }
}

#[test]
fn walking_with_the_cube_held_while_looking_down_at_the_plate_never_stops_the_player() {
    let world = world();
    let (mut engine, mut game, _) = holding_the_cube(&world, 3.0);
    // Looking down near the plate, walking across it: the held cube used to float at the floor
    // in front of the feet and catch on the plate's rim. Two things now keep the walk going:
    // the hold point stays above −40° and to the side, and the character's moves skip its own
    // held body. With neither (checked by hand), this walk stops after 1.65 m at 0.7 m/s.
    if let Some(player) = game.inner_mut().player_mut() {
        player.pitch = -70f32.to_radians();
    }
    let start = game
        .inner()
        .player()
        .map(|p| p.feet(engine.world()))
        .expect("player");
    engine.input_mut().key(KeyCode::KeyW, true);
    let mut slowest = f32::INFINITY;
    let mut before = start;
    // Speed over each sixth of a second (a frame may run no step or two).
    for window in 0..15 {
        frames(&mut engine, &mut game, 10);
        let feet = game
            .inner()
            .player()
            .map(|p| p.feet(engine.world()))
            .expect("player");
        if window > 1 {
            slowest = slowest.min((feet - before).xz().length() * 6.0);
        }
        before = feet;
    }
    engine.input_mut().key(KeyCode::KeyW, false);
    let held = game.inner().player().and_then(|p| p.held(engine.world()));
    assert!(held.is_some(), "the cube was dropped on the way");
    let walked = (before - start).xz().length();
    assert!(
        walked > 4.0 && slowest > 1.0,
        "walked {walked:.2} m in 2.5 s, slowest {slowest:.2} m/s: the held cube stopped the player"
    );
}

#[test]
fn a_cube_falling_tilted_onto_the_plates_rim_presses_it_or_settles_flat() {
    let world = world();
    // Dropped from a hand's height, tilted, with its centre over the plate's edge and just
    // beyond it, on each side: wherever it comes to rest, it is pressing the plate or lying flat
    // on a face (never propped on the rim, out of the plate's reach).
    let mut outcomes = Vec::new();
    for (dx, dz, tilt) in [
        (0.55f32, 0.0f32, 0.6f32),
        (0.65, 0.0, -0.5),
        (0.0, 0.6, 0.45),
        (-0.7, 0.0, 0.8),
    ] {
        let (mut engine, mut game, cube) = chamber_1(&world);
        frames(&mut engine, &mut game, 5);
        let at = PLATE + Vec3::new(dx, 0.8, dz);
        let rotation = glam::Quat::from_rotation_z(tilt) * glam::Quat::from_rotation_x(tilt * 0.5);
        engine.physics_mut().set_pose(cube, at, rotation);
        frames(&mut engine, &mut game, 240);
        let (rest, rotation) = engine.physics().pose(cube).expect("the cube's pose");
        let flat = [Vec3::X, Vec3::Y, Vec3::Z]
            .iter()
            .any(|&axis| (rotation * axis).y.abs() > 0.99);
        let pressed = door_open(&game);
        outcomes.push(format!(
            "from {dx:+.2}, {dz:+.2} tilted {tilt}: rests at {rest:?}, flat {flat}, pressing {pressed}"
        ));
        assert!(
            flat || pressed,
            "the cube rests tilted off the plate:\n{}",
            outcomes.join("\n")
        );
        let _ = engine.shutdown();
    }
    println!("{}", outcomes.join("\n"));
}
