//! Panels and glass: the mirrorable `mirror_panel` and `curved_panel` (one material each, so a
//! per-instance override turns the whole piece into a mirror), the `glass_cube`, the
//! `glass_pane_4x4` window and the sliding `door` leaf. Metres, +Y up.
//! Must not: write files.

use glam::{Vec2, Vec3};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// The 2 × 2 m mirrorable panel: x ∈ [−1, 1], y ∈ [0, 2], face at z = 0, 0.06 m thick,
/// bevelled; `panel_white` only.
pub fn mirror_panel() -> Piece {
    let mut b = Builder::new(1);
    b.bevel_box(
        0,
        Vec3::new(-1.0, 0.0, -0.06),
        Vec3::new(1.0, 2.0, 0.0),
        0.02,
        Uv::Unit,
    );
    Piece::new("mirror_panel", vec![mat::panel_white()], b)
}

/// Radius of the curved panel's concave face, m.
pub const CURVE_RADIUS: f32 = 3.0;
/// Angular width of the curved panel, degrees.
pub const CURVE_DEGREES: f64 = 60.0;
/// Segments across the curved panel.
const CURVE_SEGMENTS: u32 = 48;

/// The mirrorable curved section: a cylinder arc of radius 3 m about the vertical line through
/// (0, ·, 3), 60° wide, y ∈ [0, 2], its concave face towards +Z with the arc's midpoint at the
/// origin, 0.06 m thick behind; `panel_white` only. The ends of the arc come forward to
/// z = 3 − 3 cos 30° ≈ 0.402.
pub fn curved_panel() -> Piece {
    let mut b = Builder::new(1);
    let centre = Vec3::new(0.0, 0.0, CURVE_RADIUS);
    let (front_r, back_r, height) = (CURVE_RADIUS, CURVE_RADIUS + 0.06, 2.0);
    let half = (CURVE_DEGREES / 2.0).to_radians();
    // Outward direction (away from the centre) at segment edge `i`.
    let direction = |i: u32| {
        let angle = -half + 2.0 * half * f64::from(i) / f64::from(CURVE_SEGMENTS);
        Vec3::new(angle.sin() as f32, 0.0, -(angle.cos() as f32))
    };
    let at = |d: Vec3, r: f32, y: f32| centre + d * r + Vec3::Y * y;
    for i in 0..CURVE_SEGMENTS {
        let (d0, d1) = (direction(i), direction(i + 1));
        let (u0, u1) = (
            i as f32 / CURVE_SEGMENTS as f32,
            (i + 1) as f32 / CURVE_SEGMENTS as f32,
        );
        // The concave face (normals towards the centre) and the back.
        b.quad(
            0,
            [
                (at(d0, front_r, 0.0), -d0, Vec2::new(u0, 1.0)),
                (at(d1, front_r, 0.0), -d1, Vec2::new(u1, 1.0)),
                (at(d1, front_r, height), -d1, Vec2::new(u1, 0.0)),
                (at(d0, front_r, height), -d0, Vec2::new(u0, 0.0)),
            ],
        );
        b.quad(
            0,
            [
                (at(d0, back_r, 0.0), d0, Vec2::new(u0, 1.0)),
                (at(d0, back_r, height), d0, Vec2::new(u0, 0.0)),
                (at(d1, back_r, height), d1, Vec2::new(u1, 0.0)),
                (at(d1, back_r, 0.0), d1, Vec2::new(u1, 1.0)),
            ],
        );
        // Top and bottom edges.
        for (y, n) in [(0.0, -Vec3::Y), (height, Vec3::Y)] {
            let edge = Vec2::new(0.5, 0.0);
            b.quad(
                0,
                [
                    (at(d0, front_r, y), n, edge),
                    (at(d1, front_r, y), n, edge),
                    (at(d1, back_r, y), n, edge),
                    (at(d0, back_r, y), n, edge),
                ],
            );
        }
    }
    // The two end faces.
    for (i, sign) in [(0, -1.0f32), (CURVE_SEGMENTS, 1.0)] {
        let d = direction(i);
        let n = Vec3::new(-d.z, 0.0, d.x) * sign;
        let edge = Vec2::new(0.0, 0.5);
        b.quad(
            0,
            [
                (at(d, front_r, 0.0), n, edge),
                (at(d, back_r, 0.0), n, edge),
                (at(d, back_r, height), n, edge),
                (at(d, front_r, height), n, edge),
            ],
        );
    }
    Piece::new("curved_panel", vec![mat::panel_white()], b)
}

