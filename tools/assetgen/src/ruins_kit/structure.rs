//! The ruins' building stones: three sandstone blocks, steps, a column (drum + capital), a
//! carved glyph panel, a lintel and a temple tier (the stair pyramid is tiers stacked, each
//! scaled down). Metres, +Y up, every piece sits on y = 0 centred on the Y axis; a face that
//! matters (a panel's relief, the steps' front) looks towards +Z. Must not: write files.

use glam::{Vec2, Vec3};

use super::materials as mat;
use super::shapes::{Wear, lathe};
use super::stone::Stone;
use super::{Piece, piece};
use crate::reflect_kit::mesh::Builder;

/// A sandstone block `size` (x, y, z) sitting on y = 0, centred on the Y axis.
pub fn block(name: &'static str, size: Vec3, seed: u64) -> Piece {
    let mut b = Builder::new(1);
    let half = Vec3::new(size.x / 2.0, 0.0, size.z / 2.0);
    let mut stone = Stone::new(-half, half + Vec3::Y * size.y, seed);
    stone.chip = 0.07 + 0.05 * size.y;
    stone.band = 0.12 + 0.1 * size.y;
    stone.uv_offset = Vec2::new(0.13 * seed as f32, 0.37 * seed as f32);
    stone.build(&mut b, 0);
    piece(name, vec![mat::sandstone()], b)
}

/// Three steps, 3 m wide (x ∈ [−1.5, 1.5]), 0.3 m rise and 0.45 m run, climbing towards −Z from
/// the front edge at z = 0: y ∈ [0, 0.9], z ∈ [−1.35, 0]. Each step is its own worn slab.
pub fn steps() -> Piece {
    let mut b = Builder::new(1);
    for i in 0..3 {
        let y0 = 0.3 * i as f32;
        let mut stone = Stone::new(
            Vec3::new(-1.5, y0, -1.35),
            Vec3::new(1.5, y0 + 0.3, -0.45 * i as f32),
            40 + i,
        );
        stone.chip = 0.07;
        stone.band = 0.12;
        stone.build(&mut b, 0);
    }
    piece("steps", vec![mat::sandstone_worn()], b)
}

/// A column drum: radius 0.4 m, 1 m tall (y ∈ [0, 1]), 40 sides, chipped rims.
/// Drums stack (place the next at y + 1).
pub fn column_drum() -> Piece {
    let mut b = Builder::new(1);
    let profile = [
        (0.0, 0.0),
        (0.36, 0.0),
        (0.4, 0.03),
        (0.4, 0.35),
        (0.4, 0.65),
        (0.4, 0.97),
        (0.36, 1.0),
        (0.0, 1.0),
    ];
    let wear = Wear {
        chip: 0.07,
        band: 0.15,
        seed: 51,
    };
    lathe(&mut b, 0, &profile, 40, wear, 2.0);
    piece("column_drum", vec![mat::sandstone()], b)
}

/// A column capital: a round echinus (radius 0.4 → 0.56 m, y ∈ [0, 0.3]) under a square
/// abacus 1.2 × 0.3 × 1.2 m (y ∈ [0.3, 0.6]). Sits on a drum.
pub fn column_capital() -> Piece {
    let mut b = Builder::new(1);
    let profile = [
        (0.0, 0.0),
        (0.4, 0.0),
        (0.43, 0.1),
        (0.5, 0.2),
        (0.56, 0.3),
        (0.0, 0.3),
    ];
    let wear = Wear {
        chip: 0.05,
        band: 0.1,
        seed: 52,
    };
    lathe(&mut b, 0, &profile, 32, wear, 2.0);
    let mut abacus = Stone::new(Vec3::new(-0.6, 0.3, -0.6), Vec3::new(0.6, 0.6, 0.6), 53);
    abacus.chip = 0.08;
    abacus.build(&mut b, 0);
    piece("column_capital", vec![mat::sandstone()], b)
}

/// A carved panel: 2 × 2 m (x ∈ [−1, 1], y ∈ [0, 2]), 0.3 m deep (z ∈ [−0.3, 0]), the four
/// glyphs of the carved-stone texture in relief on its +Z face.
pub fn carved_panel() -> Piece {
    let mut b = Builder::new(1);
    let mut stone = Stone::new(Vec3::new(-1.0, 0.0, -0.3), Vec3::new(1.0, 2.0, 0.0), 61);
    stone.chip = 0.04;
    stone.band = 0.1;
    stone.uv_offset = Vec2::new(0.5, 0.0);
    stone.build(&mut b, 0);
    piece("carved_panel", vec![mat::carved()], b)
}

/// A lintel: 3.2 × 0.6 × 0.8 m (x ∈ [−1.6, 1.6], y ∈ [0, 0.6], z ∈ [−0.4, 0.4]), a row of
/// glyphs along its faces. Spans two columns 2.4 m apart.
pub fn lintel() -> Piece {
    let mut b = Builder::new(1);
    let mut stone = Stone::new(Vec3::new(-1.6, 0.0, -0.4), Vec3::new(1.6, 0.6, 0.4), 71);
    stone.chip = 0.08;
    stone.band = 0.15;
    stone.tile = 1.2;
    stone.uv_offset = Vec2::new(0.0, 0.0);
    stone.build(&mut b, 0);
    piece("lintel", vec![mat::carved()], b)
}

/// One tier of the stair pyramid: a battered platform 8 × 8 m at its foot, about 6.8 × 6.8 m
/// on top (x, z ∈ [−4, 4] at y = 0), 1.5 m tall, laid as three heavily weathered courses of
/// 0.5 m, each set back from the one below. Stack tiers scaled down (e.g. 0.8 × in x and z
/// per tier) and set `steps` up the front.
pub fn temple_tier() -> Piece {
    let mut b = Builder::new(1);
    for course in 0..3 {
        let (y0, y1) = (0.5 * course as f32, 0.5 * (course + 1) as f32);
        let half = 4.0 - 0.2 * course as f32;
        let mut stone = Stone::new(
            Vec3::new(-half, y0, -half),
            Vec3::new(half, y1, half),
            81 + course,
        );
        stone.taper = (half - 0.12) / half;
        stone.radius = 0.06;
        stone.cell = 0.4;
        stone.chip = 0.16;
        stone.band = 0.3;
        stone.uv_offset = Vec2::new(0.31 * course as f32, 0.0);
        stone.build(&mut b, 0);
    }
    piece("temple_tier", vec![mat::sandstone()], b)
}
