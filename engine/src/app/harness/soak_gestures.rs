//! The shell soak's editor gestures (`soak_shell.rs`): the egui events of a click on an
//! instance where the editor's camera shows it, and of a drag of the selection's gizmo handle,
//! one list of events per pass, on the soak's view of [`VIEW`] points.
//!
//! Owns: [`Gesture`], [`select`], [`drag`]. Main thread, between the editor's passes. Must not:
//! change the editor's state (the passes that carry the events do).

use std::collections::VecDeque;

use glam::Vec2;

use crate::app::edit::{EditMode, project};

/// The screen the shell and the editor are laid out on, points.
pub(super) const VIEW: Vec2 = Vec2::new(1280.0, 720.0);

/// The editor gesture under way: one list of events per pass, then what to check.
pub(super) struct Gesture {
    pub(super) passes: VecDeque<(Vec<egui::Event>, egui::Modifiers)>,
    /// After a drag: the instance dragged and its translation before.
    pub(super) dragged: Option<(usize, [f32; 3])>,
}

/// The document's translation of instance `index`.
pub(super) fn translation(mode: &EditMode, index: usize) -> Option<[f32; 3]> {
    let entry = mode.state.doc.level.instances.get(index)?;
    Some(entry.transform.translation)
}

fn moved(p: Vec2) -> egui::Event {
    egui::Event::PointerMoved(egui::pos2(p.x, p.y))
}

fn button(p: Vec2, pressed: bool) -> egui::Event {
    egui::Event::PointerButton {
        pos: egui::pos2(p.x, p.y),
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    }
}

/// A click where instance `pick` (modulo the document's count) shows, if it is in view.
pub(super) fn select(mode: &EditMode, pick: u32) -> Option<Gesture> {
    let camera = mode.camera?.desc();
    let instances = &mode.state.doc.level.instances;
    let n = instances.len();
    // The first of the instances from `pick` on whose origin is in the view.
    let p = (0..n).find_map(|k| {
        let entry = &instances[(pick as usize + k) % n];
        let p = project(&camera, VIEW, glam::Vec3::from(entry.transform.translation))?;
        (p.cmpge(Vec2::ZERO).all() && p.cmplt(VIEW).all()).then_some(p)
    })?;
    let none = egui::Modifiers::NONE;
    Some(Gesture {
        passes: [
            vec![moved(p)],
            vec![button(p, true)],
            vec![button(p, false)],
        ]
        .into_iter()
        .map(|e| (e, none))
        .collect(),
        dragged: None,
    })
}

/// A drag of the selection's gizmo handle `axis` by `by` points, over six passes.
pub(super) fn drag(mode: &EditMode, axis: usize, by: Vec2) -> Option<Gesture> {
    let index = mode.state.selection.primary()?;
    let camera = mode.camera?.desc();
    let entry = mode.state.doc.level.instances.get(index)?;
    let handles = mode.gizmo.handles(&camera, VIEW, entry)?;
    let end = handles.ends_px.get(axis).copied().flatten()?;
    let grab = handles.centre_px.lerp(end, 0.7);
    let mut passes = vec![vec![moved(grab)], vec![button(grab, true)]];
    for k in 1..=6 {
        passes.push(vec![moved(grab + by * k as f32 / 6.0)]);
    }
    passes.push(vec![button(grab + by, false)]);
    passes.push(Vec::new());
    Some(Gesture {
        passes: passes
            .into_iter()
            .map(|e| (e, egui::Modifiers::NONE))
            .collect(),
        dragged: Some((index, entry.transform.translation)),
    })
}
