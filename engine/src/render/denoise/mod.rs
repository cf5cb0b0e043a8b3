//! The denoiser: spatiotemporal variance-guided filtering (SVGF, Schied et al. 2017) of the
//! path tracer's frames, in Rust (this module, the reference) and in WGSL
//! (`render/gpu/denoise.rs`, `shaders/denoise_*.wgsl`), agreeing within f32 rounding.
//!
//! Owns: the guide buffers' type, the stages (one file each) and their order (`svgf`).
//! Linear radiance in, linear radiance out; render thread. Off for captures and references,
//! on in games (`RenderConfig::denoise`, `capture --denoise`). Biased: it trades noise for
//! blur, measured in `docs/ACCURACY.md` ("Denoiser").
//! Must not: trace rays (the guide pass, `render/cpu/guides.rs`, does) or know the tracer.

mod atrous;
mod atrous_block;
mod guides;
mod planes;
mod reproject;
mod reproject_edge;
mod svgf;
mod temporal;
mod upscale;
mod variance;
mod view;
pub mod weights;

pub use atrous::{Pass, atrous_pixel};
pub use guides::{Guides, NO_INSTANCE};
pub use reproject::{
    NORMAL_COS, PLANE_TOLERANCE, PrevFrame, ReprojectStats, SNAP_PIXELS, motions, reproject,
    world_from_object,
};
pub use svgf::{AtrousKernel, DenoiseError, Svgf, SvgfParams};
pub use temporal::{History, Reprojection, accumulate_albedo, temporal_pixel};
pub use upscale::{Traced, filled, splat};
pub use variance::variance_pixel;
pub use view::View;
