//! Evaluating a capture script at a frame: the camera from its keyframes, and an instance's
//! transform from its rest transform and its motions (the rules are in `script.rs`'s module doc).
//!
//! Owns: keyframe interpolation (linear; cubic Hermite with Catmull–Rom tangents scaled by the
//! key spacing; slerp for rotations) and the procedural motions (orbit, bob, slide, spin).
//! Pure functions of the script, the frame and `seconds_per_frame`: the same inputs give the same
//! bits. Main thread. Must not: touch the world or the engine.

use std::f32::consts::TAU;

use glam::{EulerRot, Mat3, Quat, Vec3};

use super::desc::{CameraKey, Interpolation, Motion, ObjectKey};
use crate::assets::CameraDesc;
use crate::ecs::Transform;

/// Hermite basis at `s` in [0, 1].
fn hermite(p0: Vec3, m0: Vec3, p1: Vec3, m1: Vec3, s: f32) -> Vec3 {
    let (s2, s3) = (s * s, s * s * s);
    p0 * (2.0 * s3 - 3.0 * s2 + 1.0)
        + m0 * (s3 - 2.0 * s2 + s)
        + p1 * (-2.0 * s3 + 3.0 * s2)
        + m1 * (s3 - s2)
}

/// A keyframed vector value: `frames` increasing, `breaks[i]` when key `i` starts a new shot
/// (no interpolation into it; zero tangents at shot ends).
struct Track<'a> {
    frames: &'a [u32],
    values: &'a [Vec3],
    interpolation: &'a [Interpolation],
    breaks: &'a [bool],
}

impl Track<'_> {
    /// Frames per unit of `values` change at key `j` (Catmull–Rom, 0 at shot ends).
    fn tangent(&self, j: usize) -> Vec3 {
        let last = self.frames.len() - 1;
        let starts = j == 0 || self.breaks[j];
        let ends = j == last || self.breaks[j + 1];
        if starts || ends {
            return Vec3::ZERO;
        }
        let span = (self.frames[j + 1] - self.frames[j - 1]) as f32;
        (self.values[j + 1] - self.values[j - 1]) / span
    }

    /// The segment at `frame`: key `i` and how far towards key `i + 1` (`None`: hold key `i`).
    fn segment(&self, frame: f32) -> (usize, Option<f32>) {
        let last = self.frames.len() - 1;
        if frame <= self.frames[0] as f32 {
            return (0, None);
        }
        if frame >= self.frames[last] as f32 {
            return (last, None);
        }
        let i = self.frames.partition_point(|&f| f as f32 <= frame) - 1;
        if self.breaks[i + 1] {
            return (i, None);
        }
        let span = (self.frames[i + 1] - self.frames[i]) as f32;
        (i, Some((frame - self.frames[i] as f32) / span))
    }

    fn at(&self, frame: f32) -> Vec3 {
        let (i, s) = self.segment(frame);
        let Some(s) = s else {
            return self.values[i];
        };
        let (p0, p1) = (self.values[i], self.values[i + 1]);
        match self.interpolation[i] {
            Interpolation::Linear => p0.lerp(p1, s),
            Interpolation::Smooth => {
                let span = (self.frames[i + 1] - self.frames[i]) as f32;
                hermite(
                    p0,
                    self.tangent(i) * span,
                    p1,
                    self.tangent(i + 1) * span,
                    s,
                )
            }
        }
    }
}

/// The camera at `frame` from `keys` (checked by `Script::validate`); `level` gives the view
/// without keys and the first key's default field of view.
pub fn camera_at(keys: &[CameraKey], frame: u32, level: &CameraDesc) -> CameraDesc {
    if keys.is_empty() {
        return *level;
    }
    let frames: Vec<u32> = keys.iter().map(|k| k.frame).collect();
    let interpolation: Vec<Interpolation> = keys.iter().map(|k| k.interpolation).collect();
    let breaks: Vec<bool> = keys.iter().map(|k| k.cut).collect();
    let mut fov = level.vertical_fov_deg;
    let fovs: Vec<Vec3> = keys
        .iter()
        .map(|k| {
            fov = k.fov_deg.unwrap_or(fov);
            Vec3::splat(fov)
        })
        .collect();
    let positions: Vec<Vec3> = keys.iter().map(|k| Vec3::from(k.position)).collect();
    let targets: Vec<Vec3> = keys.iter().map(|k| Vec3::from(k.look_at)).collect();
    let track = |values| Track {
        frames: &frames,
        values,
        interpolation: &interpolation,
        breaks: &breaks,
    };
    let f = frame as f32;
    let position = track(&positions).at(f);
    let mut look_at = track(&targets).at(f);
    if look_at == position {
        look_at = position + Vec3::NEG_Z;
    }
    CameraDesc {
        position: position.to_array(),
        look_at: look_at.to_array(),
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: track(&fovs).at(f).x.clamp(1e-3, 179.0),
        aperture_radius: 0.0,
        focus_distance: None,
    }
}

/// Whether a camera key at `frame` asks for a cut.
pub fn cut_at(keys: &[CameraKey], frame: u32) -> bool {
    keys.iter().any(|k| k.frame == frame && k.cut)
}

