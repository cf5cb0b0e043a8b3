//! What `app::persist::stored` says and does with a player's file beyond the settings and
//! progress tests (found by cargo-mutants, docs/RELIABILITY.md "Mutation scores"): an unknown
//! name is called by its kind (mouse button, gamepad axis, binding kind) and the few names it
//! could have been are listed, up to twelve and no more; a value written without `Some(…)`
//! loads, as the module promises; and a file that cannot be read (a folder in its place) gives
//! the defaults with a warning, and is left where it is rather than kept aside as corrupt.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{ActionSet, Binding, Settings, parse_checked};
use serde::Deserialize;

/// The one-line problem for `text` read as `T` (which must not parse).
fn problem<T: serde::de::DeserializeOwned + std::fmt::Debug>(text: &str) -> String {
    match parse_checked::<T>(text, |_| Ok(())) {
        Ok(v) => panic!("{text} parsed as {v:?}"),
        Err(p) => p,
    }
}

#[test]
fn unknown_names_say_their_kind_and_list_the_few_they_could_be() {
    let cases = [
        (
            "Mouse(Thumb)",
            "unknown mouse button `Thumb` (expected one of Left, Right, Middle, Back, Forward, \
             Other)",
        ),
        (
            "PadAxis(Trigger)",
            "unknown gamepad axis `Trigger` (expected one of LeftStickX, LeftStickY, \
             RightStickX, RightStickY)",
        ),
        (
            "Joystick(KeyW)",
            "unknown binding kind `Joystick` (expected one of Key, Mouse, MouseX, MouseY, Wheel, \
             Pad, PadAxis)",
        ),
    ];
    for (text, expected) in cases {
        let p = problem::<Binding>(text);
        assert!(p.starts_with("line 1, column "), "{text}: {p}");
        assert!(p.ends_with(expected), "{text}: {p}");
    }
    // Keys and gamepad buttons are too many to list: the name alone.
    assert!(problem::<Binding>("Key(KeyQQ)").ends_with("unknown key name `KeyQQ`"));
    assert!(problem::<Binding>("Pad(Triangle)").ends_with("unknown gamepad button `Triangle`"));
}

/// Twelve names: the most an error lists.
#[derive(Debug, Deserialize)]
#[allow(dead_code)]
enum Twelve {
    A,
    B,
    C,
    D,
    E,
    F,
    G,
    H,
    I,
    J,
    K,
    L,
}

/// Thirteen names: one too many to list.
#[derive(Debug, Deserialize)]
#[allow(dead_code)]
enum Thirteen {
    A,
    B,
    C,
    D,
    E,
    F,
    G,
    H,
    I,
    J,
    K,
    L,
    M,
}

#[test]
fn twelve_names_are_listed_and_thirteen_are_not() {
    let p = problem::<Twelve>("Z");
    assert!(
        p.ends_with("unknown name `Z` (expected one of A, B, C, D, E, F, G, H, I, J, K, L)"),
        "{p}"
    );
    let p = problem::<Thirteen>("Z");
    assert!(p.ends_with("unknown name `Z`"), "{p}");
}

#[test]
fn a_value_written_without_some_loads() -> Result<()> {
    let dir = Scratch::new("stored_implicit_some");
    let path = dir.join("settings.ron");
    std::fs::write(&path, "(target_fps: 60.0)")?;
    let loaded = Settings::load(&path, &ActionSet::standard());
    assert_eq!(loaded.warning, None);
    assert_eq!(loaded.value.target_fps, Some(60.0));
    Ok(())
}

#[test]
fn a_file_that_cannot_be_read_gives_defaults_warns_and_stays() -> Result<()> {
    let dir = Scratch::new("stored_unreadable");
    let path = dir.join("settings.ron");
    // A folder where the file should be: reading it fails, but it is not a corrupt file.
    std::fs::create_dir(&path)?;
    std::fs::write(path.join("inside"), "kept")?;
    let loaded = Settings::load(&path, &ActionSet::standard());
    assert_eq!(loaded.value, Settings::default());
    let w = loaded.warning.expect("an unreadable file is reported");
    assert_eq!(w.path, path);
    assert!(w.problem.starts_with("cannot read: "), "{}", w.problem);
    assert_eq!(w.kept_aside, None);
    assert_eq!(w.aside_error, None);
    let message = w.to_string();
    assert!(message.ends_with("; using defaults"), "{message}");
    assert!(path.is_dir(), "left where it is");
    assert_eq!(Scratch::entries(dir.path()), ["settings.ron"]);
    Ok(())
}
