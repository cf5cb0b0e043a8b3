//! The CPU tracer: the same path tracing algorithm as the GPU tracer, in Rust, parallel over
//! image tiles with rayon, reading the same flattened scene.

pub mod bsdf;
pub mod cone;
mod direct;
pub mod guides;
pub mod integrator;
pub mod light_tree;
pub mod lines;
pub mod microfacet;
pub mod night;
pub mod rng;
pub mod sampling;
pub mod surface;
pub mod texture;
mod tracer;

pub use tracer::{CpuTracer, trace_rect};