/// The entity transform of a camera at `camera` (looking along its local −Z, +Y up; straight
/// up or down it keeps −Z as the image's up).
pub fn camera_transform(camera: &CameraDesc) -> Transform {
    let eye = Vec3::from(camera.position);
    let dir = (Vec3::from(camera.look_at) - eye).normalize_or(Vec3::NEG_Z);
    let up = if dir.cross(Vec3::Y).length_squared() < 1e-8 {
        Vec3::NEG_Z
    } else {
        Vec3::Y
    };
    // Columns of world_from_view: right, up, backwards (−forward).
    let right = dir.cross(up).normalize();
    let view_up = right.cross(dir);
    let rotation = Quat::from_mat3(&Mat3::from_cols(right, view_up, -dir)).normalize();
    Transform {
        translation: eye,
        rotation,
        scale: Vec3::ONE,
    }
}

fn rotation_from_deg(r: [f32; 3]) -> Quat {
    let [x, y, z] = r.map(f32::to_radians);
    Quat::from_euler(EulerRot::YXZ, y, x, z)
}

fn keyframes(keys: &[ObjectKey], rest: &Transform, frame: f32) -> Transform {
    let frames: Vec<u32> = keys.iter().map(|k| k.frame).collect();
    let interpolation: Vec<Interpolation> = keys.iter().map(|k| k.interpolation).collect();
    let breaks = vec![false; keys.len()];
    let translations: Vec<Vec3> = keys
        .iter()
        .map(|k| k.translation.map(Vec3::from).unwrap_or(rest.translation))
        .collect();
    let scales: Vec<Vec3> = keys
        .iter()
        .map(|k| k.scale.map(Vec3::from).unwrap_or(rest.scale))
        .collect();
    let track = |values| Track {
        frames: &frames,
        values,
        interpolation: &interpolation,
        breaks: &breaks,
    };
    let translation = track(&translations).at(frame);
    let scale = track(&scales).at(frame);
    let rotations: Vec<Quat> = keys
        .iter()
        .map(|k| {
            k.rotation_deg
                .map(rotation_from_deg)
                .unwrap_or(rest.rotation)
        })
        .collect();
    let (i, s) = track(&translations).segment(frame);
    let rotation = match s {
        None => rotations[i],
        Some(s) => {
            let s = match interpolation[i] {
                Interpolation::Linear => s,
                Interpolation::Smooth => s * s * (3.0 - 2.0 * s),
            };
            rotations[i].slerp(rotations[i + 1], s)
        }
    };
    Transform {
        translation,
        rotation,
        scale,
    }
}

