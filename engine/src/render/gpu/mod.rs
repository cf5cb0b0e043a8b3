//! The GPU tracer: wgpu device set-up, the shader registry, scene upload and the tracing pass;
//! and the GPU twin of the denoiser.

mod context;
mod denoise;
mod denoise_passes;
mod dispatch;
mod ray_batch;
mod shaders;
mod tracer;
mod upload;

pub use context::{GpuContext, map_for_reading};
pub use denoise::GpuDenoiser;
pub use shaders::{PRESENT, PRESENT_SHARED, SHARED, ShaderSource, compose, compose_with};
pub use tracer::GpuTracer;
