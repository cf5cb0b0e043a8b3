//! Collider shapes: boxes, spheres, capsules, convex hulls and triangle meshes, described in
//! engine types and checked before rapier ever sees them.
//!
//! Owns: [`ColliderShape`] (plain data, metres, in the body's frame: right-handed, +Y up),
//! its validation ([`ShapeError`]), building rapier's shared shape from it, and deriving hulls,
//! triangle meshes and bounding boxes from a [`Model`] (all its placed meshes, scaled).
//! Must not: create bodies or touch the ECS (see `bodies`).

use glam::{Mat4, Vec3};
use rapier3d::prelude::SharedShape;

use super::convert::points_to_rapier;
use crate::assets::Model;

/// A collider's geometry in its body's frame. Lengths in metres.
#[derive(Clone, Debug, PartialEq)]
pub enum ColliderShape {
    /// An axis-aligned box of the given half extents.
    Box {
        half_extents: Vec3,
    },
    Sphere {
        radius: f32,
    },
    /// A capsule along local +Y: a cylinder of length `2 · half_height` capped by hemispheres.
    Capsule {
        half_height: f32,
        radius: f32,
    },
    /// The convex hull of the points (at least four, not all in one plane).
    ConvexHull {
        points: Vec<Vec3>,
    },
    /// A triangle mesh (static geometry; counter-clockwise triangles seen from the front).
    Trimesh {
        vertices: Vec<Vec3>,
        triangles: Vec<[u32; 3]>,
    },
}

/// Why a shape cannot become a collider.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ShapeError {
    #[error("{what} must be positive and finite, not {value}")]
    NotPositive { what: &'static str, value: f32 },
    #[error("a point is not finite")]
    NotFinite,
    #[error("a convex hull needs at least 4 points not in one plane ({points} given)")]
    DegenerateHull { points: usize },
    #[error("a triangle mesh needs at least one triangle")]
    EmptyTrimesh,
    #[error("triangle {triangle} uses vertex {index}, but there are only {vertices}")]
    IndexOutOfRange {
        triangle: usize,
        index: u32,
        vertices: usize,
    },
    #[error("the triangle mesh is rejected: {0}")]
    Trimesh(String),
}

fn positive(what: &'static str, value: f32) -> Result<(), ShapeError> {
    if value > 0.0 && value.is_finite() {
        Ok(())
    } else {
        Err(ShapeError::NotPositive { what, value })
    }
}

impl ColliderShape {
    /// A cube of edge `edge_meters`.
    pub fn cube(edge_meters: f32) -> Self {
        Self::Box {
            half_extents: Vec3::splat(edge_meters * 0.5),
        }
    }

    /// Checks the numbers and builds rapier's shape (hulls are computed here).
    pub fn build(&self) -> Result<SharedShape, ShapeError> {
        match self {
            Self::Box { half_extents } => {
                positive("half extent x", half_extents.x)?;
                positive("half extent y", half_extents.y)?;
                positive("half extent z", half_extents.z)?;
                Ok(SharedShape::cuboid(
                    half_extents.x,
                    half_extents.y,
                    half_extents.z,
                ))
            }
            Self::Sphere { radius } => {
                positive("radius", *radius)?;
                Ok(SharedShape::ball(*radius))
            }
            Self::Capsule {
                half_height,
                radius,
            } => {
                positive("half height", *half_height)?;
                positive("radius", *radius)?;
                Ok(SharedShape::capsule_y(*half_height, *radius))
            }
            Self::ConvexHull { points } => {
                if !points.iter().all(|p| p.is_finite()) {
                    return Err(ShapeError::NotFinite);
                }
                let degenerate = ShapeError::DegenerateHull {
                    points: points.len(),
                };
                if points.len() < 4 || !spans_volume(points) {
                    return Err(degenerate);
                }
                SharedShape::convex_hull(&points_to_rapier(points)).ok_or(degenerate)
            }
            Self::Trimesh {
                vertices,
                triangles,
            } => {
                if triangles.is_empty() {
                    return Err(ShapeError::EmptyTrimesh);
                }
                if !vertices.iter().all(|p| p.is_finite()) {
                    return Err(ShapeError::NotFinite);
                }
                for (triangle, t) in triangles.iter().enumerate() {
                    if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                        return Err(ShapeError::IndexOutOfRange {
                            triangle,
                            index,
                            vertices: vertices.len(),
                        });
                    }
                }
                SharedShape::trimesh(points_to_rapier(vertices), triangles.clone())
                    .map_err(|e| ShapeError::Trimesh(format!("{e:?}")))
            }
        }
    }

    /// The convex hull of every vertex of `model`, scaled by `scale` (model space × scale).
    pub fn hull_of(model: &Model, scale: Vec3) -> Self {
        let (points, _) = model_geometry(model, scale, false);
        Self::ConvexHull { points }
    }

    /// Every triangle of `model`, scaled by `scale`.
    pub fn trimesh_of(model: &Model, scale: Vec3) -> Self {
        let (vertices, triangles) = model_geometry(model, scale, true);
        Self::Trimesh {
            vertices,
            triangles,
        }
    }

    /// The bounding box of `model` scaled by `scale`: the box and its centre in the body's
    /// frame (metres). `None` for a model without vertices.
    pub fn bounds_of(model: &Model, scale: Vec3) -> Option<(Self, Vec3)> {
        let (points, _) = model_geometry(model, scale, false);
        let first = *points.first()?;
        let (lo, hi) = points
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        let half_extents = (hi - lo) * 0.5;
        Some((Self::Box { half_extents }, (hi + lo) * 0.5))
    }
}

