//! Saving a part of a composed world with its base (`editor::save_world`, issue 33), at the
//! level of the editor's state (no UI, no engine): with nothing edited the part alone is
//! written, as a save of one file is; with both edited both are written, the base first; with
//! only the base edited the part's file is not written again. Found by cargo-mutants
//! (docs/RELIABILITY.md "Mutation scores"): the UI test `editor_composed` covers only the
//! base-only save.

use crate::editor_common;

use std::path::PathBuf;

use anyhow::Result;
use candela::assets::{Level, TransformDesc};
use candela::editor::{
    Document, Edit, EditorState, InstanceField, MaterialField, SaveReport, backup_path,
};
use editor_common::{Scratch, assets, copy_dir, reflect_files};

fn written(reports: &[SaveReport]) -> Vec<PathBuf> {
    reports.iter().map(|r| r.path.clone()).collect()
}

/// `common.ron`'s `wall_white` given `roughness`.
fn base_edit(state: &EditorState, roughness: f32) -> Result<Edit> {
    let base = state.base().ok_or_else(|| anyhow::anyhow!("no base"))?;
    let white = (base.materials.iter())
        .position(|m| m.name == "wall_white")
        .ok_or_else(|| anyhow::anyhow!("common.ron defines wall_white"))?;
    Ok(Edit::Base(Box::new(Edit::Material {
        index: white,
        field: MaterialField::Roughness(roughness),
    })))
}

#[test]
fn a_composed_save_writes_the_files_that_changed_and_the_part_when_none_did() -> Result<()> {
    let scratch = Scratch::new("save_world");
    let levels = scratch.path().join("reflect/levels");
    copy_dir(&assets().join("reflect/levels"), &levels)?;
    let (base, parts) = reflect_files(scratch.path());
    let chamber = parts[0].clone();
    let mut state = EditorState::open(&chamber)?;
    state.set_base(&base, Document::open(&base)?);
    let base_before = std::fs::read(&base)?;

    // Nothing edited: the part is written (a save always writes the open file), the base not.
    assert_eq!(written(&state.save_world(Vec::new())?), [chamber.clone()]);
    assert_eq!(std::fs::read(&base)?, base_before);
    assert!(!backup_path(&base).exists(), "the base was written");

    // Both edited: both written, the base first, each reading back as edited.
    let moved = TransformDesc {
        translation: [1.25, 0.0, -6.0],
        ..TransformDesc::default()
    };
    state.apply(Edit::Instance {
        index: 0,
        field: InstanceField::Transform(moved),
    })?;
    state.apply(base_edit(&state, 0.25)?)?;
    assert_eq!(
        written(&state.save_world(Vec::new())?),
        [base.clone(), chamber.clone()]
    );
    assert_eq!(Some(&Level::read(&base)?), state.base());
    assert_eq!(Level::read(&chamber)?, state.doc.level);

    // Only the base edited: the part's file is not written again (no new backup of it).
    std::fs::remove_file(backup_path(&chamber))?;
    let chamber_bytes = std::fs::read(&chamber)?;
    state.apply(base_edit(&state, 0.5)?)?;
    assert_eq!(written(&state.save_world(Vec::new())?), [base.clone()]);
    assert_eq!(std::fs::read(&chamber)?, chamber_bytes);
    assert!(!backup_path(&chamber).exists(), "the part was written");
    assert_eq!(Some(&Level::read(&base)?), state.base());
    Ok(())
}
