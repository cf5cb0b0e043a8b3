//! A composed level edited as one world (issue 33): the editor over Reflect's first chamber,
//! a part of the world composed over `common.ron`, shows a wall's `common.ron` material in the
//! inspector and edits it; Ctrl+S writes the changed material to `common.ron` (one line
//! changed, the minimal-diff save) and leaves the chamber's file byte for byte as it was, and
//! the status line names the file written. The saved files, loaded again through the loader
//! the game uses (`level::load_composed`), give the world the editor held.
//!
//! Driven by synthetic input through the egui context (`editor_common::mode_run`) over a
//! headless engine, in a scratch copy of Reflect's assets.

use crate::editor_common;

use candela::assets::AssetRoot;
use candela::level::{compose_levels, load_composed};
use editor_common::input::replace_text;
use editor_common::mode_run::{self, Run, click, key, pass, pass_painted};
use editor_common::reflect_files;
use glam::Vec2;

fn centre(r: egui::Rect) -> Vec2 {
    Vec2::new(r.center().x, r.center().y)
}

/// Clicks the last text painted for which `keep` holds.
fn click_where(run: &mut Run, what: &str, keep: impl Fn(&str) -> bool) -> anyhow::Result<()> {
    let painted = pass_painted(run, Vec::new())?;
    let at = (painted.find_where(|t, _| keep(t)))
        .ok_or_else(|| anyhow::anyhow!("no {what} painted: {:?}", painted.texts()))?;
    click(run, centre(at), egui::Modifiers::NONE)
}

#[test]
fn a_common_material_edited_from_a_chamber_is_saved_to_common_ron_only() -> anyhow::Result<()> {
    let mut run = mode_run::start_chamber("editor_composed", 0)?;
    let root = run.mode.world.target.root.clone();
    let (base_path, parts) = reflect_files(root.path());
    let chamber_before = std::fs::read(&parts[0])?;
    let common_before = std::fs::read_to_string(&base_path)?;
    assert!(
        run.mode.state.doc.level.materials.is_empty(),
        "chamber 1 defines no material of its own"
    );
    // A wall drawn with common.ron's wall_white, selected in the outliner: the inspector
    // shows the base material's fields.
    let level = &run.mode.state.doc.level;
    let wall = (level.instances.iter())
        .position(|i| i.material.as_deref() == Some("wall_white"))
        .expect("chamber 1 has a wall_white wall");
    let label = format!("{} #{wall}", level.instances[wall].model);
    click_where(&mut run, &label, |t| t == label)?;
    assert_eq!(run.mode.state.selection.primary(), Some(wall));
    // The material's fields are below the instance's: scroll the inspector down (the wheel
    // over its transform fields).
    let over = pass_painted(&mut run, Vec::new())?.find("translation (m)")?;
    let wheel = egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, -400.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
        modifiers: egui::Modifiers::NONE,
    };
    pass(
        &mut run,
        vec![egui::Event::PointerMoved(over.center()), wheel],
    )?;
    for _ in 0..20 {
        pass(&mut run, Vec::new())?;
    }
    let painted = pass_painted(&mut run, Vec::new())?;
    assert!(painted.has_prefix("Material \"wall_white\" (Diffuse, base file)"));
    // Type 0.25 into the roughness slider's value field.
    let label = painted.find("roughness")?;
    let field = (painted.number_left_of(label))
        .ok_or_else(|| anyhow::anyhow!("no value beside the roughness slider"))?;
    click(&mut run, centre(field), egui::Modifiers::NONE)?;
    assert!(
        run.ctx.egui_wants_keyboard_input(),
        "the field has the keyboard"
    );
    pass(&mut run, replace_text("0.25"))?;
    pass(&mut run, Vec::new())?;
    let base = run.mode.state.base().expect("the chamber's base").clone();
    let wall_white = |level: &candela::assets::Level| {
        (level.materials.iter())
            .find(|m| m.name == "wall_white")
            .map(|m| m.roughness)
    };
    assert_eq!(wall_white(&base), Some(0.25), "the base's material edited");
    assert_eq!(run.mode.state.history.undo_len(), 1, "one command");
    // Ctrl+S: common.ron written, the chamber not.
    pass(&mut run, vec![key(egui::Key::S, egui::Modifiers::COMMAND)])?;
    let said = run.mode.messages().last().cloned().unwrap_or_default();
    assert!(said.starts_with("saved "), "{said}");
    assert!(
        said.contains("common.ron") && !said.contains("chamber_1.ron"),
        "{said}"
    );
    assert!(!run.mode.state.dirty());
    assert_eq!(
        std::fs::read(&parts[0])?,
        chamber_before,
        "the chamber's file is byte-identical"
    );
    let common_after = std::fs::read_to_string(&base_path)?;
    let changed: Vec<(&str, &str)> = (common_before.lines().zip(common_after.lines()))
        .filter(|(a, b)| a != b)
        .collect();
    assert_eq!(
        common_before.lines().count(),
        common_after.lines().count(),
        "{common_after}"
    );
    assert_eq!(
        changed.len(),
        1,
        "one line of common.ron changed: {changed:?}"
    );
    assert!(
        changed[0].1.contains("wall_white") && changed[0].1.contains("roughness: 0.25"),
        "{changed:?}"
    );
    // Loaded again as the game loads its world: what the editor held.
    let root = AssetRoot::new(root.path())?;
    let (loaded, _) = load_composed(&base_path, &parts, &root)?;
    assert_eq!(wall_white(&loaded), Some(0.25));
    let mut held = Vec::new();
    for (k, path) in parts.iter().enumerate() {
        let level = if k == 0 {
            run.mode.state.doc.level.clone()
        } else {
            candela::assets::Level::read(path)?
        };
        held.push((path.clone(), level));
    }
    assert_eq!(loaded, compose_levels(&base, &held)?, "the world as edited");
    // Ctrl+Z undoes it, and the next save gives common.ron its old material again.
    pass(&mut run, vec![key(egui::Key::Z, egui::Modifiers::COMMAND)])?;
    pass(&mut run, vec![key(egui::Key::S, egui::Modifiers::COMMAND)])?;
    let old = candela::assets::Level::parse(&base_path, &common_before)?;
    assert_eq!(candela::assets::Level::read(&base_path)?, old);
    assert_eq!(std::fs::read(&parts[0])?, chamber_before);
    Ok(())
}

