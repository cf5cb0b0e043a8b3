//! The committed replays solve Reflect: each chamber's replay, played headless on the CPU
//! tracer at 16×9 (the lasers and the mirror gun query the committed scene), finishes its
//! chamber through its puzzle's rules in order; the whole game's replay finishes every chamber
//! in order and reaches the ending. A replay that no longer solves its chamber fails here,
//! loudly: re-record with `cargo run --release -p reflect --example record_replays`.

use std::path::PathBuf;

use reflect::game::ReflectEvent;
use reflect::headless::{RunSummary, play_replay};
use reflect::world::ReflectWorld;

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

fn replay(id: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../assets/reflect/replays/{id}.replay"))
}

/// Step at which rule `name` first rose.
fn rose(run: &RunSummary, name: &str) -> Option<u64> {
    run.log.iter().find_map(|(step, e)| match e {
        ReflectEvent::Rule {
            name: n,
            rising: true,
        } if n == name => Some(*step),
        _ => None,
    })
}

/// Asserts the rules rose, in this order.
fn in_order(run: &RunSummary, rules: &[&str]) {
    let steps: Vec<Option<u64>> = rules.iter().map(|r| rose(run, r)).collect();
    for (rule, step) in rules.iter().zip(&steps) {
        assert!(step.is_some(), "rule {rule} never rose; log: {:?}", run.log);
    }
    let steps: Vec<u64> = steps.into_iter().flatten().collect();
    assert!(
        steps.windows(2).all(|w| w[0] <= w[1]),
        "rules {rules:?} rose at {steps:?}, out of order"
    );
}

fn play(world: &ReflectWorld, id: &str) -> RunSummary {
    let run = play_replay(world, &replay(id)).unwrap_or_else(|e| panic!("{id}: {e:#}"));
    println!("{}", run.line(world));
    run
}

#[test]
fn chamber_1_the_cube_on_the_plate_opens_the_door() {
    let world = world();
    let run = play(&world, "chamber_1");
    assert!(
        run.solved(false),
        "chamber 1 not finished: {}",
        run.line(&world)
    );
    in_order(&run, &["lights_1", "door_1"]);
    assert_eq!(run.finished, vec![0]);
}

#[test]
fn chamber_2_a_mirror_sends_the_fence_into_the_receiver() {
    let world = world();
    let run = play(&world, "chamber_2");
    assert!(
        run.solved(false),
        "chamber 2 not finished: {}",
        run.line(&world)
    );
    in_order(&run, &["lights_2", "mirror_on", "solve_2"]);
    assert_eq!(run.mirrors, 1);
    // The shutter closed over the emitter: the fence now ends a few centimetres from it.
    let beam = run
        .beams
        .iter()
        .find(|b| b.laser == "emitter_2")
        .expect("the fence");
    assert_eq!(beam.stopped_at.as_deref(), Some("shutter_2"), "{beam:?}");
}

#[test]
fn chamber_3_the_glass_cube_turns_the_beam_into_the_receiver() {
    let world = world();
    let run = play(&world, "chamber_3");
    assert!(
        run.solved(false),
        "chamber 3 not finished: {}",
        run.line(&world)
    );
    in_order(&run, &["turn_3", "solve_3"]);
    let beam = run
        .beams
        .iter()
        .find(|b| b.laser == "emitter_3")
        .expect("the beam");
    // Emitter → into the cube → total internal reflection → out of the cube → the receiver.
    assert!(
        beam.points.len() >= 5,
        "the beam did not pass the cube: {beam:?}"
    );
    assert_eq!(beam.stopped_at.as_deref(), Some("receiver_3"), "{beam:?}");
    let end = beam.points.last().expect("points");
    assert!(
        end.x < -7.0,
        "the beam does not end on the left wall: {beam:?}"
    );
}

#[test]
fn chamber_4_two_mirrors_light_two_receivers_and_the_cube_holds_the_plate() {
    let world = world();
    let run = play(&world, "chamber_4");
    assert!(
        run.solved(false),
        "chamber 4 not finished: {}",
        run.line(&world)
    );
    in_order(&run, &["lights_4", "door_4"]);
    assert_eq!(run.mirrors, 2);
    let beam = run
        .beams
        .iter()
        .find(|b| b.laser == "emitter_4")
        .expect("the beam");
    assert_eq!(beam.stopped_at.as_deref(), Some("receiver_4b"), "{beam:?}");
    assert_eq!(
        beam.points.len(),
        4,
        "emitter, two mirrors, receiver: {beam:?}"
    );
}

#[test]
fn chamber_5_the_elevator_rises_to_the_ending() {
    let world = world();
    let run = play(&world, "chamber_5");
    assert!(run.ending && run.solved(false), "{}", run.line(&world));
    in_order(&run, &["ride_5", "surface"]);
}

#[test]
fn the_whole_game_replay_reaches_the_ending_through_every_chamber_in_order() {
    let world = world();
    let run = play(&world, "full_game");
    assert!(run.solved(true), "{}", run.line(&world));
    assert_eq!(run.finished, vec![0, 1, 2, 3, 4], "{}", run.line(&world));
    in_order(
        &run,
        &[
            "door_1",
            "close_behind_2",
            "solve_2",
            "close_behind_3",
            "turn_3",
            "solve_3",
            "close_behind_4",
            "door_4",
            "close_behind_5",
            "ride_5",
            "surface",
        ],
    );
    assert_eq!(run.mirrors, 3);
    assert_eq!(
        run.sent_back, 0,
        "the bot walks where no beam is: {:?}",
        run.log
    );
    assert!(
        run.seconds > 30.0 && run.seconds < 180.0,
        "{}",
        run.line(&world)
    );
}

#[test]
fn a_replay_plays_the_same_way_twice() {
    let world = world();
    let a = play(&world, "chamber_2");
    let b = play(&world, "chamber_2");
    assert_eq!(a.state_hash, b.state_hash);
    assert_eq!(a.log, b.log);
}
