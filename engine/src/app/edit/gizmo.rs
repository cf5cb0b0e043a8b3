//! [`Gizmo`]: the transform tools drawn over the view with egui's `Painter` — translate (W),
//! rotate (E) and scale (R) along or about the X, Y and Z axes, in world or local space
//! (the primary selected instance's axes), with the editor's grid, angle and scale snapping
//! applied to the drag's amount. A whole drag is one command: every frame of it gives one
//! `Edit::Batch` of transforms computed from the transforms at the drag's start, which the
//! history merges while the drag lasts.
//!
//! Main thread. Must not: touch the world (edits go through `EditorState`) or read devices
//! (the mode hands it the pointer). Screen positions are egui points from the top-left corner.

use glam::{EulerRot, Quat, Vec2, Vec3};

use super::camera::project;
use crate::assets::{CameraDesc, InstanceEntry, TransformDesc};
use crate::editor::{Edit, InstanceField, Snap, snap_angle_deg, snap_scale, snap_value};
use crate::trace::Ray;

/// Which tool the gizmo is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    Translate,
    Rotate,
    Scale,
}

/// Whose axes the gizmo uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Space {
    World,
    /// The primary selected instance's rotation.
    Local,
}

/// Points from the pointer to a handle's segment that still grab it.
pub const GRAB_POINTS: f32 = 8.0;
/// Degrees of rotation per point of pointer motion.
pub const DEGREES_PER_POINT: f32 = 0.5;
/// Points of pointer motion along an axis that double (or halve) a scale.
pub const POINTS_PER_SCALE: f32 = 100.0;

/// The gizmo as drawn this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handles {
    /// World-space centre (the primary selected instance's translation), metres.
    pub centre: Vec3,
    /// World-space unit axes.
    pub axes: [Vec3; 3],
    /// Where the centre and each axis's end appear (`None` behind the eye).
    pub centre_px: Vec2,
    pub ends_px: [Option<Vec2>; 3],
}

#[derive(Clone, Debug)]
struct Drag {
    axis: usize,
    dir: Vec3,
    centre: Vec3,
    start: Vec<(usize, TransformDesc)>,
    start_param: f32,
    start_pointer: Vec2,
    screen_dir: Vec2,
}

/// The transform tools.
#[derive(Clone, Debug)]
pub struct Gizmo {
    pub tool: Tool,
    pub space: Space,
    drag: Option<Drag>,
}

impl Default for Gizmo {
    fn default() -> Self {
        Self {
            tool: Tool::Translate,
            space: Space::World,
            drag: None,
        }
    }
}

/// The rotation of a level transform (degrees about X, Y, Z; applied Y, X, Z as the loader).
pub fn rotation_of(t: &TransformDesc) -> Quat {
    let [x, y, z] = t.rotation_deg.map(f32::to_radians);
    Quat::from_euler(EulerRot::YXZ, y, x, z)
}

/// Degrees about X, Y, Z of `q`, the inverse of [`rotation_of`].
pub fn degrees_of(q: Quat) -> [f32; 3] {
    let (y, x, z) = q.to_euler(EulerRot::YXZ);
    [x.to_degrees(), y.to_degrees(), z.to_degrees()].map(|v| v + 0.0)
}

impl Gizmo {
    /// Whether a drag is under way, and along which axis.
    pub fn dragging(&self) -> Option<usize> {
        self.drag.as_ref().map(|d| d.axis)
    }

    /// A translate drag's axis (world, unit) and the dragged item's centre at its start
    /// (metres); `None` for no drag or another tool.
    pub fn drag_line(&self) -> Option<(Vec3, Vec3)> {
        let drag = self.drag.as_ref()?;
        (self.tool == Tool::Translate).then_some((drag.dir, drag.centre))
    }

    /// The handles for `primary` (the primary selected instance), seen by `camera` in a view
    /// of `size` points.
    pub fn handles(
        &self,
        camera: &CameraDesc,
        size: Vec2,
        primary: &InstanceEntry,
    ) -> Option<Handles> {
        let centre = Vec3::from(primary.transform.translation);
        let centre_px = project(camera, size, centre)?;
        let rotation = match self.space {
            Space::World => Quat::IDENTITY,
            Space::Local => rotation_of(&primary.transform),
        };
        let axes = [Vec3::X, Vec3::Y, Vec3::Z].map(|a| rotation * a);
        let eye = Vec3::from(camera.position);
        let forward = (Vec3::from(camera.look_at) - eye).normalize_or(Vec3::NEG_Z);
        let depth = (centre - eye).dot(forward).max(1e-3);
        let tan_half = (camera.vertical_fov_deg.to_radians() * 0.5).tan();
        // An eighth of the view's height, whatever the distance.
        let length = depth * tan_half * 0.25;
        let ends_px = axes.map(|a| project(camera, size, centre + a * length));
        Some(Handles {
            centre,
            axes,
            centre_px,
            ends_px,
        })
    }

    /// The axis whose handle is under `pointer`, if any (the nearest within [`GRAB_POINTS`]).
    pub fn hit(handles: &Handles, pointer: Vec2) -> Option<usize> {
        let mut best: Option<(usize, f32)> = None;
        for (axis, end) in handles.ends_px.iter().enumerate() {
            let Some(end) = *end else { continue };
            let d = segment_distance(pointer, handles.centre_px, end);
            if d <= GRAB_POINTS && best.is_none_or(|(_, b)| d < b) {
                best = Some((axis, d));
            }
        }
        best.map(|(axis, _)| axis)
    }

