//! [`RenderCamera`]: the view as it crosses the commit — an eye, an orthonormal basis, a vertical
//! field of view and a thin lens — built once, here, from the world's camera (or a level's
//! [`CameraDesc`]), and read as is by the render side (frame uniforms for both tracers), audio
//! (the listener) and games (a player's yaw and pitch).
//!
//! Spaces and units: world space, right-handed, +Y up, metres and radians. The basis is
//! camera-to-world: `right` is the view's +X, `up` its +Y and `forward` the direction it looks
//! along, its −Z (so `right × up = −forward`). The basis does not depend on render space's
//! origin (`accel::origin`); the frame uniforms subtract the origin from the eye only.
//!
//! Owns: turning a [`CameraDesc`] (the level file's authoring form: position, look-at, up hint,
//! degrees) into that basis, with the very float operations the frame uniforms used before the
//! basis was built here (issue 31), so nothing changed bit for bit: not a committed replay's
//! state hash, not the listener, not an image while render space's origin is the world origin
//! (every committed level and test scene). The frame uniforms used to build the basis from the
//! eye and look-at *after* subtracting the origin; where the origin had moved and that
//! subtraction rounded, the world-space basis differs from the old one by a rounding of the
//! direction (about 1e-7 rad). Main thread. Must not: know which tracer, listener or game reads
//! it.

use glam::{Mat3, Quat, Vec3};

use crate::assets::CameraDesc;
use crate::ecs::CameraRig;

/// A perspective camera in world space (pinhole, or thin lens when
/// [`lens_radius_meters`](Self::lens_radius_meters) is above 0). See the module doc for the
/// basis's convention.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderCamera {
    position: Vec3,
    right: Vec3,
    up: Vec3,
    forward: Vec3,
    vertical_fov_radians: f32,
    lens_radius_meters: f32,
    focus_distance_meters: f32,
    /// `look_at` was the eye: `forward` is the stand-in −Z.
    forward_fallback: bool,
    /// The up hint was along the view (or not finite): `right` is a stand-in.
    right_fallback: bool,
}

impl RenderCamera {
    /// The camera `desc` describes. `forward` is the unit direction from `position` to
    /// `look_at`, `right` the unit `forward × up`, `up` the unit `right × forward`; when
    /// `look_at` equals `position` the view looks along −Z, and when `up` is parallel to the
    /// view `right` is any unit vector across it (see [`is_fallback`](Self::is_fallback)).
    /// The field of view is clamped to [1e-3°, 179°], the lens radius to ≥ 0, and the focus
    /// distance (default: the distance to `look_at`) to ≥ 0.1 mm.
    pub fn from_desc(desc: &CameraDesc) -> Self {
        let position = Vec3::from(desc.position);
        let look_at = Vec3::from(desc.look_at);
        let forward = (look_at - position).try_normalize();
        let up_hint = Vec3::from(desc.up);
        let right = forward
            .unwrap_or(Vec3::NEG_Z)
            .cross(up_hint)
            .try_normalize();
        let (forward_fallback, right_fallback) = (forward.is_none(), right.is_none());
        let forward = forward.unwrap_or(Vec3::NEG_Z);
        let right = right.unwrap_or_else(|| forward.any_orthonormal_vector());
        let up = right.cross(forward);
        let focus_distance_meters = desc
            .focus_distance
            .unwrap_or_else(|| (look_at - position).length())
            .max(1e-4);
        Self {
            position,
            right,
            up,
            forward,
            vertical_fov_radians: desc.vertical_fov_deg.clamp(1e-3, 179.0).to_radians(),
            lens_radius_meters: desc.aperture_radius.max(0.0),
            focus_distance_meters,
            forward_fallback,
            right_fallback,
        }
    }

