//! The CPU tracer: the same path tracing algorithm as the GPU tracer, in Rust, parallel over
//! image tiles with rayon, reading the same flattened scene.

pub(crate) mod bsdf;
pub mod clouds;
pub(crate) mod cone;
mod direct;
pub mod guides;
pub mod integrator;
pub mod interleave;
pub mod light_tree;
pub mod lines;
pub(crate) mod microfacet;
pub mod night;
pub mod rng;
pub mod sampling;
pub mod surface;
pub(crate) mod texture;
mod tracer;

pub use tracer::{CpuTracer, trace_rect};
