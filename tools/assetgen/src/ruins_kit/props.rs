//! The ruins' puzzle props: torch (post + bowl) and its flame, sun altar and its disc, lever
//! base and handle, glyph tile and its glowing inlays, pressure plate and its frame, the
//! pushable block and the boulder. Parts that move or switch are separate pieces; where they
//! go on their base is stated on each function. Metres, +Y up, sitting on y = 0 centred on
//! the Y axis unless stated. Must not: write files.

use glam::{Affine3A, Quat, Vec2, Vec3};

use super::materials as mat;
use super::shapes::{CLEAN, Wear, boulder as rock, glyph_inlay, lathe};
use super::stone::Stone;
use super::{Piece, piece};
use crate::reflect_kit::mesh::Builder;

/// Height of the torch bowl's rim: place `torch_flame` at the torch's position + (0, 1.5, 0).
pub const TORCH_FLAME_Y: f32 = 1.5;
/// Centre of the sun disc above the altar's base: place `sun_disc` at + (0, 1.45, 0).
pub const SUN_DISC_Y: f32 = 1.45;
/// The lever's pivot above its base: place `lever_handle` at + (0, 0.5, 0).
pub const LEVER_PIVOT_Y: f32 = 0.5;
/// The pressure plate's rest height in its frame: place `pressure_plate` at + (0, 0.02, 0).
pub const PLATE_Y: f32 = 0.02;

/// A torch: a square sandstone post 0.24 m wide, 1.3 m tall, a stone bowl on top (radius
/// 0.28 m, rim at y = 1.5) holding charred wood. x, z ∈ [−0.28, 0.28], y ∈ [0, 1.5].
pub fn torch() -> Piece {
    let (stone, wood) = (0, 1);
    let mut b = Builder::new(2);
    let mut post = Stone::new(
        Vec3::new(-0.12, 0.0, -0.12),
        Vec3::new(0.12, 1.32, 0.12),
        91,
    );
    post.chip = 0.03;
    post.band = 0.06;
    post.radius = 0.02;
    post.cell = 0.15;
    post.build(&mut b, stone);
    let bowl = [
        (0.0, 1.28),
        (0.1, 1.28),
        (0.2, 1.36),
        (0.28, 1.5),
        (0.25, 1.5),
        (0.18, 1.4),
        (0.0, 1.4),
    ];
    let wear = Wear {
        chip: 0.02,
        band: 0.04,
        seed: 92,
    };
    lathe(&mut b, stone, &bowl, 24, wear, 1.0);
    let embers = [(0.0, 1.4), (0.17, 1.4), (0.12, 1.46), (0.0, 1.48)];
    lathe(&mut b, wood, &embers, 12, CLEAN, 1.0);
    piece("torch", vec![mat::sandstone(), mat::charred_wood()], b)
}

/// A torch's flame: a twisted teardrop 0.5 m tall (y ∈ [0, 0.5]), radius up to 0.13 m;
/// emissive only, its own piece so a light group can switch it.
pub fn torch_flame() -> Piece {
    let mut b = Builder::new(1);
    let profile = [
        (0.0, 0.0),
        (0.1, 0.02),
        (0.13, 0.1),
        (0.11, 0.2),
        (0.07, 0.32),
        (0.03, 0.43),
        (0.0, 0.5),
    ];
    let twist = Affine3A::from_quat(Quat::from_rotation_y(0.3));
    b.with(twist, |b| lathe(b, 0, &profile, 10, CLEAN, 1.0));
    piece("torch_flame", vec![mat::flame()], b)
}

