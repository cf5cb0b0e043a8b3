//! Poses: the local transform (translation, rotation, scale) and morph weights of every target
//! at one moment, built from a rest pose by applying sampled clip channels, blended for
//! crossfades, and turned into world matrices over a node hierarchy.
//!
//! Owns: [`NodeTree`] (the hierarchy and rest transforms), [`Pose`], [`Pose::apply_clip`],
//! [`Pose::blend`] (whole or masked), [`NodeTree::world_matrices`]. Must not: read files or deform vertices.
//! Units: metres, seconds; right-handed, +Y up. Local = T · R · S; world = parent · local.
//! Rotations are used as stored (see `sample`): the matrix of a non-unit quaternion is
//! scaled by |q|², as in three.js and glam's `from_scale_rotation_translation`.

use glam::{Mat4, Quat, Vec3};

use super::clip::{Clip, Property};
use super::sample::sample_channel;

/// One node of a hierarchy, with its rest (file) transform.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeRest {
    pub name: Option<String>,
    pub parent: Option<usize>,
    pub children: Vec<usize>,
    pub translation: Vec3,
    pub rotation: Quat,
    pub scale: Vec3,
    /// The node's `matrix` when the file gives one (used while no channel animates the node;
    /// `translation`/`rotation`/`scale` then hold its decomposition).
    pub matrix: Option<Mat4>,
    pub mesh: Option<usize>,
    pub skin: Option<usize>,
    /// The node's own default morph weights (else the mesh's apply).
    pub weights: Option<Vec<f32>>,
}

/// A node hierarchy: every node has at most one parent and there are no cycles (the loader
/// checks both). `order` lists nodes parents first: the default scene's depth-first order,
/// then any node outside it (evaluated as if it were a root).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NodeTree {
    pub nodes: Vec<NodeRest>,
    /// Root nodes of the default scene.
    pub scene_roots: Vec<usize>,
    /// Every node, parents before children, the default scene's nodes first.
    pub order: Vec<usize>,
    /// Whether each node is reachable from the default scene.
    pub in_scene: Vec<bool>,
}

/// Local transforms and morph weights of a set of targets at one moment.
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    pub translation: Vec<Vec3>,
    pub rotation: Vec<Quat>,
    pub scale: Vec<Vec3>,
    /// Morph weights per target (empty where the target has none).
    pub weights: Vec<Vec<f32>>,
    /// Whether a channel wrote this target's transform (a node `matrix` is used only if not).
    pub animated: Vec<bool>,
}

impl Pose {
    /// `count` targets at the identity with no weights (authored clips' rest).
    pub fn identity(count: usize) -> Self {
        Self {
            translation: vec![Vec3::ZERO; count],
            rotation: vec![Quat::IDENTITY; count],
            scale: vec![Vec3::ONE; count],
            weights: vec![Vec::new(); count],
            animated: vec![false; count],
        }
    }

    /// Number of targets.
    pub fn len(&self) -> usize {
        self.translation.len()
    }

    /// Whether the pose has no targets.
    pub fn is_empty(&self) -> bool {
        self.translation.is_empty()
    }

    /// The local matrix T · R · S of target `index`.
    pub fn local_matrix(&self, index: usize) -> Mat4 {
        Mat4::from_scale_rotation_translation(
            self.scale[index],
            self.rotation[index],
            self.translation[index],
        )
    }

