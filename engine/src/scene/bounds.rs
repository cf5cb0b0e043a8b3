//! Axis-aligned bounding boxes in any one space (object or world), metres.
//!
//! Owns: [`Aabb`], the box type of the acceleration-structure API (`build_blas` returns one,
//! `build_tlas` takes one per instance). Pure value code: no allocation, any thread.
//! Must not: know about BVH layouts or tracers.

use glam::{Mat4, Vec3};

/// An axis-aligned box `min..=max` (metres). A box with any `min > max` component is empty;
/// [`Aabb::EMPTY`] is the canonical empty box (`min = +inf`, `max = -inf`), the identity of
/// [`Aabb::union`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Default for Aabb {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl Aabb {
    /// The empty box: contains nothing, `EMPTY.union(b) == b`.
    pub const EMPTY: Self = Self {
        min: Vec3::INFINITY,
        max: Vec3::NEG_INFINITY,
    };

    /// The box `min..=max`, taken as given (no reordering).
    pub const fn new(min: Vec3, max: Vec3) -> Self {
        Self { min, max }
    }

    /// The smallest box containing every point (empty for no points).
    pub fn from_points(points: impl IntoIterator<Item = Vec3>) -> Self {
        points.into_iter().fold(Self::EMPTY, Self::grow)
    }

    /// This box grown to contain `point`.
    #[must_use]
    pub fn grow(self, point: Vec3) -> Self {
        Self {
            min: self.min.min(point),
            max: self.max.max(point),
        }
    }

    /// The smallest box containing both boxes.
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// True when the box contains no point (some `min > max`, or a NaN bound).
    pub fn is_empty(&self) -> bool {
        !(self.min.cmple(self.max).all())
    }

    /// True when the box is non-empty and all six bounds are finite.
    pub fn is_finite(&self) -> bool {
        !self.is_empty() && self.min.is_finite() && self.max.is_finite()
    }

    /// Edge lengths (metres); zero for an empty box.
    pub fn extent(&self) -> Vec3 {
        if self.is_empty() {
            Vec3::ZERO
        } else {
            self.max - self.min
        }
    }

    /// Centre point; meaningless (non-finite) for an empty box.
    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Surface area in square metres; zero for an empty box.
    pub fn surface_area(&self) -> f32 {
        let e = self.extent();
        2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
    }

    /// The box of this box's eight corners after the affine transform `m` (for example
    /// `world_from_object`); the result contains the transformed box. Empty stays empty.
    /// Uses Arvo's method (1990): per output axis, sum the smaller and larger products.
    #[must_use]
    pub fn transformed(&self, m: &Mat4) -> Self {
        if self.is_empty() {
            return Self::EMPTY;
        }
        let t = m.w_axis.truncate();
        let (mut min, mut max) = (t, t);
        for (axis, col) in [m.x_axis, m.y_axis, m.z_axis].iter().enumerate() {
            let a = col.truncate() * self.min[axis];
            let b = col.truncate() * self.max[axis];
            min += a.min(b);
            max += a.max(b);
        }
        Self { min, max }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Quat;

    #[test]
    fn union_area_and_empty() {
        let a = Aabb::new(Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(Aabb::EMPTY.union(a), a);
        assert!(Aabb::EMPTY.is_empty());
        assert!(!a.is_empty());
        assert_eq!(a.surface_area(), 2.0 * (2.0 + 6.0 + 3.0));
        assert_eq!(Aabb::EMPTY.surface_area(), 0.0);
        let b = Aabb::from_points([Vec3::splat(-1.0), Vec3::new(0.5, 4.0, 0.0)]);
        let u = a.union(b);
        assert_eq!(u.min, Vec3::splat(-1.0));
        assert_eq!(u.max, Vec3::new(1.0, 4.0, 3.0));
    }

    #[test]
    fn transform_contains_every_corner() {
        let a = Aabb::new(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(3.0, 1.0, 2.5));
        let m = Mat4::from_scale_rotation_translation(
            Vec3::new(2.0, 0.5, 3.0),
            Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0),
            Vec3::new(10.0, -4.0, 1.0),
        );
        let t = a.transformed(&m);
        let mut exact = Aabb::EMPTY;
        for i in 0..8 {
            let c = Vec3::new(
                if i & 1 == 0 { a.min.x } else { a.max.x },
                if i & 2 == 0 { a.min.y } else { a.max.y },
                if i & 4 == 0 { a.min.z } else { a.max.z },
            );
            exact = exact.grow(m.transform_point3(c));
        }
        assert!((t.min - exact.min).abs().max_element() < 1e-4);
        assert!((t.max - exact.max).abs().max_element() < 1e-4);
        assert!(Aabb::EMPTY.transformed(&m).is_empty());
    }
}
