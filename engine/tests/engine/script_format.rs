//! The capture-script format: a script using every field survives a write and read unchanged,
//! the committed scripts parse and bind to their levels, and every kind of bad script fails with
//! the typed error that names the file and the item (unknown field with line and column, frames
//! out of range, keys out of order, bad values, unknown or static instances, patterns matching
//! nothing, unknown light groups, missing level, missing files).

use std::path::{Path, PathBuf};

use candela::app::{Motion, Script, ScriptError};
use candela::level::PlayableLevel;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default()
}

fn small_script_path() -> PathBuf {
    repo().join("assets/test_scenes/script/determinism.ron")
}

fn small_text() -> String {
    std::fs::read_to_string(small_script_path()).expect("determinism.ron")
}

fn small_level() -> PlayableLevel {
    Script::read(&small_script_path())
        .expect("script")
        .load_level()
        .expect("small level loads")
}

fn parse(text: &str) -> Result<Script, ScriptError> {
    Script::parse(Path::new("scripts/bad.ron"), text)
}

/// A minimal valid script with `extra` fields spliced in.
fn with(extra: &str) -> String {
    format!("Script(frames: 10, seconds_per_frame: 0.1, {extra})")
}

#[test]
fn every_field_round_trips() -> Result<(), ScriptError> {
    let script = Script::parse(&small_script_path(), &small_text())?;
    assert_eq!(script.camera.len(), 5);
    assert!(script.camera[3].cut);
    assert!(matches!(script.motions[3].motion, Motion::Keyframes(ref k) if k.len() == 2));
    assert_eq!(script.screenshots[0].stem(), "still");
    let text = script.to_ron()?;
    let back = Script::parse(&small_script_path(), &text)?;
    assert_eq!(back, script);
    // Defaults: a screenshot without a name is named after its frame.
    let s = parse(&with("screenshots: [(frame: 7)]"))?;
    assert_eq!(s.screenshots[0].stem(), "frame_00007");
    assert_eq!(s.render.width, 640);
    Ok(())
}

#[test]
fn committed_scripts_parse_and_bind() -> Result<(), ScriptError> {
    let script = Script::read(&small_script_path())?;
    let bound = script.bind(&small_level().scene)?;
    // "crate_*" moves the three crates in level order; "gate" one instance.
    assert_eq!(bound.motion_targets[0], vec![5, 6, 7]);
    assert_eq!(bound.motion_targets[3], vec![8]);
    let fly = Script::read(&repo().join("assets/test_scenes/demo/flythrough.ron"))?;
    assert_eq!(fly.frames, 240);
    Ok(())
}

#[test]
fn unknown_field_names_line_column_and_field() {
    let text = "Script(\n    frames: 10,\n    seconds_per_frame: 0.1,\n    camera: [(frame: 0, position: (0, 1, 2), look_at: (0, 0, 0), fvo: 30)],\n)";
    match parse(text) {
        Err(ScriptError::Parse {
            path,
            line,
            column,
            message,
        }) => {
            assert_eq!(path, Path::new("scripts/bad.ron"));
            assert_eq!(line, 4);
            assert!(column > 60, "column {column}");
            assert!(message.contains("fvo"), "{message}");
        }
        other => panic!("expected a parse error, got {other:?}"),
    }
    // Inside a motion variant too.
    let text = with("motions: [(instance: \"a\", motion: Spin(deg_per_second: 1, speed: 2))]");
    assert!(
        matches!(parse(&text), Err(ScriptError::Parse { ref message, .. }) if message.contains("speed"))
    );
}

fn expect_out_of_range(text: &str, want_item: &str, want_frame: u32) {
    match parse(text) {
        Err(ScriptError::FrameOutOfRange {
            item,
            frame,
            frames,
            path,
        }) => {
            assert_eq!(path, Path::new("scripts/bad.ron"));
            assert!(item.starts_with(want_item), "{item} vs {want_item}");
            assert_eq!((frame, frames), (want_frame, 10));
        }
        other => panic!("expected frame {want_frame} out of range in {want_item}, got {other:?}"),
    }
}

#[test]
fn frames_out_of_range_name_the_item() {
    expect_out_of_range(
        &with(
            "camera: [(frame: 0, position: (0, 1, 2), look_at: (0, 0, 0)), (frame: 10, position: (0, 1, 3), look_at: (0, 0, 0))]",
        ),
        "camera[1]",
        10,
    );
    expect_out_of_range(
        &with("motions: [(instance: \"a\", motion: Keyframes([(frame: 2), (frame: 12)]))]"),
        "motions[0] (\"a\") key[1]",
        12,
    );
    expect_out_of_range(
        &with("lights: [(frame: 99, group: 1, on: true)]"),
        "lights[0]",
        99,
    );
    expect_out_of_range(
        &with("screenshots: [(frame: 1), (frame: 10)]"),
        "screenshots[1]",
        10,
    );
}