    /// The camera of an entity at `position` (world metres) turned by `rotation` (its view
    /// looks along the rotated −Z, the rotated +Y up) with `rig`'s field of view and lens. The
    /// pose goes through the look-at form (a point one metre ahead, the field of view in
    /// degrees) on purpose: the basis then rounds exactly as it did when the commit carried that
    /// form, so images and replays stay the same bit for bit.
    pub fn from_pose(position: Vec3, rotation: Quat, rig: &CameraRig) -> Self {
        let forward = rotation * Vec3::NEG_Z;
        let up = rotation * Vec3::Y;
        Self::from_desc(&CameraDesc {
            position: position.to_array(),
            look_at: (position + forward).to_array(),
            up: up.to_array(),
            vertical_fov_deg: rig.vertical_fov.to_degrees(),
            aperture_radius: rig.aperture_radius,
            focus_distance: Some(rig.focus_distance),
        })
    }

    /// The eye, world metres.
    pub fn position(&self) -> Vec3 {
        self.position
    }

    /// Unit vector to the right of the view (its +X), world space.
    pub fn right(&self) -> Vec3 {
        self.right
    }

    /// Unit vector up the view (its +Y), world space; perpendicular to `forward`.
    pub fn up(&self) -> Vec3 {
        self.up
    }

    /// Unit direction the camera looks along (its −Z), world space.
    pub fn forward(&self) -> Vec3 {
        self.forward
    }

    /// Vertical field of view, radians (in [1e-3°, 179°]).
    pub fn vertical_fov_radians(&self) -> f32 {
        self.vertical_fov_radians
    }

    /// Thin-lens radius, metres (0: pinhole).
    pub fn lens_radius_meters(&self) -> f32 {
        self.lens_radius_meters
    }

    /// Distance to the plane in focus along `forward`, metres (≥ 1e-4).
    pub fn focus_distance_meters(&self) -> f32 {
        self.focus_distance_meters
    }

    /// Whether the description did not define a view (look-at at the eye, or the up hint along
    /// the view) and the basis is the stand-in [`from_desc`](Self::from_desc) names: the
    /// renderer draws with it, the audio listener keeps its last orientation.
    pub fn is_fallback(&self) -> bool {
        self.forward_fallback || self.right_fallback
    }

    /// Whether `look_at` was the eye, so that `forward` is the stand-in −Z (the view has no
    /// direction of its own; a player spawned at it faces yaw 0).
    pub fn forward_is_fallback(&self) -> bool {
        self.forward_fallback
    }

    /// The rotation taking view space (looking along −Z, +Y up) to world space: the columns
    /// `right`, `up`, `−forward`, as a unit quaternion (the audio listener's orientation).
    pub fn orientation(&self) -> Quat {
        Quat::from_mat3(&Mat3::from_cols(self.right, self.up, -self.forward)).normalize()
    }
}

impl From<&CameraDesc> for RenderCamera {
    fn from(desc: &CameraDesc) -> Self {
        Self::from_desc(desc)
    }
}

impl From<CameraDesc> for RenderCamera {
    fn from(desc: CameraDesc) -> Self {
        Self::from_desc(&desc)
    }
}

