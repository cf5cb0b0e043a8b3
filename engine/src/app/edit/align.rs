//! Measure and align (issue 33): the selection's bounds in metres for the inspector
//! (`EditorState::bounds`), snapping a translate drag along a world axis to another
//! instance's face, and the grid drawn on the plane the drag moves in.
//!
//! Face snapping: the dragged instances' world box (the union of their models' bounds at the
//! new transforms) is shifted along the drag's axis by the smallest offset, under
//! [`FACE_SNAP_METRES`], that makes one of its two faces across that axis touch another
//! instance's opposite face (the two boxes overlapping across the other two axes: set against
//! it, stacked on it) or line up with the same face of any other instance (flush). Grid
//! snapping applies first; a face wins over the grid. Local axes that are not world axes, and
//! rotate and scale drags, do not snap to faces.
//!
//! Main thread, inside the editor's pass. Must not: touch the world or apply edits (it only
//! changes the drag's edit before `EditorState` applies it).

use glam::{Vec2, Vec3};

use super::camera::project;
use super::mode::EditMode;
use crate::assets::CameraDesc;
use crate::editor::{Edit, InstanceField};

/// How near (metres, along the drag's axis) a face must come to another face to snap to it.
pub const FACE_SNAP_METRES: f32 = 0.1;
/// Grid lines drawn each side of the dragged item on the drag's plane.
const GRID_LINES: i32 = 10;
/// The drag grid's colour (faint).
const GRID_COLOUR: egui::Color32 = egui::Color32::from_rgba_premultiplied(90, 90, 90, 90);

/// A world box: min and max corners, metres.
type Aabb = (Vec3, Vec3);

fn aabb(corners: &[Vec3]) -> Option<Aabb> {
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for &c in corners {
        lo = lo.min(c);
        hi = hi.max(c);
    }
    (lo.x <= hi.x).then_some((lo, hi))
}

/// Whether `a` and `b` overlap (strictly) across every axis but `k`.
fn overlap_across(a: Aabb, b: Aabb, k: usize) -> bool {
    (0..3)
        .filter(|&j| j != k)
        .all(|j| a.0[j] < b.1[j] && b.0[j] < a.1[j])
}

/// The offset along axis `k` (metres) that snaps `moved` to a face of one of `others`, if one
/// is within [`FACE_SNAP_METRES`] (see the module doc).
pub fn face_offset(moved: Aabb, others: &[Aabb], k: usize) -> Option<f32> {
    let mut best: Option<f32> = None;
    for &other in others {
        let mut candidates = vec![other.0[k] - moved.0[k], other.1[k] - moved.1[k]];
        if overlap_across(moved, other, k) {
            candidates.extend([other.0[k] - moved.1[k], other.1[k] - moved.0[k]]);
        }
        for d in candidates {
            if d.abs() < FACE_SNAP_METRES && best.is_none_or(|b| d.abs() < b.abs()) {
                best = Some(d);
            }
        }
    }
    best
}

/// The world axis (0, 1, 2) `dir` runs along, if it is one.
fn world_axis(dir: Vec3) -> Option<usize> {
    let a = dir.abs();
    (0..3).find(|&k| a[k] > 0.9999)
}

impl EditMode {
    /// The selection's world box (metres), from the world's model bounds; `None` when nothing
    /// selected has known bounds.
    pub fn selection_bounds(&self) -> Option<Aabb> {
        let level = &self.state.doc.level;
        let corners: Vec<Vec3> = (self.state.selection.instances().iter())
            .filter_map(|&i| self.world.world_box(level, i))
            .flatten()
            .collect();
        aabb(&corners)
    }

    /// `edit` (a translate drag's batch of transforms along `dir`) shifted so that the moved
    /// instances' box meets another instance's face (see the module doc).
    pub(super) fn align_to_faces(&self, edit: Edit, dir: Vec3) -> Edit {
        let Some(k) = world_axis(dir) else {
            return edit;
        };
        let Edit::Batch(mut edits) = edit else {
            return edit;
        };
        let level = &self.state.doc.level;
        let mut moved_corners = Vec::new();
        let mut moved = Vec::new();
        for e in &edits {
            if let Edit::Instance {
                index,
                field: InstanceField::Transform(t),
            } = e
            {
                moved.push(*index);
                moved_corners.extend(self.world.box_at(*index, t).into_iter().flatten());
            }
        }
        let Some(moved_box) = aabb(&moved_corners) else {
            return Edit::Batch(edits);
        };
        let others: Vec<Aabb> = (0..level.instances.len())
            .filter(|i| !moved.contains(i))
            .filter_map(|i| self.world.world_box(level, i))
            .filter_map(|c| aabb(&c))
            .collect();
        if let Some(d) = face_offset(moved_box, &others, k) {
            for e in &mut edits {
                if let Edit::Instance {
                    field: InstanceField::Transform(t),
                    ..
                } = e
                {
                    t.translation[k] += d;
                }
            }
        }
        Edit::Batch(edits)
    }

    /// Draws the grid of the plane a translate drag moves in: the plane through the dragged
    /// item's centre holding the drag's axis and the other world axis that faces the camera
    /// most; lines a grid step apart (the grid snap's, else 1 m).
    pub(super) fn draw_drag_grid(
        &self,
        painter: &egui::Painter,
        desc: &CameraDesc,
        view: Vec3,
        size: Vec2,
        origin: egui::Pos2,
    ) {
        let Some((dir, centre)) = self.gizmo.drag_line() else {
            return;
        };
        let Some(k) = world_axis(dir) else {
            return;
        };
        let Some(j) = (0..3)
            .filter(|&j| j != k)
            .max_by(|&a, &b| view[a].abs().total_cmp(&view[b].abs()))
        else {
            return;
        };
        // The plane holds axis k and the axis other than j (j is the most face-on: its normal).
        let Some(m) = (0..3).find(|&m| m != k && m != j) else {
            return;
        };
        let step = self.state.snap.grid.unwrap_or(1.0).max(0.01);
        let snap = |v: f32| (v / step).round() * step;
        let mut base = centre;
        base[k] = snap(base[k]);
        base[m] = snap(base[m]);
        let axis = |i: usize| Vec3::AXES[i];
        let reach = GRID_LINES as f32 * step;
        let at = |p: Vec3| project(desc, size, p).map(|v| origin + egui::vec2(v.x, v.y));
        let stroke = egui::Stroke::new(1.0, GRID_COLOUR);
        for n in -GRID_LINES..=GRID_LINES {
            let offset = n as f32 * step;
            for (along, across) in [(k, m), (m, k)] {
                let mid = base + axis(across) * offset;
                let (a, b) = (mid - axis(along) * reach, mid + axis(along) * reach);
                if let (Some(a), Some(b)) = (at(a), at(b)) {
                    painter.line_segment([a, b], stroke);
                }
            }
        }
    }
}
