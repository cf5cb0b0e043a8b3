//! Ray cones for texture level of detail (Akenine-Möller et al., "Texture Level of Detail
//! Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20, 2019); twin: the `cone_*`
//! functions of `shaders/shared/texture.wgsl`.
//!
//! Owns: a path's cone (width in metres at the last vertex, spread angle in radians), its start
//! at the camera (one pixel's angle), its growth along a segment, its widening at a bounce, and
//! the footprint [`Lod`] it gives at a hit. Render thread (per path, pure).
//! Must not: read textures (`texture.rs`) or choose directions (the integrator does).

use glam::Vec3;

use super::texture::Lod;
use crate::layout::GpuFrameUniforms;

/// Most a rough bounce widens the cone, radians: past this every lookup of an indirect
/// bounce reads a coarse level (the diffuse integral blurs the texture anyway).
pub const BOUNCE_SPREAD_MAX: f32 = 1.0;

/// A path's ray cone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// Width at the vertex the current ray leaves from, metres.
    pub width: f32,
    /// Full spread angle, radians (small-angle: width grows by `spread` per metre).
    pub spread: f32,
}

impl Cone {
    /// The cone of a camera ray: width 0, spread one pixel's vertical angle
    /// (`2·tan(vfov/2) / film height`).
    pub fn camera(u: &GpuFrameUniforms) -> Cone {
        Cone {
            width: 0.0,
            spread: 2.0 * Vec3::from(u.camera_up).length() / u.height.max(1) as f32,
        }
    }

    /// Grows the cone along a segment of `t` metres to a hit.
    pub fn travel(&mut self, t: f32) {
        self.width += self.spread * t.max(0.0);
    }

    /// The footprint at a hit: `log2(width / |n·d|) + ½·log2(uv_density)` where `uv_density` is
    /// the triangle's UV area per world area (1/m²), `n` its unit geometric normal and `d` the
    /// unit ray direction. `random` picks between levels.
    pub fn lod(&self, uv_density: f32, normal: Vec3, direction: Vec3, random: f32) -> Lod {
        let cos = normal.dot(direction).abs().max(1e-6);
        let footprint = (self.width / cos).log2() + 0.5 * uv_density.log2();
        Lod {
            footprint: if footprint.is_nan() {
                f32::NEG_INFINITY
            } else {
                footprint
            },
            random,
        }
    }

    /// Widens the cone at a bounce whose sampled direction had density `pdf` (1/sr): a delta
    /// lobe (mirror, glass) keeps the spread; otherwise the spread grows by the full angle of a
    /// cone of solid angle `1/pdf`, `2·sqrt(1 / (π·pdf))`, at most [`BOUNCE_SPREAD_MAX`].
    pub fn bounce(&mut self, pdf: f32, delta: bool) {
        if delta {
            return;
        }
        let widen = if pdf > 0.0 {
            (2.0 * (1.0 / (std::f32::consts::PI * pdf)).sqrt()).min(BOUNCE_SPREAD_MAX)
        } else {
            BOUNCE_SPREAD_MAX
        };
        self.spread += widen;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layout::GpuTexture;

    /// A quad facing the camera at distance d whose texels each cover one pixel reads level 0;
    /// at 4d it reads level 2.
    #[test]
    fn texel_per_pixel_is_level_zero() {
        let (height, tan_half) = (180u32, 0.5f32);
        let mut u: GpuFrameUniforms = bytemuck::Zeroable::zeroed();
        u.camera_up = [0.0, tan_half, 0.0];
        u.height = height;
        let d = 3.0;
        // One pixel at distance d spans 2·tan_half·d / height metres; a 256² texture over a
        // square quad of side 256 pixels' spans maps one texel to one pixel.
        let pixel = 2.0 * tan_half * d / height as f32;
        let side = 256.0 * pixel;
        let uv_density = 1.0 / (side * side);
        let t = GpuTexture {
            width: 256,
            height: 256,
            flags: 9 << crate::layout::TEXTURE_LEVELS_SHIFT,
            ..Default::default()
        };
        let at = |distance: f32| {
            let mut cone = Cone::camera(&u);
            cone.travel(distance);
            let lod = cone.lod(uv_density, Vec3::Z, -Vec3::Z, 0.0);
            lod.footprint + 0.5 * (256.0f32 * 256.0).log2()
        };
        assert!(at(d).abs() < 1e-4, "λ at d: {}", at(d));
        assert!((at(4.0 * d) - 2.0).abs() < 1e-4, "λ at 4d: {}", at(4.0 * d));
        let mut cone = Cone::camera(&u);
        cone.travel(4.0 * d);
        assert_eq!(cone.lod(uv_density, Vec3::Z, -Vec3::Z, 0.0).level(&t, 9), 2);
        // λ = 2.5: level 2 or 3 by the random number.
        cone = Cone::camera(&u);
        cone.travel(4.0 * 2f32.sqrt() * d);
        assert_eq!(cone.lod(uv_density, Vec3::Z, -Vec3::Z, 0.4).level(&t, 9), 3);
        assert_eq!(cone.lod(uv_density, Vec3::Z, -Vec3::Z, 0.6).level(&t, 9), 2);
        // A mirror keeps the spread, a diffuse bounce widens it.
        let before = cone;
        cone.bounce(1.0, true);
        assert_eq!(cone, before);
        cone.bounce(std::f32::consts::FRAC_1_PI, false);
        assert!(cone.spread > before.spread + 0.5);
    }
}
