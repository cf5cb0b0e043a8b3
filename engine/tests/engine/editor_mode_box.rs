//! The editor over a running level, headless (issue 12), continued: a left drag off the
//! gizmo is a box select of what it wholly holds (Shift adds, Ctrl toggles, a band over
//! nothing clears); the recovery file follows every finished command (not mid-drag), keeps an
//! offered older one aside, and goes when undo reaches the file's state.

use crate::editor_common;

use candela::app::edit::older_recovery_path;
use candela::editor::{Edit, recovery_path, restore_recovery};
use editor_common::mode_run::*;
use glam::{Vec2, Vec3};

#[test]
fn a_box_drag_selects_what_it_holds_with_shift_adding_and_ctrl_toggling() -> anyhow::Result<()> {
    let mut run = start("mode_box")?;
    let (left, right) = (Vec3::new(-1.5, 1.0, 0.0), Vec3::new(1.5, 1.0, 0.0));
    let (lo, hi) = cube_band(&run, left, 30.0);
    drag(&mut run, lo, hi, 4)?;
    assert_eq!(
        run.mode.state.selection.instances(),
        &[1],
        "the left cube alone: the floor and wall are not wholly inside"
    );
    assert!(run.mode.box_drag().is_none(), "the band ends on release");
    let (lo, hi) = cube_band(&run, right, 30.0);
    // Dragged from the bottom-right corner to the top-left: the same band.
    drag_with(&mut run, hi, lo, 4, egui::Modifiers::SHIFT)?;
    assert_eq!(run.mode.state.selection.instances(), &[1, 2]);
    let (lo, _) = cube_band(&run, left, 30.0);
    let (_, hi) = cube_band(&run, right, 30.0);
    drag_with(&mut run, lo, hi, 4, egui::Modifiers::CTRL)?;
    assert!(run.mode.state.selection.is_empty(), "both toggled off");
    drag(&mut run, lo, hi, 4)?;
    assert_eq!(run.mode.state.selection.instances(), &[1, 2]);
    // A band over nothing wholly (the floor reaches past it) clears the selection; a band is
    // no edit.
    drag(
        &mut run,
        Vec2::new(1100.0, 1000.0),
        Vec2::new(1400.0, 1100.0),
        3,
    )?;
    assert!(run.mode.state.selection.is_empty());
    assert!(!run.mode.state.history.can_undo(), "selecting is no edit");
    Ok(())
}

#[test]
fn the_recovery_file_follows_every_finished_command_and_keeps_an_offered_one() -> anyhow::Result<()>
{
    // An older session's recovery file, newer than the level: offered on opening.
    let older = "Level(instances: [])";
    let mut run = start_with("mode_recovery", |path| {
        std::fs::write(recovery_path(path), older)?;
        let level_time = std::time::SystemTime::now() - std::time::Duration::from_secs(60);
        std::fs::File::options()
            .write(true)
            .open(path)?
            .set_modified(level_time)?;
        Ok(())
    })?;
    let path = run.mode.state.path.clone();
    let recovery = recovery_path(&path);
    assert_eq!(
        std::fs::read_to_string(&recovery)?,
        older,
        "offered, untouched"
    );
    let cube = screen(&run, Vec3::new(1.5, 1.0, 0.5));
    click(&mut run, cube, egui::Modifiers::NONE)?;
    assert_eq!(
        std::fs::read_to_string(&recovery)?,
        older,
        "a click is no edit"
    );
    let h = handles(&run, 2);
    let grab = h.centre_px.lerp(h.ends_px[0].expect("X"), 0.7);
    // Mid-drag the file waits for the command to end.
    pass(&mut run, vec![moved_to(grab)])?;
    pass(&mut run, vec![button(grab, true, egui::Modifiers::NONE)])?;
    for k in 1..=3 {
        pass(
            &mut run,
            vec![moved_to(grab + Vec2::new(40.0 * k as f32, 0.0))],
        )?;
    }
    assert!(run.mode.state.history.dragging());
    assert_eq!(std::fs::read_to_string(&recovery)?, older);
    pass(
        &mut run,
        vec![button(
            grab + Vec2::new(120.0, 0.0),
            false,
            egui::Modifiers::NONE,
        )],
    )?;
    pass(&mut run, Vec::new())?;
    // Released: the offered file is kept aside and the recovery file holds the move.
    assert_eq!(std::fs::read_to_string(older_recovery_path(&path))?, older);
    assert_eq!(restore_recovery(&path)?, run.mode.state.doc);
    assert!(translation(&run, 2).x > 1.6);
    run.mode
        .apply(&mut run.engine, Edit::DuplicateInstance { index: 1 })?;
    assert_eq!(
        restore_recovery(&path)?,
        run.mode.state.doc,
        "after a typed edit too"
    );
    // Undone back to the file: nothing left to recover.
    assert!(run.mode.undo(&mut run.engine)?);
    assert!(run.mode.undo(&mut run.engine)?);
    assert!(!run.mode.state.dirty());
    assert!(!recovery.exists(), "no recovery file for the saved state");
    assert!(run.mode.redo(&mut run.engine)?);
    assert_eq!(
        restore_recovery(&path)?,
        run.mode.state.doc,
        "redone: written again"
    );
    Ok(())
}
