//! Rays, hits, and the per-ray values every traversal derives from a ray.
//!
//! Owns: [`Ray`], [`Hit`], the safe reciprocal and octant rules, and the object-space transform
//! of a ray for an instance. Pure value code, any thread. Must not: walk trees.

use glam::Vec3;

use crate::layout::{GpuInstance, INSTANCE_FLAG_IDENTITY};

/// A ray `origin + t · direction` for `t_min < t < t_max`. `direction` need not be unit length;
/// `t` is measured in units of `direction`. All components must be finite (NaN or infinite
/// values give unspecified results, never a panic). `t_min >= 0` is expected.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: Vec3,
    pub t_min: f32,
    pub direction: Vec3,
    pub t_max: f32,
}

impl Ray {
    /// A ray over `0 < t < +inf`.
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        Self {
            origin,
            t_min: 0.0,
            direction,
            t_max: f32::INFINITY,
        }
    }

    /// A ray over `t_min < t < t_max`.
    pub fn with_range(origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Self {
        Self {
            origin,
            t_min,
            direction,
            t_max,
        }
    }
}

/// The closest intersection of a ray. The hit point is `v0 + u·e1 + v·e2` of the triangle
/// (barycentric weights `(1-u-v, u, v)` of its vertices 0, 1, 2), `t` the ray parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
    /// Index into `TraceScene::instances` (`INVALID` for the single-BLAS entry points).
    pub instance: u32,
    /// Mesh-local triangle index (`GpuTri4::prim`).
    pub triangle: u32,
}

/// Direction components smaller than this in magnitude count as zero for the slab test.
pub const RCP_MIN_ABS: f32 = 1e-30;

/// What every slab test needs from a ray, computed once per ray (and per instance).
///
/// Per axis, near planes give `t = fma(plane, rcp, -near_orcp)` and far planes
/// `t = fma(plane, far_rcp, -far_sub)`: one fused multiply-add per plane, the far side already
/// widened. A slot is hit when `max(near_x, near_y, near_z, t_min) <= min(far_x, far_y, far_z,
/// far_limit(t_max))`, with `far_limit(t) = fma(t, ROBUST_FAR, margin)`.
///
/// Robustness: with u = 2⁻²⁴ and `O = max |origin·rcp|` over the non-zero axes, the fused form
/// errs by at most about `u·|t| + 3u·O` (rounding of `origin·rcp`, of `rcp`, of the result).
/// The far side is scaled by `ROBUST_FAR = 1 + 2⁻²¹` (folded into `far_rcp`) and shifted by
/// `margin = 2⁻²⁰·O` (folded into `far_sub = fma(origin·rcp, ROBUST_FAR, -margin)`), which
/// covers both with room to spare: a box that the exact ray touches within `[t_min, t_max]` is
/// never rejected (after Ize 2013, "Robust BVH Ray Traversal", extended for the absolute term).
/// Widening only ever admits more boxes.
///
/// Zero direction components (`|d| < RCP_MIN_ABS`, either sign) would give `0 · inf = NaN` for a
/// ray lying in a box face. Instead `rcp = ±1/RCP_MIN_ABS` (sign of `d`, `-0.0` negative) and the
/// origin is nudged by `δ = |o|·2⁻²⁰ + 1e-20` towards the far side for near planes and towards
/// the near side for far planes, so a face exactly at the origin's coordinate counts as inside
/// (`|t| >= δ·1e30`, far above the rounding of `o·1e30`). The slab is then `(-big, +big)` when
/// `min <= o <= max` (a box within δ of the ray counts as touched, which only costs a visit) and
/// empty otherwise. No NaN, no special case in the loop.
#[derive(Clone, Copy, Debug)]
pub struct SlabRay {
    /// Reciprocal direction for near planes.
    pub rcp: Vec3,
    /// `near_origin · rcp` (rounded), subtracted from `near_plane · rcp` in the fused form.
    pub near_orcp: Vec3,
    /// `rcp · ROBUST_FAR` (rounded), for far planes.
    pub far_rcp: Vec3,
    /// `fma(far_origin · rcp, ROBUST_FAR, -margin)`, subtracted from `far_plane · far_rcp`.
    pub far_sub: Vec3,
    /// Absolute widening of the far side (see above), ≥ 0.
    pub margin: f32,
    /// Bit 0/1/2 set when the x/y/z direction has its sign bit set (`-0.0` included).
    pub octant: u32,
}

