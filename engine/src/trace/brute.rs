//! Brute-force reference: every triangle of every instance, no tree. For tests and for checking
//! a build; O(triangles) per ray.
//!
//! Input: the original meshes (positions + index triples) and the instances (transforms, which
//! mesh each one shows). Output: the same [`Hit`] the tree traversals return: the same ray
//! transform ([`to_object_space`]), the same stored triangle form ([`tri_lane`]) and the same
//! triangle test, so `t`, `u`, `v` agree bit for bit. Any thread. Must not: read BVH data.

use glam::Vec3;

use super::ray::{Hit, Ray, to_object_space};
use super::triangle::tri_lane;
use super::triangle::{TriRay, intersect_triangle};
use crate::layout::{GpuInstance, INVALID};

/// A mesh as the BLAS builder (`accel::build_blas`) takes it.
#[derive(Clone, Copy, Debug)]
pub struct BruteMesh<'a> {
    pub positions: &'a [Vec3],
    pub triangles: &'a [[u32; 3]],
}

/// An instance: its transform and flags (as in the scene) and the index of its mesh.
#[derive(Clone, Copy, Debug)]
pub struct BruteInstance {
    pub instance: GpuInstance,
    pub mesh: usize,
}

/// Closest hit over all triangles of one mesh in its own space (`instance` = `INVALID`).
/// Triangles with an out-of-range index or a non-finite vertex are skipped, as the builder does.
pub fn closest_brute_mesh(mesh: &BruteMesh, ray: &Ray) -> Option<Hit> {
    super::scalar::with_fma(|| brute_mesh(mesh, ray))
}

#[inline(always)]
fn brute_mesh(mesh: &BruteMesh, ray: &Ray) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    let tri_ray = TriRay::new(ray.origin, ray.direction);
    for (index, t) in mesh.triangles.iter().enumerate() {
        let vertex = |i: u32| {
            mesh.positions
                .get(i as usize)
                .copied()
                .filter(|p| p.is_finite())
        };
        let (Some(a), Some(b), Some(c)) = (vertex(t[0]), vertex(t[1]), vertex(t[2])) else {
            continue;
        };
        let [v0, e1, e2] = tri_lane(a, b, c);
        let t_max = best.map_or(ray.t_max, |h| h.t);
        if let Some((t, u, v)) = intersect_triangle(v0, e1, e2, &tri_ray, ray.t_min, t_max) {
            best = Some(Hit {
                t,
                u,
                v,
                instance: INVALID,
                triangle: index as u32,
            });
        }
    }
    best
}

/// Closest hit over all instances (world-space ray).
pub fn closest_brute(meshes: &[BruteMesh], instances: &[BruteInstance], ray: &Ray) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for (index, inst) in instances.iter().enumerate() {
        let Some(mesh) = meshes.get(inst.mesh) else {
            continue;
        };
        let mut local = to_object_space(&inst.instance, ray);
        local.t_max = best.map_or(ray.t_max, |h| h.t);
        if let Some(hit) = closest_brute_mesh(mesh, &local) {
            best = Some(Hit {
                instance: index as u32,
                ..hit
            });
        }
    }
    best
}

/// Whether any triangle of any instance is hit.
pub fn occluded_brute(meshes: &[BruteMesh], instances: &[BruteInstance], ray: &Ray) -> bool {
    closest_brute(meshes, instances, ray).is_some()
}
