//! The components the engine itself understands. Games add their own.
//!
//! Owns: transforms (local and world), hierarchy links, what an entity shows (a model, an
//! optional material override), light-group membership, static/deforming markers, the camera.
//! Conventions: right-handed, +Y up, metres, radians; a camera looks along its local −Z with +Y
//! up (the glTF convention). Must not: hold GPU or BVH data (that lives in `accel`).

use glam::{Mat4, Quat, Vec3};

/// Where an entity is relative to its [`Parent`] (or the world): scale, then rotate, then
/// translate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Metres.
    pub translation: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
}

impl Transform {
    pub const IDENTITY: Self = Self {
        translation: Vec3::ZERO,
        rotation: Quat::IDENTITY,
        scale: Vec3::ONE,
    };

    pub fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            ..Self::IDENTITY
        }
    }

    /// `parent_from_local`.
    pub fn matrix(&self) -> Mat4 {
        Mat4::from_scale_rotation_translation(self.scale, self.rotation, self.translation)
    }

    /// The transform of an affine matrix (scale, rotation, translation).
    pub fn from_matrix(m: Mat4) -> Self {
        let (scale, rotation, translation) = m.to_scale_rotation_translation();
        Self {
            translation,
            rotation,
            scale,
        }
    }
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// The entity whose transform this one's is relative to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parent(pub hecs::Entity);

/// `world_from_local`, written by [`super::propagate_transforms`] every step; read-only for
/// everyone else.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalTransform(pub Mat4);

impl Default for GlobalTransform {
    fn default() -> Self {
        Self(Mat4::IDENTITY)
    }
}

/// A model registered with the scene (`accel::Upkeep::add_model`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModelHandle(pub u32);

/// The entity shows `model` at its [`GlobalTransform`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Renderable {
    pub model: ModelHandle,
    /// A level material (index into the scene's level materials) replacing every material of
    /// the model (the mirror gun's wall-to-mirror switch).
    pub material_override: Option<u32>,
}

/// Marks an entity that never moves after it is spawned: its instance is written once and
/// never compared again.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Static;

/// The light group an emitting entity belongs to (a room, a lamp set). A group that is switched
/// off leaves the light sampling distribution and its emitters go dark.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightGroup(pub u32);

/// A [`Static`] entity whose look changed once (a trigger or the mirror gun switched its
/// material): the extractor places it again and removes this marker.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Restyled;

/// A renderable whose mesh changes shape: the game writes new object-space positions here (same
/// vertex count as mesh `mesh` of the model), and the upkeep refits or rebuilds its BLAS.
#[derive(Clone, Debug, PartialEq)]
pub struct Deformable {
    /// Index of the mesh within the entity's model.
    pub mesh: usize,
    pub positions: Vec<Vec3>,
    /// New vertex normals (same count), or `None` to keep the mesh's.
    pub normals: Option<Vec<Vec3>>,
    /// Set by the game when `positions` changed this step; cleared by the upkeep.
    pub dirty: bool,
}

/// A camera: the view of the entity at its [`GlobalTransform`], looking along local −Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraRig {
    /// Vertical field of view, radians.
    pub vertical_fov: f32,
    /// Thin-lens radius, metres (0: pinhole).
    pub aperture_radius: f32,
    /// Metres to the plane in focus.
    pub focus_distance: f32,
}

impl Default for CameraRig {
    fn default() -> Self {
        Self {
            vertical_fov: 50f32.to_radians(),
            aperture_radius: 0.0,
            focus_distance: 5.0,
        }
    }
}