/// The sun altar: a stepped sandstone pedestal (1.6 m square foot, y ∈ [0, 0.9]) under a
/// carved cradle for the disc, x ∈ [−0.8, 0.8], y ∈ [0, 1.15], z ∈ [−0.8, 0.8].
pub fn sun_altar() -> Piece {
    let (stone, carved) = (0, 1);
    let mut b = Builder::new(2);
    let tiers = [(0.8, 0.0, 0.3), (0.6, 0.3, 0.55), (0.45, 0.55, 0.9)];
    for (k, (half, y0, y1)) in tiers.into_iter().enumerate() {
        let mut s = Stone::new(
            Vec3::new(-half, y0, -half),
            Vec3::new(half, y1, half),
            100 + k as u64,
        );
        s.chip = 0.06;
        s.build(&mut b, if k == 2 { carved } else { stone });
    }
    // The cradle: two cheeks in front of and behind the disc (which spins about Z).
    for z in [-0.18f32, 0.07] {
        let mut s = Stone::new(Vec3::new(-0.2, 0.9, z), Vec3::new(0.2, 1.15, z + 0.11), 110);
        s.chip = 0.02;
        s.build(&mut b, carved);
    }
    piece("sun_altar", vec![mat::sandstone(), mat::carved()], b)
}

/// The sun disc: bronze, radius 0.5 m, 0.08 m thick, centred at the origin with its faces
/// towards ±Z (it spins about Z when time turns), a raised boss on its +Z face.
/// x, y ∈ [−0.5, 0.5], z ∈ [−0.04, 0.055].
pub fn sun_disc() -> Piece {
    let mut b = Builder::new(1);
    let profile = [
        (0.0, -0.04),
        (0.3, -0.04),
        (0.47, -0.04),
        (0.5, -0.015),
        (0.5, 0.015),
        (0.47, 0.04),
        (0.3, 0.04),
        (0.26, 0.055),
        (0.0, 0.055),
    ];
    let face_z = Affine3A::from_quat(Quat::from_rotation_x(std::f32::consts::FRAC_PI_2));
    b.with(face_z, |b| lathe(b, 0, &profile, 48, CLEAN, 1.0));
    piece("sun_disc", vec![mat::bronze()], b)
}

/// The lever's base: a carved block 0.6 × 0.5 × 0.4 m (x ∈ [−0.3, 0.3], y ∈ [0, 0.5],
/// z ∈ [−0.2, 0.2]); the handle's pivot is at (0, [`LEVER_PIVOT_Y`], 0).
pub fn lever_base() -> Piece {
    let mut b = Builder::new(1);
    let mut s = Stone::new(Vec3::new(-0.3, 0.0, -0.2), Vec3::new(0.3, 0.5, 0.2), 120);
    s.chip = 0.04;
    s.band = 0.08;
    s.cell = 0.12;
    s.tile = 1.2;
    s.build(&mut b, 0);
    piece("lever_base", vec![mat::carved()], b)
}

/// The lever's handle, its pivot at the origin: a bronze hub (radius 0.08 m along X) and a
/// bronze rod 0.75 m up +Y ending in a charred-wood grip. Turn it about X to pull it.
/// x ∈ [−0.12, 0.12], y ∈ [−0.08, 0.9], z ∈ [−0.08, 0.08].
pub fn lever_handle() -> Piece {
    let (metal, wood) = (0, 1);
    let mut b = Builder::new(2);
    let along_x = Affine3A::from_quat(Quat::from_rotation_z(-std::f32::consts::FRAC_PI_2));
    let hub = [(0.0, -0.12), (0.08, -0.12), (0.08, 0.12), (0.0, 0.12)];
    b.with(along_x, |b| lathe(b, metal, &hub, 16, CLEAN, 1.0));
    let rod = [(0.0, 0.0), (0.03, 0.0), (0.025, 0.7), (0.0, 0.7)];
    lathe(&mut b, metal, &rod, 12, CLEAN, 1.0);
    let grip = [
        (0.0, 0.6),
        (0.05, 0.6),
        (0.055, 0.75),
        (0.05, 0.88),
        (0.0, 0.9),
    ];
    lathe(&mut b, wood, &grip, 12, CLEAN, 1.0);
    piece("lever_handle", vec![mat::bronze(), mat::charred_wood()], b)
}

