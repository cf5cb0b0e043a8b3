//! Morph targets: displacements added to a primitive's base attributes, scaled by weights
//! (glTF 2.0 §3.7.2.2: `base + Σ w_k · delta_k`, deltas relative to the base).
//!
//! Owns: [`MorphTarget`], [`morph_positions`], [`morph_normals`], [`morph_tangents`].
//! Must not: read files or skin (morphing happens first, skinning after, as glTF orders them).
//! Units: position deltas in metres; normal and tangent deltas are unitless and the results
//! are renormalised.

use glam::{Vec3, Vec4};

/// One morph target of one primitive: per-vertex deltas (`None` where the file gives none,
/// which counts as zero).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MorphTarget {
    pub positions: Option<Vec<Vec3>>,
    pub normals: Option<Vec<Vec3>>,
    /// Tangent direction deltas (xyz; glTF morph tangents have no `w`).
    pub tangents: Option<Vec<Vec3>>,
}

/// Adds `Σ w_k · delta_k` to a copy of `base`, for the targets that have `deltas`. Zero
/// weights are skipped; missing weights count as zero.
fn morph<T>(
    base: &[T],
    targets: &[MorphTarget],
    weights: &[f32],
    deltas: impl Fn(&MorphTarget) -> Option<&Vec<Vec3>>,
    add: impl Fn(&mut T, Vec3),
) -> Vec<T>
where
    T: Copy,
{
    let mut out = base.to_vec();
    for (target, &weight) in targets.iter().zip(weights) {
        if weight == 0.0 {
            continue;
        }
        let Some(delta) = deltas(target) else {
            continue;
        };
        for (value, d) in out.iter_mut().zip(delta) {
            add(value, *d * weight);
        }
    }
    out
}

/// Morphed positions (metres).
pub fn morph_positions(base: &[Vec3], targets: &[MorphTarget], weights: &[f32]) -> Vec<Vec3> {
    morph(
        base,
        targets,
        weights,
        |t| t.positions.as_ref(),
        |v, d| *v += d,
    )
}

/// Morphed unit normals (a zero normal, "flat here", stays zero when nothing moves it).
pub fn morph_normals(base: &[Vec3], targets: &[MorphTarget], weights: &[f32]) -> Vec<Vec3> {
    let mut out = morph(
        base,
        targets,
        weights,
        |t| t.normals.as_ref(),
        |v, d| *v += d,
    );
    out.iter_mut().for_each(|n| *n = n.normalize_or_zero());
    out
}

/// Morphed unit tangents; `w` (handedness) is kept.
pub fn morph_tangents(base: &[Vec4], targets: &[MorphTarget], weights: &[f32]) -> Vec<Vec4> {
    let mut out = morph(
        base,
        targets,
        weights,
        |t| t.tangents.as_ref(),
        |v, d| *v += d.extend(0.0),
    );
    out.iter_mut()
        .for_each(|t| *t = t.truncate().normalize_or_zero().extend(t.w));
    out
}
