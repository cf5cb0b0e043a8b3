//! The guide buffers (AOVs) the denoiser is steered by, one value per pixel at the primary
//! hit: world normal, hit distance, demodulated albedo and the instance hit.
//!
//! Owns: [`Guides`] and its packing into the `vec4` rows both denoisers read. Produced by the
//! CPU guide pass (`render/cpu/guides.rs`) on the render thread, only when the denoiser is on.
//! Units: normals are unit world-space vectors (right-handed, Y up) turned to face the camera;
//! depth is the distance from the camera to the primary hit along the ray, metres (0 = sky);
//! albedo is the base colour at the first non-specular hit (the product of the mirror tints
//! before it), 1 for the sky and behind smooth glass; rows top to bottom.
//! Must not: trace rays (the guide pass does) or filter.

use glam::{Vec3, Vec4};

/// Instance id of a pixel that sees the sky.
pub const NO_INSTANCE: u32 = u32::MAX;

/// Per-pixel guides of one frame (`Default`: 0×0).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Guides {
    pub width: u32,
    pub height: u32,
    /// Unit world-space normal facing the camera (zero for the sky).
    pub normal: Vec<Vec3>,
    /// Primary hit distance, metres (0 for the sky).
    pub depth: Vec<f32>,
    /// Demodulation albedo (linear, 0–1 per channel; 1 for the sky).
    pub albedo: Vec<Vec3>,
    /// Instance at the primary hit ([`NO_INSTANCE`] for the sky); for the reprojection's
    /// history rejection, unused by the filter itself.
    pub instance: Vec<u32>,
    /// The primary hit emits light: such pixels (a lamp seen directly, its radiance known, not
    /// noisy) pass the filter unchanged and never blur into their neighbours, as the sky does.
    pub emissive: Vec<bool>,
    /// The primary hit is specular (a mirror or smooth glass): the pixel shows light from
    /// other surfaces, which moves unlike its own; reprojection does not reuse its history.
    pub specular: Vec<bool>,
}

impl Guides {
    /// Makes `self` a copy of `other`, reusing `self`'s buffers (no allocation once the sizes
    /// have been seen: the denoiser keeps the previous frame's guides this way).
    pub fn copy_from(&mut self, other: &Guides) {
        self.width = other.width;
        self.height = other.height;
        self.normal.clone_from(&other.normal);
        self.depth.clone_from(&other.depth);
        self.albedo.clone_from(&other.albedo);
        self.instance.clone_from(&other.instance);
        self.emissive.clone_from(&other.emissive);
        self.specular.clone_from(&other.specular);
    }

    /// All sky: no surface anywhere, albedo 1.
    pub fn sky(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self {
            width,
            height,
            normal: vec![Vec3::ZERO; n],
            depth: vec![0.0; n],
            albedo: vec![Vec3::ONE; n],
            instance: vec![NO_INSTANCE; n],
            emissive: vec![false; n],
            specular: vec![false; n],
        }
    }

    /// Pixels.
    pub fn len(&self) -> usize {
        self.depth.len()
    }

    /// True for a 0-pixel image.
    pub fn is_empty(&self) -> bool {
        self.depth.is_empty()
    }

    /// True when every buffer holds `width × height` values.
    pub fn is_consistent(&self) -> bool {
        let n = self.width as usize * self.height as usize;
        self.normal.len() == n
            && self.depth.len() == n
            && self.albedo.len() == n
            && self.instance.len() == n
            && self.emissive.len() == n
            && self.specular.len() == n
    }

    /// (normal xyz, depth w) per pixel, as the passes and the GPU buffers hold them (raw: the
    /// passes sanitize every read, and read a depth that is not positive as "no surface").
    /// Emissive pixels are packed with a negated depth, so that the filter treats them as it
    /// treats the sky.
    pub fn packed_normal_depth(&self) -> Vec<Vec4> {
        self.normal
            .iter()
            .zip(&self.depth)
            .zip(&self.emissive)
            .map(|((n, &z), &e)| n.extend(if e { -z } else { z }))
            .collect()
    }

    /// (albedo rgb, 0) per pixel.
    pub fn packed_albedo(&self) -> Vec<Vec4> {
        self.albedo.iter().map(|a| a.extend(0.0)).collect()
    }
}
