//! Settings in the user's config folder: defaults when missing, a changed setting surviving a
//! save and a fresh load (a restart), older files with missing fields, and every kind of bad
//! file reported (naming the file and the problem), kept aside and replaced by defaults.
//!
//! Writing into a read-only place: these tests run as root, where `chmod` does not stop a
//! write, so the read-only places are a path whose parent is a regular file and a folder
//! inside `/proc` (which no one can create files in); `app_full_disk.rs` covers a write that
//! fails half-way.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::{
    ActionSet, Binding, KeyCode, PadButton, Settings, StoreError, UserDirs, UserDirsError,
    game_actions,
};

#[test]
fn a_missing_file_gives_the_defaults_and_writes_nothing() -> Result<()> {
    let dir = Scratch::new("settings_missing");
    let path = dir.join("settings.ron");
    let loaded = Settings::load(&path, &ActionSet::standard());
    assert_eq!(loaded.value, Settings::default());
    assert_eq!(loaded.warning, None);
    assert!(!path.exists());
    Ok(())
}

#[test]
fn a_changed_setting_survives_a_restart() -> Result<()> {
    let dir = Scratch::new("settings_restart");
    let dirs = UserDirs::under(dir.path(), "reflect")?;
    let set = ActionSet::standard();
    let path = dirs.settings_file();
    let mut s = Settings::load(&path, &set).value;
    s.resolution_scale = 0.5;
    s.target_fps = Some(60.0);
    s.vsync = false;
    s.fullscreen = true;
    s.master_volume = 0.25;
    s.effects_volume = 0.5;
    s.music_volume = 0.0;
    s.mouse_sensitivity = 2.5;
    s.invert_y = true;
    s.bindings.rebind(
        game_actions::JUMP,
        vec![Binding::Key(KeyCode::KeyJ), Binding::Pad(PadButton::North)],
    );
    s.save(&path, &set)?;
    // The file is where the player's config lives, and no temporary file is left beside it.
    assert!(path.starts_with(dir.path().join("config/candela/reflect")));
    assert_eq!(
        Scratch::entries(path.parent().expect("folder")),
        ["settings.ron"]
    );

    // "Restart": nothing shared but the file.
    let again = Settings::load(&path, &set);
    assert_eq!(again.warning, None);
    assert_eq!(again.value, s);
    let map = again.value.input_map(&set);
    assert_eq!(
        map.actions[game_actions::JUMP],
        [Binding::Key(KeyCode::KeyJ), Binding::Pad(PadButton::North)]
    );
    // Actions the player did not rebind keep the defaults.
    assert_eq!(
        map.actions[game_actions::MOVE_FORWARD],
        set.default_map().actions[game_actions::MOVE_FORWARD]
    );
    let text = std::fs::read_to_string(&path)?;
    assert!(
        !text.contains("move_forward"),
        "only rebound actions are written:\n{text}"
    );
    Ok(())
}

#[test]
fn an_older_file_with_missing_fields_loads() -> Result<()> {
    let dir = Scratch::new("settings_older");
    let path = dir.join("settings.ron");
    std::fs::write(&path, "(vsync: false, music_volume: 0.5, target_fps: None)")?;
    let loaded = Settings::load(&path, &ActionSet::standard());
    assert_eq!(loaded.warning, None);
    let expected = Settings {
        vsync: false,
        music_volume: 0.5,
        target_fps: None,
        ..Settings::default()
    };
    assert_eq!(loaded.value, expected);
    Ok(())
}

/// Each bad file and a piece of the problem its warning must name.
const BAD: &[(&str, &str)] = &[
    ("(vsync: maybe", "line 1"),
    ("(master_volume: NaN)", "master_volume is NaN"),
    ("(resolution_scale: 3.0)", "resolution_scale is 3"),
    ("(target_fps: 2.0)", "target_fps is 2"),
    ("(mouse_sensitivity: -1.0)", "mouse_sensitivity"),
    ("(vsinc: true)", "unknown field `vsinc` in `Settings`"),
    (
        r#"(bindings: {"fly": [Key(KeyF)]})"#,
        "unknown action `fly`",
    ),
    (
        r#"(bindings: {"jump": [Key(KeyQQ)]})"#,
        "unknown key name `KeyQQ`",
    ),
    (
        r#"(bindings: {"look_x": [Key(KeyX)]})"#,
        "action `look_x` takes motion input",
    ),
];