/// Applies `motion` to `current` (starting from the instance's rest transform `rest`) at
/// `frame` (fractional frames allowed), `seconds` after the start.
pub fn apply_motion(
    motion: &Motion,
    rest: &Transform,
    current: Transform,
    frame: f32,
    seconds: f32,
) -> Transform {
    let phase = |deg: f32, period: f32| deg.to_radians() + TAU * seconds / period;
    let mut t = current;
    match motion {
        Motion::Keyframes(keys) => t = keyframes(keys, rest, frame),
        Motion::Orbit {
            center,
            radius,
            period_seconds,
            axis,
            phase_deg,
        } => {
            let (u, v) = Vec3::from(*axis).normalize().any_orthonormal_pair();
            let c = center.map(Vec3::from).unwrap_or(rest.translation);
            let a = phase(*phase_deg, *period_seconds);
            t.translation = c + (u * a.cos() + v * a.sin()) * *radius;
        }
        Motion::Bob {
            amplitude,
            period_seconds,
            axis,
            phase_deg,
        } => {
            let a = phase(*phase_deg, *period_seconds);
            t.translation += Vec3::from(*axis).normalize() * (*amplitude * a.sin());
        }
        Motion::Slide {
            offset,
            period_seconds,
            phase_deg,
        } => {
            let a = phase(*phase_deg, *period_seconds);
            t.translation += Vec3::from(*offset) * (0.5 - 0.5 * a.cos());
        }
        Motion::Spin {
            axis,
            deg_per_second,
        } => {
            let q = Quat::from_axis_angle(
                Vec3::from(*axis).normalize(),
                (deg_per_second * seconds).to_radians(),
            );
            t.rotation = (q * t.rotation).normalize();
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(frame: u32, x: f32) -> CameraKey {
        CameraKey {
            frame,
            position: [x, 1.0, 0.0],
            look_at: [x, 0.0, -5.0],
            fov_deg: None,
            cut: false,
            interpolation: Interpolation::Smooth,
        }
    }

    fn level() -> CameraDesc {
        CameraDesc {
            position: [0.0, 0.0, 5.0],
            look_at: [0.0; 3],
            up: [0.0, 1.0, 0.0],
            vertical_fov_deg: 40.0,
            aperture_radius: 0.0,
            focus_distance: None,
        }
    }

    #[test]
    fn camera_passes_through_keys_holds_at_ends_and_jumps_at_cuts() {
        let mut keys = vec![key(10, 0.0), key(20, 10.0), key(30, 0.0), key(40, 5.0)];
        keys[3].cut = true;
        keys[1].interpolation = Interpolation::Linear;
        let x = |f| camera_at(&keys, f, &level()).position[0];
        assert_eq!(x(0), 0.0);
        assert_eq!(x(10), 0.0);
        assert_eq!(x(20), 10.0);
        // Linear segment 20 → 30: halfway is exactly halfway.
        assert_eq!(x(25), 5.0);
        // Before the cut key the camera holds key 2; at the cut it jumps; after, it holds.
        assert_eq!(x(39), 0.0);
        assert_eq!(x(40), 5.0);
        assert_eq!(x(99), 5.0);
        assert!(cut_at(&keys, 40) && !cut_at(&keys, 39));
        // Smooth segment 10 → 20 starts with zero slope (start of the shot) and is monotone.
        let xs: Vec<f32> = (10..=20).map(x).collect();
        assert!(xs.windows(2).all(|w| w[1] >= w[0]), "{xs:?}");
        assert!(xs[1] < 1.0, "eases in: {xs:?}");
        assert_eq!(camera_at(&keys, 0, &level()).vertical_fov_deg, 40.0);
    }

    #[test]
    fn camera_transform_looks_at_the_target() {
        let c = key(0, 3.0);
        let t = camera_transform(&CameraDesc {
            vertical_fov_deg: 50.0,
            ..level()
        });
        assert!((t.rotation * Vec3::NEG_Z - Vec3::NEG_Z).length() < 1e-6);
        let d = CameraDesc {
            position: c.position,
            look_at: c.look_at,
            ..level()
        };
        let t = camera_transform(&d);
        let forward = t.rotation * Vec3::NEG_Z;
        let want = (Vec3::from(d.look_at) - Vec3::from(d.position)).normalize();
        assert!((forward - want).length() < 1e-5, "{forward} vs {want}");
        assert_eq!(t.translation, Vec3::from(d.position));
    }

    #[test]
    fn procedural_motions_follow_their_formulas() {
        let rest = Transform::from_translation(Vec3::new(1.0, 2.0, 3.0));
        let orbit = Motion::Orbit {
            center: None,
            radius: 2.0,
            period_seconds: 4.0,
            axis: [0.0, 1.0, 0.0],
            phase_deg: 0.0,
        };
        for s in [0.0, 1.0, 2.5] {
            let t = apply_motion(&orbit, &rest, rest, 0.0, s);
            let d = t.translation - rest.translation;
            assert!((d.length() - 2.0).abs() < 1e-5 && d.y.abs() < 1e-6, "{d}");
        }
        let a = apply_motion(&orbit, &rest, rest, 0.0, 0.0).translation;
        let b = apply_motion(&orbit, &rest, rest, 0.0, 4.0).translation;
        assert!((a - b).length() < 1e-5, "one period returns");
        let slide = Motion::Slide {
            offset: [4.0, 0.0, 0.0],
            period_seconds: 2.0,
            phase_deg: 0.0,
        };
        let t = apply_motion(&slide, &rest, rest, 0.0, 1.0);
        assert!((t.translation - Vec3::new(5.0, 2.0, 3.0)).length() < 1e-5);
        let spin = Motion::Spin {
            axis: [0.0, 1.0, 0.0],
            deg_per_second: 90.0,
        };
        let t = apply_motion(&spin, &rest, rest, 0.0, 1.0);
        assert!((t.rotation * Vec3::X - Vec3::NEG_Z).length() < 1e-5);
        let bob = Motion::Bob {
            amplitude: 0.5,
            period_seconds: 4.0,
            axis: [0.0, 2.0, 0.0],
            phase_deg: 0.0,
        };
        let t = apply_motion(&bob, &rest, rest, 0.0, 1.0);
        assert!((t.translation.y - 2.5).abs() < 1e-6);
    }

    #[test]
    fn keyframes_fill_missing_parts_from_rest() {
        let rest = Transform {
            scale: Vec3::splat(2.0),
            ..Transform::from_translation(Vec3::new(0.0, 1.0, 0.0))
        };
        let keys = [
            ObjectKey {
                frame: 0,
                translation: None,
                rotation_deg: None,
                scale: None,
                interpolation: Interpolation::Linear,
            },
            ObjectKey {
                frame: 10,
                translation: Some([10.0, 1.0, 0.0]),
                rotation_deg: Some([0.0, 90.0, 0.0]),
                scale: None,
                interpolation: Interpolation::Linear,
            },
        ];
        let m = Motion::Keyframes(keys.to_vec());
        let t = apply_motion(&m, &rest, rest, 5.0, 0.0);
        assert!((t.translation - Vec3::new(5.0, 1.0, 0.0)).length() < 1e-6);
        assert_eq!(t.scale, Vec3::splat(2.0));
        let half = Quat::from_rotation_y(45f32.to_radians());
        assert!(t.rotation.angle_between(half) < 1e-4);
        let end = apply_motion(&m, &rest, rest, 30.0, 0.0);
        assert!((end.rotation * Vec3::X - Vec3::NEG_Z).length() < 1e-5);
    }
}
