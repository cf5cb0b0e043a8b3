//! [`EditorCamera`]: the editor's free camera — fly (W/A/S/D along the view, Q/E down and up,
//! Shift faster) and look while the right mouse button is held, orbit about a point in front
//! of it (middle button, or Alt with the left button), dolly with the wheel, and frame a box
//! (F: the selection) — and [`project`], the inverse of `editor::pixel_ray`.
//!
//! Main thread. Must not: read devices (the mode hands it egui's input) or the world.
//! Conventions: yaw about +Y, 0 looking along −Z; pitch positive up, within ±89°; no roll;
//! metres, seconds, radians.

use glam::{EulerRot, Quat, Vec2, Vec3};

use crate::assets::CameraDesc;
use crate::ecs::{CameraRig, Transform};
use crate::editor::ViewBasis;

const MAX_PITCH: f32 = 89.0 * std::f32::consts::PI / 180.0;

/// Radians per point of mouse motion while looking or orbiting.
pub const LOOK_RADIANS_PER_POINT: f32 = 0.005;

/// The editor's camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EditorCamera {
    /// Eye, world space, metres.
    pub position: Vec3,
    pub yaw: f32,
    pub pitch: f32,
    /// Fly speed, metres per second (Shift: four times).
    pub speed: f32,
    /// Metres to the point it orbits about, along the view.
    pub pivot_distance: f32,
    pub rig: CameraRig,
}

impl EditorCamera {
    /// A camera where `transform` (a camera entity's) looks, with its lens.
    pub fn from_transform(transform: &Transform, rig: CameraRig, speed: f32) -> Self {
        let forward = (transform.rotation * Vec3::NEG_Z)
            .try_normalize()
            .unwrap_or(Vec3::NEG_Z);
        Self {
            position: transform.translation,
            yaw: (-forward.x).atan2(-forward.z),
            pitch: forward
                .y
                .clamp(-1.0, 1.0)
                .asin()
                .clamp(-MAX_PITCH, MAX_PITCH),
            speed,
            pivot_distance: rig.focus_distance.clamp(0.5, 50.0),
            rig,
        }
    }

    pub fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    /// Unit view direction.
    pub fn forward(&self) -> Vec3 {
        self.rotation() * Vec3::NEG_Z
    }

    /// The camera entity's transform for this view.
    pub fn transform(&self) -> Transform {
        Transform {
            translation: self.position,
            rotation: self.rotation(),
            scale: Vec3::ONE,
        }
    }

    /// The view as the renderer and `editor::pixel_ray` take it.
    pub fn desc(&self) -> CameraDesc {
        let rotation = self.rotation();
        CameraDesc {
            position: self.position.to_array(),
            look_at: (self.position + rotation * Vec3::NEG_Z).to_array(),
            up: (rotation * Vec3::Y).to_array(),
            vertical_fov_deg: self.rig.vertical_fov.to_degrees(),
            aperture_radius: self.rig.aperture_radius,
            focus_distance: Some(self.rig.focus_distance),
        }
    }

    /// Turns by a mouse motion of `delta` points (right: turn right; down: look down).
    pub fn look(&mut self, delta: Vec2) {
        self.yaw -= delta.x * LOOK_RADIANS_PER_POINT;
        self.pitch = (self.pitch - delta.y * LOOK_RADIANS_PER_POINT).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Turns about the pivot (the point `pivot_distance` ahead), keeping it in view.
    pub fn orbit(&mut self, delta: Vec2) {
        let pivot = self.position + self.forward() * self.pivot_distance;
        self.look(delta);
        self.position = pivot - self.forward() * self.pivot_distance;
    }

    /// Flies for `seconds` along `direction` in the camera's frame (x right, y up, z back),
    /// each component in −1..=1.
    pub fn fly(&mut self, direction: Vec3, seconds: f32, fast: bool) {
        let step = self.speed * if fast { 4.0 } else { 1.0 } * seconds.clamp(0.0, 0.25);
        let rotation = self.rotation();
        let along = rotation * Vec3::new(direction.x, 0.0, direction.z) + Vec3::Y * direction.y;
        self.position += along.clamp_length_max(1.0) * step;
    }

    /// Moves along the view by `steps` wheel steps (positive: forward), towards the pivot.
    pub fn dolly(&mut self, steps: f32) {
        let distance = self.pivot_distance * (1.0 - (0.85f32).powf(steps));
        let distance = distance.min(self.pivot_distance - 0.1);
        self.position += self.forward() * distance;
        self.pivot_distance = (self.pivot_distance - distance).max(0.1);
    }

    /// Looks at the sphere (`centre`, `radius` metres) from where it looks now, far enough to
    /// see all of it; it becomes the pivot.
    pub fn frame(&mut self, centre: Vec3, radius: f32) {
        let half = (self.rig.vertical_fov * 0.5).clamp(0.05, 1.5);
        let distance = (radius.max(0.05) / half.sin()) * 1.1;
        self.pivot_distance = distance;
        self.position = centre - self.forward() * distance;
    }
}

/// Where world point `p` appears in a `size` (width, height) view of `camera`: the inverse of
/// `editor::pixel_ray`, in the same units as `size` (from the top-left corner, y down); `None`
/// behind the eye or nearer than a millimetre.
pub fn project(camera: &CameraDesc, size: Vec2, p: Vec3) -> Option<Vec2> {
    let b = ViewBasis::new(camera, size.x, size.y);
    let (position, forward, right, up) = (b.position, b.forward, b.right, b.up);
    let (tan_half, aspect) = (b.tan_half, b.aspect);
    let d = p - position;
    let z = d.dot(forward);
    if z < 1e-3 {
        return None;
    }
    let sx = d.dot(right) / (z * tan_half * aspect);
    let sy = d.dot(up) / (z * tan_half);
    Some(Vec2::new(
        (sx + 1.0) * 0.5 * size.x,
        (1.0 - sy) * 0.5 * size.y,
    ))
}
