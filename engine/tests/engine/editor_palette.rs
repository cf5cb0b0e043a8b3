//! Placing pieces from the palette through synthetic input over a headless engine (issue 33):
//! a click on a piece in the Palette window places it where the view's centre ray meets the
//! level (here the wall facing the camera), as one command that undo takes away; P with the
//! pointer over the view places the palette's current piece under the pointer (here on the
//! floor). The model files of the level's folder are offered too, and placing one adds its
//! model entry in the same command.

use crate::editor_common;

use candela::app::edit::palette_folder;
use candela::editor::{PaletteItem, model_files};
use editor_common::mode_run::{
    self, Run, click, key, moved_to, pass, pass_painted, screen, start, translation,
};
use glam::{Vec2, Vec3};

/// Clicks the palette entry painted as `label`.
fn click_piece(run: &mut Run, label: &str) -> anyhow::Result<()> {
    let painted = pass_painted(run, Vec::new())?;
    let at = painted.find(label)?.center();
    click(run, Vec2::new(at.x, at.y), egui::Modifiers::NONE)
}

#[test]
fn a_piece_clicked_in_the_palette_lands_on_the_wall_and_undo_takes_it_away() -> anyhow::Result<()> {
    let mut run = start("editor_palette_click")?;
    let count = run.mode.state.doc.level.instances.len();
    click_piece(&mut run, "cube")?;
    let level = &run.mode.state.doc.level;
    assert_eq!(level.instances.len(), count + 1, "one instance placed");
    assert_eq!(level.instances[count].model, "cube");
    assert_eq!(
        run.mode.state.selection.instances(),
        [count],
        "and selected"
    );
    // The view's centre ray from (0, 1, 5) towards −Z meets the wall's face at z = −2.9.
    let at = translation(&run, count);
    assert!((at - Vec3::new(0.0, 1.0, -2.9)).length() < 1e-3, "{at}");
    assert_eq!(run.mode.state.history.undo_len(), 1, "one command");
    assert_eq!(
        run.mode.state.palette.current,
        Some(PaletteItem::Model("cube".into()))
    );
    pass(&mut run, vec![key(egui::Key::Z, egui::Modifiers::COMMAND)])?;
    assert_eq!(
        run.mode.state.doc.level.instances.len(),
        count,
        "undo removes it"
    );
    // P over the floor places the current piece there.
    let floor = screen(&run, Vec3::new(0.5, 0.0, 2.0));
    pass(&mut run, vec![moved_to(floor)])?;
    pass(&mut run, vec![key(egui::Key::P, egui::Modifiers::NONE)])?;
    let level = &run.mode.state.doc.level;
    assert_eq!(level.instances.len(), count + 1);
    let at = translation(&run, count);
    assert!((at - Vec3::new(0.5, 0.0, 2.0)).length() < 0.02, "{at}");
    Ok(())
}

#[test]
fn a_model_file_of_the_levels_folder_is_offered_and_placed_with_its_model_entry()
-> anyhow::Result<()> {
    let mut run = mode_run::start_with("editor_palette_file", |level| {
        let folder = level.parent().ok_or_else(|| anyhow::anyhow!("no folder"))?;
        std::fs::create_dir_all(folder.join("kit"))?;
        std::fs::write(
            folder.join("kit/tri.obj"),
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        )?;
        Ok(())
    })?;
    let folder = palette_folder(&run.mode.state.path);
    let root = run.mode.world.target.root.path().to_path_buf();
    assert_eq!(model_files(&root, &folder), ["kit/tri.obj"]);
    assert_eq!(run.mode.state.palette.files, ["kit/tri.obj"]);
    let (models, count) = {
        let level = &run.mode.state.doc.level;
        (level.models.len(), level.instances.len())
    };
    click_piece(&mut run, "kit/tri.obj (file)")?;
    let level = &run.mode.state.doc.level;
    assert_eq!(level.models.len(), models + 1);
    assert_eq!(level.models[models].path, "kit/tri.obj");
    assert_eq!(level.instances[count].model, level.models[models].name);
    assert_eq!(
        run.mode.state.history.undo_len(),
        1,
        "model and instance: one command"
    );
    assert!(run.mode.undo(&mut run.engine)?);
    let level = &run.mode.state.doc.level;
    assert_eq!((level.models.len(), level.instances.len()), (models, count));
    Ok(())
}
