//! The ray–triangle test every tracer uses: two-sided, one division, on the stored form
//! `v0, e1 = v1 - v0, e2 = v2 - v0`, in the ray-centred sheared frame of Woop, Benthin and Wald
//! 2013 ("Watertight Ray/Triangle Intersection", JCGT 2(1)), with edge functions written in terms
//! of the edges (like Möller–Trumbore's numerators) and a relative degeneracy bound.
//!
//! Per ray: axes permuted so `k[2]` is the dominant direction axis, shear `S`. Per triangle:
//! `a = v0 - o`, sheared 2D `a'`, `e1'`, `e2'`; `det = e2'.x·e1'.y - e2'.y·e1'.x` (twice the
//! projected area, from the edges alone), `u = (a'.x·e2'.y - a'.y·e2'.x) / det`,
//! `v = (e1'.x·a'.y - e1'.y·a'.x) / det`, hit when `u, v >= -slack`, `u + v <= 1 + slack`,
//! and `t = (a_z + u·e1_z + v·e2_z) / d_z` lies in `(t_min, t_max)`.
//!
//! Watertight by a slack per edge that bounds the rounding error: the stored form (`v0` and
//! rounded edges) cannot make two triangles that share an edge evaluate it identically, and
//! `a = v0 - o` loses about `u·|v0 - o|` (u = 2⁻²⁴), so with a fixed slack a ray through a shared
//! edge from far away could slip between both triangles (35 of 5,451 such rays 20 m from a
//! 0.1 m-edged icosphere, `tests/cross/watertight.rs`). With `m = |a'.x| + |a'.y| + |a_z|` and
//! `E_i = |e_i'.x| + |e_i'.y| + |e_i.z|`, the edge function of the edge along `e_i` errs by
//! about `7u·m·E_i` (sheared offset `2u·m` per component, sheared edge `2u·E_i`, the products),
//! that is by about `7u·m` in distance across the edge; so `u >= -slack_u` with `slack_u =
//! SLACK_SCALE·m·E_2/|det| + EDGE_SLACK` (`v` likewise with `E_1`, `1 - u - v` with `E_1 + E_2`)
//! lets every ray through the exact triangle pass (edges and vertices included), whatever its
//! neighbour computes. A hit then lies at most about `11u·m` (plus `EDGE_SLACK` of the
//! triangle) outside the triangle, within the rounding of the ray's own position at that
//! distance. Costs about 19 more vector operations per block test (abs, add, mul, fused
//! multiply-add; no branch): each bound is folded into its comparison (`c·E_2 + u >=
//! -EDGE_SLACK`, one fused operation), which measured +1 to +3 % on the peer benchmark's shadow
//! and bounce rays against forming the slacks first (interleaved CPU-time A/B, 5 rounds).
//!
//! Why this and not the textbook forms (both found by the brute-force agreement tests):
//! Möller–Trumbore reported a hit a hundred units away from a sliver triangle (two edges equal
//! to one ulp: its determinant was rounding noise), and Woop's vertex-based edge functions did the
//! same for a 1e-6-sized triangle seven units off the ray (cancellation of `|a|²`-sized products).
//! Here `det = fma(e2'.x, e1'.y, -(e2'.y·e1'.x))` is rejected unless `|det| > 2⁻¹⁸ |e2'.y·e1'.x|`
//! (its rounding error is at most `u·|e2'.y·e1'.x| + u·|det|`, u = 2⁻²⁴), that is unless it is
//! far above its own rounding error (triangles seen within about 4e-6 rad of edge-on are skipped),
//! so `u`, `v` are accurate; and `t` is the depth of the point `v0 + u·e1 + v·e2` of the triangle
//! itself. A hit therefore always lies on the triangle, within rounding of the ray.
//! Cost: 27 arithmetic ops (12 of them fused multiply-adds) and one division per triangle, plus
//! the slack. Fused multiply-adds are exact-rounded everywhere (`f32::mul_add`,
//! `vfmadd`), so the scalar and SIMD kernels still agree bit for bit; on x86-64 the scalar
//! callers run this inside `#[target_feature(enable = "fma")]` functions when the CPU has FMA
//! (identical results, no libm call).
//!
//! Owns: the exact sequence of f32 operations. The SIMD kernels (`simd.rs`) repeat it lane for
//! lane, fusing exactly where this code calls `mul_add`, so every tracer returns bit-identical
//! `t`, `u`, `v` for the same triangle and ray; the tests rely on that. Any thread. Must not:
//! reorder or fuse other operations (Rust never contracts `a * b + c` into an FMA by itself).

use glam::Vec3;

use crate::layout::GpuTri4;

