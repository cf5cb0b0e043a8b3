//! Larger props: the `elevator` platform and its `railing_3`, the `pillar` and the `pipe_8`.
//! Metres, +Y up. Must not: write files.

use glam::{Affine3A, Quat, Vec2, Vec3};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// The elevator platform: 3 × 3 m (x, z ∈ [−1.5, 1.5]), its top at y = 0, 0.3 m thick below:
/// a hazard-striped deck over a dark metal body with a ring of 40 small lights round its sides.
pub fn elevator() -> Piece {
    let (deck, metal, light) = (0, 1, 2);
    let mut b = Builder::new(3);
    b.bevel_box(
        deck,
        Vec3::new(-1.5, -0.06, -1.5),
        Vec3::new(1.5, 0.0, 1.5),
        0.015,
        Uv::Unit,
    );
    b.bevel_box(
        metal,
        Vec3::new(-1.44, -0.3, -1.44),
        Vec3::new(1.44, -0.06, 1.44),
        0.025,
        Uv::Planar(1.0),
    );
    // Ten lights per side, 8 mm proud of the body's sides; each side is the +Z side turned.
    for quarter in 0..4 {
        let turn = Affine3A::from_quat(Quat::from_rotation_y(
            std::f32::consts::FRAC_PI_2 * quarter as f32,
        ));
        b.with(turn, |b| {
            for i in 0..10 {
                let x0 = -1.25 + 0.26 * i as f32;
                b.panel(
                    light,
                    Vec3::new(x0, -0.2, 1.448),
                    Vec3::new(0.18, 0.0, 0.0),
                    Vec3::new(0.0, 0.05, 0.0),
                    1,
                    1,
                    |s| s,
                );
            }
        });
    }
    Piece::new(
        "elevator",
        vec![mat::hazard_deck(), mat::metal_dark(), mat::elevator_light()],
        b,
    )
}

/// A railing 3 m along X (x ∈ [−1.5, 1.5]), 1 m high, z ∈ [−0.03, 0.03]: four posts with
/// foot plates, a top rail and an orange mid rail.
pub fn railing() -> Piece {
    let (metal, orange) = (0, 1);
    let mut b = Builder::new(2);
    for x in [-1.47f32, -0.49, 0.49, 1.47] {
        b.bevel_box(
            metal,
            Vec3::new(x - 0.025, 0.0, -0.025),
            Vec3::new(x + 0.025, 0.95, 0.025),
            0.008,
            Uv::Planar(1.0),
        );
        b.bevel_box(
            metal,
            Vec3::new((x - 0.03).max(-1.5), 0.0, -0.03),
            Vec3::new((x + 0.03).min(1.5), 0.015, 0.03),
            0.004,
            Uv::Planar(1.0),
        );
    }
    b.bevel_box(
        metal,
        Vec3::new(-1.5, 0.95, -0.03),
        Vec3::new(1.5, 1.0, 0.03),
        0.015,
        Uv::Planar(1.0),
    );
    b.bevel_box(
        orange,
        Vec3::new(-1.445, 0.5, -0.012),
        Vec3::new(1.445, 0.53, 0.012),
        0.006,
        Uv::Planar(1.0),
    );
    Piece::new(
        "railing_3",
        vec![mat::metal_dark(), mat::accent_orange()],
        b,
    )
}

/// A 1 × 1 m square pillar (x, z ∈ [−0.5, 0.5]), 8 m tall: bevelled collars at foot and head,
/// a shaft of two dark panelled halves with a groove front (+Z) and back (−Z), each groove
/// holding a blue light line of 28 segments.
pub fn pillar() -> Piece {
    let (metal, panel, light, seam) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    for (y0, y1) in [(0.0, 0.4), (7.6, 8.0)] {
        b.bevel_box(
            metal,
            Vec3::new(-0.5, y0, -0.5),
            Vec3::new(0.5, y1, 0.5),
            0.03,
            Uv::Planar(1.0),
        );
    }
    for (x0, x1) in [(-0.47, -0.035), (0.035, 0.47)] {
        b.bevel_box(
            panel,
            Vec3::new(x0, 0.4, -0.47),
            Vec3::new(x1, 7.6, 0.47),
            0.02,
            Uv::Planar(2.0),
        );
    }
    b.bevel_box(
        seam,
        Vec3::new(-0.04, 0.4, -0.43),
        Vec3::new(0.04, 7.6, 0.43),
        0.0,
        Uv::Planar(1.0),
    );
    const SEGMENTS: u32 = 28;
    let pitch = 7.0 / SEGMENTS as f32;
    for s in 0..SEGMENTS {
        let y0 = 0.5 + pitch * s as f32 + 0.01;
        let up = Vec3::new(0.0, pitch - 0.02, 0.0);
        let flat = |_: Vec2| Vec2::ZERO;
        b.panel(
            light,
            Vec3::new(-0.015, y0, 0.44),
            Vec3::X * 0.03,
            up,
            1,
            1,
            flat,
        );
        b.panel(
            light,
            Vec3::new(0.015, y0, -0.44),
            -Vec3::X * 0.03,
            up,
            1,
            1,
            flat,
        );
    }
    Piece::new(
        "pillar",
        vec![
            mat::metal_dark(),
            mat::panel_dark(),
            mat::trim_light(),
            mat::seam(),
        ],
        b,
    )
}

/// A pipe of radius 0.1 m along X, 8 m long centred at the origin (its axis the x-axis):
/// flanges at both ends, four bracket collars and an orange marker band in the middle.
/// Collars and flanges reach 0.14 m from the axis.
pub fn pipe() -> Piece {
    let (pipe, metal, orange) = (0, 1, 2);
    let mut b = Builder::new(3);
    // The tube helper builds along +Y; turn Y onto X.
    let along_x = Affine3A::from_quat(Quat::from_rotation_z(-std::f32::consts::FRAC_PI_2));
    b.with(along_x, |b| {
        b.tube(pipe, 0.1, 0.0, -4.0, 4.0, 24, true, 1.0);
        for (y0, y1) in [(-4.0, -3.94), (3.94, 4.0)] {
            b.tube(metal, 0.14, 0.1, y0, y1, 24, true, 1.0);
        }
        for y in [-3.0f32, -1.0, 1.0, 3.0] {
            b.tube(metal, 0.125, 0.1, y - 0.04, y + 0.04, 24, true, 1.0);
            b.tube(metal, 0.135, 0.1, y - 0.015, y + 0.015, 24, true, 1.0);
        }
        b.tube(orange, 0.104, 0.1, -0.15, 0.15, 24, true, 1.0);
    });
    Piece::new(
        "pipe_8",
        vec![mat::pipe_grey(), mat::metal_dark(), mat::accent_orange()],
        b,
    )
}
