//! Live play is as deterministic as a replay at any frame rate: the same recorded input played
//! through the engine's frame loop in frames of 1/60 s (one fixed step a frame) and of 1/10 s
//! (six fixed steps a frame) finishes the same chambers, logs the same events at the same
//! steps, makes the same mirrors, leaves the same laser beams and the same engine state hash
//! after the same steps. What is under the crosshair, the mirror gun's aim and the lasers come
//! from ray queries on the engine's query scene, so this fails whenever a step's queries see
//! a scene that depends on how many steps a frame runs.

use std::path::PathBuf;

use reflect::headless::{RunSummary, play_replay_at};
use reflect::world::ReflectWorld;

/// Fixed steps a 1/10 s frame runs at the default 60 Hz step.
const STEPS_PER_SLOW_FRAME: u64 = 6;

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

fn replay(id: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../assets/reflect/replays/{id}.replay"))
}

/// Plays replay `id` at 60 and at 10 frames per second, both to the same step count (the
/// first multiple of six at or after the replay's end), and asserts the runs agree.
fn same_at_10_and_60_fps(id: &str) -> RunSummary {
    let world = world();
    let path = replay(id);
    let probe = play_replay_at(&world, &path, 1.0 / 60.0, 0).expect("the replay plays");
    let steps = probe.steps.div_ceil(STEPS_PER_SLOW_FRAME) * STEPS_PER_SLOW_FRAME;
    let fast = play_replay_at(&world, &path, 1.0 / 60.0, steps).expect("60 fps");
    let slow = play_replay_at(&world, &path, 1.0 / 10.0, steps).expect("10 fps");
    println!("60 fps: {}", fast.line(&world));
    println!("10 fps: {}", slow.line(&world));
    assert_eq!(fast.steps, steps);
    assert_eq!(slow.steps, steps);
    assert_eq!(fast.finished, slow.finished, "chambers finished differ");
    assert_eq!(fast.ending, slow.ending, "the ending differs");
    assert_eq!(fast.mirrors, slow.mirrors, "mirrors made differ");
    assert_eq!(fast.sent_back, slow.sent_back, "times sent back differ");
    let first_apart = fast
        .log
        .iter()
        .zip(&slow.log)
        .position(|(a, b)| a != b)
        .unwrap_or(fast.log.len().min(slow.log.len()));
    assert!(
        fast.log == slow.log,
        "the event logs part at entry {first_apart}: 60 fps {:?}, 10 fps {:?}",
        fast.log.get(first_apart),
        slow.log.get(first_apart)
    );
    assert_eq!(fast.beams, slow.beams, "the laser beams differ");
    assert_eq!(
        fast.state_hash, slow.state_hash,
        "the engine's state hash after step {steps} differs"
    );
    fast
}

#[test]
fn chamber_2_plays_the_same_at_10_and_at_60_fps() {
    let run = same_at_10_and_60_fps("chamber_2");
    assert!(run.solved(false), "the replay no longer solves chamber 2");
}

#[test]
fn the_whole_game_plays_the_same_at_10_and_at_60_fps() {
    let run = same_at_10_and_60_fps("full_game");
    assert!(run.solved(true), "the replay no longer reaches the ending");
    assert_eq!(run.finished, vec![0, 1, 2, 3, 4]);
}