#[test]
fn a_corrupt_file_is_reported_kept_aside_and_replaced_by_defaults() -> Result<()> {
    let dir = Scratch::new("settings_corrupt");
    let set = ActionSet::standard();
    let path = dir.join("settings.ron");
    for (text, problem) in BAD {
        std::fs::write(&path, text)?;
        let loaded = Settings::load(&path, &set);
        assert_eq!(loaded.value, Settings::default(), "{text}");
        let w = loaded
            .warning
            .unwrap_or_else(|| panic!("no warning for {text}"));
        assert_eq!(w.path, path);
        assert!(w.problem.contains(problem), "{text}: {}", w.problem);
        let message = w.to_string();
        assert!(message.contains("settings.ron"), "{message}");
        let aside = w.kept_aside.expect("kept aside");
        assert_eq!(aside, dir.join("settings.ron.corrupt"));
        assert_eq!(std::fs::read_to_string(&aside)?, *text, "kept as it was");
        assert!(!path.exists(), "moved, so a save cannot overwrite it");
        std::fs::remove_file(&aside)?;
    }

    // Not text at all; and an earlier kept-aside file is never overwritten.
    std::fs::write(dir.join("settings.ron.corrupt"), "earlier")?;
    std::fs::write(&path, [0xff, 0xfe, 0x00, 0x80])?;
    let w = Settings::load(&path, &set).warning.expect("warned");
    assert!(w.problem.contains("not UTF-8"), "{}", w.problem);
    assert_eq!(w.kept_aside, Some(dir.join("settings.ron.corrupt.1")));
    assert_eq!(
        std::fs::read_to_string(dir.join("settings.ron.corrupt"))?,
        "earlier"
    );

    // The defaults then save and load cleanly.
    Settings::default().save(&path, &set)?;
    assert_eq!(Settings::load(&path, &set).warning, None);
    Ok(())
}

#[test]
fn a_write_into_a_read_only_place_fails_clearly_and_keeps_the_old_file() -> Result<()> {
    let dir = Scratch::new("settings_readonly");
    let set = ActionSet::standard();
    // The parent of the target is a regular file: no folder can be made there, even by root.
    let blocker = dir.join("not_a_folder");
    std::fs::write(&blocker, "old content")?;
    let target = blocker.join("settings.ron");
    let e = Settings::default()
        .save(&target, &set)
        .expect_err("cannot write below a file");
    let message = e.to_string();
    assert!(message.contains(&target.display().to_string()), "{message}");
    assert!(message.contains("create its folder"), "{message}");
    assert_eq!(std::fs::read_to_string(&blocker)?, "old content");

    // /proc takes no new files or folders, root or not.
    let proc_target = std::path::Path::new("/proc/candela_no_such_folder/settings.ron");
    let e = Settings::default()
        .save(proc_target, &set)
        .expect_err("cannot write into /proc");
    assert!(
        e.to_string()
            .contains("/proc/candela_no_such_folder/settings.ron"),
        "{e}"
    );

    // A value that would not load again is refused, and the old file stays.
    let path = dir.join("settings.ron");
    let good = Settings {
        invert_y: true,
        ..Settings::default()
    };
    good.save(&path, &set)?;
    let bad = Settings {
        master_volume: f32::NAN,
        ..good.clone()
    };
    match bad.save(&path, &set) {
        Err(StoreError::Invalid { path: p, problem }) => {
            assert_eq!(p, path);
            assert!(problem.contains("master_volume"), "{problem}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    assert_eq!(Settings::load(&path, &set).value, good);
    Ok(())
}

#[test]
fn user_folders_follow_xdg_and_reject_bad_game_names() -> Result<()> {
    let s = |v: &str| Some(v.to_string());
    let d = UserDirs::from_vars("reflect", s("/cfg"), s("/dat"), s("/home/p"))?;
    assert_eq!(
        d.settings_file(),
        std::path::Path::new("/cfg/candela/reflect/settings.ron")
    );
    assert_eq!(
        d.progress_file(),
        std::path::Path::new("/dat/candela/reflect/progress.ron")
    );
    // Unset or relative XDG values fall back to $HOME.
    let d = UserDirs::from_vars("reflect", None, s("relative/dir"), s("/home/p"))?;
    assert_eq!(
        d.config,
        std::path::Path::new("/home/p/.config/candela/reflect")
    );
    assert_eq!(
        d.data,
        std::path::Path::new("/home/p/.local/share/candela/reflect")
    );
    assert!(matches!(
        UserDirs::from_vars("reflect", None, None, None),
        Err(UserDirsError::NoHome { .. })
    ));
    for bad in ["", "..", "a/b", "my game", "x\\y"] {
        assert!(
            matches!(
                UserDirs::under(std::path::Path::new("/tmp"), bad),
                Err(UserDirsError::BadGameName(_))
            ),
            "{bad:?}"
        );
    }
    Ok(())
}