/// A floor glyph tile: a worn slab 1 × 0.12 × 1 m (x, z ∈ [−0.5, 0.5], y ∈ [0, 0.12]); a
/// `glyph_glow_<n>` inlay lies on its top (place it at the same transform).
pub fn glyph_tile() -> Piece {
    let mut b = Builder::new(1);
    let mut s = Stone::new(Vec3::new(-0.5, 0.0, -0.5), Vec3::new(0.5, 0.12, 0.5), 130);
    s.chip = 0.03;
    s.band = 0.08;
    s.cell = 0.1;
    s.build(&mut b, 0);
    piece("glyph_tile", vec![mat::sandstone_worn()], b)
}

/// Glyph `n`'s glowing inlay (0 sun, 1 step fret, 2 eye, 3 serpent) for `glyph_tile`: flat
/// emissive quads in a 0.8 m square at y = 0.121, facing +Y. Emissive only.
pub fn glyph_glow(name: &'static str, glyph: usize) -> Piece {
    let mut b = Builder::new(1);
    glyph_inlay(&mut b, 0, glyph, 24, 0.8, 0.121);
    piece(name, vec![mat::glyph_glow()], b)
}

/// The pressure plate's frame: four worn kerb stones round a 1.24 m square hole,
/// x, z ∈ [−0.8, 0.8], y ∈ [0, 0.15].
pub fn pressure_plate_frame() -> Piece {
    let mut b = Builder::new(1);
    let kerbs = [
        (Vec3::new(-0.8, 0.0, -0.8), Vec3::new(0.8, 0.15, -0.62)),
        (Vec3::new(-0.8, 0.0, 0.62), Vec3::new(0.8, 0.15, 0.8)),
        (Vec3::new(-0.8, 0.0, -0.62), Vec3::new(-0.62, 0.15, 0.62)),
        (Vec3::new(0.62, 0.0, -0.62), Vec3::new(0.8, 0.15, 0.62)),
    ];
    for (k, (min, max)) in kerbs.into_iter().enumerate() {
        let mut s = Stone::new(min, max, 140 + k as u64);
        s.chip = 0.03;
        s.band = 0.06;
        s.cell = 0.15;
        s.build(&mut b, 0);
    }
    piece("pressure_plate_frame", vec![mat::sandstone_worn()], b)
}

/// The pressure plate: a carved slab 1.2 × 0.12 × 1.2 m (x, z ∈ [−0.6, 0.6], y ∈ [0, 0.12])
/// showing one glyph on top; it sinks into its frame when weighed down.
pub fn pressure_plate() -> Piece {
    let mut b = Builder::new(1);
    let mut s = Stone::new(Vec3::new(-0.6, 0.0, -0.6), Vec3::new(0.6, 0.12, 0.6), 150);
    s.chip = 0.02;
    s.band = 0.05;
    s.cell = 0.15;
    s.tile = 2.4;
    s.uv_offset = Vec2::new(0.25, 0.25);
    s.build(&mut b, 0);
    piece("pressure_plate", vec![mat::carved()], b)
}

/// The pushable block: a carved 1.2 m cube (x, z ∈ [−0.6, 0.6], y ∈ [0, 1.2]) with a glyph on
/// each side, so a player can tell it from the walls.
pub fn push_block() -> Piece {
    let mut b = Builder::new(1);
    let mut s = Stone::new(Vec3::new(-0.6, 0.0, -0.6), Vec3::new(0.6, 1.2, 0.6), 160);
    s.chip = 0.05;
    s.band = 0.12;
    s.cell = 0.15;
    s.tile = 2.4;
    s.uv_offset = Vec2::new(0.25, 0.0);
    s.build(&mut b, 0);
    piece("push_block", vec![mat::carved()], b)
}

/// The boulder: a jittered, slightly flattened icosphere of radius about 0.9 m **centred at
/// the origin** (so it rolls about its centre: place it at its radius above the ground),
/// 1,280 triangles.
pub fn boulder() -> Piece {
    let mut b = Builder::new(1);
    rock(&mut b, 0, 0.9, 0.2, 3, 170);
    piece("boulder", vec![mat::sandstone()], b)
}
