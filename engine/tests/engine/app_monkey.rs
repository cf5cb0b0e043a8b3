//! The soak monkey: the same seed gives the same input, every game button and axis of the
//! standard set is exercised within a minute of steps, and the runner's buttons (pause, editor)
//! stay untouched unless asked for.

use candela::app::{ActionKind, ActionSet, Monkey, game_actions};

const STEPS: usize = 3600;

fn run(seed: u64, runner: bool) -> Vec<candela::app::ActionFrame> {
    let set = ActionSet::standard();
    let mut monkey = Monkey::new(seed);
    monkey.runner_buttons = runner;
    (0..STEPS).map(|_| monkey.frame(&set)).collect()
}

#[test]
fn same_seed_same_input_other_seed_other_input() {
    assert_eq!(run(7, false), run(7, false));
    assert_ne!(run(7, false), run(8, false));
}

#[test]
fn every_game_action_is_exercised_and_runner_buttons_only_when_asked() {
    let set = ActionSet::standard();
    let frames = run(11, false);
    let runner = [game_actions::PAUSE, game_actions::EDITOR_TOGGLE];
    for (i, def) in set.defs().iter().enumerate() {
        let bit = 1_u64 << i;
        let held = frames.iter().filter(|f| f.held & bit != 0).count();
        let pressed = frames.iter().filter(|f| f.pressed & bit != 0).count();
        let moved = frames.iter().filter(|f| f.values[i] != 0).count();
        match def.kind {
            ActionKind::Button if runner.contains(&def.name.as_str()) => {
                assert_eq!(
                    held + pressed,
                    0,
                    "{} pressed without runner_buttons",
                    def.name
                );
            }
            ActionKind::Button => {
                assert!(
                    pressed >= 3,
                    "{} pressed {pressed} times in {STEPS} steps",
                    def.name
                );
                assert!(held > pressed, "{} never held beyond a tap", def.name);
                assert!(
                    held < STEPS / 2,
                    "{} held {held} of {STEPS} steps",
                    def.name
                );
            }
            ActionKind::Axis | ActionKind::Motion => {
                assert!(
                    moved > STEPS / 4,
                    "{} non-zero in only {moved} steps",
                    def.name
                );
            }
        }
        // A press is always part of a hold.
        assert!(frames.iter().all(|f| f.pressed & !f.held == 0));
    }
    let with_runner = run(11, true);
    let pause = set.id(game_actions::PAUSE).expect("standard action");
    let steps = 200_000 / STEPS;
    let presses: usize = (0..steps as u64)
        .map(|s| {
            let mut m = Monkey::new(s);
            m.runner_buttons = true;
            (0..STEPS).filter(|_| m.frame(&set).pressed(pause)).count()
        })
        .sum();
    assert!(
        presses > 0,
        "runner_buttons never pressed pause in 200k steps"
    );
    assert_ne!(with_runner, frames, "runner buttons change the sequence");
}
