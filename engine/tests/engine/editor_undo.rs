//! The editor's commands and history (issue 12): N random edits of every kind followed by N
//! undos give back the identical level document (comments included), redo gives back the
//! edited one, failed edits change nothing, a drag is one command, rewiring a rule, comments
//! following deleted instances, the selection following inserts and deletes, snapping.

use crate::editor_common;

use candela::assets::{ConditionEntry, TransformDesc};
use candela::editor::{
    Edit, EditError, EditorState, InstanceField, SelectMode, Snap, Touch, render_document,
    snap_angle_deg, snap_scale, snap_value,
};
use editor_common::{Rng, platform, platform_with_laser, random_edit};
use glam::Vec3;

const N: usize = 200;

fn state() -> anyhow::Result<EditorState> {
    Ok(EditorState::new(
        std::path::Path::new("first_person.ron"),
        platform_with_laser()?,
    ))
}

/// Applies random edits until `n` have succeeded; every failed one must leave the document
/// as it was. Returns how many failed.
fn random_edits(state: &mut EditorState, rng: &mut Rng, n: usize) -> usize {
    let (mut applied, mut failed) = (0, 0);
    while applied < n {
        let edit = random_edit(rng, &state.doc);
        let before = state.doc.clone();
        match state.apply(edit.clone()) {
            Ok(_) => applied += 1,
            Err(e) => {
                assert_eq!(
                    state.doc, before,
                    "the failed edit {edit:?} ({e}) changed the level"
                );
                failed += 1;
            }
        }
        assert!(failed < 20 * n, "almost every random edit fails");
    }
    failed
}

#[test]
fn n_random_edits_then_n_undos_give_back_the_identical_level() -> anyhow::Result<()> {
    for seed in [1, 2, 3, 4, 5, 6] {
        let mut state = state()?;
        let original = state.doc.clone();
        let mut rng = Rng::new(seed);
        let failed = random_edits(&mut state, &mut rng, N);
        assert!(failed > 0, "seed {seed}: no failing edit was tried");
        assert_eq!(
            state.history.undo_len(),
            N,
            "seed {seed}: commands merged without a drag"
        );
        assert_ne!(
            state.doc, original,
            "seed {seed}: the edits changed nothing"
        );
        let edited = state.doc.clone();
        for k in 0..N {
            assert!(
                state.undo()?.is_some(),
                "seed {seed}: undo {k} found nothing"
            );
        }
        assert!(state.undo()?.is_none());
        assert_eq!(state.doc, original, "seed {seed}: undoing every edit");
        assert!(!state.dirty(), "seed {seed}: back to the file's state");
        for k in 0..N {
            assert!(
                state.redo()?.is_some(),
                "seed {seed}: redo {k} found nothing"
            );
        }
        assert!(state.redo()?.is_none());
        assert_eq!(state.doc, edited, "seed {seed}: redoing every edit");
        while state.undo()?.is_some() {}
        assert_eq!(state.doc, original, "seed {seed}: undoing the redone edits");
    }
    Ok(())
}

#[test]
fn undo_and_redo_back_and_forth_in_the_middle() -> anyhow::Result<()> {
    let mut state = state()?;
    let mut rng = Rng::new(99);
    random_edits(&mut state, &mut rng, 50);
    let mut snapshots = vec![state.doc.clone()];
    for _ in 0..20 {
        state.undo()?;
        snapshots.push(state.doc.clone());
    }
    for k in (0..20).rev() {
        state.redo()?;
        assert_eq!(
            state.doc, snapshots[k],
            "redo back to the state {k} undos before"
        );
    }
    // A new edit after undos drops the redo stack.
    state.undo()?;
    state.apply(Edit::DuplicateInstance { index: 0 })?;
    assert!(!state.history.can_redo());
    Ok(())
}

fn move_to(x: f32) -> Edit {
    Edit::Instance {
        index: 7,
        field: InstanceField::Transform(TransformDesc {
            translation: [x, 0.1, -2.0],
            ..TransformDesc::default()
        }),
    }
}

#[test]
fn a_drag_is_one_command_and_other_fields_do_not_merge() -> anyhow::Result<()> {
    let mut state = state()?;
    let original = state.doc.clone();
    state.begin_drag();
    for k in 1..=10 {
        assert_eq!(
            state.apply(move_to(k as f32 * 0.1))?,
            Touch::Transforms(vec![7])
        );
    }
    state.end_drag();
    assert_eq!(state.history.undo_len(), 1);
    assert_eq!(state.doc.level.instances[7].transform.translation[0], 1.0);
    let entries = state.history.entries();
    assert_eq!(entries.len(), 1);
    assert_eq!(
        entries[0].description,
        "Set transform of instance 7 (\"lift\")"
    );
    // Outside a drag, each edit is a command.
    state.apply(move_to(2.0))?;
    state.apply(move_to(3.0))?;
    assert_eq!(state.history.undo_len(), 3);
    // Within a drag, another field or another instance starts a new command.
    state.begin_drag();
    state.apply(move_to(4.0))?;
    let material = Edit::Instance {
        index: 7,
        field: InstanceField::Material(Some("plate".into())),
    };
    assert_eq!(state.apply(material)?, Touch::Level);
    state.apply(move_to(5.0))?;
    state.end_drag();
    assert_eq!(state.history.undo_len(), 6);
    for _ in 0..5 {
        state.undo()?;
    }
    assert_eq!(state.doc.level.instances[7].transform.translation[0], 1.0);
    state.undo()?;
    assert_eq!(state.doc, original, "one undo takes back the whole drag");
    Ok(())
}