    /// Overwrites the targets `clip` animates with its values at `time_seconds` (no wrapping:
    /// times outside the keys hold the end values). Channels whose target or width does not
    /// fit this pose are skipped (clips are checked against their model when loaded).
    pub fn apply_clip(&mut self, clip: &Clip, time_seconds: f64) {
        let mut value = [0.0f32; 4];
        for channel in &clip.channels {
            let target = channel.target;
            if target >= self.len() {
                continue;
            }
            match channel.property {
                Property::Weights => {
                    let weights = &mut self.weights[target];
                    weights.resize(channel.width, 0.0);
                    sample_channel(channel, time_seconds, weights);
                }
                property => {
                    if channel.width != property.components().unwrap_or(0) {
                        continue;
                    }
                    sample_channel(channel, time_seconds, &mut value);
                    match property {
                        Property::Translation => {
                            self.translation[target] = Vec3::from_slice(&value[..3]);
                        }
                        Property::Scale => self.scale[target] = Vec3::from_slice(&value[..3]),
                        _ => self.rotation[target] = Quat::from_slice(&value),
                    }
                    self.animated[target] = true;
                }
            }
        }
    }

    /// Blends towards `other` by `weight` in [0, 1] (0 keeps `self`, 1 gives `other`):
    /// translation, scale and weights lerp, rotations nlerp along the shortest path (enough
    /// for crossfades, whose two poses are close and change every frame).
    pub fn blend(&mut self, other: &Pose, weight: f32) {
        let weight = weight.clamp(0.0, 1.0);
        for i in 0..self.len().min(other.len()) {
            self.blend_node(other, i, weight);
        }
    }

    /// Blends node `i` towards `other` by `mask[i] · weight` (a node past the mask's end is
    /// kept): a layer over part of a body.
    pub fn blend_masked(&mut self, other: &Pose, mask: &[f32], weight: f32) {
        for i in 0..self.len().min(other.len()).min(mask.len()) {
            let w = (mask[i] * weight).clamp(0.0, 1.0);
            if w > 0.0 {
                self.blend_node(other, i, w);
            }
        }
    }

    fn blend_node(&mut self, other: &Pose, i: usize, weight: f32) {
        self.translation[i] = self.translation[i].lerp(other.translation[i], weight);
        self.scale[i] = self.scale[i].lerp(other.scale[i], weight);
        let mut target = other.rotation[i];
        if self.rotation[i].dot(target) < 0.0 {
            target = -target;
        }
        let mixed = self.rotation[i] * (1.0 - weight) + target * weight;
        if mixed.length_squared() > 0.0 {
            self.rotation[i] = mixed.normalize();
        }
        let (mine, theirs) = (&mut self.weights[i], &other.weights[i]);
        mine.resize(mine.len().max(theirs.len()), 0.0);
        for (k, w) in mine.iter_mut().enumerate() {
            let t = theirs.get(k).copied().unwrap_or(0.0);
            *w += (t - *w) * weight;
        }
        self.animated[i] |= other.animated[i];
    }
}

impl NodeTree {
    /// The rest pose: each node's file transform and default weights (`mesh_weights` gives
    /// each mesh's default weights, used for nodes without their own).
    pub fn rest_pose(&self, mesh_weights: &[Vec<f32>]) -> Pose {
        let mut pose = Pose::identity(self.nodes.len());
        for (i, node) in self.nodes.iter().enumerate() {
            pose.translation[i] = node.translation;
            pose.rotation[i] = node.rotation;
            pose.scale[i] = node.scale;
            pose.weights[i] = node
                .weights
                .clone()
                .or_else(|| node.mesh.and_then(|m| mesh_weights.get(m).cloned()))
                .unwrap_or_default();
        }
        pose
    }

    /// World matrices of every node in `pose` (world = parent world · local). A node given
    /// by a `matrix` keeps it unless a channel animated the node.
    pub fn world_matrices(&self, pose: &Pose) -> Vec<Mat4> {
        let mut world = vec![Mat4::IDENTITY; self.nodes.len()];
        for &index in &self.order {
            let node = &self.nodes[index];
            let local = match node.matrix {
                Some(matrix) if !pose.animated.get(index).copied().unwrap_or(false) => matrix,
                _ if index < pose.len() => pose.local_matrix(index),
                _ => Mat4::IDENTITY,
            };
            world[index] = match node.parent {
                Some(parent) => world[parent] * local,
                None => local,
            };
        }
        world
    }
}
