//! Saving a level onto a full disk (issue 12, faults): the save reports the file and the
//! stage, the level file keeps its old bytes and no temporary file is left. A full disk is
//! simulated as in `app_full_disk.rs`: the file size limit (`RLIMIT_FSIZE`, `SIGXFSZ`
//! ignored so a write returns `EFBIG`) lets the backup of the old level (5 kB) through but
//! not the grown level; it works as root. The limit is per process: the test runs alone in
//! its process under any runner (`tests/support/alone.rs`).

use crate::editor_common;

use candela::editor::{Edit, EditorState, SaveError, backup_path, render_document};
use editor_common::{Scratch, assets};

const LIMIT: u64 = 8 * 1024;

#[test]
fn saving_onto_a_full_disk_reports_it_and_keeps_the_old_level() -> anyhow::Result<()> {
    // Changes process-wide state: alone in its process under any test runner.
    if !crate::app_common::alone::alone_in_process(
        "editor_full_disk::saving_onto_a_full_disk_reports_it_and_keeps_the_old_level",
    ) {
        return Ok(());
    }
    let scratch = Scratch::new("full_disk");
    let path = scratch.path().join("first_person.ron");
    std::fs::copy(
        assets().join("test_scenes/platform/first_person.ron"),
        &path,
    )?;
    let old = std::fs::read(&path)?;
    assert!(
        (old.len() as u64) < LIMIT,
        "the backup must fit under the limit"
    );
    let mut state = EditorState::open(&path)?;
    // Twice the limit as a whole file: a save that changes only the edited items writes
    // about as much (the copies' lines), well past the limit.
    while render_document(&state.doc)?.len() as u64 <= 2 * LIMIT {
        state.apply(Edit::DuplicateInstance { index: 0 })?;
    }
    // SAFETY: a signal disposition and this process's own resource limit; no other test runs
    // in this binary.
    let old_limit = unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        let mut lim = std::mem::zeroed::<libc::rlimit>();
        assert_eq!(libc::getrlimit(libc::RLIMIT_FSIZE, &mut lim), 0);
        let small = libc::rlimit {
            rlim_cur: LIMIT,
            rlim_max: lim.rlim_max,
        };
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &small), 0);
        lim
    };
    let result = state.save(None);
    // SAFETY: restoring the limit read above.
    unsafe {
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &old_limit), 0);
    }
    let Err(SaveError::Write(e)) = result else {
        panic!("the save did not fail on the full disk: {result:?}");
    };
    assert_eq!(e.path, path);
    assert_eq!(e.stage, "write");
    assert_eq!(e.source.raw_os_error(), Some(libc::EFBIG));
    assert_eq!(std::fs::read(&path)?, old, "the level was damaged");
    assert_eq!(std::fs::read(backup_path(&path))?, old);
    let mut files: Vec<String> = std::fs::read_dir(scratch.path())?
        .map(|e| Ok(e?.file_name().to_string_lossy().into_owned()))
        .collect::<anyhow::Result<_>>()?;
    files.sort();
    assert_eq!(files, ["first_person.ron", "first_person.ron.bak"]);
    assert!(state.dirty(), "the edits are still unsaved");
    // With room again, the same save succeeds.
    state.save(None)?;
    assert!(!state.dirty());
    Ok(())
}
