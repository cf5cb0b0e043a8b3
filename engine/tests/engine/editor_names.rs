//! Names first in the editor's outliner and inspector (issue 33, item 5): an egui pass over
//! Reflect's chamber 1 with `door_1` selected heads the inspector with the door's name, lists
//! the unnamed floor by model and index, and draws no "Instance <number>" anywhere.

use crate::editor_common;

use candela::editor::ui::{outliner::instance_label, panels};
use candela::editor::{EditorState, SelectMode};
use editor_common::assets;

/// Every text egui was asked to draw.
fn texts(shapes: &[egui::epaint::ClippedShape]) -> Vec<String> {
    fn walk(shape: &egui::Shape, out: &mut Vec<String>) {
        match shape {
            egui::Shape::Text(t) => out.push(t.galley.text().to_string()),
            egui::Shape::Vec(v) => v.iter().for_each(|s| walk(s, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for s in shapes {
        walk(&s.shape, &mut out);
    }
    out
}

#[test]
fn the_outliner_and_the_inspector_name_instances_by_their_names() -> anyhow::Result<()> {
    let path = assets().join("reflect/levels/chamber_1.ron");
    let mut state = EditorState::open(&path)?;
    let level = &state.doc.level;
    let door = level
        .instances
        .iter()
        .position(|i| i.name.as_deref() == Some("door_1"))
        .expect("chamber 1 has door_1");
    assert_eq!(
        instance_label(door, &level.instances[door]),
        "door_1  (door)"
    );
    assert_eq!(instance_label(0, &level.instances[0]), "floor_8x8 #0");
    state.selection.click(Some(door), SelectMode::Replace);
    let ctx = egui::Context::default();
    let mut drawn = Vec::new();
    for _ in 0..2 {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 720.0),
            )),
            ..Default::default()
        };
        let output = ctx.run_pass(input, |ctx| {
            panels(ctx, &mut state);
        });
        drawn = texts(&output.shapes);
    }
    assert!(drawn.iter().any(|t| t == "door_1  (door)"), "{drawn:?}");
    assert!(drawn.iter().any(|t| t == "floor_8x8 #0"), "{drawn:?}");
    assert!(
        !drawn.iter().any(|t| t.starts_with("Instance ")),
        "{drawn:?}"
    );
    Ok(())
}
