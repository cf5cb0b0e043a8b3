//! [`Queries`]: closest hit, occlusion and batches of rays on the game side's flattened scene.
//!
//! Owns: turning a traversal hit into what game code wants (entity, instance, triangle,
//! material, world position, normals, texture coordinates). Reads the `Upkeep`'s scene, which
//! holds the BVH of the last sealed commit while game rules run, so queries never wait for and
//! never disturb the render thread. Main thread (batches fan out over rayon).
//! Must not: modify the scene.

use glam::{Vec2, Vec3};
use hecs::Entity;
use rayon::prelude::*;

use crate::accel::Upkeep;
use crate::scene::surface::resolve;
use crate::scene::{Optics, optics_of};
use crate::trace::Ray;

/// Most refused hits [`Queries::closest_where`] passes through before giving up.
pub const MAX_PASSED: usize = 64;

/// What a query ray hit (world space, metres).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QueryHit {
    /// The entity whose instance was hit (`None` for instances placed without an entity).
    pub entity: Option<Entity>,
    pub instance: u32,
    /// Mesh-local triangle index.
    pub triangle: u32,
    /// Global material index (after the instance's override).
    pub material: u32,
    /// Distance along the ray in units of its direction.
    pub t: f32,
    pub position: Vec3,
    /// Unit front-face normal of the triangle.
    pub geometric_normal: Vec3,
    /// Unit interpolated vertex normal, on the geometric normal's side.
    pub shading_normal: Vec3,
    pub uv: Vec2,
}

/// Ray queries against an [`Upkeep`]'s scene.
#[derive(Clone, Copy)]
pub struct Queries<'a> {
    upkeep: &'a Upkeep,
}

impl Upkeep {
    /// Queries on the scene as of the last sealed commit.
    pub fn queries(&self) -> Queries<'_> {
        Queries { upkeep: self }
    }
}

impl Queries<'_> {
    /// `ray` (world space) in render space (world − the scene's origin, see `accel::origin`).
    fn to_render(&self, ray: &Ray) -> Ray {
        Ray {
            origin: ray.origin - self.upkeep.scene().origin,
            ..*ray
        }
    }

    /// Whether the scene holds no instance yet (the first fixed steps of a level run before
    /// its first commit): a ray then meets nothing, which says nothing about the world.
    pub fn is_empty(&self) -> bool {
        self.upkeep.scene().instances.is_empty()
    }

    /// The closest hit of `ray` (world space; `t_min < t < t_max`).
    pub fn closest(&self, ray: &Ray) -> Option<QueryHit> {
        let scene = self.upkeep.scene();
        let ray = &self.to_render(ray);
        let hit = scene.trace_scene().closest(ray)?;
        let surface = resolve(scene, &hit, ray.direction);
        Some(QueryHit {
            entity: self.upkeep.entity_of_instance(hit.instance),
            instance: hit.instance,
            triangle: hit.triangle,
            material: surface.material,
            t: hit.t,
            position: surface.position + scene.origin,
            geometric_normal: surface.geometric_normal,
            shading_normal: surface.shading_normal,
            uv: surface.uv,
        })
    }

    /// The closest hit of `ray` on an entity `accept` takes (instances without an entity are
    /// offered as `None`): hits it refuses are passed through, at most [`MAX_PASSED`] of them
    /// (then `None`). For things rays should not see, such as a laser's own visible beam.
    pub fn closest_where(
        &self,
        ray: &Ray,
        accept: impl Fn(Option<Entity>) -> bool,
    ) -> Option<QueryHit> {
        let mut ray = *ray;
        for _ in 0..=MAX_PASSED {
            let hit = self.closest(&ray)?;
            if accept(hit.entity) {
                return Some(hit);
            }
            // Strictly beyond the refused hit (`t_min < t`), same origin: nothing is lost to
            // moving the origin.
            ray.t_min = hit.t.max(ray.t_min);
        }
        None
    }

    /// What material `index` of the scene (as in [`QueryHit::material`]) does to an ideal ray
    /// such as a laser; an index the scene does not have is [`Optics::Opaque`].
    pub fn optics(&self, index: u32) -> Optics {
        self.upkeep
            .scene()
            .materials
            .get(index as usize)
            .map_or(Optics::Opaque, optics_of)
    }

    /// Whether anything blocks `ray` within `(t_min, t_max)`.
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.upkeep
            .scene()
            .trace_scene()
            .occluded(&self.to_render(ray))
    }

    /// [`Queries::closest`] for many rays at once, on all cores.
    pub fn closest_batch(&self, rays: &[Ray]) -> Vec<Option<QueryHit>> {
        rays.par_iter().map(|r| self.closest(r)).collect()
    }

    /// [`Queries::occluded`] for many rays at once, on all cores.
    pub fn occluded_batch(&self, rays: &[Ray]) -> Vec<bool> {
        rays.par_iter().map(|r| self.occluded(r)).collect()
    }
}