#[test]
fn rewiring_a_rule_moves_its_condition_to_another_volume() -> anyhow::Result<()> {
    let mut state = state()?;
    let original = state.doc.clone();
    let rewire = Edit::RewireRule {
        index: 0,
        from: "plate".into(),
        to: "lift".into(),
    };
    state.apply(rewire)?;
    assert_eq!(
        state.doc.level.gameplay.rules[0].when,
        ConditionEntry::All(vec![
            ConditionEntry::Occupied("lift".into()),
            ConditionEntry::Occupied("lift".into())
        ])
    );
    assert_eq!(
        state.history.entries()[0].description,
        "Rewire rule \"lift_up\" from \"plate\" to \"lift\""
    );
    state.undo()?;
    assert_eq!(state.doc, original);
    // The lever rule waits for an event and uses no volume.
    let unused = Edit::RewireRule {
        index: 1,
        from: "plate".into(),
        to: "lift".into(),
    };
    assert_eq!(
        state.apply(unused),
        Err(EditError::NotWired {
            rule: "lever_pulled".into(),
            volume: "plate".into()
        })
    );
    assert_eq!(state.doc, original);
    assert!(!state.history.can_undo());
    Ok(())
}

#[test]
fn a_deleted_instance_takes_its_comments_and_an_undo_brings_them_back() -> anyhow::Result<()> {
    let mut state = EditorState::new(std::path::Path::new("first_person.ron"), platform()?);
    let comment =
        "// The upper floor: z from −8 to −3, its top at y = 3.2 (the lift's top at the end).";
    assert_eq!(state.doc.level.instances[5].model, "upper");
    let before = state
        .doc
        .comments
        .item("instances", 5)
        .map(|a| a.before.clone());
    assert_eq!(before, Some(vec![comment.to_string()]));
    state.apply(Edit::DeleteInstance { index: 5 })?;
    assert!(!render_document(&state.doc)?.contains(comment));
    // The lift (was 7, now 6) keeps its own comment.
    let lift = state
        .doc
        .comments
        .item("instances", 6)
        .expect("the lift's comment");
    assert!(
        lift.before[0].starts_with("// The lift: 2 × 2 m"),
        "{lift:?}"
    );
    state.undo()?;
    assert!(render_document(&state.doc)?.contains(comment));
    assert_eq!(
        state.doc,
        EditorState::new(std::path::Path::new("x"), platform()?).doc
    );
    Ok(())
}

#[test]
fn the_selection_follows_duplicates_and_deletes() -> anyhow::Result<()> {
    let mut state = state()?;
    let n = state.doc.level.instances.len();
    state.selection.click(Some(7), SelectMode::Replace);
    state.selection.click(Some(9), SelectMode::Add);
    state.selection.click(Some(12), SelectMode::Toggle);
    state.selection.click(Some(12), SelectMode::Toggle);
    assert_eq!(state.selection.instances(), &[7, 9]);
    state.duplicate_selected()?;
    let names: Vec<_> = state
        .doc
        .level
        .instances
        .iter()
        .map(|i| i.name.clone())
        .collect();
    assert_eq!(state.doc.level.instances.len(), n + 2);
    // The copies sit right after their originals, with fresh names, and are selected.
    assert_eq!(names[8].as_deref(), Some("lift_2"));
    assert_eq!(names[11].as_deref(), Some("glass_cube_2"));
    assert_eq!(state.selection.instances(), &[8, 11]);
    assert_eq!(state.history.undo_len(), 1, "one command for the group");
    state.translate_selected(Vec3::new(0.0, 1.0, 0.0))?;
    assert_eq!(
        state.doc.level.instances[8].transform.translation,
        [0.0, 1.1, -2.0]
    );
    state.selection.click(Some(3), SelectMode::Add);
    state.delete_selected()?;
    assert_eq!(state.doc.level.instances.len(), n - 1);
    assert!(
        state.selection.is_empty(),
        "deleted instances leave the selection"
    );
    state.selection.click(Some(9), SelectMode::Replace);
    assert_eq!(state.doc.level.instances[9].name.as_deref(), Some("switch"));
    state.undo()?; // the delete: instances 3, 8 and 11 come back, the switch moves to 12
    assert_eq!(state.selection.instances(), &[12]);
    assert_eq!(
        state.doc.level.instances[12].name.as_deref(),
        Some("switch")
    );
    state.selection.click(None, SelectMode::Replace);
    assert!(state.selection.is_empty());
    Ok(())
}

#[test]
fn snapping_rounds_to_grid_angle_and_scale_steps() {
    assert_eq!(snap_value(0.26, 0.25), 0.25);
    assert_eq!(
        snap_value(-0.1, 0.25).to_bits(),
        0.0f32.to_bits(),
        "no negative zero"
    );
    assert_eq!(snap_value(1.3, 0.0), 1.3, "a zero step is no snapping");
    assert_eq!(snap_angle_deg(44.0, 15.0), 45.0);
    assert_eq!(snap_angle_deg(-97.0, 15.0), -90.0);
    assert_eq!(snap_scale(0.05, 0.25), 0.25, "never a zero scale");
    assert_eq!(snap_scale(-0.05, 0.25), -0.25, "a mirror stays a mirror");
    assert_eq!(snap_scale(1.9, 0.5), 2.0);
    let snap = Snap {
        grid: Some(0.5),
        angle_deg: Some(90.0),
        scale: None,
    };
    let t = snap.transform(TransformDesc {
        translation: [0.3, 1.74, -2.2],
        rotation_deg: [10.0, 130.0, -50.0],
        scale: [1.3, 1.0, 0.7],
    });
    assert_eq!(t.translation, [0.5, 1.5, -2.0]);
    assert_eq!(t.rotation_deg, [0.0, 90.0, -90.0]);
    assert_eq!(t.scale, [1.3, 1.0, 0.7]);
}
