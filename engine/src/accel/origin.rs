//! Camera-relative rendering: where render space's origin lies in the world, and moving it.
//!
//! Owns: the rebase policy of the [`Upkeep`]. World positions are f32 metres, so a point at
//! distance d from the world origin is only known to about d · 2⁻²⁴ (0.008 m at 1e5 m). That
//! is the game's own precision and nothing here can add to it; what this module prevents is the
//! *renderer* losing more: ray origins, hit points and light samples computed at 1e5 m lose the
//! same 8 mm at every bounce, which shows as acne and light leaks. So the render side works in
//! render space = world − origin, with the origin near the camera: instance transforms are
//! stored relative to it (exact: their translation minus a nearby multiple of [`ORIGIN_GRID`]
//! loses no bits), meshes stay in their own space, and camera rays start near zero.
//!
//! The origin is the camera's position snapped to [`ORIGIN_GRID`], moved whenever the camera
//! strays more than [`REBASE_DISTANCE`] from it (every instance row is rewritten and the TLAS and
//! light table rebuilt: a frame of upkeep like any mover's, at most every 128 m of travel).
//! Beyond [`PRECISION_WARNING`] metres the world positions themselves are coarse (≥ 6 cm) and
//! the engine warns once. Main thread. Must not: touch BLAS data (meshes live in their own
//! space) or the camera (the frame uniforms subtract the origin).

use glam::{Mat4, Vec3};

use super::upkeep::Upkeep;
use crate::scene::SceneWrite;

/// Metres: the origin is always a multiple of this (so subtracting it is exact).
pub const ORIGIN_GRID: f32 = 64.0;

/// Metres: the camera may stray this far from the origin (per axis) before it moves.
pub const REBASE_DISTANCE: f32 = 128.0;

/// Metres from the world origin beyond which world positions (f32) are coarser than 6 cm.
pub const PRECISION_WARNING: f32 = 1.0e6;

/// `p` snapped to the origin grid.
pub fn snap_origin(p: Vec3) -> Vec3 {
    if !p.is_finite() {
        return Vec3::ZERO;
    }
    (p / ORIGIN_GRID).round() * ORIGIN_GRID
}

impl Upkeep {
    /// Where render space's origin is in the world (metres).
    pub fn origin(&self) -> Vec3 {
        self.scene.origin
    }

    /// Keeps the origin near `camera` (world metres): moves it when the camera is more than
    /// [`REBASE_DISTANCE`] away along any axis. Returns whether it moved.
    pub fn follow_camera(&mut self, camera: Vec3) -> bool {
        if !camera.is_finite() {
            return false;
        }
        if camera.abs().max_element() > PRECISION_WARNING && !self.precision_warned {
            self.precision_warned = true;
            log::warn!(
                "camera at {camera} m: beyond {PRECISION_WARNING} m from the world origin, world \
                 positions (f32) are coarser than 6 cm; keep levels within 1e6 m"
            );
        }
        if (camera - self.scene.origin).abs().max_element() <= REBASE_DISTANCE {
            return false;
        }
        self.set_origin(snap_origin(camera));
        true
    }

    /// Moves render space's origin to `origin` (world metres): every instance row is rewritten
    /// relative to it, and the TLAS and light table follow at the end of the frame.
    pub fn set_origin(&mut self, origin: Vec3) {
        let origin = snap_origin(origin);
        let delta = self.scene.origin - origin;
        if delta == Vec3::ZERO {
            return;
        }
        self.scene.origin = origin;
        let mut rows = self.scene.instances.clone();
        for row in &mut rows {
            let r = row.world_from_object;
            let render_from_object = Mat4::from_translation(delta)
                * Mat4::from_cols_array_2d(&[r[0], r[1], r[2], [0.0, 0.0, 0.0, 1.0]]).transpose();
            let fresh = self.placed_row(*row, render_from_object);
            *row = fresh;
        }
        self.stats.instances_written += rows.len() as u32;
        self.push(SceneWrite::Instances {
            first: 0,
            data: rows,
        });
        self.tlas_dirty = true;
        self.lights_dirty = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snapping_is_exact_and_subtraction_keeps_every_bit() {
        for x in [0.0f32, 31.9, 32.1, -1e5 - 0.3, 123_456.78, 1e6] {
            let o = snap_origin(Vec3::splat(x));
            assert!((o.x - x).abs() <= ORIGIN_GRID / 2.0, "{x} -> {o}");
            assert_eq!(o.x % ORIGIN_GRID, 0.0);
            // A point near x keeps its exact f32 value through (p − o) + o.
            let p = x + 0.37;
            assert_eq!((p - o.x) + o.x, p, "{x}");
        }
        assert_eq!(snap_origin(Vec3::NAN), Vec3::ZERO);
    }
}
