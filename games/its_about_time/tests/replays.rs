//! The committed replay plays the whole game headless (CPU tracer) and must still solve it:
//! the Sun Disc taken, the sun gate opened only once time was turned to the afternoon (the
//! glyph lit through its slot), the ending reached. A recording cut short does not reach the
//! ending, and the binary says so with a non-zero exit.

use std::path::{Path, PathBuf};

use its_about_time::game::TimeEvent;
use its_about_time::headless::play_replay;
use its_about_time::replays::full_game;
use its_about_time::world::RuinsWorld;

fn world() -> anyhow::Result<RuinsWorld> {
    RuinsWorld::open(Some(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/its_about_time/ruins.ron"),
    ))
}

fn replay(world: &RuinsWorld) -> PathBuf {
    full_game(world.root.path())
}

#[test]
fn the_full_game_replay_takes_the_sun_disc_and_reaches_the_ending() -> anyhow::Result<()> {
    let world = world()?;
    let run = play_replay(&world, &replay(&world))?;
    let line = run.line();
    assert!(run.solved(), "{line}");
    assert_eq!(run.artifacts, ["artifact_sun"], "{line}");
    // The gate rose only after the altar turned time forward, and it rose before the disc was
    // taken (the disc lies behind it).
    let first_turn = run
        .log
        .iter()
        .find(|(_, e)| matches!(e, TimeEvent::Turned(s) if *s > 0.0));
    let gate = run
        .log
        .iter()
        .find(|(_, e)| matches!(e, TimeEvent::Rule { name, rising: true } if name == "sun_gate"));
    let taken = run
        .log
        .iter()
        .find(|(_, e)| matches!(e, TimeEvent::Artifact(_)));
    let (Some(turn), Some(gate), Some(taken)) = (first_turn, gate, taken) else {
        panic!("turn {first_turn:?}, gate {gate:?}, taken {taken:?}: {line}");
    };
    assert!(
        turn.0 < gate.0 && gate.0 < taken.0,
        "{turn:?} {gate:?} {taken:?}"
    );
    // Time was turned from the morning (08:50 local) into the afternoon, where the slot lets
    // the sun onto the glyph (about 15:15 local solar time).
    let hours = run
        .local_hours
        .ok_or_else(|| anyhow::anyhow!("no time of day"))?;
    assert!(
        (14.0..16.5).contains(&hours),
        "ended at {hours} h local: {line}"
    );
    Ok(())
}

#[test]
fn a_replay_cut_short_does_not_reach_the_ending() -> anyhow::Result<()> {
    let world = world()?;
    let mut cut = candela::app::Recording::read(&replay(&world))?;
    let total: u32 = cut.runs.iter().map(|r| r.steps).sum();
    let mut keep = total / 3;
    cut.runs.retain_mut(|run| {
        let take = run.steps.min(keep);
        keep -= take;
        run.steps = take;
        take > 0
    });
    let path = std::env::temp_dir().join(format!("iat_cut_{}.replay", std::process::id()));
    cut.write(&path)?;
    let run = play_replay(&world, &path)?;
    let _ = std::fs::remove_file(&path);
    assert!(!run.solved() && !run.ending, "{}", run.line());
    assert!(run.artifacts.is_empty(), "{}", run.line());
    // And the binary exits non-zero naming the file.
    cut.write(&path)?;
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_its_about_time"))
        .args(["--headless", "--replay"])
        .arg(&path)
        .output()?;
    let _ = std::fs::remove_file(&path);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{err}");
    assert!(err.contains("did not reach the ending"), "{err}");
    Ok(())
}
