//! The editor's first panels, headless (issue 12): egui passes with no window draw the
//! outliner, inspector, gameplay widgets and history without changing the level; the editor's
//! keys (Ctrl+Z, Ctrl+Shift+Z, Ctrl+D, Delete, Ctrl+S) act on the state; while a text field
//! has the keyboard, they do not.

use crate::editor_common;

use candela::assets::TransformDesc;
use candela::editor::ui::{PanelOutput, outliner::SEARCH_ID, panels};
use candela::editor::{Edit, EditorState, InstanceField, SelectMode};
use editor_common::platform_with_laser;

fn key(key: egui::Key, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

/// One egui pass of the panels with `events` on a 1280 × 720 screen.
fn pass(ctx: &egui::Context, state: &mut EditorState, events: Vec<egui::Event>) -> PanelOutput {
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(1280.0, 720.0),
        )),
        events,
        ..Default::default()
    };
    let mut out = PanelOutput::default();
    let _ = ctx.run_pass(input, |ctx| out = panels(ctx, state));
    out
}

#[test]
fn the_panels_draw_without_changing_the_level_and_the_keys_edit() -> anyhow::Result<()> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    let original = state.doc.clone();
    let ctx = egui::Context::default();
    state.selection.click(Some(7), SelectMode::Replace);
    for _ in 0..3 {
        let out = pass(&ctx, &mut state, Vec::new());
        assert_eq!(out, PanelOutput::default());
    }
    assert_eq!(state.doc, original, "drawing changed the level");
    assert!(!state.history.can_undo());
    let command = egui::Modifiers::COMMAND;
    // Ctrl+D duplicates the selection, Ctrl+Z undoes it, Ctrl+Shift+Z redoes it.
    let out = pass(&ctx, &mut state, vec![key(egui::Key::D, command)]);
    assert_eq!(
        state.doc.level.instances.len(),
        original.level.instances.len() + 1
    );
    assert_eq!(out.touched.len(), 1);
    pass(&ctx, &mut state, vec![key(egui::Key::Z, command)]);
    assert_eq!(state.doc, original);
    let shift_command = command | egui::Modifiers::SHIFT;
    pass(&ctx, &mut state, vec![key(egui::Key::Z, shift_command)]);
    assert_eq!(
        state.doc.level.instances.len(),
        original.level.instances.len() + 1
    );
    pass(&ctx, &mut state, vec![key(egui::Key::Z, command)]);
    // Delete removes the selection; Ctrl+S asks the runner to save.
    let out = pass(
        &ctx,
        &mut state,
        vec![
            key(egui::Key::Delete, egui::Modifiers::NONE),
            key(egui::Key::S, command),
        ],
    );
    assert!(out.save);
    assert_eq!(
        state.doc.level.instances.len(),
        original.level.instances.len() - 1
    );
    assert!(state.selection.is_empty());
    pass(&ctx, &mut state, vec![key(egui::Key::Z, command)]);
    assert_eq!(state.doc, original);
    Ok(())
}

#[test]
fn keys_typed_into_a_text_field_are_not_editor_keys() -> anyhow::Result<()> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    state.apply(Edit::Instance {
        index: 7,
        field: InstanceField::Transform(TransformDesc::default()),
    })?;
    state.selection.click(Some(7), SelectMode::Replace);
    let edited = state.doc.clone();
    let ctx = egui::Context::default();
    pass(&ctx, &mut state, Vec::new());
    ctx.memory_mut(|m| m.request_focus(egui::Id::unique(SEARCH_ID)));
    pass(&ctx, &mut state, Vec::new());
    assert!(
        ctx.egui_wants_keyboard_input(),
        "the search field has the keyboard"
    );
    let command = egui::Modifiers::COMMAND;
    pass(
        &ctx,
        &mut state,
        vec![
            key(egui::Key::Z, command),
            key(egui::Key::Delete, egui::Modifiers::NONE),
            key(egui::Key::D, command),
        ],
    );
    assert_eq!(
        state.doc, edited,
        "a key meant for the text field edited the level"
    );
    assert_eq!(state.history.undo_len(), 1);
    // With the keyboard back, Ctrl+Z undoes.
    ctx.memory_mut(|m| m.surrender_focus(egui::Id::unique(SEARCH_ID)));
    pass(&ctx, &mut state, Vec::new());
    pass(&ctx, &mut state, vec![key(egui::Key::Z, command)]);
    assert_eq!(state.history.undo_len(), 0);
    Ok(())
}
