//! Round and organic shapes for the ruins kit: [`lathe`] (a weathered surface of revolution:
//! column drums, capitals, bowls, discs, flames) and [`boulder`] (a jittered icosphere), plus
//! [`glyph_inlay`] (flat quads over a glyph mask, for the glowing pieces).
//!
//! Metres, right-handed, +Y up; the lathe's axis is the Y axis. Normals are smoothed over the
//! welded surface (`stone::emit`). Angles come from `f64` `cos`/`sin`, whose last-bit
//! differences are removed by the builder's 10 µm grid. Must not: know about materials beyond
//! their index.

use glam::{Vec2, Vec3};

use super::glyphs;
use super::noise::{fbm3, smoothstep};
use super::stone::emit;
use crate::reflect_kit::mesh::Builder;

/// Weathering of a lathe: radial chips near the profile's ends, erosion everywhere.
#[derive(Clone, Copy, Debug)]
pub struct Wear {
    /// Deepest chip, m.
    pub chip: f32,
    /// Height of the chipped band at the bottom and top of the profile, m.
    pub band: f32,
    pub seed: u64,
}

/// No weathering (metal, flames).
pub const CLEAN: Wear = Wear {
    chip: 0.0,
    band: 0.0,
    seed: 0,
};

/// A surface of revolution of `profile` (`(radius, y)` points, from the bottom up along the
/// outside and back in over the top: a radius of 0 is a pole) with `segments` around.
/// Texture coordinates: u around in metres of the widest radius / `tile`, v = −y / `tile`.
pub fn lathe(
    b: &mut Builder,
    material: usize,
    profile: &[(f32, f32)],
    segments: u32,
    wear: Wear,
    tile: f32,
) {
    let (y0, y1) = profile
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
    let widest = profile.iter().fold(0.0f32, |m, p| m.max(p.0));
    let (mut positions, mut uvs, mut keys) = (Vec::new(), Vec::new(), Vec::new());
    for (j, &(r, y)) in profile.iter().enumerate() {
        for i in 0..=segments {
            let angle = std::f64::consts::TAU * f64::from(i % segments) / f64::from(segments);
            let d = Vec3::new(angle.cos() as f32, 0.0, -(angle.sin() as f32));
            let p = d * r + Vec3::Y * y;
            let depth = if wear.chip > 0.0 && r > 0.0 {
                let rim = smoothstep(wear.band, 0.0, (y - y0).min(y1 - y));
                let chips = smoothstep(0.42, 0.7, fbm3(p.to_array(), 0.15, wear.seed));
                let erosion = fbm3(p.to_array(), 0.4, wear.seed + 3);
                let lift = smoothstep(0.0, 0.04, y - y0);
                (wear.chip * lift * (rim * chips + 0.18 * erosion)).min(r * 0.5)
            } else {
                0.0
            };
            positions.push(p - d * depth);
            let u = i as f32 / segments as f32 * std::f32::consts::TAU * widest;
            uvs.push(Vec2::new(u, -y) / tile);
            let around = if r > 0.0 { i64::from(i % segments) } else { 0 };
            keys.push([around, j as i64, 0]);
        }
    }
    let ring = segments + 1;
    let mut triangles = Vec::new();
    for j in 0..profile.len() as u32 - 1 {
        for i in 0..segments {
            let v00 = j * ring + i;
            let (v10, v01, v11) = (v00 + 1, v00 + ring, v00 + ring + 1);
            for t in [[v00, v10, v11], [v00, v11, v01]] {
                let k = t.map(|v| keys[v as usize]);
                if k[0] != k[1] && k[1] != k[2] && k[0] != k[2] {
                    triangles.push(t);
                }
            }
        }
    }
    emit(b, material, &positions, &uvs, &keys, &triangles);
}

/// A boulder: an icosphere (`subdivisions` times split) of radius `radius` centred at the
/// origin, each vertex pushed in or out by up to `jitter` × `radius` (3D noise).
pub fn boulder(
    b: &mut Builder,
    material: usize,
    radius: f32,
    jitter: f32,
    subdivisions: u32,
    seed: u64,
) {
    let t = (1.0 + 5.0f32.sqrt()) / 2.0;
    let mut points: Vec<Vec3> = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
    .collect();
    let mut faces: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut middle = std::collections::BTreeMap::new();
        let mut mid = |a: u32, c: u32, points: &mut Vec<Vec3>| {
            *middle.entry((a.min(c), a.max(c))).or_insert_with(|| {
                points.push(((points[a as usize] + points[c as usize]) * 0.5).normalize());
                points.len() as u32 - 1
            })
        };
        let mut next = Vec::with_capacity(faces.len() * 4);
        for [a, c, d] in faces {
            let (ac, cd, da) = (
                mid(a, c, &mut points),
                mid(c, d, &mut points),
                mid(d, a, &mut points),
            );
            next.extend([[a, ac, da], [c, cd, ac], [d, da, cd], [ac, cd, da]]);
        }
        faces = next;
    }
    let positions: Vec<Vec3> = points
        .iter()
        .map(|&n| {
            let big = fbm3((n * 2.2).to_array(), 0.6, seed) - 0.5;
            let small = fbm3((n * 6.0).to_array(), 0.5, seed + 5) - 0.5;
            // Flatten a little (a boulder rests on a broad side).
            let squash = Vec3::new(1.0, 0.88, 1.0);
            n * squash * radius * (1.0 + jitter * (1.4 * big + 0.6 * small))
        })
        .collect();
    let uvs: Vec<Vec2> = positions
        .iter()
        .map(|p| Vec2::new(p.x + p.z, -p.y) / 2.0)
        .collect();
    let keys: Vec<[i64; 3]> = (0..positions.len() as i64).map(|i| [i, 0, 0]).collect();
    // Outward winding for the icosahedron's faces as listed.
    emit(b, material, &positions, &uvs, &keys, &faces);
}

/// Flat quads over glyph `glyph`'s mask sampled on a `cells × cells` grid, covering the square
/// of side `size` centred on the origin in the plane y = `y`, facing +Y (glyph x along +X,
/// glyph y up along −Z). Runs of covered cells along a row become one quad.
pub fn glyph_inlay(b: &mut Builder, material: usize, glyph: usize, cells: u32, size: f32, y: f32) {
    let step = size / cells as f32;
    let half = size / 2.0;
    for row in 0..cells {
        let gy = 1.0 - (row as f32 + 0.5) / cells as f32 * 2.0;
        let mut col = 0;
        while col < cells {
            let covered =
                |c: u32| glyphs::covers(glyph, (c as f32 + 0.5) / cells as f32 * 2.0 - 1.0, gy);
            if !covered(col) {
                col += 1;
                continue;
            }
            let start = col;
            while col < cells && covered(col) {
                col += 1;
            }
            let (x0, x1) = (-half + start as f32 * step, -half + col as f32 * step);
            let (z0, z1) = (-half + row as f32 * step, -half + (row + 1) as f32 * step);
            let corner = |x: f32, z: f32| {
                (
                    Vec3::new(x, y, z),
                    Vec3::Y,
                    Vec2::new((x + half) / size, (z + half) / size),
                )
            };
            b.quad(
                material,
                [
                    corner(x0, z0),
                    corner(x0, z1),
                    corner(x1, z1),
                    corner(x1, z0),
                ],
            );
        }
    }
}
