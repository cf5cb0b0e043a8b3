//! Extraction: the world's renderable state → typed, deduplicated scene changes, and the view
//! as a [`RenderCamera`] (the camera that crosses the commit).

mod camera;
mod changes;

pub use camera::RenderCamera;
pub use changes::{Extracted, Extractor, SceneChange};
