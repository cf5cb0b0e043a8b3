//! Per-pixel reprojection of the denoiser's history (issue 13, part 2): where each pixel of
//! this frame was in the previous one, and whether the history found there is the same
//! surface.
//!
//! Owns: [`View`] (a frame's camera as the guide pass uses it: pixel centres, pinhole),
//! [`PrevFrame`] (what reprojection keeps of the previous frame: its view, guides and the
//! instances' transforms) and [`reproject`]. A pixel's world position is its guide depth along
//! its centre ray; a point on an instance moves with the instance (previous world-from-object
//! times this frame's object-from-world), then projects into the previous view. The history
//! is gathered bilinearly from the 2×2 previous pixels around that point, each tap kept only
//! if it saw the same instance, a normal within [`NORMAL_COS`] and the expected depth within
//! [`DEPTH_TOLERANCE`]; no kept tap, a specular first hit (its reflection moves differently
//! from its surface) or a point off screen resets the pixel's history (length 0). A point that
//! lands within [`SNAP_PIXELS`] of a pixel centre takes that pixel alone, so a still camera
//! over a still scene reprojects every pixel onto itself exactly and converges as before.
//! Positions are in the frame uniforms' space (camera-relative to the scene origin; a moved
//! origin is a cut). Render thread (rows on rayon's pool).
//! Must not: trace rays or blend (see `temporal`).

use glam::{Affine3A, Mat3A, Vec3, Vec3A, Vec4};
use rayon::prelude::*;

use super::guides::{Guides, NO_INSTANCE};
use super::temporal::History;
use crate::layout::{GpuFrameUniforms, GpuInstance};

/// Smallest cosine between a pixel's normal and a history tap's normal (about 25°).
pub const NORMAL_COS: f32 = 0.9;
/// Largest relative difference between the expected and the stored depth of a tap.
pub const DEPTH_TOLERANCE: f32 = 0.05;
/// A reprojected point this close to a pixel centre (in pixels) takes that pixel alone.
pub const SNAP_PIXELS: f32 = 1e-2;

/// A frame's pinhole camera: position and the pre-scaled basis of the frame uniforms (a pixel
/// centre's direction is `forward + right·sx + up·sy`, `sx, sy ∈ [−1, 1]`), image size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub position: Vec3,
    pub forward: Vec3,
    pub right: Vec3,
    pub up: Vec3,
    pub width: u32,
    pub height: u32,
}

impl View {
    pub fn of(u: &GpuFrameUniforms) -> Self {
        Self {
            position: Vec3::from(u.camera_position),
            forward: Vec3::from(u.camera_forward),
            right: Vec3::from(u.camera_right),
            up: Vec3::from(u.camera_up),
            width: u.width,
            height: u.height,
        }
    }

    /// Unit direction through the centre of pixel (x, y).
    pub fn centre_direction(&self, x: u32, y: u32) -> Vec3 {
        let sx = 2.0 * (x as f32 + 0.5) / self.width as f32 - 1.0;
        let sy = 1.0 - 2.0 * (y as f32 + 0.5) / self.height as f32;
        (self.forward + self.right * sx + self.up * sy).normalize()
    }

    /// Continuous image coordinates (pixels, (0, 0) the top left corner, centres at +0.5) of
    /// the direction `d` from the camera; `None` behind the camera or for a degenerate basis.
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

/// An instance's world-from-object transform (its three packed rows), as [`PrevFrame`] and
/// [`reproject`] take them.
pub fn world_from_object(instance: &GpuInstance) -> Affine3A {
    let [r0, r1, r2] = instance.world_from_object;
    Affine3A {
        matrix3: Mat3A::from_cols(
            Vec3A::new(r0[0], r1[0], r2[0]),
            Vec3A::new(r0[1], r1[1], r2[1]),
            Vec3A::new(r0[2], r1[2], r2[2]),
        ),
        translation: Vec3A::new(r0[3], r1[3], r2[3]),
    }
}

/// Each instance's motion since the previous frame: its previous world-from-object times this
/// frame's object-from-world (a point on it now, in world space, to where it was), by instance
/// index; identity for an instance the previous frame did not have. The GPU twin uploads these.
pub fn motions(before: &[Affine3A], now: &[Affine3A]) -> Vec<Affine3A> {
    now.iter()
        .enumerate()
        .map(|(k, now)| match before.get(k) {
            Some(before) => *before * now.inverse(),
            None => Affine3A::IDENTITY,
        })
        .collect()
}

/// What reprojection keeps of the previous frame.
#[derive(Clone, Debug)]
pub struct PrevFrame {
    pub view: View,
    pub guides: Guides,
    /// World-from-object of every instance, by instance index (the guides' ids).
    pub world_from_object: Vec<Affine3A>,
}

/// How many pixels kept their history.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReprojectStats {
    pub kept: usize,
    pub reset: usize,
}

