//! A fly camera for test levels and the `view` tool: an entity with [`FlyCamera`],
//! [`CameraRig`] and [`Transform`], moved once per rendered frame by [`fly_camera_system`] —
//! WASD (or arrows) along the view, Q/E down and up, shift to go faster, mouse look while the
//! mouse is captured.
//!
//! Owns: yaw/pitch and speeds of the camera; nothing else. Main thread. Must not: read window
//! events (it reads the [`InputState`]) or run inside fixed steps (a camera follows frames).
//! Conventions: yaw about +Y, 0 looking along −Z; pitch positive up, within ±89°; no roll.

use glam::{EulerRot, Quat, Vec3};
use hecs::World;

use crate::app::input::InputState;
use crate::assets::CameraDesc;
use crate::ecs::{CameraRig, Transform};

// The action names the fly camera reads (declared in `input`, beside the default bindings).
use crate::app::input::fly_actions as actions;

/// Largest pitch, radians (just short of straight up, where yaw would be undefined).
const MAX_PITCH: f32 = 89.0 * std::f32::consts::PI / 180.0;

/// Free flight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlyCamera {
    /// Metres per second.
    pub speed: f32,
    /// Speed multiplier while `fast` is held.
    pub fast_factor: f32,
    /// Radians per mouse count (0.002: a 1000-count swipe turns about 115°).
    pub look_radians_per_count: f32,
    /// Radians about +Y; 0 looks along −Z.
    pub yaw: f32,
    /// Radians, positive up.
    pub pitch: f32,
}

impl FlyCamera {
    /// The rotation of yaw and pitch (camera looks along its local −Z).
    pub fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    /// A camera at a level's view: position, direction, field of view and lens; `speed` in
    /// metres per second. The level's `up` is not kept (the fly camera has no roll).
    pub fn from_view(desc: &CameraDesc, speed: f32) -> (Self, Transform, CameraRig) {
        let position = Vec3::from(desc.position);
        let to_target = Vec3::from(desc.look_at) - position;
        let forward = to_target.try_normalize().unwrap_or(Vec3::NEG_Z);
        let camera = Self {
            speed,
            fast_factor: 5.0,
            look_radians_per_count: 0.002,
            yaw: (-forward.x).atan2(-forward.z),
            pitch: forward
                .y
                .clamp(-1.0, 1.0)
                .asin()
                .clamp(-MAX_PITCH, MAX_PITCH),
        };
        let transform = Transform {
            translation: position,
            rotation: camera.rotation(),
            scale: Vec3::ONE,
        };
        let rig = CameraRig {
            vertical_fov: desc.vertical_fov_deg.to_radians(),
            aperture_radius: desc.aperture_radius,
            focus_distance: desc.focus_distance.unwrap_or(to_target.length()).max(1e-4),
        };
        (camera, transform, rig)
    }
}

/// Moves every [`FlyCamera`] by this frame's input over `frame_seconds`.
pub fn fly_camera_system(world: &mut World, input: &InputState, frame_seconds: f32) {
    use actions::*;
    for (camera, transform) in world.query_mut::<(&mut FlyCamera, &mut Transform)>() {
        camera.yaw -= input.motion(LOOK_X) * camera.look_radians_per_count;
        camera.pitch = (camera.pitch - input.motion(LOOK_Y) * camera.look_radians_per_count)
            .clamp(-MAX_PITCH, MAX_PITCH);
        let rotation = camera.rotation();
        let forward = rotation * Vec3::NEG_Z;
        let right = rotation * Vec3::X;
        let direction = forward * input.axis(FORWARD, BACK)
            + right * input.axis(RIGHT, LEFT)
            + Vec3::Y * input.axis(UP, DOWN);
        let speed = camera.speed
            * if input.held(FAST) {
                camera.fast_factor
            } else {
                1.0
            };
        transform.translation += direction.normalize_or_zero() * speed * frame_seconds;
        transform.rotation = rotation;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::input::{InputMap, KeyCode};

    fn desc(position: [f32; 3], look_at: [f32; 3]) -> CameraDesc {
        CameraDesc {
            position,
            look_at,
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 40.0,
            aperture_radius: 0.0,
            focus_distance: None,
        }
    }

    #[test]
    fn starts_looking_where_the_level_looks() {
        for target in [[1.0, 2.0, -3.0], [-4.0, -1.0, 2.0], [0.0, 0.5, 5.0]] {
            let d = desc([0.5, 1.0, 0.0], target);
            let (_, transform, rig) = FlyCamera::from_view(&d, 2.0);
            let want = (Vec3::from(target) - Vec3::from(d.position)).normalize();
            let got = transform.rotation * Vec3::NEG_Z;
            assert!((got - want).length() < 1e-5, "{got} vs {want}");
            assert!((transform.rotation * Vec3::X).y.abs() < 1e-6, "no roll");
            let distance = (Vec3::from(target) - Vec3::from(d.position)).length();
            assert!((rig.focus_distance - distance).abs() < 1e-5);
        }
    }

    #[test]
    fn keys_move_along_the_view_and_the_mouse_turns() {
        let mut world = World::new();
        let (camera, transform, rig) = FlyCamera::from_view(&desc([0.0; 3], [0.0, 0.0, -1.0]), 2.0);
        let entity = world.spawn((camera, transform, rig));
        let mut input = InputState::new(&InputMap::fly_camera_defaults());
        input.key(KeyCode::KeyW, true);
        fly_camera_system(&mut world, &input, 0.5);
        let t = *world.get::<&Transform>(entity).expect("transform");
        assert!((t.translation - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-6);
        input.key(KeyCode::ShiftLeft, true);
        input.key(KeyCode::KeyD, true);
        fly_camera_system(&mut world, &input, 0.1);
        let t2 = *world.get::<&Transform>(entity).expect("transform");
        let step = t2.translation - t.translation;
        assert!(
            (step.length() - 1.0).abs() < 1e-5,
            "2 m/s × 5 × 0.1 s: {step}"
        );
        assert!(step.x > 0.0 && step.z < 0.0, "forward and right: {step}");
        input.release_all();
        // A quarter turn to the left: mouse moves left by π/2 / 0.002 counts.
        input.mouse_motion(-std::f32::consts::FRAC_PI_2 / 0.002, 0.0);
        fly_camera_system(&mut world, &input, 0.1);
        let t3 = *world.get::<&Transform>(entity).expect("transform");
        assert_eq!(t3.translation, t2.translation, "no key held: no motion");
        let forward = t3.rotation * Vec3::NEG_Z;
        assert!((forward - Vec3::NEG_X).length() < 1e-4, "{forward}");
        input.end_frame();
        input.mouse_motion(0.0, -1e6);
        fly_camera_system(&mut world, &input, 0.1);
        let camera = *world.get::<&FlyCamera>(entity).expect("camera");
        assert!((camera.pitch - MAX_PITCH).abs() < 1e-6, "pitch clamps");
    }
}