/// Per-ray constants of the watertight test: the axis permutation `k` (`k[2]` = the dominant
/// direction axis, `k[0] = (k[2] + 1) % 3`, `k[1] = (k[0] + 1) % 3`), the origin in that order,
/// and the shear `(d[k0]/d[k2], d[k1]/d[k2], 1/d[k2])`.
#[derive(Clone, Copy, Debug)]
pub struct TriRay {
    pub k: [usize; 3],
    pub origin: [f32; 3],
    pub shear: [f32; 3],
}

impl TriRay {
    #[inline(always)]
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        let a = direction.abs();
        let kz = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let sz = 1.0 / direction[kz];
        Self {
            k: [kx, ky, kz],
            origin: [origin[kx], origin[ky], origin[kz]],
            shear: [direction[kx] * sz, direction[ky] * sz, sz],
        }
    }
}

/// `|det|` must exceed this times `|e2'.y·e1'.x|` (see the module docs).
pub const DEGENERATE_RATIO: f32 = 1.0 / 262_144.0;

/// Slack of the inside test per unit of `m · E / |det|` (see `slacks`): 8 u, u = 2⁻²⁴.
pub const SLACK_SCALE: f32 = 1.0 / 2_097_152.0;

/// Least slack of the inside test, barycentric units (2⁻²⁰): covers the rounding of the stored
/// edges when the ray starts at the triangle (32 of the 230,400 primary rays of the peer
/// benchmark's cornell box slipped through shared edges without it).
pub const EDGE_SLACK: f32 = 1.0 / 1_048_576.0;

/// Intersection of the ray with the triangle `(v0, e1, e2)` (components in the ray's `k` order):
/// `Some((t, u, v))` with the hit point `v0 + u·e1 + v·e2`, edges inclusive. Degenerate
/// triangles (and a zero direction, whose shear is NaN) fail the determinant test.
#[inline(always)]
pub fn intersect_permuted(
    v0: [f32; 3],
    e1: [f32; 3],
    e2: [f32; 3],
    ray: &TriRay,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let [sx, sy, sz] = ray.shear;
    let a0 = v0[0] - ray.origin[0];
    let a1 = v0[1] - ray.origin[1];
    let a2 = v0[2] - ray.origin[2];
    // Shear so that the ray runs along +z through the origin: x - s·z, one rounding each.
    let ax = (-sx).mul_add(a2, a0);
    let ay = (-sy).mul_add(a2, a1);
    let e1x = (-sx).mul_add(e1[2], e1[0]);
    let e1y = (-sy).mul_add(e1[2], e1[1]);
    let e2x = (-sx).mul_add(e2[2], e2[0]);
    let e2y = (-sy).mul_add(e2[2], e2[1]);
    // Edge functions (weights of v1 and v2) and twice the projected area.
    let w1 = ax.mul_add(e2y, -(ay * e2x));
    let w2 = e1x.mul_add(ay, -(e1y * ax));
    let p2 = e2y * e1x;
    let det = e2x.mul_add(e1y, -p2);
    let bound = p2.abs() * DEGENERATE_RATIO;
    let inv_det = 1.0 / det;
    let u = w1 * inv_det;
    let v = w2 * inv_det;
    let t = v.mul_add(e2[2], u.mul_add(e1[2], a2)) * sz;
    // The rounding-error slack of each edge (see the module docs), in this order everywhere.
    let c = (ax.abs() + ay.abs() + a2.abs()) * (inv_det.abs() * SLACK_SCALE);
    let len1 = e1x.abs() + e1y.abs() + e1[2].abs();
    let len2 = e2x.abs() + e2y.abs() + e2[2].abs();
    // `u >= -(c·len2 + EDGE_SLACK)` is tested as `c·len2 + u >= -EDGE_SLACK` with one
    // rounding (two operations fewer per lane than forming the slack first), and so on.
    let hit = det.abs() > bound
        && c.mul_add(len2, u) >= -EDGE_SLACK
        && c.mul_add(len1, v) >= -EDGE_SLACK
        && (-c).mul_add(len1 + len2, u + v) <= 1.0 + EDGE_SLACK
        && t > t_min
        && t < t_max;
    hit.then_some((t, u, v))
}

/// [`intersect_permuted`] on a triangle given in xyz order.
#[inline(always)]
pub fn intersect_triangle(
    v0: Vec3,
    e1: Vec3,
    e2: Vec3,
    ray: &TriRay,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let p = |v: Vec3| [v[ray.k[0]], v[ray.k[1]], v[ray.k[2]]];
    intersect_permuted(p(v0), p(e1), p(e2), ray, t_min, t_max)
}

