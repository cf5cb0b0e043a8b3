//! The inspector edits every kind of item, driven by synthetic input (issue 33,
//! `editor_common::input`): the outliner puts a volume, laser, material or clip in focus
//! (found through its search field), and typed fields, check boxes and combo boxes change
//! what it detects, every laser field, a material shared by several instances, a clip's
//! duration and autoplay, an instance's body and the light groups that start off — each
//! change one undoable command. A click on a problem puts the item it names in focus,
//! whatever its kind.

use crate::editor_common;

use candela::assets::{BodyEntry, ConditionEntry, Detect, PlayMode, ShapeEntry};
use candela::editor::{EditorState, SelectMode, Touch, check_references};
use candela::level::ItemRef;
use editor_common::input::Panels;
use editor_common::platform_with_laser;

/// The platform level's panels, nothing selected.
fn panels() -> anyhow::Result<Panels> {
    let state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    Ok(Panels::new(state))
}

/// Types `query` into the outliner's search field, then clicks the highest `label` below it.
fn focus(ui: &mut Panels, query: &str, label: &str) -> anyhow::Result<()> {
    let search = ui.painted.find("search")?;
    ui.type_into(search, query)?;
    let below = search.bottom();
    let at = (ui.painted.0.iter())
        .filter(|(t, r)| t == label && r.top() > below)
        .map(|(_, r)| *r)
        .min_by(|a, b| a.top().total_cmp(&b.top()))
        .ok_or_else(|| anyhow::anyhow!("the outliner shows no {label:?}"))?;
    ui.click_at(at);
    Ok(())
}

/// The rect of `text` in the inspector (the right half of the screen).
fn right(ui: &Panels, text: &str) -> anyhow::Result<egui::Rect> {
    (ui.painted)
        .find_where(|t, r| t == text && r.left() > 640.0)
        .ok_or_else(|| anyhow::anyhow!("the inspector shows no {text:?}"))
}

#[test]
fn a_volume_in_focus_changes_what_it_detects() -> anyhow::Result<()> {
    let mut ui = panels()?;
    focus(&mut ui, "plate on", "plate on plate")?;
    assert_eq!(ui.state.selection.item(), Some(ItemRef::Volume(0)));
    assert!(
        ui.painted.has_prefix("Volume \"plate\""),
        "the inspector shows it"
    );
    let lasers = right(&ui, "Lasers")?;
    ui.click_at(lasers);
    let volume = &ui.state.doc.level.gameplay.volumes[0];
    assert_eq!(volume.detects, vec![Detect::Bodies, Detect::Lasers]);
    assert_eq!(ui.state.history.undo_len(), 1);
    Ok(())
}

#[test]
fn every_field_of_a_laser_is_typed() -> anyhow::Result<()> {
    let mut ui = panels()?;
    focus(&mut ui, "laser 0", "laser 0 on switch")?;
    assert_eq!(ui.state.selection.item(), Some(ItemRef::Laser(0)));
    ui.type_beside("max reflections", 0, "7")?;
    ui.type_beside("max reflections", 1, "12.5")?;
    ui.type_beside("origin (m)", 2, "0.3")?;
    let laser = &ui.state.doc.level.gameplay.lasers[0];
    assert_eq!(laser.max_reflections, 7);
    assert_eq!(laser.max_length, 12.5);
    assert_eq!(laser.origin, [0.0, 0.1, 0.3]);
    assert_eq!(ui.state.history.undo_len(), 3, "one command per field");
    Ok(())
}

#[test]
fn a_material_in_focus_changes_for_every_instance_using_it() -> anyhow::Result<()> {
    let mut ui = panels()?;
    focus(&mut ui, "glass", "glass")?;
    assert_eq!(ui.state.selection.item(), Some(ItemRef::Material(6)));
    let label = right(&ui, "roughness")?;
    let field = (ui.painted.number_left_of(label))
        .ok_or_else(|| anyhow::anyhow!("no value beside the roughness slider"))?;
    ui.type_into(field, "0.25")?;
    assert_eq!(ui.state.doc.level.materials[6].roughness, 0.25);
    assert_eq!(ui.state.history.undo_len(), 1);
    // The level material itself changed: the runner re-spawns every model that uses it.
    assert!(ui.outputs.iter().any(|o| o.touched.contains(&Touch::Level)));
    Ok(())
}

