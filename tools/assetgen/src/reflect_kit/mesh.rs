//! Mesh building for the Reflect kit: a [`Builder`] that collects vertices and per-material
//! triangles, with the shapes the pieces are made of: flat (subdivided) quads, bevelled boxes,
//! tubes and discs. Metres, right-handed, +Y up; triangles wind counter-clockwise seen from
//! the side their normal points to.
//!
//! Deterministic: positions, normals and texture coordinates are rounded to 1e-5 (10 µm, an
//! exact grid far below anything visible) before they become `f32`, so a last-bit difference
//! of `sin`/`cos` between machines does not reach the written bytes.
//! Must not: know about materials beyond their index, or write files.

use glam::{Affine3A, Vec2, Vec3};

use crate::gltf_writer::MeshData;

/// How a bevelled box's faces get texture coordinates.
#[derive(Clone, Copy, Debug)]
pub enum Uv {
    /// Metres along the face divided by the given tile size (world-planar).
    Planar(f32),
    /// 0..1 across each face (v = 0 at the face's top).
    Unit,
}

/// Collects one piece's geometry.
pub struct Builder {
    data: MeshData,
    transform: Affine3A,
}

fn quantize(v: f32) -> f32 {
    ((f64::from(v) * 1e5).round() / 1e5) as f32
}

impl Builder {
    /// A builder for a piece with `material_count` materials.
    pub fn new(material_count: usize) -> Self {
        Self {
            data: MeshData {
                indices: vec![Vec::new(); material_count],
                ..MeshData::default()
            },
            transform: Affine3A::IDENTITY,
        }
    }

    /// Runs `build` with `transform` applied (after the current one) to everything it adds.
    pub fn with(&mut self, transform: Affine3A, build: impl FnOnce(&mut Self)) {
        let saved = self.transform;
        self.transform = saved * transform;
        build(self);
        self.transform = saved;
    }

    /// Adds a vertex (in the current transform's space) and returns its index.
    pub fn vertex(&mut self, position: Vec3, normal: Vec3, uv: Vec2) -> u32 {
        let p = self.transform.transform_point3(position);
        let n = self.transform.transform_vector3(normal).normalize_or_zero();
        self.data
            .positions
            .push([quantize(p.x), quantize(p.y), quantize(p.z)]);
        self.data
            .normals
            .push([quantize(n.x), quantize(n.y), quantize(n.z)]);
        self.data.uvs.push([quantize(uv.x), quantize(uv.y)]);
        (self.data.positions.len() - 1) as u32
    }

    /// Adds triangle `a b c` to material `material`.
    pub fn triangle(&mut self, material: usize, a: u32, b: u32, c: u32) {
        self.data.indices[material].extend_from_slice(&[a, b, c]);
    }

    /// Adds the quad of four vertices (in order around it) as two triangles, wound so that
    /// they face the way the vertices' normals point on average.
    pub fn quad(&mut self, material: usize, corners: [(Vec3, Vec3, Vec2); 4]) {
        let [a, b, c, d] = corners;
        let face = (b.0 - a.0).cross(c.0 - a.0) + (c.0 - a.0).cross(d.0 - a.0);
        let normal_sum = a.1 + b.1 + c.1 + d.1;
        let ids = corners.map(|(p, n, uv)| self.vertex(p, n, uv));
        if face.dot(normal_sum) >= 0.0 {
            self.triangle(material, ids[0], ids[1], ids[2]);
            self.triangle(material, ids[0], ids[2], ids[3]);
        } else {
            self.triangle(material, ids[0], ids[2], ids[1]);
            self.triangle(material, ids[0], ids[3], ids[2]);
        }
    }

