//! The cloud layer as the CPU tracer reads it (twin: `shaders/shared/clouds.wgsl`): the plane
//! from the frame uniforms, the one transmittance that both estimators of the sun's (or moon's)
//! disc are multiplied by — next-event estimation in `direct.rs`, the escaping ray that hits
//! the disc in `integrator.rs` — so MIS between them stays unbiased, and the sky seen through
//! the layer.
//!
//! Any thread; pure functions over the uniforms and the scene's cloud texels
//! (`SkyTable::clouds`). Positions are render-space metres, directions unit vectors, radiance
//! linear RGB. Must not: sample or trace (a cloud is a transmittance, not a surface).

use glam::{Vec2, Vec3};

use crate::layout::GpuFrameUniforms;
use crate::sky::{CloudPlane, cloud_transmittance};

/// The uniforms' cloud plane (`cloud_plane`, `cloud_texels`).
pub fn plane(u: &GpuFrameUniforms) -> CloudPlane {
    CloudPlane {
        height: u.cloud_plane[0],
        offset: Vec2::new(u.cloud_plane[1], u.cloud_plane[2]),
        size: u.cloud_plane[3],
        texels: u.cloud_texels,
    }
}

/// T_cloud(p, ω): exp(−τ) where the ray from `p` along unit `w` crosses the cloud plane
/// going up; exactly 1 without clouds or for rays that do not cross it.
pub fn transmittance(u: &GpuFrameUniforms, tau: &[f32], p: Vec3, w: Vec3) -> f32 {
    if u.cloud_plane[3] <= 0.0 {
        return 1.0;
    }
    cloud_transmittance(&plane(u), tau, p, w)
}

/// The sky `sky` seen through a cloud of transmittance `t`: sky · t plus the cloud's own
/// in-scatter, `cloud_light` · (1 − t); `sky` itself (the same bits) when `t` is 1.
pub fn through(u: &GpuFrameUniforms, sky: Vec3, t: f32) -> Vec3 {
    if t == 1.0 {
        return sky;
    }
    sky * t + Vec3::from(u.cloud_light) * (1.0 - t)
}