#[test]
fn a_clip_in_focus_takes_a_duration_and_loops_from_the_start() -> anyhow::Result<()> {
    let mut ui = panels()?;
    // The clip and the rule share the name; the Clips section comes first.
    focus(&mut ui, "lift_up", "lift_up")?;
    assert_eq!(ui.state.selection.item(), Some(ItemRef::Clip(0)));
    ui.type_beside("duration (s)", 0, "6")?;
    let clip = &ui.state.doc.level.gameplay.animations[0];
    let times: Vec<f32> = clip.tracks[0].keys.iter().map(|k| k.time_seconds).collect();
    assert_eq!(times, [0.0, 6.0], "every key scaled");
    assert_eq!(clip.events[0].time_seconds, 6.0, "its event too");
    ui.choose("no (a rule starts it)", "Loop")?;
    let autoplay = &ui.state.doc.level.gameplay.autoplay;
    assert_eq!(autoplay.len(), 1);
    assert_eq!(
        (autoplay[0].clip.as_str(), autoplay[0].mode),
        ("lift_up", PlayMode::Loop)
    );
    assert_eq!(ui.state.history.undo_len(), 2);
    Ok(())
}

#[test]
fn a_body_changes_kind_and_mass() -> anyhow::Result<()> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    // Instance 9: the glass cube, a dynamic body of 4 kg.
    state.selection.click(Some(9), SelectMode::Replace);
    let mut ui = Panels::new(state);
    ui.type_beside("mass (kg)", 0, "12.5")?;
    let body = ui.state.doc.level.instances[9].body.clone();
    let dynamic = |mass| BodyEntry::Dynamic {
        shape: ShapeEntry::Box,
        mass,
        ccd: false,
    };
    assert_eq!(body, Some(dynamic(12.5)));
    ui.choose("Dynamic", "Sensor")?;
    let body = ui.state.doc.level.instances[9].body.clone();
    assert_eq!(
        body,
        Some(BodyEntry::Sensor {
            shape: ShapeEntry::Box
        })
    );
    assert_eq!(ui.state.history.undo_len(), 2);
    ui.state.undo()?;
    assert_eq!(ui.state.doc.level.instances[9].body, Some(dynamic(12.5)));
    Ok(())
}

#[test]
fn a_light_group_is_selected_and_starts_on() -> anyhow::Result<()> {
    let mut ui = panels()?;
    focus(&mut ui, "group 2", "group 2")?;
    assert_eq!(ui.state.selection.instances(), [12], "the group's instance");
    // The inspector shows the lamp, its group, and whether the group starts off.
    assert_eq!(ui.state.doc.level.gameplay.lights_off, [2]);
    let starts_off = right(&ui, "starts off")?;
    ui.click_at(starts_off);
    assert!(ui.state.doc.level.gameplay.lights_off.is_empty());
    assert_eq!(ui.state.history.undo_len(), 1);
    Ok(())
}

#[test]
fn a_click_on_a_rules_problem_puts_the_rule_in_focus() -> anyhow::Result<()> {
    let mut state = EditorState::new(std::path::Path::new("x.ron"), platform_with_laser()?);
    state.doc.level.gameplay.rules[1].when = ConditionEntry::Occupied("nowhere".into());
    state.problems = check_references(&state.doc.level);
    // The rule's problem (the event it no longer waits for is one too).
    let message = (state.problems.iter())
        .find(|p| p.item == ItemRef::Rule(1))
        .map(ToString::to_string)
        .ok_or_else(|| anyhow::anyhow!("no problem of the rule: {:?}", state.problems))?;
    let mut ui = Panels::new(state);
    ui.click_text(&message)?;
    assert_eq!(ui.state.selection.item(), Some(ItemRef::Rule(1)));
    assert!(
        ui.painted.has_prefix("Rule \"lever_pulled\""),
        "the inspector shows it"
    );
    Ok(())
}
