//! The chamber shell: walls (`wall_8x4`, `wall_4x4`, `wall_4x4_door`), `floor_8x8`,
//! `ceiling_8x8` with its segmented light strips, the `trim_8` baseboard and the
//! `light_strip_4` wall bar. Sizes and origins are the kit's contract with the chamber levels
//! (`docs/LEVELS.md`, "The Reflect kit"). Metres, +Y up, visible face towards +Z unless noted.
//! Must not: write files.

use glam::{Vec2, Vec3};

use super::Piece;
use super::materials as mat;
use super::mesh::{Builder, Uv};

/// Gap between neighbouring panels (each panel is inset by half of it), m.
const SEAM: f32 = 0.024;

/// Bevelled panels filling the rectangle cells `xs[i]..xs[i+1]` × `ys[j]..ys[j+1]` in the
/// plane z ∈ `z`, each inset by half a seam. Texture 0..1 across each panel.
fn wall_panels(b: &mut Builder, material: usize, xs: &[f32], ys: &[f32], z: (f32, f32)) {
    let inset = SEAM / 2.0;
    for x in xs.windows(2) {
        for y in ys.windows(2) {
            b.bevel_box(
                material,
                Vec3::new(x[0] + inset, y[0] + inset, z.0),
                Vec3::new(x[1] - inset, y[1] - inset, z.1),
                0.025,
                Uv::Unit,
            );
        }
    }
}

/// A wall `width` m wide × 4 m high of 2 m panels: face at z = 0, back at z = −0.2.
pub fn wall(name: &'static str, width: f32) -> Piece {
    let (panel, seam) = (0, 1);
    let mut b = Builder::new(2);
    let half = width / 2.0;
    b.bevel_box(
        seam,
        Vec3::new(-half, 0.0, -0.2),
        Vec3::new(half, 4.0, -0.06),
        0.0,
        Uv::Planar(1.0),
    );
    let columns = (width / 2.0).round() as usize;
    let xs: Vec<f32> = (0..=columns).map(|i| -half + 2.0 * i as f32).collect();
    wall_panels(&mut b, panel, &xs, &[0.0, 2.0, 4.0], (-0.09, 0.0));
    Piece::new(name, vec![mat::panel_dark(), mat::seam()], b)
}

/// A 4 × 4 m wall with a 2.4 m × 3 m doorway at the bottom centre, a dark metal frame round
/// the opening (through the wall's depth) and an orange stripe above it.
pub fn wall_door() -> Piece {
    let (panel, seam, metal, orange) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    let slab = |b: &mut Builder, x0: f32, x1: f32, y0: f32, y1: f32| {
        b.bevel_box(
            seam,
            Vec3::new(x0, y0, -0.2),
            Vec3::new(x1, y1, -0.06),
            0.0,
            Uv::Planar(1.0),
        );
    };
    // The back slab around the opening (frame x ∈ ±1.35, up to y = 3.15).
    slab(&mut b, -2.0, -1.35, 0.0, 4.0);
    slab(&mut b, 1.35, 2.0, 0.0, 4.0);
    slab(&mut b, -1.35, 1.35, 3.15, 4.0);
    wall_panels(
        &mut b,
        panel,
        &[-2.0, -1.35],
        &[0.0, 2.0, 4.0],
        (-0.09, 0.0),
    );
    wall_panels(&mut b, panel, &[1.35, 2.0], &[0.0, 2.0, 4.0], (-0.09, 0.0));
    wall_panels(
        &mut b,
        panel,
        &[-1.35, 0.0, 1.35],
        &[3.3, 4.0],
        (-0.09, 0.0),
    );
    // The frame: jambs and header through the whole depth, bevelled.
    let frame = |b: &mut Builder, min: Vec3, max: Vec3| {
        b.bevel_box(metal, min, max, 0.02, Uv::Planar(1.0));
    };
    frame(
        &mut b,
        Vec3::new(-1.35, 0.0, -0.2),
        Vec3::new(-1.2, 3.0, 0.0),
    );
    frame(&mut b, Vec3::new(1.2, 0.0, -0.2), Vec3::new(1.35, 3.0, 0.0));
    frame(
        &mut b,
        Vec3::new(-1.35, 3.0, -0.2),
        Vec3::new(1.35, 3.15, 0.0),
    );
    // The orange accent stripe above the header, and small orange markers on the jambs.
    b.bevel_box(
        orange,
        Vec3::new(-1.35, 3.16, -0.08),
        Vec3::new(1.35, 3.29, -0.005),
        0.01,
        Uv::Planar(1.0),
    );
    for x in [-1.3, 1.25] {
        b.bevel_box(
            orange,
            Vec3::new(x, 1.2, -0.01),
            Vec3::new(x + 0.05, 1.8, 0.0),
            0.004,
            Uv::Planar(1.0),
        );
    }
    Piece::new(
        "wall_4x4_door",
        vec![
            mat::panel_dark(),
            mat::seam(),
            mat::metal_dark(),
            mat::accent_orange(),
        ],
        b,
    )
}

