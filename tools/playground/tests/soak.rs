//! A short soak of the first-person test level in CI (the 100,000-frame soak is the same
//! command with a larger count, `playground LEVEL --soak 100000`): 3,000 frames of random input
//! with no NaN in any transform or in the film, nothing falling out of the world, and resident
//! memory after the warm-up not growing by more than a bound that a leak of one small
//! allocation per frame would already break (64 MiB over 2,700 frames is 24 KiB a frame).

use std::path::Path;

use candela::app::FirstPersonGame;
use candela::assets::AssetRoot;

#[test]
fn three_thousand_random_frames_leave_everything_finite_and_in_the_world() -> anyhow::Result<()> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/test_scenes/platform");
    let level = folder.join("first_person.ron");
    let mut game = FirstPersonGame::load(&level, &AssetRoot::new(&folder)?)?;
    let environment = game.environment();
    let report = candela::app::soak::soak(&mut game, environment, 3000, 7)?;
    assert_eq!(report.frames, 3000);
    assert_eq!(report.film_checks, 6, "a film check every 500 frames");
    assert!(report.rss_warm > 0, "resident memory was not read");
    let growth = report.rss_end.saturating_sub(report.rss_warm);
    assert!(
        growth < 64 << 20,
        "resident memory grew by {} MiB after the warm-up",
        growth >> 20
    );
    Ok(())
}
