//! An animated model: what `gltf_anim` reads from a glTF file for animation — the node
//! hierarchy, skins, clips and per-primitive vertex data (base attributes, joint influences,
//! morph targets) — and the queries on it (clip lookup, poses at a time).
//!
//! Owns: [`AnimatedModel`], [`AnimMesh`], [`AnimPrimitive`]. Deforming vertices lives in
//! `deform`. Must not: read files, or know about BVHs or GPUs.
//! Units: metres, seconds; right-handed, +Y up (glTF's own conventions, unconverted).

use std::path::PathBuf;

use glam::{Mat4, Vec3, Vec4};

use super::clip::Clip;
use super::error::{AnimError, AnimResult};
use super::morph::MorphTarget;
use super::pose::{NodeTree, Pose};
use super::skin::{Influence, Skin};

/// One glTF primitive's vertex data, as stored (no welding, no de-indexing): vertex `i` is
/// element `i` of its POSITION accessor.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnimPrimitive {
    /// glTF primitive mode (4 = TRIANGLES, 5 = strip, 6 = fan; 0–3 points and lines).
    pub mode: u32,
    /// Metres, in the mesh's space.
    pub positions: Vec<Vec3>,
    pub normals: Option<Vec<Vec3>>,
    pub tangents: Option<Vec<Vec4>>,
    /// JOINTS_0 / WEIGHTS_0, one per position (`None` when the primitive is not skinned).
    pub influences: Option<Vec<Influence>>,
    pub morph_targets: Vec<MorphTarget>,
}

impl AnimPrimitive {
    /// Whether the engine's mesh loader turns this primitive into triangles (so its vertices
    /// are part of the engine [`Mesh`](crate::assets::Mesh) of the same glTF mesh).
    pub fn is_triangles(&self) -> bool {
        matches!(self.mode, 4..=6)
    }
}

/// One glTF mesh: its primitives and default morph weights.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnimMesh {
    pub name: Option<String>,
    pub primitives: Vec<AnimPrimitive>,
    /// The mesh's `weights` (zeros for each target when the file gives none).
    pub default_weights: Vec<f32>,
}

/// Everything animation needs from one glTF file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnimatedModel {
    /// The file it came from (for messages).
    pub file: PathBuf,
    pub nodes: NodeTree,
    pub meshes: Vec<AnimMesh>,
    pub skins: Vec<Skin>,
    /// The file's animations, in file order (a glTF animation is one clip).
    pub clips: Vec<Clip>,
    /// What the loader did that a user should know (ignored channels, unused data).
    pub notes: Vec<String>,
}

impl AnimatedModel {
    /// The rest pose: every node's file transform and default morph weights.
    pub fn rest_pose(&self) -> Pose {
        let weights: Vec<Vec<f32>> = self
            .meshes
            .iter()
            .map(|m| m.default_weights.clone())
            .collect();
        self.nodes.rest_pose(&weights)
    }

    /// The pose at `time_seconds` into clip `clip` (no wrapping: past the end the last keys
    /// hold), starting from the rest pose. An index out of range gives the rest pose.
    pub fn pose_at(&self, clip: usize, time_seconds: f64) -> Pose {
        let mut pose = self.rest_pose();
        if let Some(clip) = self.clips.get(clip) {
            pose.apply_clip(clip, time_seconds);
        }
        pose
    }

    /// World matrices of every node in `pose`.
    pub fn world_matrices(&self, pose: &Pose) -> Vec<Mat4> {
        self.nodes.world_matrices(pose)
    }

    /// Finds a clip by exact name, else by index written in decimal.
    pub fn find_clip(&self, name_or_index: &str) -> AnimResult<usize> {
        if let Some(index) = self.clips.iter().position(|c| c.name == name_or_index) {
            return Ok(index);
        }
        match name_or_index.parse::<usize>() {
            Ok(index) if index < self.clips.len() => Ok(index),
            _ => Err(AnimError::NoSuchClip {
                file: self.file.clone(),
                clip: name_or_index.to_string(),
                count: self.clips.len(),
            }),
        }
    }

    /// Finds a joint of the model's skins by its node name (`"hand_r"`, to attach a torch):
    /// the index of its node (into [`Pose`]s and [`AnimatedModel::world_matrices`]). A name
    /// no skin joint has is [`AnimError::NoSuchJoint`], naming the joint and the file.
    pub fn find_joint(&self, name: &str) -> AnimResult<usize> {
        let joints = || self.skins.iter().flat_map(|s| s.joints.iter().copied());
        let name_of = |node: usize| self.nodes.nodes.get(node).and_then(|n| n.name.as_deref());
        if let Some(node) = joints().find(|&node| name_of(node) == Some(name)) {
            return Ok(node);
        }
        let mut names: Vec<String> = joints()
            .filter_map(|n| name_of(n).map(String::from))
            .collect();
        names.dedup();
        Err(AnimError::NoSuchJoint {
            file: self.file.clone(),
            joint: name.to_string(),
            joints: names,
        })
    }
}
