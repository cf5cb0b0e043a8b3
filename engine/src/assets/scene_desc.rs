//! A scene as loaded: models, level materials, placed instances, camera, sun, sky, settings.
//!
//! Owns: [`SceneDesc`], the hand-over from loading (a level file, or code in tests and tools)
//! to the renderer, which flattens it (`accel`, into a `scene::RenderScene`). Plain data, no logic.
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
#[derive(Clone, Debug)]
pub struct SceneInstance {
    /// Index into [`SceneDesc::models`].
    pub model: usize,
    /// Affine map from model space to world space (metres).
    pub world_from_model: Mat4,
    /// Index into [`SceneDesc::level_materials`] replacing every material of the model.
    pub material_override: Option<usize>,
    /// The level's name for the instance.
    pub name: Option<String>,
    /// Moves at run time (otherwise static).
    pub dynamic: bool,
    pub light_group: Option<u32>,
    pub waves: Option<super::level::WaveDesc>,
}

impl SceneInstance {
    /// A static, unnamed placement of `model`.
    pub fn placed(model: usize, world_from_model: Mat4) -> Self {
        Self {
            model,
            world_from_model,
            material_override: None,
            name: None,
            dynamic: false,
            light_group: None,
            waves: None,
        }
    }
}

impl SceneDesc {
    /// A scene of one model placed once at the origin.
    pub fn single(model: Model, camera: CameraDesc) -> Self {
        Self {
            source: PathBuf::new(),
            models: vec![model],
            level_materials: Vec::new(),
            instances: vec![SceneInstance::placed(0, Mat4::IDENTITY)],
            camera,
            sun: None,
            sky: SkyDesc::default(),
            render: RenderSettings::default(),
        }
    }
}
