//! Extraction: the world's renderable state → typed, deduplicated scene changes.

mod changes;

pub use changes::{Extracted, Extractor, SceneChange};
