//! The camera and the per-render uniforms built around it.
//!
//! Owns: turning a `RenderCamera` (eye, camera-to-world basis, vertical FOV, lens; built once by
//! `extract`, never rebuilt here) plus image size, sampling settings, sun and sky into a
//! `GpuFrameUniforms`. The pixel-to-ray mapping is the
//! one of the reference renders (`shared/external/reference/*/scene.md`): for pixel (px, py),
//! py downward, sampled at (u, v) in [0,1)², `sx = 2 (px+u)/W − 1`, `sy = 1 − 2 (py+v)/H`,
//! direction = normalize(forward + sx·right + sy·up) with right and up pre-scaled by
//! tan(vfov/2)·aspect and tan(vfov/2).
//! Must not: know which tracer consumes the uniforms.

use crate::assets::{RenderSettings, SkyDesc, SunDesc};
use crate::extract::RenderCamera;
use crate::layout::GpuFrameUniforms;
use crate::scene::SceneHeader;
use crate::scene::lights::fill_sun_and_sky;

/// What one render call needs besides the scene.
#[derive(Clone, Copy, Debug)]
pub struct FrameSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel traced by this call.
    pub spp: u32,
    /// Global index of the first sample (so successive calls continue the same sequence).
    pub sample_base: u32,
    pub seed: u32,
    pub max_bounces: u32,
    pub roulette_start: u32,
    /// Multiplies the roulette survival probability; 1 is the default.
    pub roulette_scale: f32,
    /// Weight of this render's mean in the film (see `GpuFrameUniforms::film_blend`).
    pub film_blend: f32,
    /// The estimator (`layout::METHOD_*` bits).
    pub method: u32,
}

impl FrameSettings {
    /// Settings for a `width × height` image with the level's bounce settings.
    pub fn new(width: u32, height: u32, spp: u32, seed: u32, render: &RenderSettings) -> Self {
        Self {
            width,
            height,
            spp,
            sample_base: 0,
            seed,
            max_bounces: render.max_bounces,
            roulette_start: render.roulette_start,
            roulette_scale: 1.0,
            film_blend: 1.0,
            method: method_of(render.light_sampling) | render.indirect_method(),
        }
    }

    /// Continues an exact running mean: this call's `spp` samples follow `sample_base` earlier
    /// ones (sets `sample_base` and `film_blend`).
    pub fn continuing(mut self, sample_base: u32) -> Self {
        self.sample_base = sample_base;
        self.film_blend = self.spp as f32 / (sample_base + self.spp).max(1) as f32;
        self
    }
}

/// The default estimator (`layout::METHOD_DEFAULT`: NEE + MIS) with lights picked by
/// `sampling`.
pub fn method_of(sampling: crate::assets::LightSampling) -> u32 {
    match sampling {
        crate::assets::LightSampling::Power => crate::layout::METHOD_DEFAULT,
        crate::assets::LightSampling::Tree => {
            crate::layout::METHOD_DEFAULT | crate::layout::METHOD_LIGHT_TREE
        }
    }
}

/// Builds the uniforms of one render call. Light totals, the TLAS root and the render-space
/// origin come from the scene's header: the camera's eye (world metres) is placed in render
/// space (world − origin, see `accel::origin`) here, so tracers only ever see render space; its
/// basis is direction only and is used as it is. `camera` is a `&RenderCamera` (a commit's), or
/// a level's `&CameraDesc`, converted here by `RenderCamera::from_desc` (tools and tests that
/// render a level's view).
pub fn frame_uniforms(
    camera: impl Into<RenderCamera>,
    sun: Option<&SunDesc>,
    sky: &SkyDesc,
    frame: &FrameSettings,
    scene: &SceneHeader,
) -> GpuFrameUniforms {
    let camera: RenderCamera = camera.into();
    let (light_count, light_weight_total, tlas_root) =
        (scene.light_count, scene.light_weight_total, scene.tlas_root);
    let position = camera.position() - scene.origin;
    let tan_half = (camera.vertical_fov_radians() * 0.5).tan();
    let aspect = frame.width.max(1) as f32 / frame.height.max(1) as f32;
    let mut u = GpuFrameUniforms {
        camera_position: position.to_array(),
        lens_radius: camera.lens_radius_meters(),
        camera_right: (camera.right() * tan_half * aspect).to_array(),
        focus_distance: camera.focus_distance_meters(),
        camera_up: (camera.up() * tan_half).to_array(),
        film_blend: frame.film_blend,
        camera_forward: camera.forward().to_array(),
        method: frame.method,
        sun_direction: [0.0, 1.0, 0.0],
        sun_cos_radius: 1.0,
        sun_radiance: [0.0; 3],
        sun_solid_angle: -1.0,
        sky_zenith: [0.0; 4],
        sky_horizon: [0.0; 4],
        sky_ground: [0.0; 4],
        width: frame.width,
        height: frame.height,
        spp: frame.spp,
        sample_base: frame.sample_base,
        seed: frame.seed,
        max_bounces: frame.max_bounces,
        roulette_start: frame.roulette_start,
        light_count,
        light_weight_total,
        roulette_scale: frame.roulette_scale,
        sky_kind: 0,
        tlas_root,
        sun_terminator: [0.0; 3],
        sun_sin_radius: 0.0,
        second_direction: [0.0, 1.0, 0.0],
        second_cos_radius: 1.0,
        second_radiance: [0.0; 3],
        second_sin_radius: 0.0,
        second_terminator: [0.0; 3],
        star_radiance: 0.0,
        airglow: [0.0; 3],
        star_sin_radius: 0.0,
        zenith_transmittance: [1.0; 3],
        pixel_jitter: 0,
        celestial_x: [1.0, 0.0, 0.0, 0.0],
        celestial_y: [0.0, 1.0, 0.0, 0.0],
        celestial_z: [0.0, 0.0, 1.0, 0.0],
        cloud_plane: [0.0; 4],
        cloud_light: [0.0; 3],
        cloud_texels: 0,
        moon_sky: [0.0; 4],
    };
    fill_sun_and_sky(&mut u, sun, sky);
    // The cloud plane in render space: the scene is traced relative to `origin`.
    let size = u.cloud_plane[3];
    if size > 0.0 {
        let origin = scene.origin;
        u.cloud_plane[0] -= origin.y;
        u.cloud_plane[1] = (u.cloud_plane[1] - origin.x).rem_euclid(size);
        u.cloud_plane[2] = (u.cloud_plane[2] - origin.z).rem_euclid(size);
    }
    u
}
