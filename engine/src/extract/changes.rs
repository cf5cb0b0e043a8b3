//! [`Extractor`]: compares the world with what was extracted last frame and reports what
//! changed, once per entity (Bevy's extract phase, rapier's modified-set idea).
//!
//! Owns: the memory of what each renderable entity looked like at the last extraction, and the
//! camera. Produces [`SceneChange`]s (place, remove, deform) and the view (a [`RenderCamera`],
//! built here once per extraction). Entities marked
//! [`Static`] are extracted once and never compared again, unless marked [`Restyled`]. Main thread, after transforms are
//! propagated. Must not: touch BVHs or buffers (the upkeep applies the changes).

use std::collections::HashMap;

use glam::{Mat4, Quat, Vec3};
use hecs::{Entity, World};

use super::camera::RenderCamera;
use crate::ecs::{
    CameraRig, Deformable, GlobalTransform, LightGroup, ModelHandle, Renderable, Restyled, Static,
};

/// One change of the rendered scene.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneChange {
    /// `entity` shows `model` at `world_from_model` (new, moved, or restyled).
    Place {
        entity: Entity,
        model: ModelHandle,
        world_from_model: Mat4,
        material_override: Option<u32>,
        light_group: Option<u32>,
    },
    /// `entity` no longer shows anything.
    Remove { entity: Entity },
    /// Mesh `mesh` of `model` has new object-space vertex positions.
    Deform {
        model: ModelHandle,
        mesh: usize,
        positions: Vec<Vec3>,
        normals: Option<Vec<Vec3>>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Placed {
    model: ModelHandle,
    world_from_model: Mat4,
    material_override: Option<u32>,
    light_group: Option<u32>,
    is_static: bool,
}

/// What one extraction found.
#[derive(Clone, Debug, Default)]
pub struct Extracted {
    pub changes: Vec<SceneChange>,
    /// The view of the first entity with a [`CameraRig`], if any.
    pub camera: Option<RenderCamera>,
    /// How far that camera moved (metres + radians) since it last counted as moving: 0 while
    /// it stays within `CAMERA_STILL_TOLERANCE` of that pose; infinite for its first view.
    pub camera_motion: f32,
}

/// The extraction state.
#[derive(Clone, Debug, Default)]
pub struct Extractor {
    known: HashMap<Entity, Placed>,
    /// The camera's pose when it last counted as moving (the anchor of
    /// [`CAMERA_STILL_TOLERANCE`]).
    camera: Option<(Vec3, Quat)>,
}

/// How far (metres of translation plus radians of rotation) the camera may wander from where
/// it last counted as moving and still count as still. A standing first-person character's
/// controller nudges the eye up and down by 1e-4 m between physics steps (rapier's normal
/// nudge), which read as motion above the converging policy's threshold and restarted a still
/// view's image on most frames (issue 37). 5e-4 rad is a quarter of a pixel of a 1280×720,
/// 70° view, and 0.5 mm half a pixel of a surface half a metre away. Motion is measured from
/// the anchor, not frame to frame, so slow drift still adds up and counts.
pub const CAMERA_STILL_TOLERANCE: f32 = 5e-4;

impl Extractor {
    pub fn new() -> Self {
        Self::default()
    }

    /// Compares `world` with the last extraction. Clears the `dirty` flag of every
    /// [`Deformable`] it reports.
    pub fn extract(&mut self, world: &mut World) -> Extracted {
        let mut out = Extracted::default();
        let mut seen = HashMap::with_capacity(self.known.len());
        let mut restyled = Vec::new();
        for (entity, renderable, global, group, is_static, restyle) in world
            .query::<(
                Entity,
                &Renderable,
                &GlobalTransform,
                Option<&LightGroup>,
                Option<&Static>,
                Option<&Restyled>,
            )>()
            .iter()
        {
            if restyle.is_some() {
                restyled.push(entity);
            }
            let placed = Placed {
                model: renderable.model,
                world_from_model: global.0,
                material_override: renderable.material_override,
                light_group: group.map(|g| g.0),
                is_static: is_static.is_some(),
            };
            seen.insert(entity, ());
            match self.known.get(&entity) {
                Some(before) if (before.is_static && restyle.is_none()) || *before == placed => {
                    continue;
                }
                _ => {}
            }
            self.known.insert(entity, placed);
            out.changes.push(SceneChange::Place {
                entity,
                model: placed.model,
                world_from_model: placed.world_from_model,
                material_override: placed.material_override,
                light_group: placed.light_group,
            });
        }
        for entity in restyled {
            let _ = world.remove_one::<Restyled>(entity);
        }
        let gone: Vec<Entity> = self
            .known
            .keys()
            .filter(|e| !seen.contains_key(e))
            .copied()
            .collect();
        for entity in gone {
            self.known.remove(&entity);
            out.changes.push(SceneChange::Remove { entity });
        }
        for (renderable, deformable) in world.query_mut::<(&Renderable, &mut Deformable)>() {
            if deformable.dirty {
                deformable.dirty = false;
                out.changes.push(SceneChange::Deform {
                    model: renderable.model,
                    mesh: deformable.mesh,
                    positions: deformable.positions.clone(),
                    normals: deformable.normals.clone(),
                });
            }
        }
        if let Some((rig, global)) = world
            .query::<(&CameraRig, &GlobalTransform)>()
            .iter()
            .next()
        {
            let (_, rotation, position) = global.0.to_scale_rotation_translation();
            out.camera = Some(RenderCamera::from_pose(position, rotation, rig));
            out.camera_motion = match self.camera {
                Some((p, r)) => {
                    let moved = (position - p).length() + rotation_angle(r, rotation);
                    if moved <= CAMERA_STILL_TOLERANCE {
                        0.0
                    } else {
                        self.camera = Some((position, rotation));
                        moved
                    }
                }
                None => {
                    self.camera = Some((position, rotation));
                    f32::INFINITY
                }
            };
        }
        out
    }
}

/// The angle in radians of the rotation taking `from` to `to` (both unit quaternions), exact
/// near zero: `2·atan2(|v|, |w|)` of the relative quaternion. `Quat::angle_between`'s
/// `2·acos(|from·to|)` is not: a dot product that rounds to 1 − 2⁻²⁴ (as `q·q` does for many
/// unit `q`) reads as 6.9e-4 rad of turn, above the converging policy's camera threshold, so a
/// still view restarted its image on every frame.
pub fn rotation_angle(from: Quat, to: Quat) -> f32 {
    if from == to {
        return 0.0;
    }
    let relative = from.conjugate() * to;
    2.0 * Vec3::new(relative.x, relative.y, relative.z)
        .length()
        .atan2(relative.w.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_still_rotation_measures_zero_and_a_small_turn_its_angle() {
        let mut worst_still = 0.0f32;
        let mut acos_resets = 0;
        for i in 0..2000 {
            let yaw = i as f32 * 0.0137;
            let pitch = (i as f32 * 0.0071).sin() * 1.4;
            let q = Quat::from_euler(glam::EulerRot::YXZ, yaw, pitch, 0.0);
            // The same pose, rebuilt as the extractor sees it (decomposed from a matrix).
            let (_, again, _) = Mat4::from_quat(q).to_scale_rotation_translation();
            worst_still = worst_still.max(rotation_angle(q, again));
            if q.angle_between(again) > 1e-4 {
                acos_resets += 1;
            }
            let turned = Quat::from_rotation_y(1e-3) * q;
            let angle = rotation_angle(q, turned);
            assert!((angle - 1e-3).abs() < 2e-5, "turn of 1e-3 read as {angle}");
        }
        assert!(worst_still < 1e-5, "a still pose read as {worst_still} rad");
        // What this replaces: the acos form reads many still poses as a turn.
        assert!(acos_resets > 0);
    }

    fn place(world: &mut World, camera: Entity, at: Vec3) {
        if let Ok(mut global) = world.get::<&mut GlobalTransform>(camera) {
            *global = GlobalTransform(Mat4::from_translation(at));
        }
    }

    #[test]
    fn a_jittering_eye_counts_as_still_and_slow_drift_adds_up() {
        let mut world = World::new();
        let rig = CameraRig {
            vertical_fov: 1.2,
            aperture_radius: 0.0,
            focus_distance: 2.0,
        };
        let camera = world.spawn((rig, GlobalTransform(Mat4::from_translation(Vec3::Y))));
        let mut x = Extractor::new();
        assert_eq!(x.extract(&mut world).camera_motion, f32::INFINITY);
        // A standing character's eye: up and down by 1e-4 m from step to step.
        for i in 0..20 {
            let y = 1.0 + if i % 2 == 0 { 1e-4 } else { 0.0 };
            place(&mut world, camera, Vec3::new(0.0, y, 0.0));
            assert_eq!(x.extract(&mut world).camera_motion, 0.0, "step {i}");
        }
        // A slow drift of 1e-4 m a frame is reported once it adds up past the tolerance.
        let mut reported = Vec::new();
        for i in 1..=20 {
            place(&mut world, camera, Vec3::new(0.0, 1.0, i as f32 * 1e-4));
            reported.push(x.extract(&mut world).camera_motion);
        }
        let moves: Vec<f32> = reported.iter().copied().filter(|&m| m > 0.0).collect();
        assert!(moves.len() >= 3, "{reported:?}");
        assert!(
            moves.iter().all(|&m| m > CAMERA_STILL_TOLERANCE),
            "{reported:?}"
        );
        // A real step is reported at once, at its size.
        place(&mut world, camera, Vec3::new(0.0, 1.0, 0.5));
        let m = x.extract(&mut world).camera_motion;
        assert!(m > 0.49 && m < 0.51, "{m}");
    }
}
