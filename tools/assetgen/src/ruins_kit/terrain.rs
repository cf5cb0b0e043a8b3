//! The sand terrain tile: a 40 × 40 m heightfield (x, z ∈ [−20, 20]) of wind-shaped dunes on a
//! 0.5 m grid (12,800 triangles). The height function repeats every 40 m, so tiles placed side
//! by side at 40 m steps meet without a seam (same heights and normals along shared edges).
//! Heights are shifted so the lowest grid point is at y = 0; the highest is below
//! [`SAND_MAX_HEIGHT`]. Texture coordinates: metres / 4 (the sand image's tile).
//! Must not: write files.

use glam::{Vec2, Vec3};

use super::materials as mat;
use super::noise::{fbm2, smoothstep};
use super::{Piece, piece};
use crate::reflect_kit::mesh::Builder;

/// The tile's side, m.
pub const SAND_TILE: f32 = 40.0;
/// Grid quads along each side.
pub const SAND_DIVISIONS: u32 = 80;
/// Upper bound of the terrain's height, m.
pub const SAND_MAX_HEIGHT: f32 = 1.6;

/// Dune height (before the shift) at tile coordinates `(u, v)` ∈ tiles (period 1).
fn dune(u: f32, v: f32) -> f32 {
    // Dunes: ridged noise (sharp crests), elongated across the wind (+X).
    let n = fbm2(u + 0.15 * fbm2(u, v, 2, 2, 0.5, 301), v, 3, 3, 0.5, 302);
    let ridge = 1.0 - (2.0 * n - 1.0).abs();
    let swell = fbm2(u, v, 2, 2, 0.5, 303);
    let detail = fbm2(u, v, 12, 2, 0.5, 304);
    1.1 * smoothstep(0.35, 1.0, ridge) + 0.5 * swell + 0.08 * detail
}

/// The sand terrain tile.
pub fn sand_terrain() -> Piece {
    let n = SAND_DIVISIONS as i64;
    let step = SAND_TILE / SAND_DIVISIONS as f32;
    let height_at = |i: i64, j: i64| {
        let (u, v) = (
            i.rem_euclid(n) as f32 / n as f32,
            j.rem_euclid(n) as f32 / n as f32,
        );
        dune(u, v)
    };
    let mut low = f32::INFINITY;
    for j in 0..n {
        for i in 0..n {
            low = low.min(height_at(i, j));
        }
    }
    let mut b = Builder::new(1);
    let mut ids = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
    for j in 0..=n {
        for i in 0..=n {
            let x = -SAND_TILE / 2.0 + i as f32 * step;
            let z = -SAND_TILE / 2.0 + j as f32 * step;
            let y = (height_at(i, j) - low).min(SAND_MAX_HEIGHT);
            // Central differences over the wrapped grid: seamless normals across tiles.
            let dx = (height_at(i + 1, j) - height_at(i - 1, j)) / (2.0 * step);
            let dz = (height_at(i, j + 1) - height_at(i, j - 1)) / (2.0 * step);
            let normal = Vec3::new(-dx, 1.0, -dz).normalize();
            ids.push(b.vertex(Vec3::new(x, y, z), normal, Vec2::new(x, z) / 4.0));
        }
    }
    let row = (n + 1) as usize;
    for j in 0..n as usize {
        for i in 0..n as usize {
            let (a, c) = (ids[j * row + i], ids[j * row + i + 1]);
            let (d, e) = (ids[(j + 1) * row + i], ids[(j + 1) * row + i + 1]);
            // Seen from above (+Y, x right, z towards the viewer) a → d → e runs
            // counter-clockwise.
            b.triangle(0, a, d, e);
            b.triangle(0, a, e, c);
        }
    }
    piece("sand_terrain", vec![mat::sand()], b)
}
