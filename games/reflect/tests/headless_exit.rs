//! `reflect --replay FILE --headless` through the binary, as CI and a player's script call it
//! (issue 32, weak test 9): a replay that solves its chamber exits 0 and prints its summary
//! line; one cut short of solving, a corrupt file and a missing `--replay` each exit non-zero
//! with a message naming the problem (and the file).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use candela::app::Recording;

fn replays() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/reflect/replays")
}

/// Runs the game binary with `args`, its user folders in `home` (nothing is written beside the
/// player's own).
fn reflect(home: &Path, args: &[&str]) -> std::io::Result<Output> {
    Command::new(env!("CARGO_BIN_EXE_reflect"))
        .args(args)
        .env("HOME", home)
        .env("XDG_CONFIG_HOME", home.join("config"))
        .env("XDG_DATA_HOME", home.join("data"))
        .output()
}

#[test]
fn the_headless_replays_exit_code_says_whether_it_solved() -> anyhow::Result<()> {
    let home = std::env::temp_dir().join(format!("reflect_headless_exit_{}", std::process::id()));
    std::fs::create_dir_all(&home)?;
    let good = replays().join("chamber_1.replay");
    let good_arg = good.to_string_lossy().into_owned();

    let solved = reflect(&home, &["--replay", &good_arg, "--headless"])?;
    let stdout = String::from_utf8_lossy(&solved.stdout);
    assert!(
        solved.status.success(),
        "{:?}\n{stdout}\n{}",
        solved.status,
        String::from_utf8_lossy(&solved.stderr)
    );
    assert!(
        stdout.contains("chambers finished 1/") && stdout.contains("state hash"),
        "{stdout}"
    );

    // The same recording cut to its first fifth of steps: the chamber is not solved.
    let mut short = Recording::read(&good)?;
    let total: u32 = short.runs.iter().map(|r| r.steps).sum();
    let mut keep = total / 5;
    short.runs.retain_mut(|run| {
        let take = run.steps.min(keep);
        keep -= take;
        run.steps = take;
        take > 0
    });
    let cut = home.join("cut.replay");
    short.write(&cut)?;
    let cut_arg = cut.to_string_lossy().into_owned();
    let unsolved = reflect(&home, &["--replay", &cut_arg, "--headless"])?;
    let stderr = String::from_utf8_lossy(&unsolved.stderr);
    assert!(!unsolved.status.success(), "a cut replay passed: {stderr}");
    assert!(
        stderr.contains("did not solve") || stderr.contains("did not finish"),
        "{stderr}"
    );

    let corrupt = home.join("corrupt.replay");
    std::fs::write(&corrupt, b"not a recording at all")?;
    let corrupt_arg = corrupt.to_string_lossy().into_owned();
    let broken = reflect(&home, &["--replay", &corrupt_arg, "--headless"])?;
    let stderr = String::from_utf8_lossy(&broken.stderr);
    assert!(!broken.status.success(), "a corrupt replay passed");
    assert!(stderr.contains("corrupt.replay"), "{stderr}");

    let missing = reflect(&home, &["--headless"])?;
    let stderr = String::from_utf8_lossy(&missing.stderr);
    assert!(!missing.status.success());
    assert!(stderr.contains("--replay"), "{stderr}");
    let _ = std::fs::remove_dir_all(&home);
    Ok(())
}
