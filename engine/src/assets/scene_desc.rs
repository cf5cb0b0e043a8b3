//! A scene as loaded: models, level materials, placed instances, camera, sun, sky, settings.
//!
//! Owns: [`SceneDesc`], the hand-over from loading (a level file, or code in tests and tools)
//! to the renderer, which flattens it (`render::scene`). Plain data, no logic.
//! Must not: hold GPU or BVH data.

use std::path::PathBuf;

use glam::Mat4;

use super::level::{CameraDesc, RenderSettings, SkyDesc, SunDesc};
use super::model::{Material, Model};

/// Everything a renderer needs to build its scene.
#[derive(Clone, Debug)]
pub struct SceneDesc {
    /// The level file it came from (empty when built in code), for messages.
    pub source: PathBuf,
    pub models: Vec<Model>,
    /// Materials defined by the level, referenced by [`SceneInstance::material_override`].
    pub level_materials: Vec<Material>,
    pub instances: Vec<SceneInstance>,
    pub camera: CameraDesc,
    pub sun: Option<SunDesc>,
    pub sky: SkyDesc,
    pub render: RenderSettings,
}

/// One placed copy of a model.
#[derive(Clone, Copy, Debug)]
pub struct SceneInstance {
    /// Index into [`SceneDesc::models`].
    pub model: usize,
    /// Affine map from model space to world space (metres).
    pub world_from_model: Mat4,
    /// Index into [`SceneDesc::level_materials`] replacing every material of the model.
    pub material_override: Option<usize>,
}

impl SceneDesc {
    /// A scene of one model placed once at the origin.
    pub fn single(model: Model, camera: CameraDesc) -> Self {
        Self {
            source: PathBuf::new(),
            models: vec![model],
            level_materials: Vec::new(),
            instances: vec![SceneInstance {
                model: 0,
                world_from_model: Mat4::IDENTITY,
                material_override: None,
            }],
            camera,
            sun: None,
            sky: SkyDesc::default(),
            render: RenderSettings::default(),
        }
    }
}
