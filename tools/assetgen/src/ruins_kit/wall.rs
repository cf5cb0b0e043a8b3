//! The pre-fractured brittle wall: a 4 × 3 × 0.6 m sandstone wall (x ∈ [−2, 2], y ∈ [0, 3],
//! z ∈ [−0.3, 0.3]) cut into [`WALL_PIECES`] convex pieces by a Voronoi diagram of jittered
//! sites on its face, each piece the cell's polygon extruded through the wall's thickness.
//! Every piece is written in the wall's own space, so all of them placed at one transform
//! make the whole wall; together they tile its box exactly (the fracture faces coincide).
//!
//! Cells are clipped from the wall rectangle by the bisector half-planes of the other sites
//! (exact for Voronoi cells, which are convex). Metres, +Y up, the wall's faces towards ±Z.
//! Must not: write files.

use glam::{Vec2, Vec3};

use super::materials as mat;
use super::noise::hash3;
use super::{Piece, piece};
use crate::reflect_kit::mesh::Builder;

/// The wall's size, m (x, y, z).
pub const WALL_SIZE: [f32; 3] = [4.0, 3.0, 0.6];
/// How many pieces the wall breaks into.
pub const WALL_PIECES: usize = 9;
/// The pieces' names, in order.
pub const WALL_PIECE_NAMES: [&str; WALL_PIECES] = [
    "brittle_wall_piece_0",
    "brittle_wall_piece_1",
    "brittle_wall_piece_2",
    "brittle_wall_piece_3",
    "brittle_wall_piece_4",
    "brittle_wall_piece_5",
    "brittle_wall_piece_6",
    "brittle_wall_piece_7",
    "brittle_wall_piece_8",
];

/// The Voronoi sites: a 3 × 3 grid over the face, each jittered within its cell.
fn sites() -> Vec<Vec2> {
    let (w, h) = (WALL_SIZE[0], WALL_SIZE[1]);
    (0..WALL_PIECES)
        .map(|i| {
            let (cx, cy) = ((i % 3) as i64, (i / 3) as i64);
            let jx = 0.2 + 0.6 * hash3(cx, cy, 0, 201);
            let jy = 0.2 + 0.6 * hash3(cx, cy, 1, 201);
            Vec2::new(
                -w / 2.0 + (cx as f32 + jx) * w / 3.0,
                (cy as f32 + jy) * h / 3.0,
            )
        })
        .collect()
}

/// Keeps the part of convex polygon `poly` (counter-clockwise) where `(p − mid) · dir ≤ 0`.
fn clip(poly: &[Vec2], mid: Vec2, dir: Vec2) -> Vec<Vec2> {
    let side = |p: Vec2| (p - mid).dot(dir);
    let mut out = Vec::new();
    for (k, &a) in poly.iter().enumerate() {
        let c = poly[(k + 1) % poly.len()];
        let (sa, sc) = (side(a), side(c));
        if sa <= 0.0 {
            out.push(a);
        }
        if (sa < 0.0 && sc > 0.0) || (sa > 0.0 && sc < 0.0) {
            out.push(a + (c - a) * (sa / (sa - sc)));
        }
    }
    out
}

/// The face polygon (counter-clockwise seen from +Z, x right, y up) of piece `index`.
pub fn cell(index: usize) -> Vec<Vec2> {
    let (w, h) = (WALL_SIZE[0], WALL_SIZE[1]);
    let all = sites();
    let me = all[index];
    let mut poly = vec![
        Vec2::new(-w / 2.0, 0.0),
        Vec2::new(w / 2.0, 0.0),
        Vec2::new(w / 2.0, h),
        Vec2::new(-w / 2.0, h),
    ];
    for (k, &other) in all.iter().enumerate() {
        if k != index {
            poly = clip(&poly, (me + other) * 0.5, other - me);
        }
    }
    poly
}

/// Brittle wall piece `index` (0..[`WALL_PIECES`]).
pub fn wall_piece(index: usize) -> Piece {
    let poly = cell(index);
    let half = WALL_SIZE[2] / 2.0;
    let mut b = Builder::new(1);
    let uv = |p: Vec2, flip: f32| Vec2::new(p.x * flip, -p.y) / 2.0;
    // Front (+Z) and back (−Z) faces as fans (the cell is convex).
    for (z, n, flip) in [(half, Vec3::Z, 1.0f32), (-half, -Vec3::Z, -1.0)] {
        let ids: Vec<u32> = poly
            .iter()
            .map(|&p| b.vertex(Vec3::new(p.x, p.y, z), n, uv(p, flip)))
            .collect();
        for k in 1..ids.len() - 1 {
            if n.z > 0.0 {
                b.triangle(0, ids[0], ids[k], ids[k + 1]);
            } else {
                b.triangle(0, ids[0], ids[k + 1], ids[k]);
            }
        }
    }
    // Sides: outward normal (dy, −dx) of each counter-clockwise edge.
    for k in 0..poly.len() {
        let (a, c) = (poly[k], poly[(k + 1) % poly.len()]);
        let edge = c - a;
        let length = edge.length();
        if length < 1e-5 {
            continue;
        }
        let n = Vec3::new(edge.y, -edge.x, 0.0) / length;
        let corner =
            |p: Vec2, z: f32, along: f32| (Vec3::new(p.x, p.y, z), n, Vec2::new(along, z) / 2.0);
        b.quad(
            0,
            [
                corner(a, half, 0.0),
                corner(a, -half, 0.0),
                corner(c, -half, length),
                corner(c, half, length),
            ],
        );
    }
    piece(WALL_PIECE_NAMES[index], vec![mat::sandstone()], b)
}
