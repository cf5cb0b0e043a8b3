//! The entity-component world (hecs) and the order its systems run in.

mod components;
mod hierarchy;
mod schedule;

pub use components::{
    CameraRig, Deformable, GlobalTransform, LightGroup, ModelHandle, Parent, Renderable, Restyled,
    Static, Transform,
};
pub use hierarchy::propagate_transforms;
pub use schedule::SYSTEM_ORDER;