/// The nine coordinate rows of a block (`v0 x y z`, `e1 x y z`, `e2 x y z`, four lanes each),
/// so a kernel can read rows in the ray's `k` order.
#[inline(always)]
pub fn block_rows(b: &GpuTri4) -> [&[f32; 4]; 9] {
    [
        &b.v0_x, &b.v0_y, &b.v0_z, &b.e1_x, &b.e1_y, &b.e1_z, &b.e2_x, &b.e2_y, &b.e2_z,
    ]
}

/// [`intersect_permuted`] on lane `lane` (0..4) of a block.
#[inline(always)]
pub fn intersect_lane(
    block: &GpuTri4,
    lane: usize,
    ray: &TriRay,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let rows = block_rows(block);
    let [k0, k1, k2] = ray.k;
    let get = |base: usize| {
        [
            rows[base + k0][lane],
            rows[base + k1][lane],
            rows[base + k2][lane],
        ]
    };
    intersect_permuted(get(0), get(3), get(6), ray, t_min, t_max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hit(o: Vec3, d: Vec3, v0: Vec3, e1: Vec3, e2: Vec3, t_max: f32) -> Option<(f32, f32, f32)> {
        intersect_triangle(v0, e1, e2, &TriRay::new(o, d), 0.0, t_max)
    }

    #[test]
    fn hits_inside_misses_outside_and_degenerate() {
        let (v0, e1, e2) = (Vec3::ZERO, Vec3::X, Vec3::Y);
        let d = Vec3::new(0.0, 0.0, -2.0);
        let (t, u, v) = hit(Vec3::new(0.25, 0.5, 1.0), d, v0, e1, e2, 10.0).expect("hit");
        assert_eq!((t, u, v), (0.5, 0.25, 0.5));
        // Two-sided: from below too.
        assert!(hit(Vec3::new(0.2, 0.2, -1.0), -d, v0, e1, e2, 10.0).is_some());
        // Outside, behind, beyond t_max, zero area, parallel, zero direction.
        assert!(hit(Vec3::new(0.8, 0.8, 1.0), d, v0, e1, e2, 10.0).is_none());
        assert!(hit(Vec3::new(0.2, 0.2, 1.0), -d, v0, e1, e2, 10.0).is_none());
        assert!(hit(Vec3::new(0.2, 0.2, 1.0), d, v0, e1, e2, 0.4).is_none());
        assert!(hit(Vec3::new(0.2, 0.0, 1.0), d, v0, e1, e1, 9.0).is_none());
        assert!(hit(Vec3::new(-1.0, 0.2, 0.0), Vec3::X, v0, e1, e2, 9.0).is_none());
        assert!(hit(Vec3::new(0.2, 0.2, 1.0), Vec3::ZERO, v0, e1, e2, 9.0).is_none());
        // Unused block lanes never hit.
        let ray = TriRay::new(Vec3::ZERO, Vec3::Z);
        assert!(intersect_lane(&GpuTri4::EMPTY, 0, &ray, -1.0, 1.0).is_none());
    }

    #[test]
    fn slivers_and_tiny_far_triangles_have_no_phantom_hit() {
        // Möller–Trumbore reported t = 0.667 for this ray and sliver, 100 units away.
        let v0 = Vec3::new(0.12940955, -0.9659259, -0.22414371);
        let v1 = Vec3::new(-2.2626677e-8, -1.0, 8.444392e-8);
        let v2 = Vec3::new(-4.371142e-8, -1.0, 7.5710325e-8);
        let o = Vec3::new(111.83738, -19.743622, 93.44603);
        let d = Vec3::new(-66.6212, 16.05118, -84.77757);
        assert!(hit(o, d, v0, v1 - v0, v2 - v0, 1.262138).is_none());
        // Woop's vertex-based edge functions reported t = 0.982 here, 6.9 units away.
        let v0 = Vec3::new(-4.0337796, -0.826272, -3.336366);
        let v1 = Vec3::new(-4.033781, -0.82627165, -3.3363657);
        let v2 = Vec3::new(-4.033777, -0.8262687, -3.3363643);
        let o = Vec3::new(-41.343082, -10.974098, -6.4295607);
        let d = Vec3::new(37.990543, 4.2473917, -0.38250345);
        assert!(hit(o, d, v0, v1 - v0, v2 - v0, f32::INFINITY).is_none());
    }
}

/// The stored form of a triangle: `[v0, e1 = v1 - v0, e2 = v2 - v0]`. Every consumer (blocks,
/// the brute-force reference) uses this function so that all of them intersect the same numbers.
pub fn tri_lane(v0: Vec3, v1: Vec3, v2: Vec3) -> [Vec3; 3] {
    [v0, v1 - v0, v2 - v0]
}
