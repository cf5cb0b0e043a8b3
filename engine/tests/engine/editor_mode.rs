//! The editor over a running level, headless (issue 12): `EditMode` in a headless engine (CPU
//! tracer) driven by synthetic egui input on a 2560 × 1440 point screen. A click picks the
//! cube under the pointer (Shift adds, Ctrl toggles, the sky clears); dragging the translate
//! gizmo's X handle moves the cube so that it stays under the pointer, as one command, and
//! the world follows (picked where it went); with grid snapping the move is whole steps;
//! the rotate tool (E) turns it by the snapped angle; a typed value moves it; Ctrl+Z and
//! Ctrl+Shift+Z go back and forth, the world with them. (Box select and the recovery file:
//! `editor_mode_box.rs`.)

use crate::editor_common;

use candela::app::edit::Gizmo;
use candela::assets::TransformDesc;
use candela::editor::{Edit, InstanceField};
use editor_common::mode_run::*;
use glam::{Vec2, Vec3};

#[test]
fn clicks_select_with_shift_adding_ctrl_toggling_and_the_sky_clearing() -> anyhow::Result<()> {
    let mut run = start("mode_select")?;
    let right = screen(&run, Vec3::new(1.5, 1.0, 0.5));
    let left = screen(&run, Vec3::new(-1.5, 1.0, 0.5));
    click(&mut run, right, egui::Modifiers::NONE)?;
    assert_eq!(run.mode.state.selection.instances(), &[2]);
    click(&mut run, left, egui::Modifiers::SHIFT)?;
    assert_eq!(run.mode.state.selection.instances(), &[2, 1]);
    click(&mut run, right, egui::Modifiers::CTRL)?;
    assert_eq!(run.mode.state.selection.instances(), &[1]);
    // High above the wall, between the outliner and the inspector: the sky.
    click(&mut run, Vec2::new(1280.0, 40.0), egui::Modifiers::NONE)?;
    assert!(run.mode.state.selection.is_empty());
    assert!(run.mode.last_pick.is_none());
    assert!(!run.mode.state.history.can_undo(), "selecting is no edit");
    Ok(())
}

#[test]
fn the_gizmo_moves_and_turns_the_selection_in_one_command_and_undo_redo_follow()
-> anyhow::Result<()> {
    let mut run = start("mode_gizmo")?;
    let start_at = translation(&run, 2);
    let cube = screen(&run, Vec3::new(1.5, 1.0, 0.5));
    click(&mut run, cube, egui::Modifiers::NONE)?;
    assert_eq!(run.mode.state.selection.primary(), Some(2));
    let h = handles(&run, 2);
    let x_end = h.ends_px[0].expect("the X handle");
    assert_eq!(Gizmo::hit(&h, h.centre_px.lerp(x_end, 0.7)), Some(0));
    let grab = h.centre_px.lerp(x_end, 0.7);
    let to = grab + Vec2::new(240.0, 0.0);
    drag(&mut run, grab, to, 6)?;
    let now = translation(&run, 2);
    assert!(now.x > start_at.x + 0.5, "moved along +X: {now}");
    assert!((now.y - start_at.y).abs() < 1e-4 && (now.z - start_at.z).abs() < 1e-4);
    // The grabbed point stayed under the pointer.
    let centre_now = screen(&run, now);
    let expected = to - (grab - h.centre_px);
    assert!(
        centre_now.distance(expected) < 1.0,
        "{centre_now} vs {expected}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 1, "one command");
    assert_eq!(
        drawn_at(&run, now + Vec3::Z * 0.5),
        Some(2),
        "drawn where it went"
    );
    // Grid snapping: the drag's amount is whole steps.
    run.mode.state.snap.grid = Some(0.5);
    let before = translation(&run, 2);
    let h = handles(&run, 2);
    let grab = h.centre_px.lerp(h.ends_px[0].expect("X"), 0.7);
    drag(&mut run, grab, grab + Vec2::new(173.0, 0.0), 5)?;
    let amount = translation(&run, 2).x - before.x;
    assert!(amount > 0.4, "{amount}");
    assert!(
        (amount / 0.5 - (amount / 0.5).round()).abs() < 1e-3,
        "{amount}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 2);
    // Rotate (E) about Y: 90 points of pointer at 0.5°/point, snapped to 15°, is 45°.
    run.mode.state.snap.angle_deg = Some(15.0);
    pass(&mut run, vec![key(egui::Key::E, egui::Modifiers::NONE)])?;
    let h = handles(&run, 2);
    let grab = h.centre_px.lerp(h.ends_px[1].expect("Y"), 0.7);
    drag(&mut run, grab, grab + Vec2::new(92.0, 0.0), 4)?;
    let r = run.mode.state.doc.level.instances[2].transform.rotation_deg;
    assert!(
        (r[1] - 45.0).abs() < 1e-3 && r[0].abs() < 1e-3 && r[2].abs() < 1e-3,
        "{r:?}"
    );
    assert_eq!(run.mode.state.history.entries().len(), 3);
    // A typed value moves it as well, and the world follows.
    let mut typed: TransformDesc = run.mode.state.doc.level.instances[2].transform;
    typed.translation = [0.0, 1.0, 1.0];
    run.mode.apply(
        &mut run.engine,
        Edit::Instance {
            index: 2,
            field: InstanceField::Transform(typed),
        },
    )?;
    pass(&mut run, Vec::new())?;
    assert_eq!(drawn_at(&run, Vec3::new(0.0, 1.0, 1.6)), Some(2));
    // Ctrl+Z four times: back where it started, drawn there; Ctrl+Shift+Z redoes.
    let command = egui::Modifiers::COMMAND;
    for _ in 0..4 {
        pass(&mut run, vec![key(egui::Key::Z, command)])?;
    }
    pass(&mut run, Vec::new())?;
    assert_eq!(translation(&run, 2), start_at);
    assert_eq!(
        run.mode.state.doc.level.instances[2].transform.rotation_deg,
        [0.0; 3]
    );
    assert_eq!(drawn_at(&run, Vec3::new(1.5, 1.0, 0.5)), Some(2));
    assert_eq!(
        drawn_at(&run, Vec3::new(0.0, 1.0, 1.6)),
        Some(3),
        "the wall behind"
    );
    pass(
        &mut run,
        vec![key(egui::Key::Z, command | egui::Modifiers::SHIFT)],
    )?;
    assert!(translation(&run, 2).x > start_at.x + 0.5, "redone");
    Ok(())
}