impl From<&RenderCamera> for RenderCamera {
    fn from(camera: &RenderCamera) -> Self {
        *camera
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn desc(position: [f32; 3], look_at: [f32; 3], up: [f32; 3]) -> CameraDesc {
        CameraDesc {
            position,
            look_at,
            up,
            vertical_fov_deg: 60.0,
            aperture_radius: 0.0,
            focus_distance: None,
        }
    }

    #[test]
    fn the_basis_is_orthonormal_and_camera_to_world() {
        let c = RenderCamera::from_desc(&desc([1.0, 2.0, 3.0], [4.0, 0.5, -2.0], [0.0, 1.0, 0.0]));
        for v in [c.right(), c.up(), c.forward()] {
            assert!((v.length() - 1.0).abs() < 1e-6);
        }
        assert!(c.right().dot(c.up()).abs() < 1e-6);
        assert!(c.right().dot(c.forward()).abs() < 1e-6);
        assert!(c.up().dot(c.forward()).abs() < 1e-6);
        assert!((c.right().cross(c.up()) + c.forward()).length() < 1e-6);
        assert!(c.up().y > 0.0);
        let view_z = c.orientation() * Vec3::NEG_Z;
        assert!((view_z - c.forward()).length() < 1e-6);
        assert!(!c.is_fallback());
        assert!((c.vertical_fov_radians() - 60f32.to_radians()).abs() < 1e-7);
        assert_eq!(
            c.focus_distance_meters(),
            (Vec3::new(3.0, -1.5, -5.0)).length()
        );
    }

    /// The basis, focus distance and listener as the frame uniforms and audio rebuilt them from
    /// a `CameraDesc` before issue 31 (render space's origin at the world origin), kept here to
    /// pin the move to no change of a bit.
    fn before(desc: &CameraDesc) -> ([Vec3; 3], f32, Option<Quat>) {
        let position = Vec3::from(desc.position);
        let look_at = Vec3::from(desc.look_at);
        let forward = (look_at - position).try_normalize().unwrap_or(Vec3::NEG_Z);
        let right = forward
            .cross(Vec3::from(desc.up))
            .try_normalize()
            .unwrap_or_else(|| forward.any_orthonormal_vector());
        let up = right.cross(forward);
        let focus = desc
            .focus_distance
            .unwrap_or_else(|| (look_at - position).length())
            .max(1e-4);
        let f = (look_at - position).normalize_or_zero();
        let r = f.cross(Vec3::from(desc.up)).normalize_or_zero();
        let listener = (f != Vec3::ZERO && r != Vec3::ZERO).then(|| {
            let basis = Mat3::from_cols(r, r.cross(f), -f);
            Quat::from_mat3(&basis).normalize()
        });
        ([right, up, forward], focus, listener)
    }

    #[test]
    fn the_basis_is_the_one_rebuilt_before_bit_for_bit() {
        let mut seed = 0x9e37_79b9u32;
        let mut next = move || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32
        };
        let rig = CameraRig {
            vertical_fov: 1.2,
            aperture_radius: 0.01,
            focus_distance: 3.0,
        };
        for _ in 0..20_000 {
            let position = Vec3::new(next(), next(), next()) * 200.0 - 100.0;
            let (yaw, pitch) = (next() * 6.3 - 3.15, next() * 3.1 - 1.55);
            let rotation = Quat::from_euler(glam::EulerRot::YXZ, yaw, pitch, 0.0);
            // What the extractor handed over before: the look-at form of the pose.
            let desc = CameraDesc {
                position: position.to_array(),
                look_at: (position + rotation * Vec3::NEG_Z).to_array(),
                up: (rotation * Vec3::Y).to_array(),
                vertical_fov_deg: rig.vertical_fov.to_degrees(),
                aperture_radius: rig.aperture_radius,
                focus_distance: None,
            };
            let ([right, up, forward], focus, listener) = before(&desc);
            let c = RenderCamera::from_pose(position, rotation, &rig);
            assert_eq!((c.right(), c.up(), c.forward()), (right, up, forward));
            assert_eq!(
                c.vertical_fov_radians(),
                desc.vertical_fov_deg.clamp(1e-3, 179.0).to_radians()
            );
            assert_eq!(Some(c.orientation()), listener);
            let authored = RenderCamera::from_desc(&desc);
            assert_eq!(authored.focus_distance_meters(), focus);
        }
    }

    #[test]
    fn an_undefined_view_falls_back_and_says_so() {
        let same = RenderCamera::from_desc(&desc([1.0; 3], [1.0; 3], [0.0, 1.0, 0.0]));
        assert!(same.is_fallback() && same.forward_is_fallback());
        assert_eq!(same.forward(), Vec3::NEG_Z);
        let down = RenderCamera::from_desc(&desc([0.0; 3], [0.0, -1.0, 0.0], [0.0, 1.0, 0.0]));
        assert!(down.is_fallback() && !down.forward_is_fallback());
        assert_eq!(down.forward(), Vec3::NEG_Y);
        assert!(down.right().dot(down.forward()).abs() < 1e-6);
    }
}
