//! Skinning: joint matrices from a pose, and linear blend skinning of positions, normals and
//! tangents with four influences per vertex.
//!
//! Owns: [`Skin`], [`Influence`], [`joint_matrices`], [`skin_vertices`]. Must not: read
//! files, sample clips, or touch BVHs (the deforming-mesh path takes the output as it is).
//!
//! glTF 2.0 §3.7.3: a joint's matrix is `world(joint) · inverseBind(joint)`, and a skinned
//! vertex is `Σ w_j · jointMatrix_j · p`, in the scene's space: the transform of the skinned
//! mesh's own node (and its parents) is ignored. Weights are scaled to sum to 1 (a vertex
//! with no weight follows joint 0), as three.js does on load. Normals transform by the
//! inverse transpose of the blended 3×3 (right under non-uniform scale) and are
//! renormalised; tangents transform by the blended 3×3, are renormalised, and keep their
//! handedness `w`, flipped where the blended matrix mirrors.
//!
//! Cost: sampling CesiumMan's 57 channels, its node matrices and skinning its 3273 vertices
//! with normals into mesh space (`deform::deform_mesh`) takes 0.19 ms per pose on one core
//! of the 2-core development machine (release build), so skinning stays single-threaded.

use glam::{Mat3, Mat4, Vec3, Vec4};

/// A skin: the joints (node indices) and their inverse bind matrices (metres).
#[derive(Clone, Debug, PartialEq)]
pub struct Skin {
    pub name: Option<String>,
    pub joints: Vec<usize>,
    /// One per joint; identity where the file gives none.
    pub inverse_bind_matrices: Vec<Mat4>,
}

/// The four joint influences of one vertex: indices into [`Skin::joints`] and weights that
/// sum to 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Influence {
    pub joints: [u16; 4],
    pub weights: [f32; 4],
}

impl Influence {
    /// An influence with `weights` scaled to sum to 1; all-zero weights give joint 0 weight 1.
    pub fn normalized(joints: [u16; 4], weights: [f32; 4]) -> Self {
        let sum: f32 = weights.iter().sum();
        if sum > 0.0 && sum.is_finite() {
            Self {
                joints,
                weights: weights.map(|w| w / sum),
            }
        } else {
            Self {
                joints,
                weights: [1.0, 0.0, 0.0, 0.0],
            }
        }
    }
}

/// `world(joint) · inverseBind(joint)` for every joint of `skin`, given the world matrices
/// of every node. A joint index outside `world` gives the identity (the loader refuses such
/// skins; this keeps a hand-built skin from panicking).
pub fn joint_matrices(skin: &Skin, world: &[Mat4]) -> Vec<Mat4> {
    skin.joints
        .iter()
        .enumerate()
        .map(|(j, &node)| {
            let joint_world = world.get(node).copied().unwrap_or(Mat4::IDENTITY);
            let inverse_bind = skin
                .inverse_bind_matrices
                .get(j)
                .copied()
                .unwrap_or(Mat4::IDENTITY);
            joint_world * inverse_bind
        })
        .collect()
}

/// Skinned vertices, in the scene's space.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SkinnedVertices {
    /// Metres.
    pub positions: Vec<Vec3>,
    /// Unit normals (zero stays zero: "flat here").
    pub normals: Option<Vec<Vec3>>,
    /// Unit tangents with handedness `w`.
    pub tangents: Option<Vec<Vec4>>,
}

/// Linear blend skinning of one primitive. `influences` has one entry per position;
/// `matrices` comes from [`joint_matrices`]. Vertices whose influences name a joint outside
/// `matrices` use the identity for it (the loader refuses such data).
pub fn skin_vertices(
    positions: &[Vec3],
    normals: Option<&[Vec3]>,
    tangents: Option<&[Vec4]>,
    influences: &[Influence],
    matrices: &[Mat4],
) -> SkinnedVertices {
    let blended: Vec<Mat4> = influences
        .iter()
        .map(|influence| blend(influence, matrices))
        .collect();
    let matrix = |i: usize| blended.get(i).copied().unwrap_or(Mat4::IDENTITY);
    let positions = positions
        .iter()
        .enumerate()
        .map(|(i, &p)| matrix(i).transform_point3(p))
        .collect();
    let normals = normals.map(|normals| {
        normals
            .iter()
            .enumerate()
            .map(|(i, &n)| {
                let linear = Mat3::from_mat4(matrix(i));
                let det = linear.determinant();
                let normal_matrix = if det.abs() > f32::MIN_POSITIVE {
                    linear.inverse().transpose()
                } else {
                    linear
                };
                (normal_matrix * n).normalize_or_zero()
            })
            .collect()
    });
    let tangents = tangents.map(|tangents| {
        tangents
            .iter()
            .enumerate()
            .map(|(i, &t)| {
                let linear = Mat3::from_mat4(matrix(i));
                let direction = (linear * t.truncate()).normalize_or_zero();
                let w = if linear.determinant() < 0.0 {
                    -t.w
                } else {
                    t.w
                };
                direction.extend(w)
            })
            .collect()
    });
    SkinnedVertices {
        positions,
        normals,
        tangents,
    }
}

/// `Σ w_j · matrices[joint_j]` over the four influences (zero weights skipped).
fn blend(influence: &Influence, matrices: &[Mat4]) -> Mat4 {
    let mut sum = Mat4::ZERO;
    for (&joint, &weight) in influence.joints.iter().zip(&influence.weights) {
        if weight == 0.0 {
            continue;
        }
        let matrix = matrices
            .get(usize::from(joint))
            .copied()
            .unwrap_or(Mat4::IDENTITY);
        sum += matrix * weight;
    }
    sum
}