    /// Starts dragging `axis` of `handles` with the pointer at `pointer` (its ray `ray`);
    /// `selected` are the instances it moves with their transforms now.
    pub fn begin(
        &mut self,
        axis: usize,
        handles: &Handles,
        selected: Vec<(usize, TransformDesc)>,
        pointer: Vec2,
        ray: &Ray,
    ) {
        let dir = handles.axes[axis];
        let screen = handles.ends_px[axis].map_or(Vec2::X, |e| e - handles.centre_px);
        self.drag = Some(Drag {
            axis,
            dir,
            centre: handles.centre,
            start: selected,
            start_param: line_param(handles.centre, dir, ray).unwrap_or(0.0),
            start_pointer: pointer,
            screen_dir: screen.normalize_or(Vec2::X),
        });
    }

    /// The edit that puts the dragged instances where the pointer (at `pointer`, its ray
    /// `ray`) has taken them, snapped by `snap`: one batch of transform edits.
    pub fn drag_edit(&self, pointer: Vec2, ray: &Ray, snap: &Snap) -> Option<Edit> {
        let drag = self.drag.as_ref()?;
        let moved = pointer - drag.start_pointer;
        let edits = drag
            .start
            .iter()
            .map(|&(index, start)| {
                let mut t = start;
                match self.tool {
                    Tool::Translate => {
                        let s = line_param(drag.centre, drag.dir, ray).unwrap_or(drag.start_param);
                        let amount = s - drag.start_param;
                        let amount = snap.grid.map_or(amount, |g| snap_value(amount, g));
                        t.translation = (Vec3::from(t.translation) + drag.dir * amount).to_array();
                    }
                    Tool::Rotate => {
                        let degrees = moved.x * DEGREES_PER_POINT;
                        let degrees = snap
                            .angle_deg
                            .map_or(degrees, |s| snap_angle_deg(degrees, s));
                        let turn = Quat::from_axis_angle(drag.dir, degrees.to_radians());
                        t.rotation_deg = degrees_of(turn * rotation_of(&start));
                    }
                    Tool::Scale => {
                        let factor = 2f32.powf(moved.dot(drag.screen_dir) / POINTS_PER_SCALE);
                        let scaled = start.scale[drag.axis] * factor;
                        t.scale[drag.axis] = snap.scale.map_or(scaled, |s| snap_scale(scaled, s));
                    }
                }
                Edit::Instance {
                    index,
                    field: InstanceField::Transform(t),
                }
            })
            .collect();
        Some(Edit::Batch(edits))
    }

    /// Ends the drag.
    pub fn end(&mut self) {
        self.drag = None;
    }

    /// Draws `handles`; `hot` (hovered or dragged) is drawn highlighted.
    pub fn draw(&self, painter: &egui::Painter, handles: &Handles, hot: Option<usize>) {
        let colours = [
            egui::Color32::from_rgb(230, 70, 70),
            egui::Color32::from_rgb(90, 210, 90),
            egui::Color32::from_rgb(80, 130, 240),
        ];
        let c = handles.centre_px;
        let at = |v: Vec2| egui::pos2(v.x, v.y);
        for (axis, end) in handles.ends_px.iter().enumerate() {
            let Some(end) = *end else { continue };
            let colour = if hot == Some(axis) {
                egui::Color32::from_rgb(255, 220, 60)
            } else {
                colours[axis]
            };
            let stroke = egui::Stroke::new(3.0, colour);
            painter.line_segment([at(c), at(end)], stroke);
            match self.tool {
                Tool::Translate => {
                    let d = (end - c).normalize_or(Vec2::X);
                    let side = Vec2::new(-d.y, d.x) * 5.0;
                    let tip = end + d * 10.0;
                    painter.add(egui::Shape::convex_polygon(
                        vec![at(tip), at(end + side), at(end - side)],
                        colour,
                        egui::Stroke::NONE,
                    ));
                }
                Tool::Rotate => {
                    painter.circle_stroke(at(end), 7.0, stroke);
                }
                Tool::Scale => {
                    let r = egui::Rect::from_center_size(at(end), egui::vec2(10.0, 10.0));
                    painter.rect_filled(r, 0.0, colour);
                }
            }
        }
        painter.circle_filled(at(c), 4.0, egui::Color32::WHITE);
    }
}

/// Distance from `p` to the segment `a`–`b`.
fn segment_distance(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t).distance(p)
}

/// The parameter (metres along unit `dir` from `origin`) of the point of that line nearest to
/// `ray`; `None` when the ray runs along the line.
fn line_param(origin: Vec3, dir: Vec3, ray: &Ray) -> Option<f32> {
    let d = ray.direction.normalize_or_zero();
    let w0 = origin - ray.origin;
    let b = dir.dot(d);
    let denom = 1.0 - b * b;
    if denom.abs() < 1e-6 {
        return None;
    }
    let dd = dir.dot(w0);
    let e = d.dot(w0);
    Some((b * e - dd) / denom)
}
