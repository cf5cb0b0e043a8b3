//! Sampling the light tree (twin: `shaders/shared/light_tree.wgsl`), PBRT-v4's
//! `BVHLightSampler::Sample` and `PMF`.
//!
//! Owns: a node's importance from a shading point (PBRT-v4's `LightBounds::Importance`), picking
//! one light with one uniform number by a walk from the root (the number is rescaled at each
//! node so that it stays uniform), and the exact probability of any light from the same point
//! (the walk up from its leaf), which MIS needs when a BSDF ray hits an emitter. Points are in
//! render space (metres); `n` is the shading normal, or zero away from surfaces.
//! Must not: build the tree (`scene::light_tree`) or sample points on lights (the integrator).

use glam::Vec3;

use crate::layout::{GpuLightNode, INVALID, LIGHT_NODE_LEAF, LIGHT_NODE_TWO_SIDED};

/// The largest f32 below 1.
const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// Deepest walk [`pmf`] follows (the tree is far shallower; this only stops bad data).
const MAX_WALK: u32 = 128;

#[inline]
fn safe_sqrt(x: f32) -> f32 {
    x.max(0.0).sqrt()
}

/// cos(max(0, θ_a − θ_b)) from the sines and cosines.
#[inline]
fn cos_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if cos_a > cos_b {
        1.0
    } else {
        cos_a * cos_b + sin_a * sin_b
    }
}

/// sin(max(0, θ_a − θ_b)) from the sines and cosines.
#[inline]
fn sin_sub_clamped(sin_a: f32, cos_a: f32, sin_b: f32, cos_b: f32) -> f32 {
    if cos_a > cos_b {
        0.0
    } else {
        sin_a * cos_b - cos_a * sin_b
    }
}

/// How much the emitters under `node` may light point `p` with normal `n` (PBRT-v4's
/// `LightBounds::Importance`): φ × the largest cosine at the emitters over the box × the
/// largest |cos| at `p` / the clamped squared distance to the box centre. Zero only where no
/// emitter below can reach `p`; relative units.
pub fn importance(node: &GpuLightNode, p: Vec3, n: Vec3) -> f32 {
    if !(node.phi > 0.0) {
        return 0.0;
    }
    let min = Vec3::from(node.bounds_min);
    let max = Vec3::from(node.bounds_max);
    let pc = (min + max) * 0.5;
    let d2 = p.distance_squared(pc).max((max - min).length() * 0.5);
    let to_p = p - pc;
    let len2 = to_p.length_squared();
    let wi = if len2 > 0.0 {
        to_p / len2.sqrt()
    } else {
        Vec3::ZERO
    };
    let mut cos_w = Vec3::from(node.axis).dot(wi);
    if node.flags & LIGHT_NODE_TWO_SIDED != 0 {
        cos_w = cos_w.abs();
    }
    let sin_w = safe_sqrt(1.0 - cos_w * cos_w);
    // The cone of directions from p to the box's bounding sphere.
    let radius2 = (max - pc).length_squared();
    let cos_b = if len2 < radius2 {
        -1.0
    } else {
        safe_sqrt(1.0 - radius2 / len2)
    };
    let sin_b = safe_sqrt(1.0 - cos_b * cos_b);
    let cos_o = node.cos_theta_o;
    let sin_o = safe_sqrt(1.0 - cos_o * cos_o);
    let cos_x = cos_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    let sin_x = sin_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    let cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
    if cos_p <= node.cos_theta_e {
        return 0.0;
    }
    let mut importance = node.phi * cos_p / d2;
    if n != Vec3::ZERO {
        let cos_i = wi.dot(n).abs();
        let sin_i = safe_sqrt(1.0 - cos_i * cos_i);
        importance *= cos_sub_clamped(sin_i, cos_i, sin_b, cos_b);
    }
    if importance.is_finite() {
        importance.max(0.0)
    } else {
        0.0
    }
}

/// Picks a light for point `p` (normal `n`) with one uniform number `u` in [0, 1): its index in
/// the light table and the probability it was picked with; `None` when no light can reach
/// `p`. `count` is the number of real lights (leaves naming another index are refused).
pub fn sample(nodes: &[GpuLightNode], count: u32, p: Vec3, n: Vec3, u: f32) -> Option<(u32, f32)> {
    let mut index = 0usize;
    let mut pmf = 1.0f32;
    let mut u = u;
    for _ in 0..MAX_WALK {
        let node = nodes.get(index)?;
        if node.flags & LIGHT_NODE_LEAF != 0 {
            let reachable = index > 0 || importance(node, p, n) > 0.0;
            return (reachable && node.child < count).then_some((node.child, pmf));
        }
        let second = node.child as usize;
        let i0 = importance(nodes.get(index + 1)?, p, n);
        let i1 = importance(nodes.get(second)?, p, n);
        let sum = i0 + i1;
        if !(sum > 0.0) {
            return None;
        }
        let p0 = i0 / sum;
        if u < p0 {
            pmf *= p0;
            u = (u / p0).min(ONE_MINUS_EPSILON);
            index += 1;
        } else {
            let p1 = i1 / sum;
            pmf *= p1;
            u = ((u - p0) / p1).min(ONE_MINUS_EPSILON);
            index = second;
        }
    }
    None
}

/// The probability that [`sample`] picks the light of leaf `leaf` for point `p` (normal `n`);
/// 0 for [`INVALID`] or a light no walk can reach.
pub fn pmf(nodes: &[GpuLightNode], leaf: u32, p: Vec3, n: Vec3) -> f32 {
    let Some(node) = nodes.get(leaf as usize) else {
        return 0.0;
    };
    if leaf == 0 {
        return if importance(node, p, n) > 0.0 {
            1.0
        } else {
            0.0
        };
    }
    let mut pmf = 1.0f32;
    let mut index = leaf;
    let mut parent = node.parent;
    for _ in 0..MAX_WALK {
        if parent == INVALID {
            return pmf;
        }
        let Some(up) = nodes.get(parent as usize) else {
            return 0.0;
        };
        let (Some(first), Some(second)) =
            (nodes.get(parent as usize + 1), nodes.get(up.child as usize))
        else {
            return 0.0;
        };
        let i0 = importance(first, p, n);
        let i1 = importance(second, p, n);
        let sum = i0 + i1;
        if !(sum > 0.0) {
            return 0.0;
        }
        let mine = if index == parent + 1 { i0 } else { i1 };
        pmf *= mine / sum;
        index = parent;
        parent = up.parent;
    }
    0.0
}
