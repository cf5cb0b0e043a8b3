//! The facility's moving machinery, the chambers' background motion: the ventilation fan
//! (`fan_frame`, static, and its `fan_rotor`, which a level spins with a clip), the carryable
//! `crate`, and the wall piston (`piston_sleeve`, static, and its `piston_rod`, which a level
//! slides in and out). Metres, +Y up; wall-mounted pieces face +Z from a wall at z = 0.
//! Must not: write files.

use std::f32::consts::{FRAC_PI_2, TAU};

use glam::{Affine3A, Quat, Vec3};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// Segments around the fan's and the piston's round parts (a multiple of 4: exact bounds).
const ROUND: u32 = 32;

/// Turns the tube helper's +Y axis onto +Z (a part that looks out of the wall).
fn along_z() -> Affine3A {
    Affine3A::from_quat(Quat::from_rotation_x(FRAC_PI_2))
}

/// Number of the rotor's blades: the rotor looks the same every quarter turn, so a clip that
/// turns it 90° and loops spins it without a seam.
pub const FAN_BLADES: u32 = 4;

/// The fan's frame: a 1.4 × 1.4 m dark metal square (x, y ∈ [−0.7, 0.7], z ∈ [0, 0.08]) round
/// a shroud of radius 0.62 standing out to z = 0.34, a near-black back disc, a guard of two
/// crossed bars and a ring at the shroud's mouth, and orange corner tabs. Origin at the centre
/// of its back face; the rotor goes at (0, 0, 0.18).
pub fn fan_frame() -> Piece {
    let (metal, seam, orange) = (0, 1, 2);
    let mut b = Builder::new(3);
    for (min, max) in [
        ([-0.7, 0.58], [0.7, 0.7]),
        ([-0.7, -0.7], [0.7, -0.58]),
        ([-0.7, -0.58], [-0.58, 0.58]),
        ([0.58, -0.58], [0.7, 0.58]),
    ] {
        b.bevel_box(
            metal,
            Vec3::new(min[0], min[1], 0.0),
            Vec3::new(max[0], max[1], 0.08),
            0.012,
            Uv::Planar(1.0),
        );
    }
    for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let c = Vec3::new(x * 0.64, y * 0.64, 0.08);
        b.bevel_box(
            orange,
            c - Vec3::new(0.04, 0.04, 0.0),
            c + Vec3::new(0.04, 0.04, 0.008),
            0.0,
            Uv::Planar(1.0),
        );
    }
    b.with(along_z(), |b| {
        // With Y turned onto Z, the tube's y runs from the wall outwards.
        b.tube(metal, 0.62, 0.58, 0.0, 0.34, ROUND, true, 1.0);
        b.tube(seam, 0.58, 0.0, 0.0, 0.01, ROUND, true, 1.0);
        b.tube(metal, 0.6, 0.56, 0.31, 0.33, ROUND, true, 1.0);
    });
    for angle in [0.0f32, FRAC_PI_2] {
        b.with(Affine3A::from_quat(Quat::from_rotation_z(angle)), |b| {
            b.bevel_box(
                metal,
                Vec3::new(-0.58, -0.012, 0.31),
                Vec3::new(0.58, 0.012, 0.33),
                0.0,
                Uv::Planar(1.0),
            );
        });
    }
    Piece::new(
        "fan_frame",
        vec![mat::metal_dark(), mat::seam(), mat::accent_orange()],
        b,
    )
}

/// The fan's rotor, turning about its +Z axis: a hub of radius 0.13 (z ∈ [−0.07, 0.07]) with
/// an orange cap, and [`FAN_BLADES`] grey blades from radius 0.1 to 0.55, pitched 28° about
/// their own length. Origin at the hub's centre.
pub fn fan_rotor() -> Piece {
    let (blade, metal, orange) = (0, 1, 2);
    let mut b = Builder::new(3);
    b.with(along_z(), |b| {
        b.tube(metal, 0.13, 0.0, -0.07, 0.05, ROUND, true, 1.0);
        b.tube(orange, 0.08, 0.0, 0.05, 0.07, ROUND, true, 1.0);
    });
    for k in 0..FAN_BLADES {
        let turn = Quat::from_rotation_z(TAU * k as f32 / FAN_BLADES as f32);
        let place = Affine3A::from_quat(turn)
            * Affine3A::from_translation(Vec3::new(0.325, 0.0, 0.0))
            * Affine3A::from_quat(Quat::from_rotation_x(28f32.to_radians()));
        b.with(place, |b| {
            b.bevel_box(
                blade,
                Vec3::new(-0.225, -0.08, -0.008),
                Vec3::new(0.225, 0.08, 0.008),
                0.0,
                Uv::Planar(1.0),
            );
        });
    }
    Piece::new(
        "fan_rotor",
        vec![mat::pipe_grey(), mat::metal_dark(), mat::accent_orange()],
        b,
    )
}

