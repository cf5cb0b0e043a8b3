//! A frame's pinhole camera as the denoiser's reprojection sees it (`reproject`): the frame
//! uniforms' position and pre-scaled basis, the image size, and where inside its pixel each
//! sample of the frame (and so each guide) was taken.
//!
//! Owns: [`View`]. Any thread. Units: positions in the frame uniforms' space (metres,
//! camera-relative to the scene origin), image coordinates in pixels with (0, 0) the top left
//! corner and pixel centres at +0.5, x right, y down.
//! Must not: trace rays or touch the history.

use glam::Vec3;

use crate::layout::GpuFrameUniforms;

/// A frame's pinhole camera: position and the pre-scaled basis of the frame uniforms (a
/// point's direction at image coordinates (px, py) is `forward + right·sx + up·sy`,
/// `sx = 2·px/width − 1`, `sy = 1 − 2·py/height`), the image size and the guides' offset inside
/// their pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub position: Vec3,
    pub forward: Vec3,
    pub right: Vec3,
    pub up: Vec3,
    pub width: u32,
    pub height: u32,
    /// Where in its pixel each guide was taken, in pixels from the pixel's top left corner
    /// (x right, y down; (0.5, 0.5) the centre, as the guide pass traces). Guides recorded at
    /// the tracer's first hits under a frame jitter (`render::jitter`) sit at that offset.
    pub jitter: (f32, f32),
}

impl View {
    /// The frame's camera, its guides at the pixel centres.
    pub fn of(u: &GpuFrameUniforms) -> Self {
        Self {
            position: Vec3::from(u.camera_position),
            forward: Vec3::from(u.camera_forward),
            right: Vec3::from(u.camera_right),
            up: Vec3::from(u.camera_up),
            width: u.width,
            height: u.height,
            jitter: (0.5, 0.5),
        }
    }

    /// The same camera with its guides taken at `jitter` inside their pixels.
    pub fn with_jitter(self, jitter: (f32, f32)) -> Self {
        Self { jitter, ..self }
    }

    /// Unit direction through image coordinates (px, py).
    #[inline]
    pub fn direction_at(&self, px: f32, py: f32) -> Vec3 {
        let sx = 2.0 * px / self.width as f32 - 1.0;
        let sy = 1.0 - 2.0 * py / self.height as f32;
        (self.forward + self.right * sx + self.up * sy).normalize()
    }

    /// Unit direction through the centre of pixel (x, y).
    pub fn centre_direction(&self, x: u32, y: u32) -> Vec3 {
        self.direction_at(x as f32 + 0.5, y as f32 + 0.5)
    }

    /// Unit direction of pixel (x, y)'s guide (through its [`View::jitter`] offset).
    #[inline]
    pub fn sample_direction(&self, x: u32, y: u32) -> Vec3 {
        self.direction_at(x as f32 + self.jitter.0, y as f32 + self.jitter.1)
    }

    /// Continuous image coordinates of the direction `d` from the camera; `None` behind the
    /// camera or for a degenerate basis.
    #[inline]
    pub fn project_direction(&self, d: Vec3) -> Option<(f32, f32)> {
        let (f2, r2, u2) = (
            self.forward.length_squared(),
            self.right.length_squared(),
            self.up.length_squared(),
        );
        if f2 <= 0.0 || r2 <= 0.0 || u2 <= 0.0 {
            return None;
        }
        let t = d.dot(self.forward) / f2;
        if !(t > 0.0) {
            return None;
        }
        let sx = d.dot(self.right) / r2 / t;
        let sy = d.dot(self.up) / u2 / t;
        let x = (sx + 1.0) * 0.5 * self.width as f32;
        let y = (1.0 - sy) * 0.5 * self.height as f32;
        (x.is_finite() && y.is_finite()).then_some((x, y))
    }
}
