//! Rendering: the render-side scene, lights, camera, the `Tracer` trait with its GPU and CPU
//! implementations, the film, and presenting it in a window.

pub mod balance;
pub mod camera;
pub mod cpu;
pub mod film;
pub mod gpu;
pub mod lights;
pub mod materials;
pub mod present;
pub mod scaling;
pub mod scene;
pub mod scene_writes;
pub mod thread;
pub mod tracer;

pub use camera::{FrameSettings, frame_uniforms};
pub use scene::RenderScene;
pub use scene_writes::{SceneHeader, SceneWrite};
pub use thread::{RenderConfig, RenderThread, Rendered, TracerChoice};
pub use tracer::{FilmView, RenderError, RenderStats, Tracer};
