//! The first-person platform level solved by its committed replay (issue 10, §3 and "Show"):
//! `assets/test_scenes/platform/first_person.replay` played headless on the CPU tracer through
//! the engine's own frame loop carries the glass cube onto the plate, rides the lift up and
//! pulls the lever, which wins the level; a second run goes through the identical state hash
//! at every step, and a run of eight steps per frame through the same states. If the level or
//! the player changes so that the replay no longer solves it, these assertions fail
//! (re-record: `docs/LEVELS.md`).

use std::path::PathBuf;

use candela::app::{Engine, FirstPersonGame, Game, Happened, StepInput};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::render::RenderConfig;
use candela::sim::triggers::Outcome;
use glam::Vec3;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

/// What one replayed run ended with.
struct Run {
    hashes: Vec<u64>,
    log: Vec<(u64, Happened)>,
    cube: Vec3,
    lift: Vec3,
    feet: Vec3,
    on_plate: bool,
    outcome: Option<Outcome>,
    finished: bool,
}

/// Plays the committed replay, `per_frame` fixed steps per rendered frame, hashing the state
/// after every frame.
fn play(per_frame: u64) -> anyhow::Result<Run> {
    let level = assets().join("test_scenes/platform/first_person.ron");
    let replay = assets().join("test_scenes/platform/first_person.replay");
    let root = AssetRoot::new(assets())?;
    let mut game = FirstPersonGame::load(&level, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let replay = game.open_replay(&replay)?;
    let steps = replay.steps();
    engine.set_step_input(StepInput::Replay(replay));
    let mut hashes = Vec::new();
    // One step past the end finds the replay finished.
    let mut done = 0;
    while done < steps + 1 {
        let n = per_frame.min(steps + 1 - done);
        engine.frame(n as f64 / 60.0, &mut game)?;
        let _ = engine.rendered();
        hashes.push(engine.state_hash());
        done += n;
    }
    let finished = engine.replay_finished();
    let by_name = &game.spawned().by_name;
    let pos = |name: &str| -> anyhow::Result<Vec3> {
        let e = by_name
            .get(name)
            .ok_or_else(|| anyhow::anyhow!("no {name}"))?;
        Ok(engine.world().get::<&Transform>(*e)?.translation)
    };
    let cube_entity = by_name["glass_cube"];
    let plate = engine.logic().volume_index("plate").expect("plate volume");
    let on_plate = engine
        .logic()
        .volumes()
        .occupants(plate)
        .any(|(e, _)| e == cube_entity);
    let player = game.player().expect("player");
    let run = Run {
        hashes,
        log: game.log().to_vec(),
        cube: pos("glass_cube")?,
        lift: pos("lift")?,
        feet: player.feet(engine.world()),
        on_plate,
        outcome: engine.logic().outcome().cloned(),
        finished,
    };
    let _ = engine.shutdown();
    Ok(run)
}

#[test]
fn the_committed_replay_solves_the_level_and_repeats_exactly() -> anyhow::Result<()> {
    let run = play(1)?;
    for (step, h) in &run.log {
        println!("step {step}: {h:?}");
    }
    println!(
        "cube {} lift {} feet {} over {} steps",
        run.cube,
        run.lift,
        run.feet,
        run.hashes.len()
    );
    assert!(run.finished, "the replay did not finish");
    // The cube rests on the plate (1 m square, top at 0.04; the cube is 0.4 m).
    let plate = Vec3::new(2.0, 0.04, 1.0);
    assert!(
        run.on_plate && (run.cube - plate).with_y(0.0).length() < 0.5 && run.cube.y < 0.3,
        "the cube ended at {} (on the plate's volume: {})",
        run.cube,
        run.on_plate
    );
    // The lift rose its 3 m (its centre from 0.1 to 3.1).
    assert!(
        (run.lift.y - 3.1).abs() < 1e-3,
        "the lift ended at {}",
        run.lift
    );
    // The player stands on the upper floor (top at 3.2) within reach of the lever.
    let lever = Vec3::new(0.0, 4.6, -7.85);
    assert!(
        (run.feet.y - 3.2).abs() < 0.05,
        "the player's feet ended at {}",
        run.feet
    );
    assert!(
        (run.feet - lever).with_y(0.0).length() < 2.0,
        "the player ended {} m from the lever",
        (run.feet - lever).with_y(0.0).length()
    );
    let happened = |h: &Happened| run.log.iter().any(|(_, x)| x == h);
    let rose = |name: &str| Happened::Rule {
        name: name.into(),
        rising: true,
    };
    assert!(happened(&rose("lift_up")), "the lift rule never fired");
    assert!(
        happened(&Happened::Used("lever".into())),
        "the lever was never used"
    );
    assert!(
        happened(&rose("lever_pulled")),
        "the lever rule never fired"
    );
    assert_eq!(
        run.outcome,
        Some(Outcome::Won("lever_pulled".into())),
        "the level was not won"
    );

    let again = play(1)?;
    assert_eq!(again.hashes.len(), run.hashes.len());
    for (step, (a, b)) in run.hashes.iter().zip(&again.hashes).enumerate() {
        assert_eq!(a, b, "the second run's state differs at step {step}");
    }
    assert!(
        run.hashes.windows(2).filter(|w| w[0] != w[1]).count() > run.hashes.len() / 2,
        "the state hash hardly changes: it does not see the run"
    );
    // Eight steps per frame (a faster replay, fewer renders) ends in the same state, and
    // passes through the same states every eighth step.
    let fast = play(8)?;
    assert_eq!(fast.outcome, run.outcome);
    for (frame, h) in fast.hashes.iter().enumerate().take(fast.hashes.len() - 1) {
        assert_eq!(
            *h,
            run.hashes[frame * 8 + 7],
            "eight steps per frame: the state differs after step {}",
            frame * 8 + 7
        );
    }
    assert_eq!(
        fast.hashes.last(),
        run.hashes.last(),
        "the final state differs"
    );
    Ok(())
}
