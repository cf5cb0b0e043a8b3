//! Picking: the ray from the camera through a point of the view ([`pixel_ray`], the same
//! mapping as `render::frame_uniforms` and the reference renders) and the level instance it
//! hits first ([`pick`], a ray query on the last sealed commit's scene, `query::Queries`).
//!
//! Main thread. Must not: modify the scene or the world. Entities that are not level
//! instances (beam prisms, characters' models) are passed through.

use glam::Vec3;
use hecs::Entity;

use crate::assets::CameraDesc;
use crate::query::Queries;
use crate::trace::Ray;

/// A pinhole camera's frame for a `width` × `height` view: eye, unit forward, right and up
/// (world space, right-handed), the tangent of half the vertical field of view and the aspect
/// ratio. One mapping for [`pixel_ray`] and its inverse, `app::edit::project`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewBasis {
    pub position: Vec3,
    pub forward: Vec3,
    pub right: Vec3,
    pub up: Vec3,
    pub tan_half: f32,
    pub aspect: f32,
}

impl ViewBasis {
    /// The frame of `camera` for a view of `width` × `height` (pixels or points).
    pub fn new(camera: &CameraDesc, width: f32, height: f32) -> Self {
        let position = Vec3::from(camera.position);
        let forward = (Vec3::from(camera.look_at) - position)
            .try_normalize()
            .unwrap_or(Vec3::NEG_Z);
        let right = forward
            .cross(Vec3::from(camera.up))
            .try_normalize()
            .unwrap_or_else(|| forward.any_orthonormal_vector());
        Self {
            position,
            forward,
            right,
            up: right.cross(forward),
            tan_half: (camera.vertical_fov_deg.clamp(1e-3, 179.0).to_radians() * 0.5).tan(),
            aspect: width.max(1e-3) / height.max(1e-3),
        }
    }
}

/// The ray (world space, unit direction, `t` in metres) from `camera`'s pinhole through the
/// point (`x`, `y`) of a `width` × `height` pixel view: pixels from the top-left corner, `y`
/// downward, pixel (i, j)'s centre at (i + 0.5, j + 0.5). The lens is ignored (a pick aims
/// through the centre of the lens).
pub fn pixel_ray(camera: &CameraDesc, width: u32, height: u32, x: f32, y: f32) -> Ray {
    let (w, h) = (width.max(1) as f32, height.max(1) as f32);
    let b = ViewBasis::new(camera, w, h);
    let sx = 2.0 * x / w - 1.0;
    let sy = 1.0 - 2.0 * y / h;
    let direction =
        (b.forward + b.right * (sx * b.tan_half * b.aspect) + b.up * (sy * b.tan_half)).normalize();
    Ray::new(b.position, direction)
}

/// What a pick hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Picked {
    /// Index of the instance in the level's instance list.
    pub instance: usize,
    /// World-space hit point, metres.
    pub position: Vec3,
    /// Distance along the ray, metres (for a unit direction).
    pub distance: f32,
}

/// The first level instance `ray` hits. `instances` holds the entity of each level instance
/// in the level's order (`app::SpawnedLevel::entities`); hits on other entities are passed
/// through.
pub fn pick(queries: &Queries<'_>, instances: &[Entity], ray: &Ray) -> Option<Picked> {
    let of = |e: Option<Entity>| e.and_then(|e| instances.iter().position(|&k| k == e));
    let hit = queries.closest_where(ray, |e| of(e).is_some())?;
    Some(Picked {
        instance: of(hit.entity)?,
        position: hit.position,
        distance: hit.t * ray.direction.length(),
    })
}
