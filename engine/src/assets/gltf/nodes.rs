//! The glTF node hierarchy of one scene to placed meshes with global transforms.
//!
//! glTF is right-handed, +Y up, metres, like the engine: node transforms are used as they
//! are, with no axis or unit conversion. The scene is the default scene (`scene`), else scene
//! 0; a file without scenes places the nodes that have no parent, with a note.
//! A node's global transform is its parents' product times its own (`matrix`, or
//! `T · R · S` with the rotation quaternion normalised). Node graphs that are not trees are
//! handled without trusting them: a cycle is refused, a node with several parents is placed
//! under each (bounded by [`MAX_PLACEMENTS`] and [`MAX_NODE_VISITS`]), and non-finite
//! transforms are refused. Skins and morph weights are ignored (the bind pose is placed),
//! with a note.
//! Must not: read mesh data.

use glam::{Mat4, Quat, Vec3};

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::limits::{MAX_NODE_VISITS, MAX_PLACEMENTS};

/// A glTF mesh placed by a node: (glTF mesh index, model-from-mesh transform, node index).
pub(crate) type NodePlacement = (usize, Mat4, usize);

/// Expands the chosen scene into placed meshes, in depth-first node order.
pub(crate) fn place_meshes(
    context: &mut LoadContext,
    document: &gltf::Document,
) -> AssetResult<Vec<NodePlacement>> {
    let nodes = &document.as_json().nodes;
    let children = |node: usize| -> Vec<usize> {
        nodes
            .get(node)
            .and_then(|n| n.children.as_ref())
            .map(|c| c.iter().map(|i| i.value()).collect())
            .unwrap_or_default()
    };
    check_acyclic(context, nodes.len(), &children)?;
    let scene_count = document.scenes().len();
    let roots: Vec<usize> = match document
        .default_scene()
        .or_else(|| document.scenes().next())
    {
        Some(scene) => {
            if scene_count > 1 {
                context.note(format!(
                    "the file has {scene_count} scenes: scene {} loaded",
                    scene.index()
                ));
            }
            scene.nodes().map(|n| n.index()).collect()
        }
        None => {
            let mut has_parent = vec![false; nodes.len()];
            for node in 0..nodes.len() {
                for child in children(node) {
                    if let Some(flag) = has_parent.get_mut(child) {
                        *flag = true;
                    }
                }
            }
            if !nodes.is_empty() {
                context.note("the file has no scene: every node without a parent is placed");
            }
            (0..nodes.len()).filter(|&n| !has_parent[n]).collect()
        }
    };
    let transforms = local_transforms(context, document)?;
    let mut placements = Vec::new();
    let mut visits = 0usize;
    let (mut skinned, mut morphed) = (false, false);
    let mut stack: Vec<(usize, Mat4)> = roots.iter().rev().map(|&n| (n, Mat4::IDENTITY)).collect();
    while let Some((node, parent)) = stack.pop() {
        visits += 1;
        if visits > MAX_NODE_VISITS {
            return Err(context.too_large(
                "node hierarchy (node visits)",
                visits as u64,
                MAX_NODE_VISITS as u64,
            ));
        }
        let Some(json) = nodes.get(node) else {
            continue;
        };
        let global = parent * transforms[node];
        if let Some(mesh) = json.mesh {
            placements.push((mesh.value(), global, node));
            if placements.len() > MAX_PLACEMENTS {
                return Err(context.too_large(
                    "scene (placed meshes)",
                    placements.len() as u64,
                    MAX_PLACEMENTS as u64,
                ));
            }
        }
        skinned |= json.skin.is_some();
        morphed |= json.weights.is_some();
        for child in children(node).into_iter().rev() {
            stack.push((child, global));
        }
    }
    if skinned {
        context.note("skins are ignored: skinned meshes are placed in their bind pose");
    }
    if morphed {
        context.note("morph target weights are ignored: base shapes are placed");
    }
    Ok(placements)
}

/// Each node's own transform, refusing non-finite ones.
fn local_transforms(context: &LoadContext, document: &gltf::Document) -> AssetResult<Vec<Mat4>> {
    document
        .nodes()
        .map(|node| {
            let matrix = match node.transform() {
                gltf::scene::Transform::Matrix { matrix } => Mat4::from_cols_array_2d(&matrix),
                gltf::scene::Transform::Decomposed {
                    translation,
                    rotation,
                    scale,
                } => {
                    let rotation = Quat::from_array(rotation);
                    let rotation = if rotation.length_squared() > 0.0 {
                        rotation.normalize()
                    } else {
                        Quat::IDENTITY
                    };
                    Mat4::from_scale_rotation_translation(
                        Vec3::from(scale),
                        rotation,
                        Vec3::from(translation),
                    )
                }
            };
            if matrix.is_finite() {
                Ok(matrix)
            } else {
                Err(context.gltf_error(format!("node {} has a non-finite transform", node.index())))
            }
        })
        .collect()
}

/// Refuses a node graph with a cycle (a node that is its own ancestor).
fn check_acyclic(
    context: &LoadContext,
    count: usize,
    children: &dyn Fn(usize) -> Vec<usize>,
) -> AssetResult<()> {
    // Iterative three-colour depth-first search: 0 unvisited, 1 on the current path, 2 done.
    let mut state = vec![0u8; count];
    for start in 0..count {
        if state[start] != 0 {
            continue;
        }
        state[start] = 1;
        let mut stack = vec![(start, children(start), 0usize)];
        while let Some((node, kids, next)) = stack.last_mut() {
            if let Some(&child) = kids.get(*next) {
                *next += 1;
                match state.get(child) {
                    Some(1) => {
                        return Err(context.gltf_error(format!(
                            "node {child} is its own ancestor (a loop through node {node})"
                        )));
                    }
                    Some(0) => {
                        state[child] = 1;
                        stack.push((child, children(child), 0));
                    }
                    _ => {}
                }
            } else {
                state[*node] = 2;
                stack.pop();
            }
        }
    }
    Ok(())
}
