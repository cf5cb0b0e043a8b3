//! Puzzle devices: the cube `dispenser`, the pressure `plate`, the laser `receiver` and the
//! laser `emitter`. Metres, +Y up; wall-mounted devices face +Z from a wall at z = 0.
//! Must not: write files.

use glam::{Affine3A, Quat, Vec3};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// Segments around round parts (a multiple of 4, so round bounds are exact).
const ROUND: u32 = 48;

/// The cube dispenser: a vertical tube 1 m across, y ∈ [0, 3], centred on the Y axis. Dark
/// metal rings at the bottom (y < 0.26) and top (y > 2.6), each with a recessed orange band,
/// a glass wall between them, four dark struts, and inside the top a dark hatch with a ring of
/// light under it (`elevator_light`).
pub fn dispenser() -> Piece {
    let (metal, glass, orange, light) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    let ring = |b: &mut Builder, y0: f32, y1: f32| {
        b.tube(metal, 0.5, 0.4, y0, y1, ROUND, true, 1.0);
    };
    ring(&mut b, 0.0, 0.1);
    b.tube(orange, 0.49, 0.41, 0.1, 0.16, ROUND, false, 1.0);
    ring(&mut b, 0.16, 0.26);
    ring(&mut b, 2.6, 2.72);
    b.tube(orange, 0.49, 0.41, 2.72, 2.8, ROUND, false, 1.0);
    ring(&mut b, 2.8, 3.0);
    b.tube(glass, 0.46, 0.44, 0.26, 2.6, ROUND, true, 1.0);
    b.tube(metal, 0.4, 0.0, 2.9, 2.94, ROUND, true, 1.0);
    // A light ring under the hatch shows the tube's inside (and the cube in it).
    b.tube(light, 0.38, 0.3, 2.86, 2.88, 24, true, 1.0);
    for (x, z) in [(1.0f32, 0.0f32), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
        let centre = Vec3::new(x, 0.0, z) * 0.475;
        let half = Vec3::new(0.02 + 0.005 * x.abs(), 0.0, 0.02 + 0.005 * z.abs());
        b.bevel_box(
            metal,
            centre - half + Vec3::Y * 0.26,
            centre + half + Vec3::Y * 2.6,
            0.008,
            Uv::Planar(1.0),
        );
    }
    Piece::new(
        "dispenser",
        vec![
            mat::metal_dark(),
            mat::glass(),
            mat::accent_orange(),
            mat::elevator_light(),
        ],
        b,
    )
}

/// The pressure plate: a disc 1.4 m across, y ∈ [0, 0.08]: a stepped dark metal rim round an
/// orange top with a dark centre ring.
pub fn plate() -> Piece {
    let (metal, top) = (0, 1);
    let mut b = Builder::new(2);
    b.tube(metal, 0.7, 0.56, 0.0, 0.05, ROUND, true, 1.0);
    b.tube(metal, 0.67, 0.56, 0.05, 0.08, ROUND, true, 1.0);
    b.tube(top, 0.56, 0.0, 0.0, 0.065, ROUND, true, 1.0);
    b.tube(metal, 0.2, 0.16, 0.065, 0.07, ROUND, true, 1.0);
    Piece::new("plate", vec![mat::metal_dark(), mat::plate_top()], b)
}

/// The housing shared by receiver and emitter: a 0.6 × 0.6 m back plate (z ∈ [0, 0.05]) and a
/// bevelled body to z = 0.18, with four corner bolts.
fn housing(b: &mut Builder, metal: usize, seam: usize) {
    b.bevel_box(
        metal,
        Vec3::new(-0.3, 0.0, 0.0),
        Vec3::new(0.3, 0.6, 0.05),
        0.015,
        Uv::Planar(1.0),
    );
    b.bevel_box(
        metal,
        Vec3::new(-0.24, 0.06, 0.05),
        Vec3::new(0.24, 0.54, 0.18),
        0.035,
        Uv::Planar(1.0),
    );
    for (x, y) in [(-0.27, 0.03), (0.27, 0.03), (-0.27, 0.57), (0.27, 0.57)] {
        b.bevel_box(
            seam,
            Vec3::new(x - 0.012, y - 0.012, 0.05),
            Vec3::new(x + 0.012, y + 0.012, 0.058),
            0.003,
            Uv::Planar(1.0),
        );
    }
}

/// Along +Z from the point `(0, 0.3, z0)`: rotates the Y axis onto Z.
fn along_z(z0: f32) -> Affine3A {
    Affine3A::from_rotation_translation(
        Quat::from_rotation_x(std::f32::consts::FRAC_PI_2),
        Vec3::new(0.0, 0.3, z0),
    )
}

/// The laser receiver: the housing (x ∈ [−0.3, 0.3], y ∈ [0, 0.6], z ∈ [0, 0.25]) with an
/// orange ring and a milky lens whose front centre is at (0, 0.3, 0.25).
pub fn receiver() -> Piece {
    let (metal, seam, orange, lens) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    housing(&mut b, metal, seam);
    b.with(along_z(0.18), |b| {
        b.tube(orange, 0.19, 0.135, 0.0, 0.05, ROUND, true, 1.0);
        b.tube(metal, 0.135, 0.125, 0.0, 0.055, ROUND, true, 1.0);
        b.tube(lens, 0.125, 0.0, 0.0, 0.06, ROUND, true, 1.0);
        b.tube(lens, 0.09, 0.0, 0.06, 0.07, ROUND, true, 1.0);
    });
    Piece::new(
        "receiver",
        vec![
            mat::metal_dark(),
            mat::seam(),
            mat::accent_orange(),
            mat::lens_white(),
        ],
        b,
    )
}

/// The laser emitter: the receiver's housing with a red-tinted nozzle along +Z; its glowing
/// tip sits 2 cm inside the nozzle, whose mouth is at (0, 0.3, 0.3), where the beam leaves.
pub fn emitter() -> Piece {
    let (metal, seam, nozzle, glow) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    housing(&mut b, metal, seam);
    b.with(along_z(0.18), |b| {
        b.tube(metal, 0.16, 0.07, 0.0, 0.03, ROUND, true, 1.0);
        b.tube(nozzle, 0.11, 0.07, 0.03, 0.06, ROUND, true, 1.0);
        b.tube(nozzle, 0.07, 0.045, 0.0, 0.12, ROUND, true, 1.0);
        b.tube(glow, 0.045, 0.0, 0.08, 0.1, 16, true, 1.0);
    });
    Piece::new(
        "emitter",
        vec![
            mat::metal_dark(),
            mat::seam(),
            mat::nozzle_red(),
            mat::emitter_glow(),
        ],
        b,
    )
}