/// A 0.5 m cargo crate centred at the origin (x, y, z ∈ [−0.25, 0.25]): painted steel panels
/// set 2 cm into a frame of twelve dark metal edge bars, with an orange band round its middle.
/// Small parts here (bars, tabs, blades) are sharp boxes: a bevel under a centimetre is below
/// a traced pixel at the game's resolution and would cost 96 triangles each.
pub fn cargo_crate() -> Piece {
    let (paint, metal, orange) = (0, 1, 2);
    let mut b = Builder::new(3);
    b.bevel_box(paint, Vec3::splat(-0.23), Vec3::splat(0.23), 0.01, Uv::Unit);
    const H: f32 = 0.25;
    const BAR: f32 = 0.05;
    for axis in 0..3 {
        for (s, t) in [(-1.0f32, -1.0f32), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let (mut min, mut max) = (Vec3::ZERO, Vec3::ZERO);
            min[axis] = -H;
            max[axis] = H;
            min[i] = if s < 0.0 { -H } else { H - BAR };
            max[i] = min[i] + BAR;
            min[j] = if t < 0.0 { -H } else { H - BAR };
            max[j] = min[j] + BAR;
            b.bevel_box(metal, min, max, 0.0, Uv::Planar(1.0));
        }
    }
    for (min, max) in [
        (Vec3::new(-0.235, -0.03, -0.2), Vec3::new(-0.225, 0.03, 0.2)),
        (Vec3::new(0.225, -0.03, -0.2), Vec3::new(0.235, 0.03, 0.2)),
        (Vec3::new(-0.2, -0.03, -0.235), Vec3::new(0.2, 0.03, -0.225)),
        (Vec3::new(-0.2, -0.03, 0.225), Vec3::new(0.2, 0.03, 0.235)),
    ] {
        b.bevel_box(orange, min, max, 0.0, Uv::Planar(1.0));
    }
    Piece::new(
        "crate",
        vec![mat::crate_paint(), mat::metal_dark(), mat::accent_orange()],
        b,
    )
}

/// The piston's sleeve: a 0.5 × 0.5 m wall plate (x, y ∈ [−0.25, 0.25], z ∈ [0, 0.05]) and a
/// hollow cylinder on the Z axis, outer radius 0.14, bore 0.075, to z = 0.6, with an orange
/// collar at its mouth. Origin at the centre of the plate's back.
pub fn piston_sleeve() -> Piece {
    let (metal, orange) = (0, 1);
    let mut b = Builder::new(2);
    b.bevel_box(
        metal,
        Vec3::new(-0.25, -0.25, 0.0),
        Vec3::new(0.25, 0.25, 0.05),
        0.012,
        Uv::Planar(1.0),
    );
    b.with(along_z(), |b| {
        b.tube(metal, 0.14, 0.075, 0.05, 0.52, ROUND, true, 1.0);
        b.tube(orange, 0.14, 0.075, 0.52, 0.6, ROUND, true, 1.0);
    });
    Piece::new(
        "piston_sleeve",
        vec![mat::metal_dark(), mat::accent_orange()],
        b,
    )
}

/// The piston's rod and head, to slide along Z out of its sleeve: a grey rod of radius 0.06
/// from z = 0.1 to 1.0 and a 0.36 m square dark head plate (z ∈ [1.0, 1.08]) with an orange
/// face. Origin where the sleeve's is when the rod is drawn in.
pub fn piston_rod() -> Piece {
    let (rod, metal, orange) = (0, 1, 2);
    let mut b = Builder::new(3);
    b.with(along_z(), |b| {
        b.tube(rod, 0.06, 0.0, 0.1, 1.0, ROUND, true, 1.0);
    });
    b.bevel_box(
        metal,
        Vec3::new(-0.18, -0.18, 1.0),
        Vec3::new(0.18, 0.18, 1.07),
        0.012,
        Uv::Planar(1.0),
    );
    b.bevel_box(
        orange,
        Vec3::new(-0.14, -0.14, 1.07),
        Vec3::new(0.14, 0.14, 1.08),
        0.0,
        Uv::Planar(1.0),
    );
    Piece::new(
        "piston_rod",
        vec![mat::pipe_grey(), mat::metal_dark(), mat::accent_orange()],
        b,
    )
}
