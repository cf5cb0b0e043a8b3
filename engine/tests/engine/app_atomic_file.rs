//! The two edges of `assets::atomic_file` that the save and settings tests did not reach
//! (found by cargo-mutants, docs/RELIABILITY.md "Mutation scores"): a write whose folder does
//! not exist yet creates it and puts the temporary file there, not in the working folder;
//! and a bad file whose `.corrupt` name would be too long for the file system is reported
//! with the real reason and left where it is, instead of the search for a free name running
//! through all its 10,000 numbers.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{ActionSet, Settings, write_atomic};

#[test]
fn a_write_into_missing_folders_creates_them_and_leaves_only_the_file() -> Result<()> {
    let dir = Scratch::new("atomic_new_folders");
    let path = dir.join("config").join("candela").join("settings.ron");
    write_atomic(&path, b"first")?;
    assert_eq!(std::fs::read(&path)?, b"first");
    write_atomic(&path, b"second")?;
    assert_eq!(std::fs::read(&path)?, b"second");
    let folder = path.parent().expect("a folder");
    assert_eq!(
        Scratch::entries(folder),
        ["settings.ron"],
        "a temporary file was left behind"
    );
    Ok(())
}

#[test]
fn a_bad_file_whose_kept_aside_name_is_too_long_stays_and_says_why() -> Result<()> {
    let dir = Scratch::new("atomic_long_aside");
    let set = ActionSet::standard();
    // 254 bytes: the file system takes it (255 at most), but not `<name>.corrupt`.
    let name = format!("{}.ron", "s".repeat(250));
    let path = dir.join(&name);
    std::fs::write(&path, "(not settings")?;

    let loaded = Settings::load(&path, &set);
    assert_eq!(loaded.value, Settings::default());
    let w = loaded.warning.expect("the bad file is reported");
    assert_eq!(w.kept_aside, None, "no name was free to keep it as");
    let why = w.aside_error.as_deref().unwrap_or_default();
    assert_eq!(
        why,
        std::io::Error::from_raw_os_error(libc::ENAMETOOLONG).to_string(),
        "the reason is the name, not 10,000 earlier copies"
    );
    assert_eq!(std::fs::read_to_string(&path)?, "(not settings");
    assert_eq!(Scratch::entries(dir.path()), [name]);
    Ok(())
}
