//! [`Extractor`]: compares the world with what was extracted last frame and reports what
//! changed, once per entity (Bevy's extract phase, rapier's modified-set idea).
//!
//! Owns: the memory of what each renderable entity looked like at the last extraction, and the
//! camera. Produces [`SceneChange`]s (place, remove, deform) and the view. Entities marked
//! [`Static`] are extracted once and never compared again, unless marked [`Restyled`]. Main thread, after transforms are
//! propagated. Must not: touch BVHs or buffers (the upkeep applies the changes).

use std::collections::HashMap;

use glam::{Mat4, Quat, Vec3};
use hecs::{Entity, World};

use crate::assets::CameraDesc;
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
    pub camera: Option<CameraDesc>,
    /// How far that camera moved since the last extraction (metres + radians).
    pub camera_motion: f32,
}

/// The extraction state.
#[derive(Clone, Debug, Default)]
pub struct Extractor {
    known: HashMap<Entity, Placed>,
    camera: Option<(Vec3, Quat)>,
}

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
            let forward = rotation * Vec3::NEG_Z;
            let up = rotation * Vec3::Y;
            out.camera = Some(CameraDesc {
                position: position.to_array(),
                look_at: (position + forward).to_array(),
                up: up.to_array(),
                vertical_fov_deg: rig.vertical_fov.to_degrees(),
                aperture_radius: rig.aperture_radius,
                focus_distance: Some(rig.focus_distance),
            });
            out.camera_motion = match self.camera {
                Some((p, r)) => (position - p).length() + r.angle_between(rotation),
                None => f32::INFINITY,
            };
            self.camera = Some((position, rotation));
        }
        out
    }
}