/// Whether `points` (finite, at least one) are not all on one plane, within a millionth of
/// their extent: parry would build a flat "hull" from them, which has no mass.
fn spans_volume(points: &[Vec3]) -> bool {
    let p0 = points[0];
    let farthest = |from: &dyn Fn(Vec3) -> f32| {
        points
            .iter()
            .copied()
            .max_by(|a, b| from(*a).total_cmp(&from(*b)))
            .unwrap_or(p0)
    };
    let p1 = farthest(&|p| (p - p0).length_squared());
    let extent = (p1 - p0).length();
    let axis = (p1 - p0).normalize_or_zero();
    let p2 = farthest(&|p| (p - p0).cross(axis).length_squared());
    let normal = (p1 - p0).cross(p2 - p0).normalize_or_zero();
    let p3 = farthest(&|p| (p - p0).dot(normal).abs());
    extent > 0.0 && (p3 - p0).dot(normal).abs() > extent * 1e-6
}

/// Vertices of all placed meshes of `model` in model space times `scale`, and (when asked)
/// their triangles with indices rebased into the combined vertex list.
fn model_geometry(model: &Model, scale: Vec3, triangles: bool) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let scaled = Mat4::from_scale(scale);
    let mut vertices = Vec::new();
    let mut out_triangles = Vec::new();
    for placement in &model.placements {
        let Some(mesh) = model.meshes.get(placement.mesh) else {
            continue;
        };
        let m = scaled * placement.model_from_mesh;
        let base = vertices.len() as u32;
        vertices.extend(mesh.positions.iter().map(|&p| m.transform_point3(p)));
        if triangles {
            out_triangles.extend(mesh.triangles.iter().map(|t| t.map(|i| i + base)));
        }
    }
    (vertices, out_triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_numbers_with_the_field_named() {
        let e = ColliderShape::Sphere { radius: -1.0 }.build().err();
        assert_eq!(
            e,
            Some(ShapeError::NotPositive {
                what: "radius",
                value: -1.0
            })
        );
        let flat = ColliderShape::ConvexHull {
            points: vec![Vec3::ZERO, Vec3::X, Vec3::Z, Vec3::ONE.with_y(0.0)],
        };
        assert!(matches!(
            flat.build(),
            Err(ShapeError::DegenerateHull { points: 4 })
        ));
        let bad_index = ColliderShape::Trimesh {
            vertices: vec![Vec3::ZERO, Vec3::X, Vec3::Z],
            triangles: vec![[0, 1, 3]],
        };
        assert!(matches!(
            bad_index.build(),
            Err(ShapeError::IndexOutOfRange { index: 3, .. })
        ));
    }

    #[test]
    fn builds_every_kind() {
        let shapes = [
            ColliderShape::cube(1.0),
            ColliderShape::Sphere { radius: 0.5 },
            ColliderShape::Capsule {
                half_height: 0.5,
                radius: 0.3,
            },
            ColliderShape::ConvexHull {
                points: vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z],
            },
            ColliderShape::Trimesh {
                vertices: vec![Vec3::ZERO, Vec3::X, Vec3::Z],
                triangles: vec![[0, 2, 1]],
            },
        ];
        for s in shapes {
            assert!(s.build().is_ok(), "{s:?}");
        }
    }
}
