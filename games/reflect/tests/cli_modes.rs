//! Each headless mode of the built `reflect` binary, run as a player would run it: a chamber's
//! committed replay with `--headless` exits 0 and prints the summary line; a copy cut to its
//! first half (a valid recording that stops before the chamber is solved) exits non-zero and
//! says so; `--bench` (half a second a chamber), `--soak 100`, `--soak-shell 300` and `--capture` (64×36, two frames a
//! chamber) each complete and print what they made (one test each, so they run side by side). Small settings: the modes' plumbing is
//! under test here, not their figures (`replays.rs` checks what the replays do).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use candela::app::{Recording, Run};

type TestResult = Result<(), Box<dyn std::error::Error>>;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn replay(id: &str) -> PathBuf {
    repo().join(format!("assets/reflect/replays/{id}.replay"))
}

/// A scratch folder of this test's own under the target folder, emptied.
fn scratch(name: &str) -> Result<PathBuf, std::io::Error> {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("reflect_cli_modes/{name}"));
    if dir.exists() {
        std::fs::remove_dir_all(&dir)?;
    }
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

/// Runs the built binary from the repository root (where it finds the game file).
fn reflect(args: &[&str]) -> Result<Output, std::io::Error> {
    Command::new(env!("CARGO_BIN_EXE_reflect"))
        .args(args)
        .current_dir(repo())
        .env("RUST_LOG", "error")
        .output()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// `recording` keeping only its first `steps` steps.
fn cut(mut recording: Recording, steps: u64) -> Recording {
    let mut left = steps;
    let mut runs = Vec::new();
    for run in recording.runs {
        if left == 0 {
            break;
        }
        let keep = u64::from(run.steps).min(left);
        left -= keep;
        runs.push(Run {
            steps: keep as u32,
            frame: run.frame,
        });
    }
    recording.runs = runs;
    recording
}

#[test]
fn headless_replay_exits_zero_when_it_solves_and_non_zero_when_it_does_not() -> TestResult {
    let file = replay("chamber_1");
    let out = reflect(&["--replay", &file.display().to_string(), "--headless"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    assert!(
        stdout.starts_with("reflect: chambers finished 1/5 [chamber_1]"),
        "{stdout}"
    );
    assert!(stdout.contains("state hash "), "{stdout}");

    let recording = Recording::read(&file)?;
    let half = recording.steps() / 2;
    assert!(half > 0, "the committed replay has steps");
    let dir = scratch("truncated")?;
    let short = dir.join("chamber_1_half.replay");
    cut(recording, half).write(&short)?;
    assert_eq!(Recording::read(&short)?.steps(), half);
    let out = reflect(&["--replay", &short.display().to_string(), "--headless"])?;
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "a half replay must fail: {out:?}");
    assert!(
        stderr.contains("did not solve what it was recorded for"),
        "{stderr}"
    );
    assert!(stderr.contains("chambers finished 0/5"), "{stderr}");
    Ok(())
}

#[test]
fn bench_completes_with_a_row_per_chamber() -> TestResult {
    let out = reflect(&["--bench", "--bench-seconds", "0.5", "--denoise", "false"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    assert!(stdout.starts_with("| chamber | frames |"), "{stdout}");
    for k in 1..=5 {
        assert!(stdout.contains(&format!("| chamber_{k} |")), "{stdout}");
    }
    Ok(())
}

#[test]
fn soak_of_a_hundred_frames_completes_in_every_chamber() -> TestResult {
    let out = reflect(&["--soak", "100", "--seed", "3"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    for k in 1..=5 {
        assert!(
            stdout.contains(&format!("| chamber_{k} | 100 | 3 |")),
            "{stdout}"
        );
    }
    Ok(())
}

/// The dearest of the three (30 settling frames a chamber on the CPU tracer, fixed by the
/// mode): at 64×36 with two converging frames (640×360 took over five minutes here).
#[test]
fn capture_writes_a_png_per_chamber() -> TestResult {
    let dir = scratch("capture")?;
    let out = reflect(&[
        "--capture",
        &dir.display().to_string(),
        "--capture-frames",
        "2",
        "--capture-width",
        "64",
        "--capture-height",
        "36",
    ])?;
    assert!(out.status.success(), "{out:?}");
    for k in 1..=5 {
        let png = dir.join(format!("chamber_{k}.png"));
        let bytes = std::fs::read(&png)?;
        assert!(
            bytes.starts_with(b"\x89PNG"),
            "{} is not a PNG",
            png.display()
        );
    }
    Ok(())
}

#[test]
fn soak_inside_the_shell_completes_and_prints_its_tables() -> TestResult {
    let out = reflect(&["--soak-shell", "300", "--seed", "3"])?;
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{out:?}");
    assert!(stdout.contains("| 300 | 3 |"), "{stdout}");
    assert!(stdout.contains("Frames checked per screen:"), "{stdout}");
    Ok(())
}
