//! Atomic writes that fail half-way leave the previous file exactly as it was and no
//! temporary file behind, with an error naming the file and the stage that failed: the bare
//! `write_atomic`, and the player's settings and progress saves through their own API.
//!
//! A full disk is simulated with the file size limit (`RLIMIT_FSIZE`, with `SIGXFSZ` ignored
//! so the write returns `EFBIG` instead of killing the process): it works as root, where
//! `chmod` would not. The limit is per process: the test runs alone in its process under any
//! runner (nextest's process per test, or a child under `cargo test`: `tests/support/alone.rs`),
//! and restores the limit before it asserts.
//! Also: the longest file name the file system takes still leaves room for the temporary one.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{ActionSet, Progress, Settings, StoreError, write_atomic};

/// Runs `f` with files limited to `bytes` bytes (a disk that fills up after `bytes`).
fn with_file_size_limit<T>(bytes: u64, f: impl FnOnce() -> T) -> T {
    // SAFETY: setting a signal disposition and this process's own resource limit; the test
    // runs alone in its process (`alone_in_process`).
    let old_limit = unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        let mut lim = std::mem::zeroed::<libc::rlimit>();
        assert_eq!(libc::getrlimit(libc::RLIMIT_FSIZE, &mut lim), 0);
        let small = libc::rlimit {
            rlim_cur: bytes as libc::rlim_t,
            rlim_max: lim.rlim_max,
        };
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &small), 0);
        lim
    };
    let result = f();
    // SAFETY: restoring the limit read above.
    unsafe {
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &old_limit), 0);
    }
    result
}

/// Checks a save refused by the full disk: a write error at stage "write" (EFBIG) naming
/// `path`.
fn assert_full_disk(result: Result<(), StoreError>, path: &std::path::Path) {
    match result {
        Err(StoreError::Write(e)) => {
            assert_eq!(e.path, path);
            assert_eq!(e.stage, "write");
            assert_eq!(e.source.raw_os_error(), Some(libc::EFBIG));
            let text = StoreError::Write(e).to_string();
            assert!(text.contains(&path.display().to_string()), "{text}");
        }
        other => panic!("{}: expected a failed write, got {other:?}", path.display()),
    }
}

#[test]
fn a_failed_write_keeps_the_old_file_and_leaves_no_temporary() -> Result<()> {
    // Changes process-wide state: alone in its process under any test runner.
    if !crate::app_common::alone::alone_in_process(
        "app_full_disk::a_failed_write_keeps_the_old_file_and_leaves_no_temporary",
    ) {
        return Ok(());
    }
    let dir = Scratch::new("full_disk");
    let path = dir.join("progress.ron");
    write_atomic(&path, b"the old save")?;

    let result = with_file_size_limit(4096, || write_atomic(&path, &vec![b'x'; 256 * 1024]));
    let e = result.expect_err("the 'disk' is full");
    assert_eq!(e.path, path);
    assert_eq!(e.stage, "write");
    assert_eq!(e.source.raw_os_error(), Some(libc::EFBIG));
    assert!(e.to_string().contains("progress.ron"), "{e}");
    assert_eq!(std::fs::read(&path)?, b"the old save");
    assert_eq!(Scratch::entries(dir.path()), ["progress.ron"]);

    // The longest name the file system takes: the temporary name must still fit beside it.
    let long = dir.join(&"s".repeat(255));
    write_atomic(&long, b"old")?;
    write_atomic(&long, b"new")?;
    assert_eq!(std::fs::read(&long)?, b"new");

    // And a write that can succeed does, replacing the content whole.
    write_atomic(&path, b"the new save")?;
    assert_eq!(std::fs::read(&path)?, b"the new save");
    assert_eq!(Scratch::entries(dir.path()).len(), 2);

    // The player's files through their own API: the old settings and save stay as they were.
    let set = ActionSet::standard();
    let settings_path = dir.join("settings.ron");
    let old_settings = Settings {
        invert_y: true,
        ..Settings::default()
    };
    old_settings.save(&settings_path, &set)?;
    let old_settings_bytes = std::fs::read(&settings_path)?;
    let progress_path = dir.join("progress.ron");
    let mut old_progress = Progress::default();
    old_progress.finish_level("intro");
    old_progress.save(&progress_path)?;
    let old_progress_bytes = std::fs::read(&progress_path)?;
    let before = Scratch::entries(dir.path());

    let mut new_progress = old_progress.clone();
    new_progress.finish_level("tower");
    new_progress.add_play_time(60.0);
    let new_settings = Settings {
        invert_y: false,
        ..Settings::default()
    };
    let (settings_result, progress_result) = with_file_size_limit(16, || {
        (
            new_settings.save(&settings_path, &set),
            new_progress.save(&progress_path),
        )
    });
    assert_full_disk(settings_result, &settings_path);
    assert_full_disk(progress_result, &progress_path);
    assert_eq!(std::fs::read(&settings_path)?, old_settings_bytes);
    assert_eq!(std::fs::read(&progress_path)?, old_progress_bytes);
    assert_eq!(
        Scratch::entries(dir.path()),
        before,
        "a temporary file was left behind"
    );
    assert_eq!(Settings::load(&settings_path, &set).value, old_settings);
    assert_eq!(Progress::load(&progress_path).value, old_progress);
    Ok(())
}
