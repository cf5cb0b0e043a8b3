//! It's About Time in a real window under Xvfb, as a player would start it: the binary opens
//! the title menu, plays the committed replay of the whole slice in the window (CPU tracer),
//! takes its screenshots and quits cleanly (exit 0). The shots must show a picture: the play
//! shot differs from the title's, and neither is one flat colour.

use std::path::Path;
use std::process::Command;

use candela_tests::xvfb::start_xvfb;

/// Mean absolute difference of two RGB images of one size, 0..=255.
fn mean_difference(a: &image::RgbImage, b: &image::RgbImage) -> f64 {
    let total: u64 = a
        .pixels()
        .zip(b.pixels())
        .map(|(p, q)| (0..3).map(|c| p[c].abs_diff(q[c]) as u64).sum::<u64>())
        .sum();
    total as f64 / (3 * a.width() * a.height()) as f64
}

/// Standard deviation of the luma of `img`, 0..=255.
fn spread(img: &image::RgbImage) -> f64 {
    let luma: Vec<f64> = img
        .pixels()
        .map(|p| 0.2126 * p[0] as f64 + 0.7152 * p[1] as f64 + 0.0722 * p[2] as f64)
        .collect();
    let mean = luma.iter().sum::<f64>() / luma.len() as f64;
    (luma.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / luma.len() as f64).sqrt()
}

#[test]
fn the_game_starts_plays_its_replay_in_a_window_and_quits() -> anyhow::Result<()> {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let scratch = std::env::temp_dir().join(format!("iat_window_{}", std::process::id()));
    let runtime = scratch.join("xdg");
    std::fs::create_dir_all(&runtime)?;
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700))?;
    }
    let shots = scratch.join("shots");
    let xvfb = start_xvfb();
    let out = Command::new(env!("CARGO_BIN_EXE_its_about_time"))
        .current_dir(&repo)
        .env("DISPLAY", &xvfb.display)
        .env_remove("WAYLAND_DISPLAY")
        .env("XDG_RUNTIME_DIR", &runtime)
        .env("HOME", &scratch)
        .env("XDG_CONFIG_HOME", scratch.join("config"))
        .env("XDG_DATA_HOME", scratch.join("data"))
        .args(["--replay", "assets/its_about_time/replays/full_game.replay"])
        .arg("--screenshots")
        .arg(&shots)
        .args(["--shots-at", "60"])
        .output()?;
    drop(xvfb);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "exit {:?}: {stderr}", out.status);
    let title = image::open(shots.join("title.png"))?.to_rgb8();
    let play = image::open(shots.join("play_60.png"))?.to_rgb8();
    assert_eq!(title.dimensions(), play.dimensions());
    assert!(
        spread(&play) > 8.0,
        "the play shot is flat: {}",
        spread(&play)
    );
    let moved = mean_difference(&title, &play);
    assert!(moved > 5.0, "play looks like the title: {moved}");
    let _ = std::fs::remove_dir_all(&scratch);
    Ok(())
}
