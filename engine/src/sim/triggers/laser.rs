//! Laser beams: a beam leaves an entity, is traced by ray queries against the scene as of the
//! last commit (full detail, animated objects included), reflects off mirrors, refracts through
//! glass, and stops at anything else.
//!
//! Owns: the components [`LaserBeam`] (what the level declares) and [`LaserPath`] (the beam as
//! traced this step), and [`trace_laser`]. Main thread, fixed step. Must not: decide what a
//! beam does when it reaches something (trigger volumes read [`LaserPath`]).
//! Units: metres, world space, right-handed, +Y up.

use glam::{Mat4, Vec3};
use hecs::Entity;

use crate::query::{Optics, Queries};
use crate::trace::Ray;

/// Hits on the beam's own entity skipped before giving up (a beam starting inside its model).
const SELF_HITS: u32 = 4;

/// A laser on an entity: where it starts and where it points, in the entity's model space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaserBeam {
    /// Metres, model space.
    pub origin: Vec3,
    /// Model space, any length but zero.
    pub direction: Vec3,
    /// Most surfaces the beam turns at.
    pub max_reflections: u32,
    /// Total length, metres.
    pub max_length: f32,
}

/// The beam as traced in the last fixed step: `points[0]` is its start, each next point where
/// it turned or stopped (world space, metres).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LaserPath {
    pub points: Vec<Vec3>,
    /// The entity the beam stopped at (a receiver, a wall), if it hit one.
    pub stopped_at: Option<Entity>,
}

impl LaserPath {
    /// The straight pieces of the beam.
    pub fn segments(&self) -> impl Iterator<Item = (Vec3, Vec3)> + '_ {
        self.points.windows(2).map(|w| (w[0], w[1]))
    }
}

/// Snell refraction of unit `d` at a surface with unit normal `n` (either side), from outside
/// into a medium of index `ior` when `d` enters against `n`; total internal reflection
/// reflects.
fn refract(d: Vec3, n: Vec3, ior: f32) -> Vec3 {
    let entering = d.dot(n) < 0.0;
    let (n, eta) = if entering { (n, 1.0 / ior) } else { (-n, ior) };
    let cos_i = -d.dot(n);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t > 1.0 {
        return d - 2.0 * d.dot(n) * n;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    (eta * d + (eta * cos_i - cos_t) * n).normalize()
}

/// Traces `beam` placed by `world_from_model`, skipping hits on `own` (the emitter itself)
/// and passing through entities `passes` names (visible beams, see `beam_geometry`).
pub fn trace_laser(
    queries: &Queries<'_>,
    world_from_model: Mat4,
    beam: &LaserBeam,
    own: Entity,
    passes: impl Fn(Entity) -> bool,
) -> LaserPath {
    let mut origin = world_from_model.transform_point3(beam.origin);
    let mut direction = world_from_model
        .transform_vector3(beam.direction)
        .normalize_or_zero();
    let mut path = LaserPath {
        points: vec![origin],
        stopped_at: None,
    };
    if direction == Vec3::ZERO || !origin.is_finite() {
        return path;
    }
    let mut left = beam.max_length;
    let mut turns = 0;
    let mut self_hits = 0;
    while left > 0.0 {
        let ray = Ray::with_range(origin, direction, 1e-4, left);
        let Some(hit) = queries.closest_where(&ray, |e| !e.is_some_and(&passes)) else {
            path.points.push(origin + direction * left);
            return path;
        };
        let travelled = hit.t.max(0.0);
        left -= travelled;
        origin = hit.position;
        if hit.entity == Some(own) && self_hits < SELF_HITS {
            // Leaving the emitter's own model: go on from just past the surface.
            self_hits += 1;
            origin += direction * 1e-3;
            continue;
        }
        path.points.push(origin);
        if turns >= beam.max_reflections {
            path.stopped_at = hit.entity;
            return path;
        }
        let n = hit.geometric_normal;
        direction = match queries.optics(hit.material) {
            Optics::Mirror => (direction - 2.0 * direction.dot(n) * n).normalize_or_zero(),
            Optics::Glass { ior } => refract(direction, n, ior),
            Optics::Opaque => {
                path.stopped_at = hit.entity;
                return path;
            }
        };
        turns += 1;
        // Off the surface on the side the beam now travels.
        let side = if direction.dot(n) >= 0.0 { n } else { -n };
        origin += side * 1e-4 * (1.0 + origin.abs().max_element());
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refraction_obeys_snell_both_ways() {
        let n = Vec3::Y;
        let d = Vec3::new(0.6, -0.8, 0.0);
        let t = refract(d, n, 1.5);
        let sin_i = 0.6;
        let sin_t = t.x;
        assert!((sin_i - 1.5 * sin_t).abs() < 1e-5, "{t}");
        assert!(t.y < 0.0);
        // Out through the parallel far face (outward normal −Y): the direction it came in with.
        let out = refract(t, -n, 1.5);
        assert!((out - d).length() < 1e-5, "{out}");
    }

    #[test]
    fn total_internal_reflection_reflects() {
        let d = Vec3::new(0.9, (1.0f32 - 0.81).sqrt(), 0.0);
        // Inside glass going up towards the surface at a grazing angle.
        let r = refract(d, Vec3::Y, 1.5);
        assert!((r - Vec3::new(d.x, -d.y, 0.0)).length() < 1e-5, "{r}");
    }
}