/// 8 × 8 m floor, top at y = 0, 0.2 m thick: 2 m tiles with seams.
pub fn floor() -> Piece {
    let (tile, seam) = (0, 1);
    let mut b = Builder::new(2);
    b.bevel_box(
        seam,
        Vec3::new(-4.0, -0.2, -4.0),
        Vec3::new(4.0, -0.05, 4.0),
        0.0,
        Uv::Planar(1.0),
    );
    let inset = SEAM / 3.0;
    for i in 0..4 {
        for j in 0..4 {
            let (x, z) = (-4.0 + 2.0 * i as f32, -4.0 + 2.0 * j as f32);
            b.bevel_box(
                tile,
                Vec3::new(x + inset, -0.1, z + inset),
                Vec3::new(x + 2.0 - inset, 0.0, z + 2.0 - inset),
                0.012,
                Uv::Unit,
            );
        }
    }
    Piece::new("floor_8x8", vec![mat::floor_tile(), mat::seam()], b)
}

/// Light segments along Z per ceiling strip.
const STRIP_SEGMENTS: u32 = 40;

/// 8 × 8 m ceiling, lower face at y = 0 facing −Y, 0.2 m thick above: white-grey panels and
/// two recessed light strips along Z at x = ±2, each of [`STRIP_SEGMENTS`] segments of 2 × 2
/// quads (640 emissive triangles in all).
pub fn ceiling() -> Piece {
    let (panel, seam, metal, light) = (0, 1, 2, 3);
    let mut b = Builder::new(4);
    b.bevel_box(
        seam,
        Vec3::new(-4.0, 0.06, -4.0),
        Vec3::new(4.0, 0.2, 4.0),
        0.0,
        Uv::Planar(1.0),
    );
    let inset = SEAM / 3.0;
    let columns = [(-4.0, -2.17), (-1.83, 0.0), (0.0, 1.83), (2.17, 4.0)];
    for (x0, x1) in columns {
        for j in 0..4 {
            let z = -4.0 + 2.0 * j as f32;
            b.bevel_box(
                panel,
                Vec3::new(x0 + inset, 0.0, z + inset),
                Vec3::new(x1 - inset, 0.08, z + 2.0 - inset),
                0.015,
                Uv::Unit,
            );
        }
    }
    let pitch = 8.0 / STRIP_SEGMENTS as f32;
    for centre in [-2.0f32, 2.0] {
        // The channel's housing (dark metal) above the segments.
        b.bevel_box(
            metal,
            Vec3::new(centre - 0.16, 0.05, -4.0),
            Vec3::new(centre + 0.16, 0.06, 4.0),
            0.0,
            Uv::Planar(1.0),
        );
        for s in 0..STRIP_SEGMENTS {
            let z0 = -4.0 + pitch * s as f32 + 0.012;
            let length = pitch - 0.024;
            // Facing −Y: u along +X, v along +Z, and (+X) × (+Z) = −Y.
            b.panel(
                light,
                Vec3::new(centre - 0.11, 0.03, z0),
                Vec3::new(0.22, 0.0, 0.0),
                Vec3::new(0.0, 0.0, length),
                2,
                2,
                |s| s,
            );
        }
    }
    Piece::new(
        "ceiling_8x8",
        vec![
            mat::ceiling_white(),
            mat::seam(),
            mat::metal_dark(),
            mat::light_strip(),
        ],
        b,
    )
}

