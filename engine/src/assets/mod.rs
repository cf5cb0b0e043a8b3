//! Assets: files in, engine-side [`Model`]s and levels out. Every path goes through an
//! [`AssetRoot`]; every failure is an [`AssetError`] naming the file and the problem.

mod error;
mod model;
mod root;

pub use error::{AssetError, AssetResult};
pub use model::{Material, MaterialKind, Mesh, Model, Placement, Texture, TextureRef, Wrap};
pub use root::AssetRoot;

mod level;
pub use level::{
    CameraDesc, InstanceEntry, Level, LevelMaterial, ModelEntry, RenderSettings, SkyDesc, SunDesc,
    TransformDesc,
};

mod scene_desc;
pub use scene_desc::{SceneDesc, SceneInstance};
