//! The editor's inspector driven as a designer drives it, headless, through the synthetic-input
//! harness (`editor_common::input`, issues 32 and 33): pointer clicks at the places the widgets
//! were painted and typed text, through egui's own input. Typing a number into the
//! translation's X field moves the instance to exactly that value, as one undoable command;
//! picking a material from the material combo box gives the instance that override; in a
//! composed world (a Reflect chamber over `common.ron`) the base file's models are in the
//! palette and its materials in the combo box.

use crate::editor_common;

use candela::assets::Level;
use candela::editor::ui::PanelOutput;
use candela::editor::{Document, EditorState, PaletteItem, SelectMode};
use editor_common::input::Panels;
use editor_common::platform_with_laser;

/// The editor with instance `index` of the platform level selected.
fn editor_at(index: usize) -> anyhow::Result<Panels> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    state.selection.click(Some(index), SelectMode::Replace);
    Ok(Panels::new(state))
}

#[test]
fn a_number_typed_into_the_translation_moves_the_instance_as_one_command() -> anyhow::Result<()> {
    // Instance 1: the west wall at x = −5.1.
    let mut ui = editor_at(1)?;
    let before = ui.state.doc.level.instances[1].transform;
    assert_eq!(before.translation[0], -5.1);
    // The X field: the first number right of the label; click, select all, type, Enter.
    ui.type_beside("translation (m)", 0, "3.5")?;
    let after = ui.state.doc.level.instances[1].transform;
    assert_eq!(
        after.translation,
        [3.5, before.translation[1], before.translation[2]]
    );
    assert_eq!(after.rotation_deg, before.rotation_deg);
    assert_eq!(
        ui.state.history.undo_len(),
        1,
        "one command for the typed value"
    );
    assert!(ui.state.undo()?.is_some(), "it undoes");
    assert_eq!(ui.state.doc.level.instances[1].transform, before);
    Ok(())
}

#[test]
fn a_material_picked_from_the_combo_box_overrides_the_instances() -> anyhow::Result<()> {
    // Instance 0: the floor, drawn with its model's own material.
    let mut ui = editor_at(0)?;
    assert_eq!(ui.state.doc.level.instances[0].material, None);
    ui.choose("(the model's own)", "lift")?;
    assert_eq!(
        ui.state.doc.level.instances[0].material.as_deref(),
        Some("lift")
    );
    assert_eq!(ui.state.history.undo_len(), 1);
    // The inspector now shows the override's fields.
    ui.pass(Vec::new());
    assert!(
        ui.painted.has_prefix("Material \"lift\""),
        "override fields shown"
    );
    Ok(())
}

#[test]
fn a_composed_worlds_base_offers_its_models_and_materials() -> anyhow::Result<()> {
    let base = Level::parse(
        std::path::Path::new("common.ron"),
        r#"Level(
            materials: [(name: "wall_white", kind: Diffuse, base_color: (0.8, 0.8, 0.8))],
            boxes: [(name: "kit_crate", size: (1, 1, 1), material: "wall_white")],
            camera: (position: (0, 1, 5), look_at: (0, 1, 0), vertical_fov_deg: 50),
        )"#,
    )?;
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    state.selection.click(Some(0), SelectMode::Replace);
    state.set_base(std::path::Path::new("common.ron"), Document::new(base));
    // A chamber defines few materials of its own (a long list scrolls in the popup).
    state.doc.level.materials.truncate(2);
    let mut ui = Panels::new(state);
    // The palette lists the base's model (found through its search field, the list scrolls);
    // a click asks the runner to place it.
    let search = ui.painted.find("search pieces")?;
    ui.type_into(search, "kit")?;
    ui.click_text("kit_crate (base)")?;
    let asked: Vec<&PanelOutput> = ui.outputs.iter().filter(|o| o.place.is_some()).collect();
    assert_eq!(asked.len(), 1);
    assert_eq!(asked[0].place, Some(PaletteItem::Model("kit_crate".into())));
    // The material combo box offers the base's material.
    ui.choose("(the model's own)", "wall_white")?;
    assert_eq!(
        ui.state.doc.level.instances[0].material.as_deref(),
        Some("wall_white")
    );
    ui.pass(Vec::new());
    assert!(
        ui.painted
            .has_prefix("Material \"wall_white\" (Diffuse, base file)")
    );
    Ok(())
}
