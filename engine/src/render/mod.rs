//! Rendering, on the render thread: the thread itself (apply commits, converge, scale, render,
//! present), the camera uniforms, the `Tracer` trait with its GPU and CPU implementations, the
//! film, and presenting it in a window. The scene it renders is [`crate::scene`]'s.

pub mod auto;
pub mod balance;
pub(crate) mod camera;
pub mod cpu;
pub mod denoise;
pub mod denoise_stage;
mod device_loss;
pub mod film;
mod frame_render;
pub mod gpu;
pub mod jitter;
pub mod present;
pub mod scaling;
pub(crate) mod thread;
pub(crate) mod tracer;

pub use camera::{FrameSettings, frame_uniforms, method_of};
pub use denoise_stage::DenoiseStage;
pub use thread::{OpenTracer, RenderConfig, RenderThread, Rendered, TracerChoice};
pub use tracer::{FilmView, RenderError, RenderStats, Tracer};
