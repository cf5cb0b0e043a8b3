//! Box select: a left drag over the view that does not start on a gizmo handle (and without
//! Alt, which orbits) draws a rubber band; on release the instances whose projected bounds lie
//! wholly inside it are selected — alone, added with Shift, toggled with Ctrl, as a click
//! selects ([`crate::editor::SelectMode`]). Wholly inside, so that a drag over a few props does
//! not also take the floor and walls they stand in.
//!
//! Main thread, inside the editor's egui pass. Must not: touch the world or the document (it
//! changes the selection only).

use glam::{Vec2, Vec3};

use super::camera::project;
use crate::assets::CameraDesc;

/// Points the pointer must travel before a drag is a box rather than a click.
pub const MIN_BOX_POINTS: f32 = 4.0;

/// A rubber band being dragged: where the press was and where the pointer is, in points from
/// the view's top-left corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxDrag {
    pub start: Vec2,
    pub end: Vec2,
}

impl BoxDrag {
    /// The band's corners, lowest and highest.
    pub fn rect(&self) -> (Vec2, Vec2) {
        (self.start.min(self.end), self.start.max(self.end))
    }

    /// Whether the pointer went far enough for a box (else the press was a click).
    pub fn is_box(&self) -> bool {
        (self.end - self.start).abs().max_element() >= MIN_BOX_POINTS
    }
}

/// The instances among `boxes` (index, world-space corners of its bounds) whose eight corners
/// all project inside `band` in a `size` view of `camera`; an instance with a corner behind the
/// eye is not inside.
pub fn instances_in(
    camera: &CameraDesc,
    size: Vec2,
    band: (Vec2, Vec2),
    boxes: impl IntoIterator<Item = (usize, [Vec3; 8])>,
) -> Vec<usize> {
    let (lo, hi) = band;
    boxes
        .into_iter()
        .filter(|(_, corners)| {
            corners.iter().all(|&c| {
                project(camera, size, c).is_some_and(|p| p.cmpge(lo).all() && p.cmple(hi).all())
            })
        })
        .map(|(index, _)| index)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> CameraDesc {
        CameraDesc {
            position: [0.0, 0.0, 5.0],
            look_at: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 50.0,
            aperture_radius: 0.0,
            focus_distance: None,
        }
    }

    fn cube(centre: Vec3, half: f32) -> [Vec3; 8] {
        std::array::from_fn(|k| {
            let s = |bit: usize| if k & bit == 0 { -half } else { half };
            centre + Vec3::new(s(1), s(2), s(4))
        })
    }

    #[test]
    fn only_boxes_wholly_inside_the_band_are_taken() {
        let size = Vec2::new(200.0, 100.0);
        let boxes = [
            (0, cube(Vec3::new(-1.0, 0.0, 0.0), 0.2)),
            (1, cube(Vec3::new(1.0, 0.0, 0.0), 0.2)),
            (2, cube(Vec3::ZERO, 50.0)),
            (3, cube(Vec3::new(-1.0, 0.0, 8.0), 0.2)),
        ];
        let left_half = (Vec2::ZERO, Vec2::new(100.0, 100.0));
        assert_eq!(instances_in(&camera(), size, left_half, boxes), vec![0]);
        let all = (Vec2::ZERO, size);
        assert_eq!(instances_in(&camera(), size, all, boxes), vec![0, 1]);
        let none = (Vec2::ZERO, Vec2::new(10.0, 10.0));
        assert!(instances_in(&camera(), size, none, boxes).is_empty());
    }

    #[test]
    fn a_short_drag_is_a_click() {
        let drag = BoxDrag {
            start: Vec2::new(10.0, 10.0),
            end: Vec2::new(12.0, 9.0),
        };
        assert!(!drag.is_box());
        let drag = BoxDrag {
            end: Vec2::new(30.0, 2.0),
            ..drag
        };
        assert!(drag.is_box());
        assert_eq!(drag.rect(), (Vec2::new(10.0, 2.0), Vec2::new(30.0, 10.0)));
    }
}