/// The history of `prev` moved onto this frame's pixels (`guides`, `view`,
/// `world_from_object` of this frame). Pixels without a matching history get length 0.
pub fn reproject(
    history: &History,
    prev: &PrevFrame,
    guides: &Guides,
    view: &View,
    world_from_object: &[Affine3A],
) -> (History, ReprojectStats) {
    let (w, h) = (guides.width, guides.height);
    let mut out = History::new(w, h);
    let pw = prev.view.width as usize;
    if history.width != prev.view.width
        || history.height != prev.view.height
        || !prev.guides.is_consistent()
        || prev.guides.width != prev.view.width
        || prev.guides.height != prev.view.height
    {
        let n = w as usize * h as usize;
        return (out, ReprojectStats { kept: 0, reset: n });
    }
    // Each instance's motion, once per frame rather than once per pixel.
    let moved = motions(&prev.world_from_object, world_from_object);
    let rows: Vec<Vec<(Vec4, Vec4)>> = (0..h)
        .into_par_iter()
        .map(|y| {
            (0..w)
                .map(|x| {
                    let i = y as usize * w as usize + x as usize;
                    let dir = view.centre_direction(x, y);
                    pixel(history, prev, guides, i, dir, view, &moved, pw)
                })
                .collect()
        })
        .collect();
    let mut stats = ReprojectStats::default();
    for (i, (il, m)) in rows.into_iter().flatten().enumerate() {
        if il.w > 0.0 {
            stats.kept += 1;
        } else {
            stats.reset += 1;
        }
        out.illumination[i] = il;
        out.moments[i] = m;
    }
    (out, stats)
}

/// One pixel's gathered (illumination with length, moments); length 0 when nothing matched.
/// `moved` is each instance's motion since the previous frame (identity where unknown).
#[allow(clippy::too_many_arguments)]
fn pixel(
    history: &History,
    prev: &PrevFrame,
    guides: &Guides,
    i: usize,
    dir: Vec3,
    view: &View,
    moved: &[Affine3A],
    pw: usize,
) -> (Vec4, Vec4) {
    let none = (Vec4::ZERO, Vec4::ZERO);
    if guides.specular.get(i).copied().unwrap_or(true) {
        return none;
    }
    let (instance, depth, normal) = (guides.instance[i], guides.depth[i], guides.normal[i]);
    let sky = instance == NO_INSTANCE || !(depth > 0.0);
    // Where the point was, and the direction and distance it had from the previous camera.
    let (prev_dir, expected) = if sky {
        (dir, 0.0)
    } else {
        let world = view.position + dir * depth;
        let moved = moved
            .get(instance as usize)
            .copied()
            .unwrap_or(Affine3A::IDENTITY);
        let before = moved.transform_point3(world) - prev.view.position;
        (before, before.length())
    };
    let Some((qx, qy)) = prev.view.project_direction(prev_dir) else {
        return none;
    };
    let (fx, fy) = (qx - 0.5, qy - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (ax, ay) = (fx - x0, fy - y0);
    let taps: [(f32, f32, f32); 4] = if (ax.min(1.0 - ax)).max(ay.min(1.0 - ay)) < SNAP_PIXELS {
        [
            (fx.round(), fy.round(), 1.0),
            (0.0, 0.0, 0.0),
            (0.0, 0.0, 0.0),
            (0.0, 0.0, 0.0),
        ]
    } else {
        [
            (x0, y0, (1.0 - ax) * (1.0 - ay)),
            (x0 + 1.0, y0, ax * (1.0 - ay)),
            (x0, y0 + 1.0, (1.0 - ax) * ay),
            (x0 + 1.0, y0 + 1.0, ax * ay),
        ]
    };
    let (mut il, mut mo, mut weight, mut length) = (Vec4::ZERO, Vec4::ZERO, 0.0f32, f32::MAX);
    for (tx, ty, wt) in taps {
        if wt <= 0.0 || tx < 0.0 || ty < 0.0 {
            continue;
        }
        let (tx, ty) = (tx as usize, ty as usize);
        if tx >= pw || ty >= prev.view.height as usize {
            continue;
        }
        let j = ty * pw + tx;
        let g = &prev.guides;
        let same = if sky {
            g.instance[j] == NO_INSTANCE
        } else {
            g.instance[j] == instance
                && !g.specular[j]
                && g.normal[j].dot(normal) >= NORMAL_COS
                && (g.depth[j] - expected).abs() <= DEPTH_TOLERANCE * expected
        };
        let hist = history.illumination[j];
        if !same || hist.w <= 0.0 {
            continue;
        }
        il += hist * wt;
        mo += history.moments[j] * wt;
        weight += wt;
        length = length.min(hist.w);
    }
    if weight <= 0.0 {
        return none;
    }
    let il = il / weight;
    (il.truncate().extend(length), mo / weight)
}