fn expect_invalid(text: &str, want_item: &str, want_words: &str) {
    match parse(text) {
        Err(ScriptError::Invalid {
            item,
            message,
            path,
        }) => {
            assert_eq!(path, Path::new("scripts/bad.ron"));
            assert!(item.starts_with(want_item), "{item} vs {want_item}");
            assert!(
                message.contains(want_words),
                "{message} lacks {want_words:?}"
            );
        }
        other => panic!("expected {want_item} to be invalid, got {other:?}"),
    }
}

#[test]
fn bad_values_name_the_item() {
    expect_invalid(
        "Script(frames: 0, seconds_per_frame: 0.1)",
        "frames",
        "at least 1",
    );
    expect_invalid(
        "Script(frames: 3, seconds_per_frame: -0.1)",
        "seconds_per_frame",
        "positive",
    );
    expect_invalid(&with("render: (width: 0)"), "render", "width");
    expect_invalid(
        &with(
            "camera: [(frame: 4, position: (0, 1, 2), look_at: (0, 0, 0)), (frame: 4, position: (0, 1, 3), look_at: (0, 0, 0))]",
        ),
        "camera[1]",
        "increase",
    );
    expect_invalid(
        &with("camera: [(frame: 0, position: (1, 1, 1), look_at: (1, 1, 1))]"),
        "camera[0]",
        "differ",
    );
    expect_invalid(
        &with("camera: [(frame: 0, position: (0, 1, 2), look_at: (0, 0, 0), fov_deg: 180)]"),
        "camera[0]",
        "fov_deg",
    );
    expect_invalid(
        &with("motions: [(instance: \"a\", motion: Orbit(radius: 1, period_seconds: 0))]"),
        "motions[0] (\"a\")",
        "periods positive",
    );
    expect_invalid(
        &with("motions: [(instance: \"a\", motion: Spin(axis: (0, 0, 0), deg_per_second: 5))]"),
        "motions[0]",
        "axes",
    );
    expect_invalid(
        &with("motions: [(instance: \"a\", motion: Keyframes([(frame: 1, scale: (1, 0, 1))]))]"),
        "motions[0]",
        "scales",
    );
    expect_invalid(
        &with("motions: [(instance: \"a\", motion: Keyframes([]))]"),
        "motions[0]",
        "at least one key",
    );
    expect_invalid(
        &with("motions: [(instance: \"*\", motion: Spin(deg_per_second: 5))]"),
        "motions[0]",
        "prefix",
    );
    expect_invalid(
        &with("screenshots: [(frame: 1, name: \"../escape\")]"),
        "screenshots[0]",
        "letters",
    );
    expect_invalid(
        &with("screenshots: [(frame: 1, name: \"a\"), (frame: 2, name: \"a\")]"),
        "screenshots[1]",
        "twice",
    );
}

#[test]
fn names_the_level_lacks_are_errors() {
    let level = small_level().scene;
    let bind = |extra: &str| parse(&with(extra)).and_then(|s| s.bind(&level));
    match bind(
        "motions: [(instance: \"crate_0\", motion: Spin(deg_per_second: 1)), (instance: \"boat\", motion: Spin(deg_per_second: 1))]",
    ) {
        Err(ScriptError::UnknownInstance { item, name, path }) => {
            assert_eq!((item.as_str(), name.as_str()), ("motions[1]", "boat"));
            assert_eq!(path, Path::new("scripts/bad.ron"));
        }
        other => panic!("expected an unknown instance, got {other:?}"),
    }
    assert!(matches!(
        bind("motions: [(instance: \"boat_*\", motion: Spin(deg_per_second: 1))]"),
        Err(ScriptError::UnknownInstance { ref name, .. }) if name == "boat_*"
    ));
    assert!(matches!(
        bind("motions: [(instance: \"pillar\", motion: Spin(deg_per_second: 1))]"),
        Err(ScriptError::StaticInstance { ref name, .. }) if name == "pillar"
    ));
    assert!(matches!(
        bind("lights: [(frame: 1, group: 1, on: false), (frame: 2, group: 7, on: false)]"),
        Err(ScriptError::UnknownLightGroup { ref item, group: 7, .. }) if item == "lights[1]"
    ));
}

#[test]
fn missing_level_and_files_are_errors() {
    let no_level = parse(&with("")).expect("parses");
    assert!(matches!(
        no_level.load_level(),
        Err(ScriptError::NoLevel { ref path }) if path == Path::new("scripts/bad.ron")
    ));
    let script_path = std::env::temp_dir().join("candela_script_format.ron");
    let missing =
        Script::parse(&script_path, &with("level: (path: \"nowhere.ron\")")).expect("parses");
    match missing.load_level() {
        Err(e @ ScriptError::Level { .. }) => {
            assert!(e.to_string().contains("nowhere.ron"), "{e}")
        }
        other => panic!("expected a level error, got {other:?}"),
    }
    assert!(matches!(
        Script::read(Path::new("/nonexistent/script.ron")),
        Err(ScriptError::Io { .. })
    ));
}
