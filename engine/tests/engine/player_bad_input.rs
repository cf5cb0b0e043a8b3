//! Bad input around the first-person platform level, each a clear error naming the file: the
//! committed replay offered to another level (the level hash differs), a truncated copy of it,
//! and level files whose `usables` name an instance that does not exist or send an event the
//! level does not declare.

use std::path::{Path, PathBuf};

use candela::app::{ActionSet, FIRST_PERSON_GAME, Replay, ReplayError, ReplayTarget, level_hash};
use candela::assets::AssetRoot;
use candela::level::load_level;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

fn platform(file: &str) -> PathBuf {
    assets().join("test_scenes/platform").join(file)
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("candela_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn open(replay: &Path, level: &Path, set: &ActionSet) -> Result<Replay, ReplayError> {
    let id = level
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let target = ReplayTarget {
        game: FIRST_PERSON_GAME,
        level_id: &id,
        level_hash: level_hash(level)?,
        step_hz: 60.0,
        actions: set,
    };
    Replay::open(replay, &target)
}

#[test]
fn the_replay_opens_for_its_own_level() {
    let set = ActionSet::standard();
    let replay = open(
        &platform("first_person.replay"),
        &platform("first_person.ron"),
        &set,
    )
    .expect("the committed replay belongs to the committed level");
    assert!(replay.steps() > 600, "{} steps", replay.steps());
}

#[test]
fn a_replay_of_another_level_is_refused_naming_the_file() {
    let set = ActionSet::standard();
    let replay = platform("first_person.replay");
    // The same level id, other content: a copy of the level with one more comment line.
    let dir = temp_dir("other_level");
    let level = dir.join("first_person.ron");
    let text = std::fs::read_to_string(platform("first_person.ron")).expect("level");
    std::fs::write(&level, format!("// edited\n{text}")).expect("write");
    let error = open(&replay, &level, &set).expect_err("another level");
    let _ = std::fs::remove_dir_all(&dir);
    let message = error.to_string();
    assert!(matches!(error, ReplayError::OtherLevel { .. }), "{message}");
    assert!(
        message.contains(&replay.display().to_string()) && message.contains("another level"),
        "{message}"
    );
}

#[test]
fn a_truncated_replay_is_refused_naming_the_file() {
    let set = ActionSet::standard();
    let bytes = std::fs::read(platform("first_person.replay")).expect("replay");
    let dir = temp_dir("truncated_replay");
    for keep in [bytes.len() / 2, bytes.len() - 1, 20] {
        let path = dir.join(format!("cut_{keep}.replay"));
        std::fs::write(&path, &bytes[..keep]).expect("write");
        let error = open(&path, &platform("first_person.ron"), &set).expect_err("truncated");
        let message = error.to_string();
        assert!(
            message.contains(&path.display().to_string()),
            "kept {keep} bytes: {message}"
        );
        assert!(
            matches!(
                error,
                ReplayError::Truncated { .. } | ReplayError::Corrupt { .. }
            ),
            "kept {keep} bytes: {message}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The platform level with its `usables` line replaced by `usables`.
fn level_with(name: &str, usables: &str) -> (PathBuf, PathBuf) {
    let text = std::fs::read_to_string(platform("first_person.ron")).expect("level");
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("usables:"))
        .expect("the level has a usables line");
    let dir = temp_dir(name);
    let path = dir.join("level.ron");
    std::fs::write(&path, text.replace(line, usables)).expect("write");
    (dir, path)
}

#[test]
fn a_usable_naming_an_unknown_instance_fails_the_load() {
    let (dir, path) = level_with(
        "usable_unknown",
        r#"usables: [(instance: "no_such_switch", prompt: "Press E", event: "lever")],"#,
    );
    let root = AssetRoot::new(&dir).expect("root");
    let Err(error) = load_level(&path, &root) else {
        panic!("an unknown usable instance must fail the load");
    };
    let _ = std::fs::remove_dir_all(&dir);
    let message = error.to_string();
    assert!(
        message.contains(&path.display().to_string()) && message.contains("no_such_switch"),
        "{message}"
    );
}

#[test]
fn a_usable_sending_an_undeclared_event_fails_the_load() {
    let (dir, path) = level_with(
        "usable_event",
        r#"usables: [(instance: "switch", prompt: "Press E", event: "not_declared")],"#,
    );
    let root = AssetRoot::new(&dir).expect("root");
    let Err(error) = load_level(&path, &root) else {
        panic!("an undeclared usable event must fail the load");
    };
    let _ = std::fs::remove_dir_all(&dir);
    let message = error.to_string();
    assert!(
        message.contains(&path.display().to_string()) && message.contains("not_declared"),
        "{message}"
    );
}
