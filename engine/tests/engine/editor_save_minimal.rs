//! Saves that change only what was edited (issue 33, item 5), through the editor's save path
//! (`EditorState::save_checked` → `write_document`) into a scratch copy of each level: moving
//! one instance of every committed level (Reflect's chamber parts included) changes exactly
//! one line; adding a rule only adds lines; a save without an edit, or after an edit undone,
//! writes the same bytes; a changed one-line instance stays one line with its field order
//! and omitted defaults; a deleted instance takes its line and nothing else; a file the
//! splicer cannot follow is rewritten whole, says so, and still loads as the edited level.

use crate::editor_common;

use std::path::{Path, PathBuf};

use candela::assets::{ActionEntry, ConditionEntry, Level, RuleEntry};
use candela::editor::{Edit, EditorState, InstanceField, SaveReport};
use editor_common::{Scratch, assets, committed_levels};

/// Every committed level file, Reflect's chamber parts and their base file included.
fn every_level_file() -> Vec<PathBuf> {
    let mut out = committed_levels();
    let parts = assets().join("reflect/levels");
    for entry in std::fs::read_dir(&parts)
        .expect("Reflect's levels")
        .flatten()
    {
        out.push(entry.path());
    }
    out.sort();
    out
}

/// `path` copied into `scratch`, opened in the editor.
fn open_copy(scratch: &Scratch, path: &Path) -> anyhow::Result<(EditorState, String)> {
    let text = std::fs::read_to_string(path)?;
    let name = path.file_name().expect("a file name");
    let copy = scratch.path().join(name);
    std::fs::write(&copy, &text)?;
    Ok((EditorState::open(&copy)?, text))
}

/// Saves through the editor (the checks are the composed world's business, not this test's)
/// and returns the report and the file's new text.
fn save(state: &mut EditorState) -> anyhow::Result<(SaveReport, String)> {
    let report = state.save_checked(Vec::new())?;
    let text = std::fs::read_to_string(&state.path)?;
    assert_eq!(
        Level::read(&state.path)?,
        state.doc.level,
        "{}: the saved file does not load as the edited level",
        state.path.display()
    );
    Ok((report, text))
}

/// The lines of `new` that differ from `old`'s, when both have as many lines.
fn changed_lines<'a>(old: &str, new: &'a str) -> Vec<&'a str> {
    assert_eq!(
        old.lines().count(),
        new.lines().count(),
        "the line count changed:\n{new}"
    );
    old.lines()
        .zip(new.lines())
        .filter(|(a, b)| a != b)
        .map(|(_, b)| b)
        .collect()
}

/// The lines `new` adds to `old`, asserting that `new` is `old` with lines added in one
/// place (no line of `old` changed or removed).
fn added_lines<'a>(old: &str, new: &'a str) -> Vec<&'a str> {
    let (o, n): (Vec<&str>, Vec<&str>) = (old.lines().collect(), new.lines().collect());
    let head = o.iter().zip(&n).take_while(|(a, b)| a == b).count();
    let tail = o[head..]
        .iter()
        .rev()
        .zip(n[head..].iter().rev())
        .take_while(|(a, b)| a == b)
        .count();
    assert_eq!(
        head + tail,
        o.len(),
        "lines of the old file changed:\n{new}"
    );
    n[head..n.len() - tail].to_vec()
}

#[test]
fn moving_one_instance_of_every_committed_level_changes_one_line() -> anyhow::Result<()> {
    let scratch = Scratch::new("minimal_move");
    let mut moved = 0;
    for path in every_level_file() {
        let (mut state, old) = open_copy(&scratch, &path)?;
        let count = state.doc.level.instances.len();
        if count == 0 {
            continue;
        }
        let index = count / 2;
        let mut t = state.doc.level.instances[index].transform;
        t.translation[0] += 0.5;
        let x = t.translation[0];
        state.apply(Edit::Instance {
            index,
            field: InstanceField::Transform(t),
        })?;
        let (report, new) = save(&mut state)?;
        let name = path.display();
        assert_eq!(report.rewritten, None, "{name}: rewritten whole");
        let changed = changed_lines(&old, &new);
        assert_eq!(changed.len(), 1, "{name}: {changed:#?}");
        assert!(changed[0].contains(&x.to_string()), "{name}: {changed:?}");
        moved += 1;
    }
    assert!(moved >= 12, "only {moved} levels have an instance to move");
    Ok(())
}

#[test]
fn saving_without_an_edit_or_after_an_undo_writes_the_same_bytes() -> anyhow::Result<()> {
    let scratch = Scratch::new("minimal_same");
    for path in every_level_file() {
        let (mut state, old) = open_copy(&scratch, &path)?;
        let (report, new) = save(&mut state)?;
        assert_eq!(report.rewritten, None, "{}", path.display());
        assert_eq!(
            new,
            old,
            "{}: an unedited save changed bytes",
            path.display()
        );
        if state.doc.level.instances.is_empty() {
            continue;
        }
        state.apply(Edit::DeleteInstance { index: 0 })?;
        state.undo()?;
        let (_, new) = save(&mut state)?;
        assert_eq!(
            new,
            old,
            "{}: delete and undo changed bytes",
            path.display()
        );
    }
    Ok(())
}

