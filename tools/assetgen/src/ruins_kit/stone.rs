//! Weathered stone shapes for the ruins kit: a [`Stone`] is a box with rounded edges, each face
//! a grid of about `cell`-metre quads, optionally tapered towards the top (a frustum), whose
//! surface is pushed inwards by 3D noise: deep chips near edges and corners, shallow erosion
//! elsewhere. Normals are smoothed over the welded surface after the displacement.
//!
//! Metres, right-handed, +Y up. Displacement is only ever inwards and the bottom face stays
//! flat at `min.y`, so a stone never grows past its box and sits on its base. Texture
//! coordinates are world-planar per face (metres / `tile`, v downwards on vertical faces so
//! image rows run along the strata). Must not: know about materials beyond their index.

use std::collections::HashMap;

use glam::{Vec2, Vec3};

use super::noise::{fbm3, smoothstep};
use crate::reflect_kit::mesh::Builder;

/// A weathered stone's shape.
#[derive(Clone, Copy, Debug)]
pub struct Stone {
    pub min: Vec3,
    pub max: Vec3,
    /// Edge rounding radius, m.
    pub radius: f32,
    /// Target quad size on the faces, m.
    pub cell: f32,
    /// Deepest chip, m (0: a clean rounded box).
    pub chip: f32,
    /// Width of the band along edges where chips happen, m.
    pub band: f32,
    /// Top face size relative to the bottom (1: a box; < 1: a frustum), in x and z.
    pub taper: f32,
    /// Texture tile, m.
    pub tile: f32,
    /// Added to every texture coordinate (moves the texture over the stone), tiles.
    pub uv_offset: Vec2,
    /// Noise seed.
    pub seed: u64,
}

impl Stone {
    /// A box `min..max` with the kit's default weathering.
    pub fn new(min: Vec3, max: Vec3, seed: u64) -> Self {
        Self {
            min,
            max,
            radius: 0.04,
            cell: 0.2,
            chip: 0.06,
            band: 0.14,
            taper: 1.0,
            tile: 2.0,
            uv_offset: Vec2::ZERO,
            seed,
        }
    }

    fn coords(&self, k: usize) -> Vec<f32> {
        let (a, b) = (self.min[k], self.max[k]);
        let r = self.radius.min((b - a) * 0.45).max(0.0);
        let (lo, hi) = (a + r, b - r);
        let steps = (((hi - lo) / self.cell).ceil() as u32).max(1);
        let mut out = Vec::new();
        if r > 0.0 {
            out.push(a);
        }
        for i in 0..=steps {
            out.push(lo + (hi - lo) * i as f32 / steps as f32);
        }
        if r > 0.0 {
            out.push(b);
        }
        out
    }

    /// The point of the (undisplaced, tapered) surface over `p` on the flat box, and its normal
    /// before tapering.
    fn surface(&self, p: Vec3) -> (Vec3, Vec3) {
        let r = self
            .radius
            .min((self.max - self.min).min_element() * 0.45)
            .max(0.0);
        let inner = p.clamp(self.min + Vec3::splat(r), self.max - Vec3::splat(r));
        let offset = p - inner;
        let n = if offset.length_squared() > 0.0 {
            offset.normalize()
        } else {
            Vec3::ZERO
        };
        let mut s = inner + n * r;
        let t = (s.y - self.min.y) / (self.max.y - self.min.y).max(1e-6);
        let centre = (self.min + self.max) * 0.5;
        let f = 1.0 + (self.taper - 1.0) * t;
        s.x = centre.x + (s.x - centre.x) * f;
        s.z = centre.z + (s.z - centre.z) * f;
        (s, n)
    }

    /// How far inwards the surface at `s` (normal `n`) is pushed, m.
    fn depth(&self, s: Vec3, p: Vec3) -> f32 {
        if self.chip <= 0.0 {
            return 0.0;
        }
        // Distance to the nearest box edge, measured on the flat box.
        let mut edge = f32::INFINITY;
        let mut on_faces = 0;
        for k in 0..3 {
            let d = (p[k] - self.min[k]).min(self.max[k] - p[k]);
            if d <= 1e-6 {
                on_faces += 1;
            } else {
                edge = edge.min(d);
            }
        }
        if on_faces >= 2 {
            edge = 0.0;
        }
        let near_edge = smoothstep(self.band, 0.0, edge);
        let chips = smoothstep(0.42, 0.7, fbm3(s.to_array(), 0.18, self.seed));
        let erosion = fbm3(s.to_array(), 0.45, self.seed + 3);
        let bottom = smoothstep(0.0, 0.04, s.y - self.min.y);
        self.chip * bottom * (near_edge * chips + 0.18 * erosion)
    }

