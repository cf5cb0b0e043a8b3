//! The light tree: a BVH over the emissive triangles, in the manner of PBRT-v4's
//! `BVHLightSampler` (Pharr, Jakob & Humphreys, *Physically Based Rendering*, 4th ed., §12.6.3).
//!
//! Owns: building [`LightTree`] from the light table's triangles — each node's render-space
//! box, power and normal cone ([`LightBounds`], their union and the cone union), the split by
//! PBRT's surface-area-orientation heuristic over 12 buckets per axis — and the lookup from a
//! hit (instance, mesh-local triangle) to its leaf, so that the exact probability of a light an
//! emitter hit stands for can be computed for MIS. Built with the light table (whenever it is
//! rebuilt: emitters moved, light groups switched) and carried in the commit with it. Any
//! thread (pure functions over plain data).
//! Must not: sample (the tracers do: `render::cpu::light_tree` and its WGSL twin) or know
//! materials beyond what the light table passes in.

use glam::Vec3;

use super::bounds::Aabb;
use crate::layout::{GpuLight, GpuLightNode, INVALID, LIGHT_NODE_LEAF, LIGHT_NODE_TWO_SIDED};

/// Splits by the bucketed heuristic up to this depth; deeper (a pathological distribution)
/// halves by count, so the tree is at most this plus log2(lights) deep.
const SAH_DEPTH: u32 = 40;

/// Buckets per axis of the split heuristic (PBRT's 12).
const BUCKETS: usize = 12;

/// The light tree: nodes in depth-first order (the root at 0, an interior node's first child
/// right after it) and the hit lookup.
#[derive(Clone, Debug, PartialEq)]
pub struct LightTree {
    /// Never empty: without lights, one leaf of zero power whose `child` is [`INVALID`].
    pub nodes: Vec<GpuLightNode>,
    /// `lookup[0]` = n instances covered; `lookup[1 + i]` = where instance `i`'s table starts
    /// in this same vector ([`INVALID`]: the instance has no light); an instance's table holds,
    /// per mesh-local triangle, its leaf node index or [`INVALID`].
    pub lookup: Vec<u32>,
}

impl Default for LightTree {
    fn default() -> Self {
        LightTree {
            nodes: vec![empty_leaf()],
            lookup: vec![0],
        }
    }
}

fn empty_leaf() -> GpuLightNode {
    GpuLightNode {
        bounds_min: [0.0; 3],
        phi: 0.0,
        bounds_max: [0.0; 3],
        cos_theta_o: 1.0,
        axis: [0.0, 1.0, 0.0],
        cos_theta_e: 0.0,
        child: INVALID,
        parent: INVALID,
        flags: LIGHT_NODE_LEAF,
        _padding: 0,
    }
}

/// What bounds a set of emitters (PBRT-v4's `LightBounds`): box, power, normal cone
/// (`axis`, cos θ_o), emission spread cos θ_e, and whether any emits from both faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightBounds {
    pub bounds: Aabb,
    pub axis: Vec3,
    pub phi: f32,
    pub cos_theta_o: f32,
    pub cos_theta_e: f32,
    pub two_sided: bool,
}

impl LightBounds {
    /// The bounds of one emissive triangle of power `phi` (its normal from the winding).
    pub fn triangle(p: [Vec3; 3], phi: f32, two_sided: bool) -> Self {
        let normal = (p[1] - p[0])
            .cross(p[2] - p[0])
            .try_normalize()
            .unwrap_or(Vec3::Y);
        LightBounds {
            bounds: Aabb::from_points(p),
            axis: normal,
            phi,
            cos_theta_o: 1.0,
            cos_theta_e: 0.0,
            two_sided,
        }
    }

    /// The bounds of both (PBRT-v4's `Union(LightBounds, LightBounds)`).
    pub fn union(self, other: Self) -> Self {
        if self.phi == 0.0 {
            return other;
        }
        if other.phi == 0.0 {
            return self;
        }
        let (axis, cos_theta_o) = cone_union(
            (self.axis, self.cos_theta_o),
            (other.axis, other.cos_theta_o),
        );
        LightBounds {
            bounds: self.bounds.union(other.bounds),
            axis,
            phi: self.phi + other.phi,
            cos_theta_o,
            cos_theta_e: self.cos_theta_e.min(other.cos_theta_e),
            two_sided: self.two_sided || other.two_sided,
        }
    }

    /// The bounds a node stores (the inverse of [`LightBounds::node`]).
    pub fn from_node(n: &GpuLightNode) -> Self {
        LightBounds {
            bounds: Aabb {
                min: Vec3::from(n.bounds_min),
                max: Vec3::from(n.bounds_max),
            },
            axis: Vec3::from(n.axis),
            phi: n.phi,
            cos_theta_o: n.cos_theta_o,
            cos_theta_e: n.cos_theta_e,
            two_sided: n.flags & LIGHT_NODE_TWO_SIDED != 0,
        }
    }