/// A rule named `name` that switches light group 7 on while `volume` is occupied.
fn rule(name: &str, volume: &str) -> RuleEntry {
    RuleEntry {
        name: name.into(),
        when: ConditionEntry::Occupied(volume.into()),
        then: vec![ActionEntry::Lights { group: 7, on: true }],
        otherwise: Vec::new(),
        once: false,
    }
}

#[test]
fn adding_a_rule_only_adds_its_lines() -> anyhow::Result<()> {
    let scratch = Scratch::new("minimal_rule");
    let levels = [
        "reflect/levels/chamber_1.ron",
        "test_scenes/platform/first_person.ron",
        "its_about_time/ruins.ron",
    ];
    for level in levels {
        let (mut state, old) = open_copy(&scratch, &assets().join(level))?;
        let volume = state.doc.level.gameplay.volumes[0].name.clone();
        state
            .doc
            .level
            .gameplay
            .rules
            .push(rule("added_rule", &volume));
        let (report, new) = save(&mut state)?;
        assert_eq!(report.rewritten, None, "{level}");
        let added = added_lines(&old, &new);
        assert_eq!(added.len(), 1, "{level}: {added:#?}");
        assert!(
            added[0].contains("(name: \"added_rule\""),
            "{level}: {added:?}"
        );
    }
    // A level without rules gets the field, and nothing else changes.
    let (mut state, old) = open_copy(&scratch, &assets().join("reflect/levels/chamber_1.ron"))?;
    state.doc.level.gameplay.rules.clear();
    let (_, cleared) = save(&mut state)?;
    assert!(cleared.len() < old.len());
    state
        .doc
        .level
        .gameplay
        .rules
        .push(rule("only_rule", "room_1"));
    let (_, new) = save(&mut state)?;
    assert_eq!(added_lines(&cleared, &new).len(), 1, "{new}");
    Ok(())
}

const CHAMBER: &str = "reflect/levels/chamber_1.ron";

#[test]
fn a_changed_instance_keeps_its_style_and_a_deleted_one_only_its_line() -> anyhow::Result<()> {
    let scratch = Scratch::new("minimal_style");
    let (mut state, old) = open_copy(&scratch, &assets().join(CHAMBER))?;
    // The last pillar is written with its light group before its transform.
    let index = (state.doc.level.instances.iter())
        .rposition(|i| i.model == "pillar" && i.light_group.is_some())
        .expect("chamber 1 has a pillar in a light group");
    let mut t = state.doc.level.instances[index].transform;
    t.translation[2] = -14.5;
    t.rotation_deg[1] = 90.0;
    state.apply(Edit::Instance {
        index,
        field: InstanceField::Transform(t),
    })?;
    let (_, new) = save(&mut state)?;
    assert_eq!(
        changed_lines(&old, &new),
        [
            "        (model: \"pillar\", light_group: 1, transform: (translation: (7, 0, -14.5), \
             rotation_deg: (0, 90, 0))),"
        ]
    );
    // Deleting the door (which has no comment above it) removes its line only.
    let (mut state, old) = open_copy(&scratch, &assets().join(CHAMBER))?;
    let door = state
        .doc
        .level
        .instances
        .iter()
        .position(|i| i.name.as_deref() == Some("door_1"))
        .expect("chamber 1 has door_1");
    state.apply(Edit::DeleteInstance { index: door })?;
    let (_, new) = save(&mut state)?;
    let removed = added_lines(&new, &old);
    assert_eq!(removed.len(), 1, "{removed:#?}");
    assert!(removed[0].contains("name: \"door_1\""));
    Ok(())
}

#[test]
fn a_file_the_splicer_cannot_follow_is_rewritten_whole_and_says_why() -> anyhow::Result<()> {
    let scratch = Scratch::new("minimal_fallback");
    let (mut state, _) = open_copy(&scratch, &assets().join(CHAMBER))?;
    state.apply(Edit::DeleteInstance { index: 0 })?;
    // The file on disk is broken behind the editor's back.
    std::fs::write(&state.path, "Level( instances: [ (model: \"floor_8x8\", ")?;
    let (report, new) = save(&mut state)?;
    let why = report.rewritten.expect("a whole rewrite");
    assert!(why.contains("does not read as a level"), "{why}");
    assert!(
        new.starts_with("// Chamber 1"),
        "written with its comments:\n{new}"
    );
    // A new file has nothing to keep.
    std::fs::remove_file(&state.path)?;
    let (report, _) = save(&mut state)?;
    assert_eq!(report.rewritten.as_deref(), Some("a new file"));
    Ok(())
}
