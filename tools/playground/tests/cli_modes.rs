//! Each headless mode of the built `playground` binary on the first-person platform level, run
//! as a player or CI would run it (every mode is the engine harness's): the committed replay
//! with `--headless` exits 0 and prints the summary line, the level won; the same replay held
//! to fewer steps than it has exits non-zero and says it did not finish; `--bench` prints the
//! same run with its speed; `--soak 100` completes. The modes' plumbing and their lines are under
//! test here; `engine/tests/engine/player_first_person.rs` checks what the replay does.

use std::path::PathBuf;
use std::process::{Command, Output};

type TestResult = Result<(), Box<dyn std::error::Error>>;

fn platform() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/test_scenes/platform")
}

/// Runs the built binary in the level's folder (its asset root) with `args` after the level.
fn playground(args: &[&str]) -> Result<Output, std::io::Error> {
    Command::new(env!("CARGO_BIN_EXE_playground"))
        .arg("first_person.ron")
        .args(args)
        .current_dir(platform())
        .env("RUST_LOG", "error")
        .output()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The hexadecimal state hash a summary line names.
fn state_hash(line: &str) -> Option<&str> {
    let rest = line.split("state hash ").nth(1)?;
    rest.get(..16)
}

#[test]
fn headless_replay_exits_zero_when_it_finishes_and_non_zero_when_held_short() -> TestResult {
    let out = playground(&["--replay", "first_person.replay", "--headless"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    // The recording's steps and one more, the step that finds it finished.
    let steps = playground_replay_steps()? + 1;
    assert!(
        stdout.starts_with(&format!(
            "first_person.ron: {steps} steps, outcome Some(Won(\"lever_pulled\")), state hash "
        )),
        "{stdout}"
    );
    assert!(
        stdout.trim_end().ends_with(&format!(
            ", replay first_person.replay ({} steps)",
            steps - 1
        )),
        "{stdout}"
    );
    let hash = state_hash(&stdout).ok_or("no state hash")?;
    assert!(u64::from_str_radix(hash, 16).is_ok(), "{stdout}");

    let out = playground(&[
        "--replay",
        "first_person.replay",
        "--headless",
        "--steps",
        "100",
    ])?;
    let stderr = text(&out.stderr);
    assert!(
        !out.status.success(),
        "a replay held short must fail: {out:?}"
    );
    assert!(
        stderr.contains("100 steps, outcome None")
            && stderr.contains("the replay did not finish in 100 steps"),
        "{stderr}"
    );
    Ok(())
}

/// The committed recording's length in fixed steps.
fn playground_replay_steps() -> Result<u64, Box<dyn std::error::Error>> {
    Ok(candela::app::Recording::read(&platform().join("first_person.replay"))?.steps())
}

#[test]
fn bench_reports_the_same_run_and_its_speed() -> TestResult {
    let plain = playground(&["--replay", "first_person.replay", "--headless"])?;
    let bench = playground(&["--replay", "first_person.replay", "--bench"])?;
    let (plain, line) = (text(&plain.stdout), text(&bench.stdout));
    assert!(bench.status.success(), "{bench:?}");
    assert!(
        line.starts_with(plain.trim_end()),
        "eight steps a frame reach the same state:\n{plain}{line}"
    );
    assert!(
        line.contains(" steps/s = ") && line.contains("(8 steps per 16×9 CPU frame)"),
        "{line}"
    );
    Ok(())
}

#[test]
fn soak_of_a_hundred_frames_completes() -> TestResult {
    let out = playground(&["--soak", "100", "--seed", "3"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    assert!(
        stdout.starts_with("first_person.ron: soak of 100 frames (seed 3): no NaN"),
        "{stdout}"
    );
    Ok(())
}
