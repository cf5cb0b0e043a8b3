//! Recovery files (issue 12): written on demand beside the level, even while the level has
//! problems; reported on open only while newer than the level; restoring gives back the
//! edited document; a successful save removes it.

use crate::editor_common;

use std::time::{Duration, SystemTime};

use candela::assets::ConditionEntry;
use candela::editor::{
    Edit, EditorState, SaveError, base_recovery_path, discard_recovery, find_recovery,
    recovery_path, restore_recovery,
};
use editor_common::{Scratch, assets};

fn set_modified(path: &std::path::Path, time: SystemTime) -> anyhow::Result<()> {
    std::fs::File::options()
        .write(true)
        .open(path)?
        .set_modified(time)?;
    Ok(())
}

#[test]
fn a_recovery_file_newer_than_its_level_is_offered_and_restores_the_edits() -> anyhow::Result<()> {
    let scratch = Scratch::new("recovery");
    let path = scratch.path().join("first_person.ron");
    std::fs::copy(
        assets().join("test_scenes/platform/first_person.ron"),
        &path,
    )?;
    let now = SystemTime::now();
    set_modified(&path, now - Duration::from_secs(120))?;
    assert_eq!(find_recovery(&path), None, "no recovery file yet");
    let mut state = EditorState::open(&path)?;
    state.apply(Edit::DuplicateInstance { index: 9 })?;
    // A level with a problem is still written to its recovery file.
    state.apply(Edit::RuleCondition {
        index: 0,
        when: ConditionEntry::Occupied("nowhere".into()),
    })?;
    let written = state.write_recovery()?;
    assert_eq!(written, recovery_path(&path));
    assert!(written.ends_with("first_person.ron.recovery"));
    set_modified(&written, now - Duration::from_secs(60))?;
    let found = find_recovery(&path).expect("a newer recovery file is offered");
    assert_eq!(found.path, written);
    assert!(found.level_modified.is_some_and(|l| l < found.modified));
    let restored = restore_recovery(&path)?;
    assert_eq!(
        restored, state.doc,
        "the recovery file holds the edits and the comments"
    );
    // Once the level is newer (saved elsewhere, or by hand), the recovery file is stale.
    set_modified(&path, now)?;
    assert_eq!(find_recovery(&path), None);
    // A successful save removes the recovery file.
    set_modified(&written, now + Duration::from_secs(5))?;
    assert!(find_recovery(&path).is_some());
    state.undo()?;
    state.save(None)?;
    assert!(!written.exists(), "the save left the recovery file");
    assert!(!discard_recovery(&path)?, "nothing left to discard");
    Ok(())
}

#[test]
fn a_recovery_file_of_a_level_that_is_gone_is_offered() -> anyhow::Result<()> {
    let scratch = Scratch::new("recovery_gone");
    let path = scratch.path().join("first_person.ron");
    std::fs::copy(
        assets().join("test_scenes/platform/first_person.ron"),
        &path,
    )?;
    let state = EditorState::open(&path)?;
    state.write_recovery()?;
    std::fs::remove_file(&path)?;
    let found = find_recovery(&path).expect("offered");
    assert_eq!(found.level_modified, None);
    assert_eq!(restore_recovery(&path)?, state.doc);
    assert!(discard_recovery(&path)?);
    assert_eq!(find_recovery(&path), None);
    Ok(())
}

#[test]
fn a_recovery_file_that_cannot_be_removed_is_reported() -> anyhow::Result<()> {
    let scratch = Scratch::new("recovery_blocked");
    let path = scratch.path().join("first_person.ron");
    std::fs::copy(
        assets().join("test_scenes/platform/first_person.ron"),
        &path,
    )?;
    // A folder where the base's recovery file would be: a recovery of a level with no base
    // removes a stale one, and this one cannot be removed as a file.
    let stale = base_recovery_path(&path);
    std::fs::create_dir(&stale)?;
    let state = EditorState::open(&path)?;
    match state.write_recovery() {
        Err(SaveError::Remove { path: p, .. }) => assert_eq!(p, stale),
        other => panic!("expected the stale base recovery to be named, got {other:?}"),
    }
    assert!(stale.is_dir(), "left as it was");
    // Discarding (after a save) says so too rather than reporting nothing there.
    assert!(
        discard_recovery(&path).is_err(),
        "a folder is not a removed file"
    );
    Ok(())
}
