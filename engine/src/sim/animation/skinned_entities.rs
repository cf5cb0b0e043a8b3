//! Skinned, morphing and rigidly animated glTF models on entities: a character whose clips
//! play through an [`AnimationPlayer`] (with crossfades), deforming its mesh into the entity's
//! [`Deformable`], which feeds the deforming-mesh BVH path (refit or rebuild per frame). A
//! rigid node's own motion is baked into the vertices too (the entity's `Transform` stays the
//! game's), so a file with one animated mesh node plays whatever its clips animate.
//!
//! Owns: the [`SkinnedAnimator`] component, [`tick_skinned`] (advances every player, once per
//! fixed step) and [`deform_skinned`] (deforms each entity whose player moved, once per frame,
//! before extraction: the pose between steps is not needed, and deforming once per frame
//! saves work when a frame runs several steps). Main thread.
//! Must not: place the entity (its `Transform` stays the game's) or touch BVHs.

use std::sync::Arc;

use glam::Mat4;
use hecs::World;

use super::deform::deform_mesh;
use super::model::AnimatedModel;
use super::player::{AnimationPlayer, FiredEvent};
use crate::assets::{Model, Placement};
use crate::ecs::Deformable;

/// Plays an animated glTF model's clips on an entity that renders the same file's [`Model`].
#[derive(Clone, Debug)]
pub struct SkinnedAnimator {
    pub model: Arc<AnimatedModel>,
    pub player: AnimationPlayer,
    /// The glTF node whose mesh is deformed.
    pub node: usize,
    /// How the renderer's model places that mesh (its [`Placement`]).
    pub model_from_mesh: Mat4,
    /// Clip events passed since the last [`deform_skinned`].
    pub events: Vec<FiredEvent>,
    moved: bool,
}

impl SkinnedAnimator {
    /// An animator for `node` of `animated`, drawn as `placement` of the renderer's model.
    pub fn new(animated: Arc<AnimatedModel>, node: usize, placement: &Placement) -> Self {
        Self {
            model: animated,
            player: AnimationPlayer::new(),
            node,
            model_from_mesh: placement.model_from_mesh,
            events: Vec::new(),
            moved: true,
        }
    }

    /// The animator and the [`Deformable`] (mesh index and rest vertices) of a file with one
    /// mesh-bearing node that is drawn once (a character); `None` otherwise.
    pub fn single(animated: Arc<AnimatedModel>, model: &Model) -> Option<(Self, Deformable)> {
        let mut nodes = animated
            .nodes
            .nodes
            .iter()
            .enumerate()
            .filter(|(i, n)| n.mesh.is_some() && animated.nodes.in_scene[*i]);
        let (node, _) = nodes.next()?;
        if nodes.next().is_some() || model.placements.len() != 1 {
            return None;
        }
        let placement = model.placements.first()?;
        let mesh = model.meshes.get(placement.mesh)?;
        let deformable = Deformable {
            mesh: placement.mesh,
            positions: mesh.positions.clone(),
            normals: None,
            dirty: false,
        };
        Some((Self::new(animated, node, placement), deformable))
    }
}

impl SkinnedAnimator {
    /// The matrix of node `node` (a joint: [`AnimatedModel::find_joint`]) in the pose the
    /// player gives now, in the glTF file's space (metres; the entity's `Transform` places
    /// that space in the world): where to attach a torch to `hand_r`. `None` for a node the
    /// model does not have.
    pub fn node_matrix(&self, node: usize) -> Option<Mat4> {
        let pose = self.player.pose(&self.model.clips, &self.model.rest_pose());
        self.model.world_matrices(&pose).get(node).copied()
    }
}

/// Advances every [`SkinnedAnimator`]'s player by `dt_seconds` (one fixed step).
pub fn tick_skinned(world: &mut World, dt_seconds: f64) {
    for animator in world.query_mut::<&mut SkinnedAnimator>() {
        let playing = animator
            .player
            .current()
            .is_some_and(|p| !p.paused && !p.finished);
        let clips = &animator.model.clips;
        let events = animator.player.tick(clips, dt_seconds);
        animator.events.extend(events);
        animator.moved |= playing;
    }
}

/// Deforms the mesh of every entity whose animator moved since the last call into its
/// [`Deformable`] (marked dirty). Returns how many meshes it deformed.
pub fn deform_skinned(world: &mut World) -> usize {
    let mut count = 0;
    for (animator, deformable) in world.query_mut::<(&mut SkinnedAnimator, &mut Deformable)>() {
        animator.events.clear();
        if !std::mem::take(&mut animator.moved) {
            continue;
        }
        let model = &animator.model;
        let pose = animator.player.pose(&model.clips, &model.rest_pose());
        let world_matrices = model.world_matrices(&pose);
        let Some(deformed) = deform_mesh(
            model,
            &pose,
            &world_matrices,
            animator.node,
            animator.model_from_mesh,
        ) else {
            continue;
        };
        if deformed.positions.len() != deformable.positions.len() {
            continue;
        }
        let rigid = model
            .nodes
            .nodes
            .get(animator.node)
            .is_some_and(|n| n.skin.is_none());
        let (mut positions, mut normals) = (deformed.positions, deformed.normals);
        if let (true, Some(node_world)) = (rigid, world_matrices.get(animator.node)) {
            // A rigid node's motion: from its animated world matrix back into the mesh space
            // the renderer places with `model_from_mesh` (the node's rest matrix).
            let m = animator.model_from_mesh.inverse() * *node_world;
            let n = glam::Mat3::from_mat4(m).inverse().transpose();
            positions
                .iter_mut()
                .for_each(|p| *p = m.transform_point3(*p));
            if let Some(normals) = &mut normals {
                normals
                    .iter_mut()
                    .for_each(|v| *v = (n * *v).normalize_or_zero());
            }
        }
        deformable.positions = positions;
        deformable.normals = normals;
        deformable.dirty = true;
        count += 1;
    }
    count
}