impl SlabRay {
    #[inline(always)]
    pub fn new(origin: Vec3, direction: Vec3) -> Self {
        let mut rcp = Vec3::ZERO;
        let mut near_orcp = Vec3::ZERO;
        let mut far_orcp = Vec3::ZERO;
        let mut largest = 0.0f32;
        for axis in 0..3 {
            let (o, d) = (origin[axis], direction[axis]);
            if d.abs() < RCP_MIN_ABS {
                let sign = 1.0f32.copysign(d);
                let delta = o.abs() * (1.0 / 1_048_576.0) + 1e-20;
                rcp[axis] = sign * (1.0 / RCP_MIN_ABS);
                near_orcp[axis] = (o + sign * delta) * rcp[axis];
                far_orcp[axis] = (o - sign * delta) * rcp[axis];
            } else {
                rcp[axis] = 1.0 / d;
                near_orcp[axis] = o * rcp[axis];
                far_orcp[axis] = o * rcp[axis];
                largest = largest.max((o * rcp[axis]).abs());
            }
        }
        let margin = largest * (1.0 / 1_048_576.0);
        Self {
            rcp,
            near_orcp,
            far_rcp: rcp * ROBUST_FAR,
            far_sub: Vec3::from_array(far_orcp.to_array().map(|f| f.mul_add(ROBUST_FAR, -margin))),
            margin,
            octant: octant(direction),
        }
    }

    /// The widened far bound `fma(t, ROBUST_FAR, margin)` that the `t_max` lane of the slab
    /// test and stack culling compare entry distances against.
    #[inline(always)]
    pub fn far_limit(&self, t: f32) -> f32 {
        t.mul_add(ROBUST_FAR, self.margin)
    }
}

/// Octant of a direction: bit 0/1/2 set when x/y/z has its sign bit set (so `-0.0` counts as
/// negative, matching the sign of [`SlabRay::rcp`]).
#[inline(always)]
pub fn octant(d: Vec3) -> u32 {
    u32::from(d.x.is_sign_negative())
        | u32::from(d.y.is_sign_negative()) << 1
        | u32::from(d.z.is_sign_negative()) << 2
}

/// Relative widening of the far side of slab intervals (see [`SlabRay`]): 1 + 2⁻²¹.
pub const ROBUST_FAR: f32 = 1.0 + 4.0 * f32::EPSILON;

/// The ray in an instance's object space: `object_from_world` applied to the origin (as a point)
/// and to the direction (as a vector, not renormalised, so `t` stays the world `t`). Identity
/// instances return the ray unchanged. Every tracer calls this function, so all agree bit for bit.
#[inline(always)]
pub fn to_object_space(instance: &GpuInstance, ray: &Ray) -> Ray {
    if instance.flags & INSTANCE_FLAG_IDENTITY != 0 {
        return *ray;
    }
    let m = &instance.object_from_world;
    let (o, d) = (ray.origin, ray.direction);
    let point = |r: &[f32; 4]| r[0] * o.x + r[1] * o.y + r[2] * o.z + r[3];
    let vector = |r: &[f32; 4]| r[0] * d.x + r[1] * d.y + r[2] * d.z;
    Ray {
        origin: Vec3::new(point(&m[0]), point(&m[1]), point(&m[2])),
        t_min: ray.t_min,
        direction: Vec3::new(vector(&m[0]), vector(&m[1]), vector(&m[2])),
        t_max: ray.t_max,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slab_ray_zero_components_are_finite_and_signed() {
        let s = SlabRay::new(Vec3::new(2.0, 0.0, -3.0), Vec3::new(0.0, -0.0, 4.0));
        assert_eq!(s.octant, 0b010);
        assert!(s.rcp.x > 1e29 && s.rcp.y < -1e29 && s.rcp.z == 0.25);
        assert_eq!(s.near_orcp.z, -0.75);
        assert_eq!(s.margin, 0.75 / 1_048_576.0);
        assert!(s.far_sub.z < -0.75 && s.far_rcp.z > 0.25);
        // A box face exactly at the origin's x or y: inside, finite distances, never NaN.
        for plane in [f32::INFINITY, f32::NEG_INFINITY, 2.0, 5.0, 0.0] {
            for axis in 0..2 {
                let near = plane.mul_add(s.rcp[axis], -s.near_orcp[axis]);
                let far = plane.mul_add(s.far_rcp[axis], -s.far_sub[axis]);
                assert!(!near.is_nan() && !far.is_nan());
            }
        }
        // x: positive zero, face at x = 2 as min (near) and as max (far) plane.
        assert!(2.0f32.mul_add(s.rcp.x, -s.near_orcp.x) <= -1e10);
        assert!(2.0f32.mul_add(s.far_rcp.x, -s.far_sub.x) >= 1e10);
        // y: negative zero, near planes are max planes: face at y = 0.
        assert!(0.0f32.mul_add(s.rcp.y, -s.near_orcp.y) <= -1e10);
        assert!(0.0f32.mul_add(s.far_rcp.y, -s.far_sub.y) >= 1e10);
    }
}
