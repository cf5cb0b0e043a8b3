//! Assets: files in, engine-side [`Model`]s and levels out. Every path goes through an
//! [`AssetRoot`]; every failure is an [`AssetError`] naming the file and the problem.
//!
//! Model loading starts at [`load_model`] (`load.rs`): OBJ + MTL (`obj`, `obj_scan`,
//! `obj_mesh`, `mtl`, `mtl_material`), glTF 2.0 (`gltf/`), textures (`texture`, `bump`), then
//! the checks and repairs every mesh goes through (`mesh_check`, `tangents`). Limits on sizes
//! are in `limits`; `context` carries one load's file, root and notes. [`load_model_bytes`]
//! loads from memory, the referenced files coming from a [`MemoryFiles`] (`memory`).

pub(crate) mod atomic_file;
mod bump;
mod city;
pub(crate) mod context;
mod error;
pub(crate) mod gltf;
mod grid;
mod limits;
mod load;
mod memory;
mod mesh_check;
mod model;
mod mtl;
mod mtl_material;
mod obj;
mod obj_mesh;
mod obj_scan;
mod root;
mod shapes;
mod tangents;
mod texture;

pub use city::{CityEntry, city_model};
pub use error::{AssetError, AssetResult};
pub use load::{load_model, load_model_bytes, load_model_file};
pub use memory::MemoryFiles;
pub use model::{Material, MaterialKind, Mesh, Model, Placement, Texture, TextureRef, Wrap};
pub use root::AssetRoot;
pub use shapes::{BoxEntry, TerrainEntry, box_model, terrain_model};

mod clip_desc;
pub use clip_desc::{
    AuthoredClip, AuthoredClipSet, AuthoredKey, AuthoredTrack, ClipEvent, Interpolation, PlayMode,
    Property,
};
mod level;
pub use level::{
    CameraDesc, GridEntry, InstanceEntry, Level, LevelMaterial, LightSampling, ModelEntry,
    RenderSettings, SkyDesc, SunDesc, TransformDesc, WaveDesc,
};

mod scene_desc;
pub use scene_desc::{SceneDesc, SceneInstance};

mod level_body;
mod level_character;
pub use level_body::{BodyEntry, ShapeEntry};
pub use level_character::{
    AnimStateEntry, BlendEntry, CapsuleEntry, CharacterEntry, Contact, ControllerEntry,
};
mod level_breakable;
pub use level_breakable::BreakableEntry;
mod level_gameplay;
pub use level_gameplay::{
    ActionEntry, AutoplayEntry, BeamEntry, ConditionEntry, CounterEntry, Detect, EmitterEntry,
    GameplayEntry, LaserEntry, MusicEntry, RuleEntry, SoundEntry, UsableEntry, VolumeEntry,
};
mod level_load;
mod level_render;
mod level_render_areas;
pub use level_render_areas::{RenderArea, check_render_areas, sampled_groups};
mod level_water;
pub use level_water::{VALIDATED_STEP_SECONDS, WaterSimDesc};
mod level_shapes;
mod needs;
pub use level_load::{load_scene, scene_from_level};
pub use needs::Needs;