    /// A flat rectangle from `origin` spanning `u_axis` × `v_axis` (full edge vectors), facing
    /// `u_axis × v_axis`, split into `nu × nv` quads; texture coordinates go 0..1 along each
    /// axis, mapped through `uv_of`.
    #[allow(clippy::too_many_arguments)]
    pub fn panel(
        &mut self,
        material: usize,
        origin: Vec3,
        u_axis: Vec3,
        v_axis: Vec3,
        nu: u32,
        nv: u32,
        uv_of: impl Fn(Vec2) -> Vec2,
    ) {
        let normal = u_axis.cross(v_axis).normalize_or_zero();
        for i in 0..nu {
            for j in 0..nv {
                let corner = |di: u32, dj: u32| {
                    let s = Vec2::new((i + di) as f32 / nu as f32, (j + dj) as f32 / nv as f32);
                    (origin + u_axis * s.x + v_axis * s.y, normal, uv_of(s))
                };
                self.quad(
                    material,
                    [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)],
                );
            }
        }
    }

    /// An axis-aligned box from `min` to `max` whose edges and corners are rounded with
    /// radius `radius` (two segments per edge; 0 gives a sharp box). Its bounds stay exactly
    /// `min..max`. 108 triangles (12 when sharp).
    pub fn bevel_box(&mut self, material: usize, min: Vec3, max: Vec3, radius: f32, uv: Uv) {
        let size = max - min;
        let r = radius.min(size.min_element() * 0.45).max(0.0);
        let coords = |k: usize| -> Vec<f32> {
            if r > 0.0 {
                vec![min[k], min[k] + r, max[k] - r, max[k]]
            } else {
                vec![min[k], max[k]]
            }
        };
        let inner_min = min + Vec3::splat(r);
        let inner_max = max - Vec3::splat(r);
        for k in 0..3 {
            for positive in [false, true] {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let (ci, cj) = (coords(i), coords(j));
                let mut axis = Vec3::ZERO;
                axis[k] = if positive { 1.0 } else { -1.0 };
                let point = |a: usize, b: usize| {
                    let mut p = Vec3::ZERO;
                    p[k] = if positive { max[k] } else { min[k] };
                    p[i] = ci[a];
                    p[j] = cj[b];
                    let inner = p.clamp(inner_min, inner_max);
                    let offset = p - inner;
                    let normal = if r > 0.0 { offset.normalize() } else { axis };
                    let surface = if r > 0.0 { inner + normal * r } else { p };
                    (surface, normal, face_uv(axis, p, min, max, uv))
                };
                for a in 0..ci.len() - 1 {
                    for b in 0..cj.len() - 1 {
                        self.quad(
                            material,
                            [
                                point(a, b),
                                point(a + 1, b),
                                point(a + 1, b + 1),
                                point(a, b + 1),
                            ],
                        );
                    }
                }
            }
        }
    }

    /// A tube around the Y axis from `y0` to `y1`, outer radius `outer`, inner radius `inner`
    /// (0: a solid cylinder with flat caps), `segments` around; vertex 0 of the ring lies on +X
    /// so the bounds are exactly ±`outer` when `segments` is a multiple of 4. Texture
    /// coordinates: u around (0..1), v along Y in metres / `uv_scale`.
    #[allow(clippy::too_many_arguments)]
    pub fn tube(
        &mut self,
        material: usize,
        outer: f32,
        inner: f32,
        y0: f32,
        y1: f32,
        segments: u32,
        caps: bool,
        uv_scale: f32,
    ) {
        let ring = |i: u32| {
            let angle = std::f64::consts::TAU * f64::from(i % segments) / f64::from(segments);
            Vec3::new(angle.cos() as f32, 0.0, -(angle.sin() as f32))
        };
        for i in 0..segments {
            let (d0, d1) = (ring(i), ring(i + 1));
            let (u0, u1) = (i as f32 / segments as f32, (i + 1) as f32 / segments as f32);
            let wall = |d: Vec3, y: f32, r: f32, n: Vec3, u: f32| {
                (d * r + Vec3::Y * y, n, Vec2::new(u, y / uv_scale))
            };
            self.quad(
                material,
                [
                    wall(d0, y0, outer, d0, u0),
                    wall(d1, y0, outer, d1, u1),
                    wall(d1, y1, outer, d1, u1),
                    wall(d0, y1, outer, d0, u0),
                ],
            );
            if inner > 0.0 {
                self.quad(
                    material,
                    [
                        wall(d0, y0, inner, -d0, u0),
                        wall(d0, y1, inner, -d0, u0),
                        wall(d1, y1, inner, -d1, u1),
                        wall(d1, y0, inner, -d1, u1),
                    ],
                );
            }
            if !caps {
                continue;
            }
            for (y, n) in [(y0, -Vec3::Y), (y1, Vec3::Y)] {
                let cap = |d: Vec3, r: f32| (d * r + Vec3::Y * y, n, Vec2::new(d.x, d.z) * r);
                if inner > 0.0 {
                    self.quad(
                        material,
                        [
                            cap(d0, inner),
                            cap(d0, outer),
                            cap(d1, outer),
                            cap(d1, inner),
                        ],
                    );
                } else {
                    let ids = [
                        self.vertex(Vec3::Y * y, n, Vec2::ZERO),
                        self.vertex(d0 * outer + Vec3::Y * y, n, Vec2::new(d0.x, d0.z) * outer),
                        self.vertex(d1 * outer + Vec3::Y * y, n, Vec2::new(d1.x, d1.z) * outer),
                    ];
                    // Seen from above (+Y), d0 → d1 runs counter-clockwise.
                    if n.y > 0.0 {
                        self.triangle(material, ids[0], ids[1], ids[2]);
                    } else {
                        self.triangle(material, ids[0], ids[2], ids[1]);
                    }
                }
            }
        }
    }

    /// The finished geometry.
    pub fn finish(self) -> MeshData {
        self.data
    }
}

/// Texture coordinates of point `p` (on the un-rounded box `min..max`) on the face whose
/// outward normal is `axis`, oriented so that the image stands upright on vertical faces.
fn face_uv(axis: Vec3, p: Vec3, min: Vec3, max: Vec3, uv: Uv) -> Vec2 {
    // (metres along u, metres along v, face width, face height); v grows downwards.
    let (u, v, w, h) = if axis.y != 0.0 {
        let v = if axis.y > 0.0 {
            p.z - min.z
        } else {
            max.z - p.z
        };
        (p.x - min.x, v, max.x - min.x, max.z - min.z)
    } else if axis.z != 0.0 {
        let u = if axis.z > 0.0 {
            p.x - min.x
        } else {
            max.x - p.x
        };
        (u, max.y - p.y, max.x - min.x, max.y - min.y)
    } else {
        let u = if axis.x > 0.0 {
            max.z - p.z
        } else {
            p.z - min.z
        };
        (u, max.y - p.y, max.z - min.z, max.y - min.y)
    };
    match uv {
        Uv::Planar(tile) => Vec2::new(u, v) / tile,
        Uv::Unit => Vec2::new(u / w.max(1e-6), v / h.max(1e-6)),
    }
}
