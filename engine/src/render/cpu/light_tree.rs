//! Sampling the light tree (twin: `shaders/shared/light_tree.wgsl`), PBRT-v4's
//! `BVHLightSampler::Sample` and `PMF`.
//!
//! Owns: a node's importance from a shading point (PBRT-v4's `LightBounds::Importance`, two
//! nodes at a time with their square roots in 4-wide instructions), picking
//! one light with one uniform number by a walk from the root (the number is rescaled at each
//! node so that it stays uniform), and the exact probability of any light from the same point
//! (the walk up from its leaf), which MIS needs when a BSDF ray hits an emitter. Points are in
//! render space (metres); `n` is the shading normal, or zero away from surfaces.
//! Must not: build the tree (`scene::light_tree`) or sample points on lights (the integrator).

use glam::{Vec3, Vec4};

use crate::layout::{GpuLightNode, INVALID, LIGHT_NODE_LEAF, LIGHT_NODE_TWO_SIDED};

/// The largest f32 below 1.
const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// Deepest walk [`pmf`] follows (the tree is far shallower; this only stops bad data).
const MAX_WALK: u32 = 128;

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

/// The quantities one node's importance reads from point `p` (normal `n`), before any square
/// root: gathered for two nodes at once so that their roots share 4-wide instructions.
struct Setup {
    phi: f32,
    /// |p − centre|², m².
    len2: f32,
    /// The box's bounding-sphere radius², m².
    r2: f32,
    /// axis · (p − centre), m (absolute for two-sided nodes).
    along_axis: f32,
    /// |n · (p − centre)|, m (0 without a normal).
    along_normal: f32,
    cos_o: f32,
    cos_e: f32,
}

impl Setup {
    #[inline(always)]
    fn new(node: &GpuLightNode, p: Vec3, n: Vec3) -> Self {
        let min = Vec3::from(node.bounds_min);
        let max = Vec3::from(node.bounds_max);
        let pc = (min + max) * 0.5;
        let to_p = p - pc;
        let mut along_axis = Vec3::from(node.axis).dot(to_p);
        if node.flags & LIGHT_NODE_TWO_SIDED != 0 {
            along_axis = along_axis.abs();
        }
        Setup {
            phi: node.phi,
            len2: to_p.length_squared(),
            r2: (max - pc).length_squared(),
            along_axis,
            along_normal: n.dot(to_p).abs(),
            cos_o: node.cos_theta_o,
            cos_e: node.cos_theta_e,
        }
    }

    /// The four square roots this node needs from `p`: |p − c|, and |p − c| times sin θ_w,
    /// cos θ_b and sin θ_i.
    #[inline(always)]
    fn radicands(&self) -> Vec4 {
        Vec4::new(
            self.len2,
            self.len2 - self.along_axis * self.along_axis,
            self.len2 - self.r2,
            self.len2 - self.along_normal * self.along_normal,
        )
        .max(Vec4::ZERO)
    }

    /// The importance from `roots` (the square roots of [`Setup::radicands`]), the bounding
    /// sphere's `radius` (m), sin θ_o, 1/|p − c| and 1/d² (the clamped squared distance).
    #[inline(always)]
    fn finish(
        &self,
        roots: Vec4,
        radius: f32,
        sin_o: f32,
        inv_len: f32,
        inv_d2: f32,
        normal: bool,
    ) -> f32 {
        if !(self.phi > 0.0) {
            return 0.0;
        }
        let importance = if self.len2 < self.r2 {
            // Inside the bounding sphere every direction may reach p: cos θ' = 1 and the
            // normal's factor 1 (θ_b = π).
            if 1.0 <= self.cos_e {
                return 0.0;
            }
            self.phi * inv_d2
        } else {
            let cos_w = self.along_axis * inv_len;
            let sin_w = roots.y * inv_len;
            let cos_b = roots.z * inv_len;
            let sin_b = radius * inv_len;
            let cos_x = cos_sub_clamped(sin_w, cos_w, sin_o, self.cos_o);
            let sin_x = sin_sub_clamped(sin_w, cos_w, sin_o, self.cos_o);
            let cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
            if !(cos_p > self.cos_e) {
                return 0.0;
            }
            let mut importance = self.phi * cos_p * inv_d2;
            if normal {
                let cos_i = self.along_normal * inv_len;
                let sin_i = roots.w * inv_len;
                importance *= cos_sub_clamped(sin_i, cos_i, sin_b, cos_b);
            }
            importance
        };
        if importance.is_finite() {
            importance.max(0.0)
        } else {
            0.0
        }
    }
}

