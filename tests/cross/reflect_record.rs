//! `reflect --record FILE` in a real window under Xvfb: the shell starts the chamber to record
//! at once, the run's fixed steps are recorded with no one at the controls, and the Quit cue
//! closes the window, which writes the file. One window run per process (winit allows one
//! event loop), so the test runs alone in its process under any runner
//! (`candela_tests::alone`).
//!
//! Checked: the file exists and is a Reflect recording of the chamber asked for, against the
//! world as it is now (it opens as a replay of that chamber); it holds the steps of the run;
//! and played back headless it is accepted and
//! judged — an idle player solves nothing, so the CLI refuses it as "did not solve", not as a
//! recording of another world.

use candela::app::Recording;
use candela_tests::repo;
use candela_tests::xvfb::{set_environment, start_xvfb};
use clap::Parser;
use reflect::cli::{Args, locate, run};
use reflect::replays::open_replay;
use reflect::world::ReflectWorld;

#[test]
fn a_windowed_run_with_record_writes_a_replay_of_its_chamber() {
    // Changes process-wide state: alone in its process under any test runner.
    if !candela_tests::alone::alone_in_process(
        "reflect_record::a_windowed_run_with_record_writes_a_replay_of_its_chamber",
    ) {
        return;
    }
    let scratch = repo().join("target/reflect_record");
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).expect("scratch");
    let xvfb = start_xvfb();
    set_environment(&xvfb.display, &scratch);
    // SAFETY: alone in its process (above); no other thread reads the environment.
    unsafe {
        std::env::set_var("XDG_CONFIG_HOME", scratch.join("config"));
        std::env::set_var("XDG_DATA_HOME", scratch.join("data"));
    }
    let game = repo().join("assets/reflect/reflect.ron");
    let file = scratch.join("run.replay");
    let arg = |p: &std::path::Path| p.to_string_lossy().into_owned();
    let args = Args::parse_from([
        "reflect".to_string(),
        "--game".into(),
        arg(&game),
        "--record".into(),
        arg(&file),
        "--record-chamber".into(),
        "chamber_2".into(),
        "--screenshots".into(),
        arg(&scratch),
    ]);
    let line = run(&args).expect("Reflect runs in the Xvfb window and records");
    eprintln!("{line}");

    let recording = Recording::read(&file).expect("the recording was written");
    assert_eq!(recording.header.game, "reflect");
    assert_eq!(recording.header.level_id, "chamber_2");
    let steps: u64 = recording.runs.iter().map(|r| u64::from(r.steps)).sum();
    eprintln!("{steps} steps in {} runs", recording.runs.len());
    assert!(steps > 0, "the run's steps are recorded");
    let (path, root) = locate(Some(&game)).expect("game file");
    let world = ReflectWorld::load(&path, &root).expect("the world loads");
    let (_, start) = open_replay(&world, &file).expect("a replay of this world");
    assert_eq!(world.chambers[start].id, "chamber_2");

    let headless = Args::parse_from([
        "reflect".to_string(),
        "--game".into(),
        arg(&game),
        "--replay".into(),
        arg(&file),
        "--headless".into(),
    ]);
    let refused = run(&headless)
        .expect_err("an idle run solves nothing")
        .to_string();
    assert!(refused.contains("did not solve"), "{refused}");
}
