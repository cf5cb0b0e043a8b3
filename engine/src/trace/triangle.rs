//! The ray–triangle test every tracer uses: Möller–Trumbore (1997) on the stored form
//! `v0, e1 = v1 - v0, e2 = v2 - v0`, two-sided, with one division per triangle.
//!
//! Owns: the exact sequence of f32 operations. The SIMD kernels (`avx2.rs`, `avx512.rs`) repeat
//! it lane for lane without fused multiply-adds, so every tracer returns bit-identical `t`, `u`,
//! `v` for the same triangle and ray; the tests rely on that. Any thread. Must not: reorder or
//! fuse operations (Rust never contracts `a * b + c` into an FMA by itself).

use glam::Vec3;

use crate::layout::GpuTri4;

/// Intersection of the ray `o + t·d` with the triangle `(v0, e1, e2)`: `Some((t, u, v))` when
/// `u >= 0`, `v >= 0`, `u + v <= 1` and `t_min < t < t_max`. A degenerate triangle (zero
/// determinant: zero area, or a ray in its plane) gives infinite or NaN `u`, which every
/// comparison rejects, so there is no special case (and none in the SIMD twins).
#[inline(always)]
pub fn intersect_triangle(
    v0: Vec3,
    e1: Vec3,
    e2: Vec3,
    o: Vec3,
    d: Vec3,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    // p = d × e2, det = e1 · p
    let px = d.y * e2.z - d.z * e2.y;
    let py = d.z * e2.x - d.x * e2.z;
    let pz = d.x * e2.y - d.y * e2.x;
    let det = e1.x * px + e1.y * py + e1.z * pz;
    // s = o - v0, u = (s · p) / det
    let sx = o.x - v0.x;
    let sy = o.y - v0.y;
    let sz = o.z - v0.z;
    let u_num = sx * px + sy * py + sz * pz;
    // q = s × e1, v = (d · q) / det, t = (e2 · q) / det
    let qx = sy * e1.z - sz * e1.y;
    let qy = sz * e1.x - sx * e1.z;
    let qz = sx * e1.y - sy * e1.x;
    let v_num = d.x * qx + d.y * qy + d.z * qz;
    let t_num = e2.x * qx + e2.y * qy + e2.z * qz;
    let inv_det = 1.0 / det;
    let u = u_num * inv_det;
    let v = v_num * inv_det;
    let t = t_num * inv_det;
    let hit = u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > t_min && t < t_max;
    hit.then_some((t, u, v))
}

/// [`intersect_triangle`] on lane `lane` (0..4) of a block.
#[inline(always)]
pub fn intersect_lane(
    block: &GpuTri4,
    lane: usize,
    o: Vec3,
    d: Vec3,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let v0 = Vec3::new(block.v0_x[lane], block.v0_y[lane], block.v0_z[lane]);
    let e1 = Vec3::new(block.e1_x[lane], block.e1_y[lane], block.e1_z[lane]);
    let e2 = Vec3::new(block.e2_x[lane], block.e2_y[lane], block.e2_z[lane]);
    intersect_triangle(v0, e1, e2, o, d, t_min, t_max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_inside_misses_outside_and_degenerate() {
        let (v0, e1, e2) = (Vec3::ZERO, Vec3::X, Vec3::Y);
        let d = Vec3::new(0.0, 0.0, -2.0);
        let (t, u, v) =
            intersect_triangle(v0, e1, e2, Vec3::new(0.25, 0.5, 1.0), d, 0.0, 10.0).expect("hit");
        assert_eq!((t, u, v), (0.5, 0.25, 0.5));
        // Two-sided: from below too.
        assert!(intersect_triangle(v0, e1, e2, Vec3::new(0.2, 0.2, -1.0), -d, 0.0, 10.0).is_some());
        // Outside, behind, beyond t_max, zero area, parallel.
        assert!(intersect_triangle(v0, e1, e2, Vec3::new(0.8, 0.8, 1.0), d, 0.0, 10.0).is_none());
        assert!(intersect_triangle(v0, e1, e2, Vec3::new(0.2, 0.2, 1.0), -d, 0.0, 10.0).is_none());
        assert!(intersect_triangle(v0, e1, e2, Vec3::new(0.2, 0.2, 1.0), d, 0.0, 0.4).is_none());
        assert!(intersect_triangle(v0, e1, e1, Vec3::new(0.2, 0.0, 1.0), d, 0.0, 9.0).is_none());
        assert!(
            intersect_triangle(v0, e1, e2, Vec3::new(-1.0, 0.2, 0.0), Vec3::X, 0.0, 9.0).is_none()
        );
        // Unused block lanes never hit.
        let block = GpuTri4::EMPTY;
        assert!(intersect_lane(&block, 0, Vec3::ZERO, Vec3::Z, -1.0, 1.0).is_none());
    }
}