/// The carried glass cube: 0.5 m, centred at the origin, bevelled edges; `glass` only.
pub fn glass_cube() -> Piece {
    let mut b = Builder::new(1);
    b.bevel_box(0, Vec3::splat(-0.25), Vec3::splat(0.25), 0.03, Uv::Unit);
    Piece::new("glass_cube", vec![mat::glass()], b)
}

/// A 4 × 4 m window (x ∈ [−2, 2], y ∈ [0, 4]), face at z = 0: a dark metal frame 0.12 m deep
/// with a cross of mullions holding four 2 cm glass panes.
pub fn glass_pane() -> Piece {
    let (metal, glass) = (0, 1);
    let mut b = Builder::new(2);
    let frame = |b: &mut Builder, x0: f32, y0: f32, x1: f32, y1: f32, z0: f32| {
        b.bevel_box(
            metal,
            Vec3::new(x0, y0, z0),
            Vec3::new(x1, y1, 0.0),
            0.02,
            Uv::Planar(1.0),
        );
    };
    frame(&mut b, -2.0, 0.0, -1.88, 4.0, -0.12);
    frame(&mut b, 1.88, 0.0, 2.0, 4.0, -0.12);
    frame(&mut b, -1.88, 0.0, 1.88, 0.12, -0.12);
    frame(&mut b, -1.88, 3.88, 1.88, 4.0, -0.12);
    frame(&mut b, -0.04, 0.12, 0.04, 3.88, -0.1);
    frame(&mut b, -1.88, 1.96, -0.04, 2.04, -0.1);
    frame(&mut b, 0.04, 1.96, 1.88, 2.04, -0.1);
    for (x0, x1) in [(-1.88, -0.04), (0.04, 1.88)] {
        for (y0, y1) in [(0.12, 1.96), (2.04, 3.88)] {
            b.bevel_box(
                glass,
                Vec3::new(x0, y0, -0.07),
                Vec3::new(x1, y1, -0.05),
                0.0,
                Uv::Unit,
            );
        }
    }
    Piece::new("glass_pane_4x4", vec![mat::metal_dark(), mat::glass()], b)
}

/// The sliding door leaf: x ∈ [−1.2, 1.2], y ∈ [0, 3], z ∈ [−0.075, 0.075]; white with dark
/// bands (centre seam, kick plate, top) and an orange light line across both faces.
pub fn door() -> Piece {
    let (white, metal, light) = (0, 1, 2);
    let mut b = Builder::new(3);
    for (x0, x1) in [(-1.2, -0.09), (0.09, 1.2)] {
        b.bevel_box(
            white,
            Vec3::new(x0, 0.16, -0.06),
            Vec3::new(x1, 2.84, 0.06),
            0.02,
            Uv::Unit,
        );
    }
    let band = |b: &mut Builder, min: Vec3, max: Vec3| {
        b.bevel_box(metal, min, max, 0.015, Uv::Planar(1.0));
    };
    band(
        &mut b,
        Vec3::new(-0.1, 0.0, -0.075),
        Vec3::new(0.1, 3.0, 0.075),
    );
    band(
        &mut b,
        Vec3::new(-1.2, 0.0, -0.07),
        Vec3::new(1.2, 0.16, 0.07),
    );
    band(
        &mut b,
        Vec3::new(-1.2, 2.84, -0.07),
        Vec3::new(1.2, 3.0, 0.07),
    );
    // The light line: 2 × 6 segments per face at y = 1.5.
    for (z, flip) in [(0.062f32, false), (-0.062, true)] {
        for s in 0..12 {
            let side = if s < 6 { -1.0f32 } else { 1.0 };
            let k = (s % 6) as f32;
            let x0 = side * (0.16 + k * 0.17);
            let x1 = side * (0.16 + k * 0.17 + 0.15);
            let (xa, xb) = if (x1 > x0) != flip {
                (x0, x1)
            } else {
                (x1, x0)
            };
            b.panel(
                light,
                Vec3::new(xa, 1.48, z),
                Vec3::new(xb - xa, 0.0, 0.0),
                Vec3::new(0.0, 0.04, 0.0),
                1,
                1,
                |s| s,
            );
        }
    }
    Piece::new(
        "door",
        vec![mat::panel_white(), mat::metal_dark(), mat::orange_light()],
        b,
    )
}