/// Four square roots in one instruction where the target has one (bit for bit the scalar
/// `f32::sqrt` of each lane: both are IEEE-754 correctly rounded).
#[inline(always)]
fn sqrt4(v: Vec4) -> Vec4 {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: SSE is part of the x86_64 baseline, so the instruction always exists.
        Vec4::from(unsafe { core::arch::x86_64::_mm_sqrt_ps(v.into()) })
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        v.sqrt()
    }
}

/// How much the emitters under each of two nodes may light point `p` with normal `n`
/// (PBRT-v4's `LightBounds::Importance`): φ × the largest cosine at the emitters over the box ×
/// the largest |cos| at `p` / the clamped squared distance to the box centre. Zero only where
/// no emitter below can reach `p`; relative units. Each lane is that node's own importance,
/// whatever the other node is ([`importance`] is one lane), so a walk down and a walk up read
/// the same values.
///
/// The angles are PBRT's, but every sine and cosine is a root of a quantity known once
/// p − c is (|p − c|² − (axis · (p − c))² for sin θ_w, |p − c|² − r² for cos θ_b, ...), times
/// 1/|p − c|: the roots of both nodes go through three 4-wide square roots and one 4-wide
/// division instead of a chain of fifteen scalar ones (the walk's cost, `docs/PERFORMANCE.md`
/// "A cheaper light-tree walk").
#[inline(always)]
pub fn importance_pair(a: &GpuLightNode, b: &GpuLightNode, p: Vec3, n: Vec3) -> [f32; 2] {
    let normal = n != Vec3::ZERO;
    let (sa, sb) = (Setup::new(a, p, n), Setup::new(b, p, n));
    let ra = sqrt4(sa.radicands());
    let rb = sqrt4(sb.radicands());
    // Radius of each box's bounding sphere and sin θ_o of each cone.
    let node = sqrt4(
        Vec4::new(
            sa.r2,
            sb.r2,
            1.0 - sa.cos_o * sa.cos_o,
            1.0 - sb.cos_o * sb.cos_o,
        )
        .max(Vec4::ZERO),
    );
    // d² is |p − c|² clamped below by the radius (PBRT's: half the box's diagonal).
    let inv = Vec4::ONE / Vec4::new(ra.x, rb.x, sa.len2.max(node.x), sb.len2.max(node.y));
    [
        sa.finish(ra, node.x, node.z, inv.x, inv.z, normal),
        sb.finish(rb, node.y, node.w, inv.y, inv.w, normal),
    ]
}

/// The importance of one node (see [`importance_pair`]).
pub fn importance(node: &GpuLightNode, p: Vec3, n: Vec3) -> f32 {
    importance_pair(node, node, p, n)[0]
}

/// Asks for node `i`'s cache line ahead of its use (a hint: no effect on any value).
#[inline(always)]
fn prefetch(nodes: &[GpuLightNode], i: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(node) = nodes.get(i) {
        use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        // SAFETY: SSE is part of the x86_64 baseline, and a prefetch of a valid reference
        // reads nothing the program sees.
        unsafe { _mm_prefetch::<_MM_HINT_T0>((node as *const GpuLightNode).cast()) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (nodes, i);
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
        let (a, b) = (nodes.get(index + 1)?, nodes.get(second)?);
        // The next level reads two of these four: fetched while this level computes.
        for (child, first) in [(a, index + 2), (b, second + 1)] {
            if child.flags & LIGHT_NODE_LEAF == 0 {
                prefetch(nodes, first);
                prefetch(nodes, child.child as usize);
            }
        }
        let [i0, i1] = importance_pair(a, b, p, n);
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
        let [i0, i1] = importance_pair(first, second, p, n);
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
