//! The reprojection's edge rule: when none of a pixel's history taps saw its surface, a tap
//! whose own surface still covers part of the pixel is taken anyway (a *mixed* pixel), so a
//! pixel on an edge keeps the mean of both sides instead of restarting whenever its guide's
//! sample lands on the other side (guides taken at the frame's jitter, `View::jitter`).
//!
//! A tap counts as still covering the pixel when both hold:
//! - its guide point, moved forward with its own instance's motion (the inverse of
//!   `reproject::motions`; a sky tap's direction as it is), projects into this frame's view
//!   inside the pixel's square (image coordinates [x, x + 1) × [y, y + 1));
//! - a pixel of this frame's 3×3 neighbourhood sees that same instance (or the sky) with its
//!   guide point within [`PLANE_TOLERANCE`] of the moved point's plane: the surface is still
//!   there, beside the pixel.
//!
//! A surface that moved away (an object's point lands where the object is now, not in the
//! pixel it left) or that is gone (no neighbour sees it) does not count: what an object
//! uncovers or covers restarts, as before. (An earlier rule took the taps whenever this
//! pixel's own surface lay within a pixel of the place; it left a trail behind a moving object,
//! whose old points it could not tell from a still edge.) A motion the instances do not carry
//! (identity transforms for something that moved) is, to this rule, a still edge.
//!
//! Owns: [`mixed_tap`]. Render thread (called per pixel from `reproject`'s rows on rayon's
//! pool). Twin: `shaders/denoise_reproject.wgsl` (`mixed_tap`). Must not: blend or write the
//! history.

use glam::{Affine3A, Vec3};

use super::guides::{Guides, NO_INSTANCE};
use super::reproject::{PLANE_TOLERANCE, PrevFrame};
use super::view::View;

/// Whether previous pixel `j`'s surface still covers part of this frame's pixel (x, y) (see the
/// module doc). `forward` is each instance's motion from the previous frame to this one, by
/// instance index (identity past its end).
pub fn mixed_tap(
    prev: &PrevFrame,
    j: usize,
    guides: &Guides,
    view: &View,
    forward: &[Affine3A],
    (x, y): (u32, u32),
) -> bool {
    let g = &prev.guides;
    if g.specular[j] {
        return false;
    }
    let pw = prev.view.width as usize;
    let (tx, ty) = ((j % pw) as u32, (j / pw) as u32);
    let dir = prev.view.sample_direction(tx, ty);
    let instance = g.instance[j];
    let sky = instance == NO_INSTANCE || !(g.depth[j] > 0.0);
    // The tap's point now, relative to this frame's camera (a direction for the sky).
    let now = if sky {
        dir
    } else {
        let world = prev.view.position + dir * g.depth[j];
        let motion = forward
            .get(instance as usize)
            .copied()
            .unwrap_or(Affine3A::IDENTITY);
        motion.transform_point3(world) - view.position
    };
    let Some((qx, qy)) = view.project_direction(now) else {
        return false;
    };
    let (px, py) = (x as f32, y as f32);
    if !(qx >= px && qx < px + 1.0 && qy >= py && qy < py + 1.0) {
        return false;
    }
    let expected = now.length();
    let (w, h) = (guides.width, guides.height);
    for ny in y.saturating_sub(1)..=(y + 1).min(h - 1) {
        for nx in x.saturating_sub(1)..=(x + 1).min(w - 1) {
            let k = (ny * w + nx) as usize;
            if guides.specular[k] {
                continue;
            }
            let depth = guides.depth[k];
            let other_sky = guides.instance[k] == NO_INSTANCE || !(depth > 0.0);
            if sky || other_sky {
                if sky && other_sky {
                    return true;
                }
                continue;
            }
            if guides.instance[k] != instance {
                continue;
            }
            let point: Vec3 = view.sample_direction(nx, ny) * depth;
            if guides.normal[k].dot(now - point).abs() <= PLANE_TOLERANCE * expected {
                return true;
            }
        }
    }
    false
}
