//! The editor's inspector driven as a designer drives it, headless: pointer clicks at the
//! places the widgets were painted and typed text, through egui's own input (issue 32, weak
//! test 6). Typing a number into the translation's X field moves the instance to exactly that
//! value, as one undoable command; picking a material from the material combo box gives the
//! instance that override. Widgets are found by the text they paint (the frame's shapes), so a
//! test breaks when the inspector stops answering its input, not when a widget moves.

use crate::editor_common;

use candela::editor::ui::panels;
use candela::editor::{EditorState, SelectMode};
use editor_common::platform_with_laser;
use egui::epaint::{ClippedShape, Shape};
use egui::{Pos2, Rect};

const SCREEN: egui::Vec2 = egui::vec2(1280.0, 720.0);

/// One egui pass of the panels with `events`; the painted text pieces, in paint order.
fn pass(
    ctx: &egui::Context,
    state: &mut EditorState,
    events: Vec<egui::Event>,
) -> Vec<(String, Rect)> {
    let input = egui::RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
        events,
        ..Default::default()
    };
    let out = ctx.run_pass(input, |ctx| {
        let _ = panels(ctx, state);
    });
    let mut texts = Vec::new();
    for ClippedShape { shape, .. } in &out.shapes {
        collect_text(shape, &mut texts);
    }
    texts
}

fn collect_text(shape: &Shape, out: &mut Vec<(String, Rect)>) {
    match shape {
        Shape::Text(t) => out.push((t.galley.text().to_string(), t.visual_bounding_rect())),
        Shape::Vec(shapes) => shapes.iter().for_each(|s| collect_text(s, out)),
        _ => {}
    }
}

/// A press and a release of the primary button at `at` (two events; egui sees a click).
fn click(at: Pos2) -> Vec<egui::Event> {
    let button = |pressed| egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    };
    vec![egui::Event::PointerMoved(at), button(true), button(false)]
}

fn key(key: egui::Key, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

/// The rect of the last painted text equal to `text`.
fn find(texts: &[(String, Rect)], text: &str) -> anyhow::Result<Rect> {
    texts
        .iter()
        .rev()
        .find(|(t, _)| t == text)
        .map(|(_, r)| *r)
        .ok_or_else(|| anyhow::anyhow!("no {text:?} painted"))
}

/// The editor with instance `index` of the platform level selected, after a first pass.
fn editor_at(index: usize) -> anyhow::Result<(egui::Context, EditorState)> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    state.selection.click(Some(index), SelectMode::Replace);
    let ctx = egui::Context::default();
    pass(&ctx, &mut state, Vec::new());
    Ok((ctx, state))
}

#[test]
fn a_number_typed_into_the_translation_moves_the_instance_as_one_command() -> anyhow::Result<()> {
    // Instance 1: the west wall at x = −5.1.
    let (ctx, mut state) = editor_at(1)?;
    let before = state.doc.level.instances[1].transform;
    assert_eq!(before.translation[0], -5.1);
    let texts = pass(&ctx, &mut state, Vec::new());
    let label = find(&texts, "translation (m)")?;
    // The X field: the first number painted right of the label, on its row.
    let x_field = texts
        .iter()
        .filter(|(t, r)| {
            t.parse::<f32>().is_ok()
                && r.left() > label.right()
                && (r.center().y - label.center().y).abs() < 4.0
        })
        .min_by(|a, b| a.1.left().total_cmp(&b.1.left()))
        .map(|(_, r)| *r)
        .ok_or_else(|| anyhow::anyhow!("no X field beside the label"))?;
    // A click turns the drag value into a text field; select all, type, Enter.
    pass(&ctx, &mut state, click(x_field.center()));
    pass(&ctx, &mut state, Vec::new());
    assert!(
        ctx.egui_wants_keyboard_input(),
        "the X field took the keyboard"
    );
    pass(
        &ctx,
        &mut state,
        vec![
            key(egui::Key::A, egui::Modifiers::COMMAND),
            egui::Event::Text("2.75".into()),
            key(egui::Key::Enter, egui::Modifiers::NONE),
        ],
    );
    pass(&ctx, &mut state, Vec::new());
    let after = state.doc.level.instances[1].transform;
    assert_eq!(
        after.translation,
        [2.75, before.translation[1], before.translation[2]]
    );
    assert_eq!(after.rotation_deg, before.rotation_deg);
    assert_eq!(
        state.history.undo_len(),
        1,
        "one command for the typed value"
    );
    assert!(state.undo()?.is_some(), "it undoes");
    assert_eq!(state.doc.level.instances[1].transform, before);
    Ok(())
}

#[test]
fn a_material_picked_from_the_combo_box_overrides_the_instances() -> anyhow::Result<()> {
    // Instance 0: the floor, drawn with its model's own material.
    let (ctx, mut state) = editor_at(0)?;
    assert_eq!(state.doc.level.instances[0].material, None);
    let texts = pass(&ctx, &mut state, Vec::new());
    let combo = find(&texts, "(the model's own)")?;
    pass(&ctx, &mut state, click(combo.center()));
    let texts = pass(&ctx, &mut state, Vec::new());
    // The popup lists the level's materials below the combo box.
    let choice = texts
        .iter()
        .rev()
        .find(|(t, r)| t == "lift" && r.top() > combo.bottom())
        .map(|(_, r)| *r)
        .ok_or_else(|| anyhow::anyhow!("the material list did not open"))?;
    pass(&ctx, &mut state, click(choice.center()));
    pass(&ctx, &mut state, Vec::new());
    assert_eq!(
        state.doc.level.instances[0].material.as_deref(),
        Some("lift")
    );
    assert_eq!(state.history.undo_len(), 1);
    // The inspector now shows the override's fields (its metallic slider among them).
    let texts = pass(&ctx, &mut state, Vec::new());
    assert!(
        texts
            .iter()
            .any(|(t, _)| t.starts_with("Material \"lift\"")),
        "override fields shown"
    );
    Ok(())
}