/// Dark metal baseboard 8 m along X, 0.3 m high, z ∈ [0, 0.08], with a thin blue light line
/// of 16 segments.
pub fn trim() -> Piece {
    let (metal, light) = (0, 1);
    let mut b = Builder::new(2);
    b.bevel_box(
        metal,
        Vec3::new(-4.0, 0.04, 0.0),
        Vec3::new(4.0, 0.27, 0.06),
        0.012,
        Uv::Planar(1.0),
    );
    for (y0, y1) in [(0.0, 0.04), (0.27, 0.3)] {
        b.bevel_box(
            metal,
            Vec3::new(-4.0, y0, 0.0),
            Vec3::new(4.0, y1, 0.08),
            0.008,
            Uv::Planar(1.0),
        );
    }
    for s in 0..16 {
        let x0 = -4.0 + 0.5 * s as f32 + 0.01;
        b.panel(
            light,
            Vec3::new(x0, 0.175, 0.064),
            Vec3::new(0.48, 0.0, 0.0),
            Vec3::new(0.0, 0.02, 0.0),
            1,
            1,
            |s| s,
        );
    }
    Piece::new("trim_8", vec![mat::metal_dark(), mat::trim_light()], b)
}

/// A wall-mounted vertical light bar: y ∈ [0, 4], 0.15 m wide, z ∈ [0, 0.08]; a dark metal
/// housing holding 48 glowing segments (front and sides emissive).
pub fn light_bar() -> Piece {
    let (metal, light) = (0, 1);
    let mut b = Builder::new(2);
    b.bevel_box(
        metal,
        Vec3::new(-0.075, 0.0, 0.0),
        Vec3::new(0.075, 4.0, 0.05),
        0.015,
        Uv::Planar(1.0),
    );
    for (y0, y1) in [(0.0, 0.08), (3.92, 4.0)] {
        b.bevel_box(
            metal,
            Vec3::new(-0.075, y0, 0.0),
            Vec3::new(0.075, y1, 0.08),
            0.012,
            Uv::Planar(1.0),
        );
    }
    const SEGMENTS: u32 = 48;
    let pitch = 3.84 / SEGMENTS as f32;
    let (z0, z1, half) = (0.05, 0.072, 0.05);
    for s in 0..SEGMENTS {
        let y0 = 0.08 + pitch * s as f32 + 0.006;
        let h = pitch - 0.012;
        let up = Vec3::new(0.0, h, 0.0);
        let flat = |_: Vec2| Vec2::ZERO;
        b.panel(
            light,
            Vec3::new(-half, y0, z1),
            Vec3::new(2.0 * half, 0.0, 0.0),
            up,
            1,
            1,
            flat,
        );
        b.panel(
            light,
            Vec3::new(half, y0, z1),
            Vec3::new(0.0, 0.0, z0 - z1),
            up,
            1,
            1,
            flat,
        );
        b.panel(
            light,
            Vec3::new(-half, y0, z0),
            Vec3::new(0.0, 0.0, z1 - z0),
            up,
            1,
            1,
            flat,
        );
    }
    Piece::new(
        "light_strip_4",
        vec![mat::metal_dark(), mat::light_strip()],
        b,
    )
}
