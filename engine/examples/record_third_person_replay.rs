//! Writes `assets/test_scenes/platform/third_person.replay`: a scripted bot's input for the
//! third-person courtyard (`third_person.ron`), one `ActionFrame` per 60 Hz step, recorded
//! through `Recorder` — stand still while looking left and back, walk forward through the
//! doorway, run, stop and stand. Open loop and deterministic: the same program writes the same
//! bytes. `engine/tests/engine/player_third_person.rs` plays the file and checks where it ends.
//!
//! Run it again after changing the level (the recording carries the level file's hash):
//! `cargo run --release -p candela --example record_third_person_replay`.

use std::path::Path;

use candela::app::{ActionFrame, ActionSet, Recorder, game_actions, level_hash};

/// The game name and level id the test opens the replay with.
const GAME: &str = "candela-third-person";
const LEVEL_ID: &str = "platform/third_person";

/// What the bot does over a range of steps.
struct Leg {
    steps: u32,
    forward: bool,
    run: bool,
    /// Mouse counts of look to the right per step.
    look_x: i32,
}

fn main() -> anyhow::Result<()> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let folder = repo.join("assets/test_scenes/platform");
    let level = folder.join("third_person.ron");
    let set = ActionSet::standard();
    let id = |name: &str| {
        set.id(name)
            .ok_or_else(|| anyhow::anyhow!("no action {name}"))
    };
    let (forward, run, look_x) = (
        id(game_actions::MOVE_FORWARD)?,
        id(game_actions::RUN)?,
        id(game_actions::LOOK_X)?,
    );
    let legs = [
        // Look 0.15 rad left, then back (2.5 mrad per count in the test's game).
        Leg {
            steps: 15,
            forward: false,
            run: false,
            look_x: -4,
        },
        Leg {
            steps: 15,
            forward: false,
            run: false,
            look_x: 4,
        },
        // Walk 5.5 s at 2 m/s: from z = 6 through the doorway (z = 0) to z ≈ −5.
        Leg {
            steps: 330,
            forward: true,
            run: false,
            look_x: 0,
        },
        // Run 1 s at 5 m/s.
        Leg {
            steps: 60,
            forward: true,
            run: true,
            look_x: 0,
        },
        // Stand 2 s: the camera eases back out.
        Leg {
            steps: 120,
            forward: false,
            run: false,
            look_x: 0,
        },
    ];
    let mut recorder = Recorder::new(GAME, LEVEL_ID, level_hash(&level)?, 60.0, &set);
    let mut held_before = 0u64;
    for leg in &legs {
        for _ in 0..leg.steps {
            let mut frame = ActionFrame::empty(&set);
            if leg.forward {
                frame.held |= 1 << forward.0;
            }
            if leg.run {
                frame.held |= 1 << run.0;
            }
            frame.pressed = frame.held & !held_before;
            held_before = frame.held;
            frame.values[look_x.0 as usize] = leg.look_x * candela::app::MOTION_PER_COUNT;
            recorder.push(frame)?;
        }
    }
    let out = folder.join("third_person.replay");
    recorder.write(&out)?;
    println!("{}: {} steps", out.display(), recorder.steps());
    Ok(())
}
