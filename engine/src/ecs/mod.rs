//! The entity-component world (hecs): the engine's components and the transform hierarchy.
//! The order systems run in is the frame's phases (`app::Phase`).

mod components;
mod hierarchy;

pub use components::{
    CameraRig, Deformable, GlobalTransform, LightGroup, ModelHandle, Parent, Renderable, Restyled,
    Static, Transform,
};
pub use hierarchy::propagate_transforms;
