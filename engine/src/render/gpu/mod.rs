//! The GPU tracer: wgpu device set-up, the shader registry, scene upload and the tracing pass.

mod context;
mod ray_batch;
mod shaders;
mod tracer;
mod upload;

pub use context::{GpuContext, map_for_reading};
pub use shaders::{PRESENT, PRESENT_SHARED, SHARED, ShaderSource, compose, compose_with};
pub use tracer::GpuTracer;
