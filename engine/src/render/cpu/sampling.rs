//! Sampling helpers of the path tracer (twin: `shaders/shared/sampling.wgsl`).
//!
//! Owns: orthonormal bases, hemisphere/cone/disc/triangle warps and their densities, the MIS
//! heuristic, luminance. All directions are unit vectors; densities are per steradian
//! (solid angle) unless a name says `_area`.
//! Must not: touch scene data or random state (callers pass the uniform numbers in).

use glam::{Vec2, Vec3};

pub const PI: f32 = std::f32::consts::PI;

pub use crate::scene::luminance;

/// An orthonormal basis (t, b, n) around unit `n` (Duff et al., "Building an Orthonormal Basis,
/// Revisited", JCGT 2017).
#[inline]
pub fn basis(n: Vec3) -> (Vec3, Vec3) {
    let sign = if n.z >= 0.0 { 1.0 } else { -1.0 };
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        Vec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// A local direction (z along `n`) to world space.
#[inline]
pub fn to_world(local: Vec3, t: Vec3, b: Vec3, n: Vec3) -> Vec3 {
    t * local.x + b * local.y + n * local.z
}

/// A world direction to the local frame (z along `n`).
#[inline]
pub fn to_local(v: Vec3, t: Vec3, b: Vec3, n: Vec3) -> Vec3 {
    Vec3::new(v.dot(t), v.dot(b), v.dot(n))
}

/// Cosine-weighted direction on the +z hemisphere; density `cos θ / π`.
#[inline]
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u.x).max(0.0).sqrt())
}

/// Uniform direction in the cone of half-angle `acos(cos_max)` around +z; density
/// `1 / (2π (1 − cos_max))`.
#[inline]
pub fn uniform_cone(u: Vec2, cos_max: f32) -> Vec3 {
    // 1 − cos is exact in f32 for cos ≥ 0.5; the sine from it keeps full precision for the
    // sun's and the moon's tiny cones, where 1 − cos² of a rounded cosine has a few hundred
    // levels (the disc's rim then gets a finite share of the samples).
    let one_minus_cos = u.x * (1.0 - cos_max);
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta)
}

/// Uniform point on the unit disc (concentric map, Shirley & Chiu 1997).
#[inline]
pub fn concentric_disc(u: Vec2) -> Vec2 {
    let a = 2.0 * u - Vec2::ONE;
    if a.x == 0.0 && a.y == 0.0 {
        return Vec2::ZERO;
    }
    let (r, phi) = if a.x.abs() > a.y.abs() {
        (a.x, (PI / 4.0) * (a.y / a.x))
    } else {
        (a.y, PI / 2.0 - (PI / 4.0) * (a.x / a.y))
    };
    Vec2::new(r * phi.cos(), r * phi.sin())
}

/// Uniform barycentric coordinates (b1, b2) on a triangle: the point is
/// `p0 + b1 (p1 − p0) + b2 (p2 − p0)`; density `1 / area`.
#[inline]
pub fn uniform_triangle(u: Vec2) -> Vec2 {
    let su = u.x.sqrt();
    Vec2::new(u.y * su, 1.0 - su)
}

/// Power heuristic (β = 2) weight of a strategy with density `a` against one with density `b`.
#[inline]
pub fn power_heuristic(a: f32, b: f32) -> f32 {
    let a2 = a * a;
    let b2 = b * b;
    if a2 + b2 > 0.0 && a2.is_finite() {
        a2 / (a2 + b2)
    } else if a2.is_infinite() {
        1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn basis_is_orthonormal() {
        for n in [
            Vec3::X,
            -Vec3::Z,
            Vec3::new(0.3, -0.5, 0.8).normalize(),
            Vec3::new(1e-7, 0.0, -1.0).normalize(),
        ] {
            let (t, b) = basis(n);
            for (x, y) in [(t, b), (t, n), (b, n)] {
                assert!(x.dot(y).abs() < 1e-5);
            }
            for v in [t, b] {
                assert!((v.length() - 1.0).abs() < 1e-5);
            }
            assert!((t.cross(b) - n).length() < 1e-5, "right-handed");
        }
    }

    #[test]
    fn warps_stay_in_their_domain() {
        for i in 0..64 {
            for j in 0..64 {
                let u = Vec2::new((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 64.0);
                let d = cosine_hemisphere(u);
                assert!(d.z >= 0.0 && (d.length() - 1.0).abs() < 1e-5);
                let c = uniform_cone(u, 0.9);
                assert!(c.z >= 0.9 - 1e-6 && (c.length() - 1.0).abs() < 1e-5);
                assert!(concentric_disc(u).length() <= 1.0 + 1e-6);
                let b = uniform_triangle(u);
                assert!(b.x >= 0.0 && b.y >= 0.0 && b.x + b.y <= 1.0 + 1e-6);
            }
        }
    }
}