#[test]
fn the_outliner_lists_common_ron_materials_and_a_click_puts_one_in_the_inspector()
-> anyhow::Result<()> {
    use candela::editor::ui::outliner::SEARCH_ID;
    use candela::level::ItemRef;
    let mut run = mode_run::start_chamber("editor_composed_outliner", 0)?;
    let base = run.mode.state.base().expect("the chamber's base").clone();
    let white = (base.materials.iter())
        .position(|m| m.name == "wall_white")
        .expect("common.ron defines wall_white");
    // Narrow the outliner to "white" (the instances list is long), as a designer would.
    run.ctx
        .memory_mut(|m| m.request_focus(egui::Id::unique(SEARCH_ID)));
    pass(&mut run, Vec::new())?;
    pass(&mut run, vec![egui::Event::Text("white".into())])?;
    let painted = pass_painted(&mut run, Vec::new())?;
    assert!(
        painted.has_prefix("Materials (common.ron)"),
        "the base's materials have their heading: {:?}",
        painted.texts()
    );
    run.ctx
        .memory_mut(|m| m.surrender_focus(egui::Id::unique(SEARCH_ID)));
    click_where(&mut run, "wall_white", |t| t == "wall_white")?;
    assert_eq!(
        run.mode.state.selection.base_item(),
        Some(ItemRef::Material(white)),
        "the base material is in focus"
    );
    assert_eq!(
        run.mode.state.selection.item(),
        None,
        "no item of the chamber"
    );
    let painted = pass_painted(&mut run, Vec::new())?;
    assert!(
        painted.has_prefix("Material \"wall_white\" (Diffuse, base file)"),
        "the inspector shows it: {:?}",
        painted.texts()
    );
    Ok(())
}