    /// The node holding these bounds (`child`: second child, or light index for a leaf).
    pub fn node(&self, child: u32, parent: u32, leaf: bool) -> GpuLightNode {
        GpuLightNode {
            bounds_min: self.bounds.min.to_array(),
            phi: self.phi,
            bounds_max: self.bounds.max.to_array(),
            cos_theta_o: self.cos_theta_o,
            axis: self.axis.to_array(),
            cos_theta_e: self.cos_theta_e,
            child,
            parent,
            flags: if leaf { LIGHT_NODE_LEAF } else { 0 }
                | if self.two_sided {
                    LIGHT_NODE_TWO_SIDED
                } else {
                    0
                },
            _padding: 0,
        }
    }
}

/// The smallest cone around both cones (axis, cos half-angle); PBRT-v4's
/// `Union(DirectionCone, DirectionCone)`. The whole sphere is (any axis, −1).
pub fn cone_union(a: (Vec3, f32), b: (Vec3, f32)) -> (Vec3, f32) {
    // Fast paths (no trigonometry): equal cones (the triangles of one flat panel), or one
    // already the whole sphere.
    if a == b || a.1 <= -1.0 {
        return a;
    }
    if b.1 <= -1.0 {
        return b;
    }
    let theta_a = a.1.clamp(-1.0, 1.0).acos();
    let theta_b = b.1.clamp(-1.0, 1.0).acos();
    let theta_d = a.0.dot(b.0).clamp(-1.0, 1.0).acos();
    let pi = std::f32::consts::PI;
    if (theta_d + theta_b).min(pi) <= theta_a {
        return a;
    }
    if (theta_d + theta_a).min(pi) <= theta_b {
        return b;
    }
    let theta_o = (theta_a + theta_d + theta_b) / 2.0;
    if theta_o >= pi {
        return (a.0, -1.0);
    }
    let theta_r = theta_o - theta_a;
    let Some(wr) = a.0.cross(b.0).try_normalize() else {
        return (a.0, -1.0);
    };
    let axis = glam::Quat::from_axis_angle(wr, theta_r) * a.0;
    (axis.normalize_or(a.0), theta_o.cos())
}

/// PBRT-v4's `EvaluateCost`: power × the solid-angle measure of the cone grown by θ_e ×
/// the box's surface area, the box stretched (`Kr`) when split along a short axis.
fn cost(b: &LightBounds, parent: &Aabb, dim: usize) -> f32 {
    let pi = std::f32::consts::PI;
    let theta_o = b.cos_theta_o.clamp(-1.0, 1.0).acos();
    let theta_e = b.cos_theta_e.clamp(-1.0, 1.0).acos();
    let theta_w = (theta_o + theta_e).min(pi);
    let sin_theta_o = (1.0 - b.cos_theta_o * b.cos_theta_o).max(0.0).sqrt();
    let m_omega = 2.0 * pi * (1.0 - b.cos_theta_o)
        + pi / 2.0
            * (2.0 * theta_w * sin_theta_o
                - (theta_o - 2.0 * theta_w).cos()
                - 2.0 * theta_o * sin_theta_o
                + b.cos_theta_o);
    let d = parent.extent();
    let kr = if d[dim] > 0.0 {
        d.max_element() / d[dim]
    } else {
        1.0
    };
    b.phi * m_omega * kr * b.bounds.surface_area()
}

/// Builds the tree over `lights` (the real ones: `lights.len()` = the table's `count`), with
/// each light's power `phi[i]` and two-sidedness; `triangle_counts[i]` is the triangle count of
/// instance `i`'s mesh and `instances` the instance count (for the hit lookup).
pub fn build_tree(
    lights: &[GpuLight],
    phi: &[f32],
    two_sided: &[bool],
    instances: usize,
    triangle_counts: &[u32],
) -> LightTree {
    let mut items: Vec<(LightBounds, u32)> = lights
        .iter()
        .enumerate()
        .filter_map(|(i, l)| {
            let power = phi.get(i).copied().unwrap_or(0.0);
            let sided = two_sided.get(i).copied().unwrap_or(false);
            let p = [l.p0, l.p1, l.p2].map(Vec3::from);
            let b = LightBounds::triangle(p, power, sided);
            (power > 0.0 && power.is_finite() && b.bounds.is_finite()).then_some((b, i as u32))
        })
        .collect();
    if items.is_empty() {
        return LightTree::default();
    }
    let mut nodes = Vec::with_capacity(2 * items.len());
    let mut leaf_of = vec![INVALID; lights.len()];
    build_node(&mut items, 0, INVALID, &mut nodes, &mut leaf_of);
    let lookup = build_lookup(lights, &leaf_of, instances, triangle_counts);
    LightTree { nodes, lookup }
}

