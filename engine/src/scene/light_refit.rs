//! Refitting the light table and its tree after emissive instances moved rigidly: the moved
//! triangles' corners are transformed again and the tree's boxes and normal cones are
//! recomputed from the changed leaves up to the root, instead of rebuilding both.
//!
//! Owns: [`refit_lights`]. A rigid motion keeps every triangle's area, so its power, the alias
//! table and the tree's topology stay valid; only positions, boxes and cones change. Sampling
//! and the MIS probabilities read the same refitted nodes, so the estimate stays unbiased; only
//! the tree's split quality can drift as emitters travel far from where it was built. A
//! triangle whose area changed (a scale) makes the refit give up, and the caller rebuilds. Any
//! thread (a pure function over plain data; the upkeep calls it on the main thread).
//! Must not: change a light's power, the alias table, the tree's shape or the hit lookup.

use glam::Vec3;

use super::light_tree::{LightBounds, leaf_of};
use super::lights::{LightTable, world_point};
use crate::layout::{GpuInstance, GpuLight, GpuLightNode, GpuTriangle, GpuVertex, INVALID};

/// Largest relative change of a moved triangle's area that still counts as rigid (f32
/// round-off of a rotated or translated triangle stays far below it).
pub const RIGID_AREA_TOLERANCE: f32 = 1e-3;

/// The entries a refit changed, by index, in increasing order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LightRefit {
    pub lights: Vec<(u32, GpuLight)>,
    pub nodes: Vec<(u32, GpuLightNode)>,
}

impl LightRefit {
    /// Runs of consecutive indices: (first index, entries), for range writes.
    pub fn runs<T: Copy>(entries: &[(u32, T)]) -> Vec<(u32, Vec<T>)> {
        let mut runs: Vec<(u32, Vec<T>)> = Vec::new();
        for &(i, value) in entries {
            match runs.last_mut() {
                Some((first, data)) if *first + data.len() as u32 == i => data.push(value),
                _ => runs.push((i, vec![value])),
            }
        }
        runs
    }
}

fn area(p: [Vec3; 3]) -> f32 {
    0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length()
}

/// The lights of the instance rows `moved` (indices into `instances`, which already hold the
/// new transforms) placed again, and the tree refitted over them. `None` when a moved
/// triangle's area changed by more than [`RIGID_AREA_TOLERANCE`] or its data cannot be found:
/// the table must be rebuilt.
pub fn refit_lights(
    table: &LightTable,
    moved: &[u32],
    instances: &[GpuInstance],
    triangles: &[GpuTriangle],
    vertices: &[GpuVertex],
) -> Option<LightRefit> {
    let mut is_moved = vec![false; instances.len()];
    for &row in moved {
        *is_moved.get_mut(row as usize)? = true;
    }
    let count = (table.count as usize).min(table.lights.len());
    let nodes = &table.tree.nodes;
    let mut refit = LightRefit::default();
    let mut dirty = vec![false; nodes.len()];
    let mut leaves = Vec::new();
    for (index, light) in table.lights[..count].iter().enumerate() {
        let row = light.instance as usize;
        if !is_moved.get(row).copied().unwrap_or(false) {
            continue;
        }
        let instance = instances.get(row)?;
        let tri = triangles.get(instance.triangle_base as usize + light.triangle as usize)?;
        let mut p = [Vec3::ZERO; 3];
        for (corner, &i) in p.iter_mut().zip(&tri.indices) {
            let v = vertices.get((instance.vertex_base + i) as usize)?;
            *corner = world_point(instance, v.position);
        }
        let before = area([light.p0, light.p1, light.p2].map(Vec3::from));
        if !((area(p) - before).abs() <= RIGID_AREA_TOLERANCE * before) {
            return None;
        }
        let mut placed = *light;
        (placed.p0, placed.p1, placed.p2) = (p[0].to_array(), p[1].to_array(), p[2].to_array());
        refit.lights.push((index as u32, placed));
        let leaf = leaf_of(&table.tree.lookup, light.instance, light.triangle);
        if (leaf as usize) < nodes.len() {
            leaves.push((leaf, p));
            // Mark the leaf and its ancestors (stop at one already marked: its are too).
            let mut k = leaf;
            while k != INVALID && !dirty[k as usize] {
                dirty[k as usize] = true;
                k = nodes.get(k as usize).map_or(INVALID, |n| n.parent);
            }
        }
    }
    let mut next: Vec<GpuLightNode> = nodes.clone();
    for (leaf, p) in leaves {
        let old = &nodes[leaf as usize];
        let b = LightBounds::triangle(p, old.phi, LightBounds::from_node(old).two_sided);
        next[leaf as usize] = b.node(old.child, old.parent, true);
    }
    // Depth-first order puts children after their parent: walk back so both are done first.
    for k in (0..nodes.len()).rev() {
        if !dirty[k] {
            continue;
        }
        let old = nodes[k];
        if old.flags & crate::layout::LIGHT_NODE_LEAF == 0 {
            let first = LightBounds::from_node(next.get(k + 1)?);
            let second = LightBounds::from_node(next.get(old.child as usize)?);
            next[k] = first.union(second).node(old.child, old.parent, false);
        }
        refit.nodes.push((k as u32, next[k]));
    }
    refit.nodes.reverse();
    Some(refit)
}
