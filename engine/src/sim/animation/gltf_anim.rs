//! Loading what animation needs from a glTF file into an [`AnimatedModel`]: the node
//! hierarchy of the default scene, skins, then (`gltf_anim_mesh`) per-primitive vertex data
//! and morph targets, then (`gltf_anim_clips`) the clips. The file is opened, validated and
//! its accessors read by the engine's glTF loader (`assets::gltf::{document, accessor}`), so
//! every bound is checked there; this module checks what is specific to animation and
//! returns an [`AnimError`] naming the file and the item for anything wrong. Panics from a
//! missing check are caught and returned as [`AnimError::LoaderPanic`].
//!
//! Owns: [`load_animation`], [`load_animation_file`], [`load_animation_bytes`] (the same
//! reading from memory, for the fuzz targets), nodes and skins.
//! Must not: convert axes or units (glTF's are the engine's), or touch the renderer.
//! Runs on whichever thread loads assets.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use glam::{Mat4, Quat, Vec3};
use gltf::json;
use gltf::json::accessor::Type;

use super::error::{AnimError, AnimResult};
use super::gltf_anim_clips::read_clips;
use super::gltf_anim_mesh::{check_joints, read_meshes};
use super::model::AnimatedModel;
use super::pose::{NodeRest, NodeTree};
use super::skin::Skin;
use crate::assets::context::LoadContext;
use crate::assets::gltf::accessor::Reader;
use crate::assets::gltf::document::open;
use crate::assets::{AssetError, AssetRoot, MemoryFiles};

/// Loads the animation data of the glTF/GLB file at `path` (relative to `root`; `referrer`
/// names the file that refers to it, for messages).
pub fn load_animation(root: &AssetRoot, referrer: &Path, path: &str) -> AnimResult<AnimatedModel> {
    let file = root.resolve(referrer, None, path)?;
    read_caught(LoadContext::new(root, file))
}

/// Loads the animation data of a glTF/GLB file held in memory (GLB known by its magic, as
/// for a file): `name` names it in messages, `bytes` is the file and `files` holds what it references (buffers) by path relative to `name`'s folder.
pub fn load_animation_bytes(
    name: &Path,
    bytes: &[u8],
    files: &MemoryFiles,
) -> AnimResult<AnimatedModel> {
    read_caught(LoadContext::in_memory(name, bytes, files))
}

