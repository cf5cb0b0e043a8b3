//! [`Environment`]: everything about the scene that is not an entity (sun, sky, render
//! settings, the view when no entity carries a camera), and the environment a level describes.
//!
//! Plain data, main thread. Must not: hold entities or engine state.

use crate::assets::{CameraDesc, RenderSettings, SceneDesc, SkyDesc, SunDesc};

/// Everything about the scene that is not an entity: sun, sky, render settings, and the view to
/// use when no entity carries a camera.
#[derive(Clone, Copy, Debug)]
pub struct Environment {
    pub sun: Option<SunDesc>,
    pub sky: SkyDesc,
    pub render: RenderSettings,
    pub default_camera: CameraDesc,
}

impl Environment {
    /// The environment a level describes (its camera becomes the default view).
    pub fn of(desc: &SceneDesc) -> Self {
        Self {
            sun: desc.sun,
            sky: desc.sky,
            render: desc.render,
            default_camera: desc.camera,
        }
    }
}
