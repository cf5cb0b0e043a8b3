//! Measure and align through synthetic input over `EditMode` and a headless engine (issue 33):
//! the inspector shows the selected cube's bounds in metres; dragging the left cube's X handle
//! so that its +X face stops 5 cm short of the right cube's −X face snaps it to touch (a face
//! within `FACE_SNAP_METRES`), as one command; a drag that stops 30 cm short stays where the
//! pointer put it.

use crate::editor_common;

use candela::app::edit::FACE_SNAP_METRES;
use editor_common::mode_run::{
    Run, click, drag, handles, pass_painted, screen, start, translation,
};
use glam::Vec3;

/// Drags cube 1's X handle so that, unsnapped, its centre would end at `x` (metres).
fn drag_left_cube_to(run: &mut Run, x: f32) -> anyhow::Result<()> {
    let h = handles(run, 1);
    let grab = h.centre_px.lerp(h.ends_px[0].expect("the X handle"), 0.7);
    // The X axis through the cube lies parallel to the picture: the grabbed point keeps its
    // offset from the centre on the screen.
    let to = screen(run, Vec3::new(x, 1.0, 0.0)) + (grab - h.centre_px);
    drag(run, grab, to, 6)
}

#[test]
fn a_dragged_cube_snaps_to_the_face_of_its_neighbour_and_shows_its_bounds() -> anyhow::Result<()> {
    let mut run = start("editor_align")?;
    let cube = screen(&run, Vec3::new(-1.5, 1.0, 0.5));
    click(&mut run, cube, egui::Modifiers::NONE)?;
    assert_eq!(run.mode.state.selection.primary(), Some(1));
    let painted = pass_painted(&mut run, Vec::new())?;
    assert!(
        painted.has_prefix("bounds (m): 1.00 × 1.00 × 1.00  (x -2.00…-1.00"),
        "{:?}",
        painted.texts()
    );
    // 30 cm short of the right cube (its −X face at x = 1): no snap.
    drag_left_cube_to(&mut run, 0.2)?;
    let at = translation(&run, 1);
    assert!((at.x - 0.2).abs() < 2e-3, "{at}");
    // 5 cm short: it snaps to touch, exactly.
    assert!(0.05 < FACE_SNAP_METRES);
    drag_left_cube_to(&mut run, 0.45)?;
    let at = translation(&run, 1);
    assert!((at.x - 0.5).abs() < 1e-5, "snapped to touch: {at}");
    assert!((at.y - 1.0).abs() < 1e-6 && at.z.abs() < 1e-6);
    assert_eq!(run.mode.state.history.undo_len(), 2, "one command per drag");
    let painted = pass_painted(&mut run, Vec::new())?;
    assert!(painted.has_prefix("bounds (m): 1.00 × 1.00 × 1.00"));
    Ok(())
}
