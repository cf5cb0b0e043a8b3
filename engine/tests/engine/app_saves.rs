//! Progress saves in the user's data folder: a round trip through a fresh load, a new player
//! when there is no save, and a broken save (bad RON, a truncated file, impossible values)
//! reported, kept aside and replaced by a new player's progress.
//!
//! Read-only places: the tests run as root, where `chmod` does not stop a write, so the
//! read-only place is a path whose parent is a regular file (see also `app_full_disk.rs`).

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{Progress, StoreError, UserDirs};

fn some_progress() -> Progress {
    let mut p = Progress::default();
    p.finish_level("intro");
    p.reach_checkpoint("intro", "door");
    p.finish_level("intro"); // finishing drops the level's checkpoint
    p.reach_checkpoint("tower", "lift_top");
    p.add_play_time(125.5);
    p.add_play_time(f64::NAN); // ignored
    p.add_play_time(-3.0); // ignored
    p
}

#[test]
fn progress_survives_a_save_and_a_fresh_load() -> Result<()> {
    let dir = Scratch::new("saves_round_trip");
    let dirs = UserDirs::under(dir.path(), "its_about_time")?;
    let path = dirs.progress_file();
    assert!(path.starts_with(dir.path().join("data/candela/its_about_time")));

    let fresh = Progress::load(&path);
    assert_eq!(fresh.value, Progress::default());
    assert_eq!(fresh.warning, None);

    let p = some_progress();
    assert!(p.is_finished("intro") && !p.is_finished("tower"));
    assert_eq!(p.checkpoint("intro"), None);
    assert_eq!(p.checkpoint("tower"), Some("lift_top"));
    assert_eq!(p.play_seconds, 125.5);
    p.save(&path)?;
    let again = Progress::load(&path);
    assert_eq!(again.warning, None);
    assert_eq!(again.value, p);
    assert_eq!(
        Scratch::entries(path.parent().expect("folder")),
        ["progress.ron"]
    );
    Ok(())
}

#[test]
fn a_broken_save_is_reported_kept_aside_and_replaced() -> Result<()> {
    let dir = Scratch::new("saves_corrupt");
    let path = dir.join("progress.ron");
    some_progress().save(&path)?;
    let good = std::fs::read_to_string(&path)?;
    let truncated = &good[..good.len() / 2];
    let cases: [(&str, &str); 5] = [
        (truncated, "line"),
        ("(play_seconds: -5.0)", "play_seconds is -5"),
        ("(play_seconds: NaN)", "play_seconds is NaN"),
        (r#"(finished: [""])"#, "empty level id"),
        ("(levels_done: 3)", "levels_done"),
    ];
    for (text, problem) in cases {
        std::fs::write(&path, text)?;
        let loaded = Progress::load(&path);
        assert_eq!(loaded.value, Progress::default(), "{text}");
        let w = loaded
            .warning
            .unwrap_or_else(|| panic!("no warning for {text}"));
        assert_eq!(w.path, path);
        assert!(w.problem.contains(problem), "{text}: {}", w.problem);
        assert!(w.to_string().contains("progress.ron"), "{w}");
        let aside = w.kept_aside.expect("kept aside");
        assert_eq!(aside, dir.join("progress.ron.corrupt"));
        assert_eq!(std::fs::read_to_string(&aside)?, text);
        std::fs::remove_file(&aside)?;
    }
    Ok(())
}

#[test]
fn a_save_into_a_read_only_place_fails_clearly_and_keeps_the_old_save() -> Result<()> {
    let dir = Scratch::new("saves_readonly");
    let blocker = dir.join("data");
    std::fs::write(&blocker, "a file where the data folder should be")?;
    let target = blocker.join("progress.ron");
    let e = some_progress()
        .save(&target)
        .expect_err("cannot write below a file");
    assert!(matches!(e, StoreError::Write(_)), "{e:?}");
    assert!(e.to_string().contains(&target.display().to_string()), "{e}");
    assert_eq!(
        std::fs::read_to_string(&blocker)?,
        "a file where the data folder should be"
    );

    // An invalid value is refused before anything is written.
    let path = dir.join("progress.ron");
    let p = some_progress();
    p.save(&path)?;
    let bad = Progress {
        play_seconds: f64::INFINITY,
        ..p.clone()
    };
    assert!(matches!(bad.save(&path), Err(StoreError::Invalid { .. })));
    assert_eq!(Progress::load(&path).value, p);
    Ok(())
}