/// [`read`], a panic turned into [`AnimError::LoaderPanic`].
fn read_caught(mut context: LoadContext) -> AnimResult<AnimatedModel> {
    let file = context.file.clone();
    match catch_unwind(AssertUnwindSafe(|| read(&mut context))) {
        Ok(result) => result,
        Err(payload) => Err(AnimError::LoaderPanic {
            file,
            message: payload
                .downcast_ref::<&str>()
                .map(|text| (*text).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".to_string()),
        }),
    }
}

/// Loads the animation data of the glTF/GLB file at `path`, with its folder as the asset
/// root (for tools and tests).
pub fn load_animation_file(path: &Path) -> AnimResult<AnimatedModel> {
    let file = path
        .canonicalize()
        .map_err(|source| AssetError::io(path, source))?;
    let (Some(folder), Some(name)) = (file.parent(), file.file_name().and_then(|n| n.to_str()))
    else {
        return Err(AssetError::Unsupported {
            path: path.to_path_buf(),
            message: "not a glTF file name".to_string(),
        }
        .into());
    };
    let root = AssetRoot::new(folder)?;
    load_animation(&root, path, name)
}

fn read(context: &mut LoadContext) -> AnimResult<AnimatedModel> {
    let gltf_file = open(context)?;
    let json = gltf_file.document.as_json();
    let reader = Reader {
        context,
        file: &gltf_file,
    };
    let file = &context.file;
    let mut notes = Vec::new();
    let nodes = read_nodes(file, json)?;
    let skins = read_skins(&reader, json)?;
    let meshes = read_meshes(&reader, json, &mut notes)?;
    check_joints(file, &nodes, &skins, &meshes)?;
    let clips = read_clips(&reader, json, &nodes, &meshes, &mut notes)?;
    let mut model = AnimatedModel {
        file: file.clone(),
        nodes,
        meshes,
        skins,
        clips,
        notes: Vec::new(),
    };
    for note in notes {
        context.note(note);
    }
    model.notes = std::mem::take(&mut context.notes);
    Ok(model)
}

/// The node hierarchy: rest transforms, parents, the default scene and evaluation order.
fn read_nodes(file: &Path, json: &json::Root) -> AnimResult<NodeTree> {
    let count = json.nodes.len();
    let bad = |node: usize, message: String| AnimError::BadNode {
        file: file.to_path_buf(),
        node,
        message,
    };
    let mut nodes = Vec::with_capacity(count);
    for (index, node) in json.nodes.iter().enumerate() {
        let (translation, rotation, scale, matrix) = match node.matrix {
            Some(m) => {
                let matrix = Mat4::from_cols_array(&m);
                let (scale, rotation, translation) = matrix.to_scale_rotation_translation();
                (translation, rotation, scale, Some(matrix))
            }
            None => (
                node.translation.map_or(Vec3::ZERO, Vec3::from),
                node.rotation
                    .map_or(Quat::IDENTITY, |q| Quat::from_array(q.0)),
                node.scale.map_or(Vec3::ONE, Vec3::from),
                None,
            ),
        };
        let finite = translation.is_finite()
            && rotation.is_finite()
            && scale.is_finite()
            && matrix.is_none_or(|m| m.is_finite());
        if !finite {
            return Err(bad(index, "has a non-finite transform".to_string()));
        }
        let children: Vec<usize> = node.children.iter().flatten().map(|c| c.value()).collect();
        if let Some(&child) = children.iter().find(|&&c| c >= count) {
            return Err(bad(index, format!("child {child} does not exist")));
        }
        nodes.push(NodeRest {
            name: node.name.clone(),
            parent: None,
            children,
            translation,
            rotation,
            scale,
            matrix,
            mesh: node.mesh.map(|m| m.value()),
            skin: node.skin.map(|s| s.value()),
            weights: node.weights.clone(),
        });
    }
    for index in 0..count {
        for child in nodes[index].children.clone() {
            if let Some(parent) = nodes[child].parent {
                return Err(bad(
                    child,
                    format!("has two parents ({parent} and {index}); animation needs a tree"),
                ));
            }
            nodes[child].parent = Some(index);
        }
    }
    let scene = json
        .scene
        .map(|s| s.value())
        .or((!json.scenes.is_empty()).then_some(0));
    let scene_roots: Vec<usize> = match scene.and_then(|s| json.scenes.get(s)) {
        Some(scene) => scene.nodes.iter().map(|n| n.value()).collect(),
        None => (0..count).filter(|&n| nodes[n].parent.is_none()).collect(),
    };
    let mut tree = NodeTree {
        nodes,
        scene_roots,
        order: Vec::with_capacity(count),
        in_scene: vec![false; count],
    };
    let mut visited = vec![false; count];
    let other_roots: Vec<usize> = (0..count)
        .filter(|&n| tree.nodes[n].parent.is_none())
        .collect();
    for (pass, roots) in [tree.scene_roots.clone(), other_roots]
        .into_iter()
        .enumerate()
    {
        for root in roots {
            let Some(node) = tree.nodes.get(root) else {
                return Err(bad(root, "is a scene root but does not exist".to_string()));
            };
            if node.parent.is_some() {
                return Err(bad(root, "is a scene root but has a parent".to_string()));
            }
            if visited[root] {
                continue;
            }
            // Parents are unique (checked above), so this walk never meets a node twice.
            let mut stack = vec![root];
            while let Some(node) = stack.pop() {
                visited[node] = true;
                tree.in_scene[node] = pass == 0;
                tree.order.push(node);
                stack.extend(tree.nodes[node].children.iter().rev());
            }
        }
    }
    if let Some(node) = (0..count).find(|&n| !visited[n]) {
        return Err(bad(node, "lies on a cycle of parents".to_string()));
    }
    Ok(tree)
}

/// Skins: joints (node indices, checked) and inverse bind matrices (identity when absent).
fn read_skins(reader: &Reader, json: &json::Root) -> AnimResult<Vec<Skin>> {
    let file = &reader.context.file;
    let mut skins = Vec::with_capacity(json.skins.len());
    for (index, skin) in json.skins.iter().enumerate() {
        let bad = |message: String| AnimError::BadSkin {
            file: file.clone(),
            skin: index,
            message,
        };
        let joints: Vec<usize> = skin.joints.iter().map(|j| j.value()).collect();
        if joints.is_empty() {
            return Err(bad("has no joints".to_string()));
        }
        if joints.len() > usize::from(u16::MAX) {
            return Err(bad(format!("has {} joints (limit 65535)", joints.len())));
        }
        if let Some(&joint) = joints.iter().find(|&&j| j >= json.nodes.len()) {
            return Err(bad(format!("joint node {joint} does not exist")));
        }
        let inverse_bind_matrices = match skin.inverse_bind_matrices {
            None => vec![Mat4::IDENTITY; joints.len()],
            Some(accessor) => {
                let (values, _) =
                    reader.read_floats(accessor.value(), &[Type::Mat4], "inverseBindMatrices")?;
                let matrices: Vec<Mat4> =
                    values.chunks_exact(16).map(Mat4::from_cols_slice).collect();
                if matrices.len() < joints.len() {
                    return Err(bad(format!(
                        "{} inverse bind matrices for {} joints",
                        matrices.len(),
                        joints.len()
                    )));
                }
                if let Some(at) = matrices.iter().position(|m| !m.is_finite()) {
                    return Err(bad(format!("inverse bind matrix {at} is not finite")));
                }
                matrices
            }
        };
        skins.push(Skin {
            name: skin.name.clone(),
            joints,
            inverse_bind_matrices,
        });
    }
    Ok(skins)
}