/// Builds the subtree over `items` at `nodes.len()`; returns its bounds.
fn build_node(
    items: &mut [(LightBounds, u32)],
    depth: u32,
    parent: u32,
    nodes: &mut Vec<GpuLightNode>,
    leaf_of: &mut [u32],
) -> LightBounds {
    let index = nodes.len() as u32;
    if let [(bounds, light)] = items {
        nodes.push(bounds.node(*light, parent, true));
        leaf_of[*light as usize] = index;
        return *bounds;
    }
    let mid = split(items, depth);
    nodes.push(empty_leaf());
    let (left, right) = items.split_at_mut(mid);
    let a = build_node(left, depth + 1, index, nodes, leaf_of);
    let second = nodes.len() as u32;
    let b = build_node(right, depth + 1, index, nodes, leaf_of);
    let bounds = a.union(b);
    nodes[index as usize] = bounds.node(second, parent, false);
    bounds
}

/// Orders `items` and returns where the second child starts (1 ..= len − 1).
fn split(items: &mut [(LightBounds, u32)], depth: u32) -> usize {
    let n = items.len();
    let bounds = items
        .iter()
        .fold(Aabb::EMPTY, |a, (b, _)| a.union(b.bounds));
    let centroids = items
        .iter()
        .fold(Aabb::EMPTY, |a, (b, _)| a.grow(b.bounds.center()));
    let extent = centroids.extent();
    let bucket_of = |c: Vec3, dim: usize| -> usize {
        let offset = (c[dim] - centroids.min[dim]) / extent[dim];
        ((BUCKETS as f32 * offset) as usize).min(BUCKETS - 1)
    };
    let mut best: Option<(f32, usize, usize)> = None;
    if depth < SAH_DEPTH {
        for dim in 0..3 {
            if !(extent[dim] > 0.0) {
                continue;
            }
            let mut buckets: [Option<LightBounds>; BUCKETS] = [None; BUCKETS];
            for (b, _) in items.iter() {
                let k = bucket_of(b.bounds.center(), dim);
                buckets[k] = Some(match buckets[k] {
                    Some(acc) => acc.union(*b),
                    None => *b,
                });
            }
            for split_after in 0..BUCKETS - 1 {
                let side = |range: std::ops::Range<usize>| {
                    buckets[range]
                        .iter()
                        .flatten()
                        .copied()
                        .reduce(LightBounds::union)
                };
                let (Some(lo), Some(hi)) =
                    (side(0..split_after + 1), side(split_after + 1..BUCKETS))
                else {
                    continue;
                };
                let c = cost(&lo, &bounds, dim) + cost(&hi, &bounds, dim);
                if c > 0.0 && c.is_finite() && best.is_none_or(|(bc, _, _)| c < bc) {
                    best = Some((c, dim, split_after));
                }
            }
        }
    }
    if let Some((_, dim, split_after)) = best {
        let mut mid = 0;
        for i in 0..n {
            if bucket_of(items[i].0.bounds.center(), dim) <= split_after {
                items.swap(i, mid);
                mid += 1;
            }
        }
        if mid > 0 && mid < n {
            return mid;
        }
    }
    // Halve by count along the centroids' longest axis.
    let dim = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = n / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        a.0.bounds.center()[dim].total_cmp(&b.0.bounds.center()[dim])
    });
    mid
}

/// The hit lookup (see [`LightTree::lookup`]).
fn build_lookup(
    lights: &[GpuLight],
    leaf_of: &[u32],
    instances: usize,
    triangle_counts: &[u32],
) -> Vec<u32> {
    let mut lookup = vec![INVALID; 1 + instances];
    lookup[0] = instances as u32;
    for (light, &leaf) in lights.iter().zip(leaf_of) {
        let i = light.instance as usize;
        if leaf == INVALID || i >= instances {
            continue;
        }
        if lookup[1 + i] == INVALID {
            let count = triangle_counts.get(i).copied().unwrap_or(0) as usize;
            lookup[1 + i] = lookup.len() as u32;
            lookup.resize(lookup.len() + count, INVALID);
        }
        let slot = lookup[1 + i] as usize + light.triangle as usize;
        if let Some(entry) = lookup.get_mut(slot) {
            *entry = leaf;
        }
    }
    lookup
}

/// The leaf of the light on `triangle` (mesh-local) of `instance`, or [`INVALID`].
pub fn leaf_of(lookup: &[u32], instance: u32, triangle: u32) -> u32 {
    let covered = lookup.first().copied().unwrap_or(0);
    if instance >= covered {
        return INVALID;
    }
    match lookup.get(1 + instance as usize) {
        Some(&base) if base != INVALID => lookup
            .get(base as usize + triangle as usize)
            .copied()
            .unwrap_or(INVALID),
        _ => INVALID,
    }
}