    /// Adds the stone to `b` with material `material`.
    pub fn build(&self, b: &mut Builder, material: usize) {
        let mut positions: Vec<Vec3> = Vec::new();
        let mut uvs: Vec<Vec2> = Vec::new();
        let mut keys: Vec<[i64; 3]> = Vec::new();
        let mut triangles: Vec<[u32; 3]> = Vec::new();
        for k in 0..3 {
            for positive in [false, true] {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let (ci, cj) = (self.coords(i), self.coords(j));
                let base = positions.len() as u32;
                for &a in &ci {
                    for &bb in &cj {
                        let mut p = Vec3::ZERO;
                        p[k] = if positive { self.max[k] } else { self.min[k] };
                        p[i] = a;
                        p[j] = bb;
                        let (s, n) = self.surface(p);
                        let inward = if n == Vec3::ZERO { Vec3::ZERO } else { -n };
                        positions.push(s + inward * self.depth(s, p));
                        uvs.push(planar_uv(k, positive, s, self.tile) + self.uv_offset);
                        keys.push(p.to_array().map(|c| (f64::from(c) * 1e5).round() as i64));
                    }
                }
                let nj = cj.len() as u32;
                for a in 0..ci.len() as u32 - 1 {
                    for c in 0..nj - 1 {
                        let v00 = base + a * nj + c;
                        let (v10, v01, v11) = (v00 + nj, v00 + 1, v00 + nj + 1);
                        // (i, j, k) is right-handed: i × j = k, so i then j winds outwards on the
                        // positive face.
                        if positive {
                            triangles.push([v00, v10, v11]);
                            triangles.push([v00, v11, v01]);
                        } else {
                            triangles.push([v00, v11, v10]);
                            triangles.push([v00, v01, v11]);
                        }
                    }
                }
            }
        }
        emit(b, material, &positions, &uvs, &keys, &triangles);
    }
}

/// Planar texture coordinates on the face with normal axis `k` (sign `positive`), m / `tile`.
fn planar_uv(k: usize, positive: bool, s: Vec3, tile: f32) -> Vec2 {
    let sign = if positive { 1.0 } else { -1.0 };
    let uv = match k {
        1 => Vec2::new(s.x, s.z * sign),
        2 => Vec2::new(s.x * sign, -s.y),
        _ => Vec2::new(-s.z * sign, -s.y),
    };
    uv / tile
}

/// Adds triangles to `b`, each vertex with the area-weighted normal of every triangle touching
/// its welded position (`keys` equal = the same point of the surface).
pub fn emit(
    b: &mut Builder,
    material: usize,
    positions: &[Vec3],
    uvs: &[Vec2],
    keys: &[[i64; 3]],
    triangles: &[[u32; 3]],
) {
    let mut welded: HashMap<[i64; 3], usize> = HashMap::new();
    let mut slot = Vec::with_capacity(keys.len());
    for key in keys {
        let next = welded.len();
        slot.push(*welded.entry(*key).or_insert(next));
    }
    let mut sums = vec![Vec3::ZERO; welded.len()];
    for t in triangles {
        let [a, b2, c] = t.map(|i| positions[i as usize]);
        let n = (b2 - a).cross(c - a);
        for &i in t {
            sums[slot[i as usize]] += n;
        }
    }
    let ids: Vec<u32> = (0..positions.len())
        .map(|i| {
            let n = sums[slot[i]].normalize_or_zero();
            b.vertex(positions[i], n, uvs[i])
        })
        .collect();
    for t in triangles {
        b.triangle(
            material,
            ids[t[0] as usize],
            ids[t[1] as usize],
            ids[t[2] as usize],
        );
    }
}
