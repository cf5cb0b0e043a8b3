//! Deforming an animated model's vertices in a pose: morph targets first, then skinning
//! (skinned primitives) or the node's world matrix (rigid ones).
//!
//! Owns: [`deform_primitive`] (world space, one primitive of one node), [`scene_primitives`]
//! and [`world_positions`] (every primitive of the default scene, in the order of the
//! animation reference data and of `inspect --dump-vertices`), and [`deform_mesh`] (one
//! node's mesh in mesh space, the shape `accel::Upkeep::deform` takes). Must not: sample
//! clips or touch BVHs.
//! Units: metres; right-handed, +Y up.

use glam::{Mat4, Vec3, Vec4};

use super::model::AnimatedModel;
use super::morph::{morph_normals, morph_positions, morph_tangents};
use super::pose::Pose;
use super::skin::{joint_matrices, skin_vertices};

/// One primitive drawn by one node: glTF mesh, node and primitive indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrimitiveRef {
    pub mesh: usize,
    pub node: usize,
    pub primitive: usize,
}

/// Deformed vertices of one primitive (or one mesh).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Deformed {
    /// Metres.
    pub positions: Vec<Vec3>,
    /// Unit normals, where the primitive has normals.
    pub normals: Option<Vec<Vec3>>,
    /// Unit tangents with handedness `w`, where the primitive has tangents.
    pub tangents: Option<Vec<Vec4>>,
}

/// Every primitive of every mesh-bearing node of the default scene, ordered by mesh index,
/// then node index (a mesh used by several nodes appears once per node), then primitive.
pub fn scene_primitives(model: &AnimatedModel) -> Vec<PrimitiveRef> {
    let mut refs = Vec::new();
    for (node_index, node) in model.nodes.nodes.iter().enumerate() {
        let (Some(mesh), true) = (node.mesh, model.nodes.in_scene[node_index]) else {
            continue;
        };
        let Some(gltf_mesh) = model.meshes.get(mesh) else {
            continue;
        };
        for primitive in 0..gltf_mesh.primitives.len() {
            refs.push(PrimitiveRef {
                mesh,
                node: node_index,
                primitive,
            });
        }
    }
    refs.sort_by_key(|r| (r.mesh, r.node, r.primitive));
    refs
}

/// The morphed (not yet skinned or placed) vertices of `at`, in mesh space.
fn morphed(model: &AnimatedModel, pose: &Pose, at: PrimitiveRef) -> Option<Deformed> {
    let primitive = model.meshes.get(at.mesh)?.primitives.get(at.primitive)?;
    let weights = pose.weights.get(at.node).map_or(&[][..], Vec::as_slice);
    let targets = &primitive.morph_targets;
    Some(Deformed {
        positions: morph_positions(&primitive.positions, targets, weights),
        normals: primitive
            .normals
            .as_ref()
            .map(|n| morph_normals(n, targets, weights)),
        tangents: primitive
            .tangents
            .as_ref()
            .map(|t| morph_tangents(t, targets, weights)),
    })
}

/// The vertices of `at` in world space: morphed, then skinned by the node's skin (which
/// ignores the node's own transform, glTF 2.0 §3.7.3) or moved by the node's world matrix.
/// `world` comes from [`AnimatedModel::world_matrices`] of the same pose. `None` when `at`
/// names no primitive.
pub fn deform_primitive(
    model: &AnimatedModel,
    pose: &Pose,
    world: &[Mat4],
    at: PrimitiveRef,
) -> Option<Deformed> {
    let morphed = morphed(model, pose, at)?;
    let primitive = &model.meshes[at.mesh].primitives[at.primitive];
    let skin = model
        .nodes
        .nodes
        .get(at.node)
        .and_then(|n| n.skin)
        .and_then(|s| model.skins.get(s));
    if let (Some(skin), Some(influences)) = (skin, primitive.influences.as_ref()) {
        let matrices = joint_matrices(skin, world);
        let skinned = skin_vertices(
            &morphed.positions,
            morphed.normals.as_deref(),
            morphed.tangents.as_deref(),
            influences,
            &matrices,
        );
        return Some(Deformed {
            positions: skinned.positions,
            normals: skinned.normals,
            tangents: skinned.tangents,
        });
    }
    let node_world = world.get(at.node).copied().unwrap_or(Mat4::IDENTITY);
    Some(transform(&morphed, node_world))
}

/// `deformed` moved by `matrix` (normals by its inverse transpose).
fn transform(deformed: &Deformed, matrix: Mat4) -> Deformed {
    let linear = glam::Mat3::from_mat4(matrix);
    let normal_matrix = if linear.determinant().abs() > f32::MIN_POSITIVE {
        linear.inverse().transpose()
    } else {
        linear
    };
    let mirrored = linear.determinant() < 0.0;
    Deformed {
        positions: deformed
            .positions
            .iter()
            .map(|&p| matrix.transform_point3(p))
            .collect(),
        normals: deformed.normals.as_ref().map(|normals| {
            normals
                .iter()
                .map(|&n| (normal_matrix * n).normalize_or_zero())
                .collect()
        }),
        tangents: deformed.tangents.as_ref().map(|tangents| {
            tangents
                .iter()
                .map(|&t| {
                    let w = if mirrored { -t.w } else { t.w };
                    (linear * t.truncate()).normalize_or_zero().extend(w)
                })
                .collect()
        }),
    }
}

/// World-space positions of every primitive of [`scene_primitives`], concatenated in that
/// order (the layout of the reference data's `.bin` files).
pub fn world_positions(model: &AnimatedModel, pose: &Pose) -> Vec<Vec3> {
    let world = model.world_matrices(pose);
    scene_primitives(model)
        .into_iter()
        .filter_map(|at| deform_primitive(model, pose, &world, at))
        .flat_map(|d| d.positions)
        .collect()
}

/// The mesh of `node` deformed in `pose`, in the space of the engine mesh that
/// `assets::load_model` made of it: the node's triangle primitives joined in order (points
/// and lines are left out, as that loader does), so the result has that mesh's vertex count.
/// Rigid primitives are only morphed (the node's motion is its instance transform); skinned
/// ones are skinned into the scene's space and then brought back by the inverse of
/// `model_from_mesh`, the placement the renderer draws the mesh with. `None` when the node
/// has no mesh.
pub fn deform_mesh(
    model: &AnimatedModel,
    pose: &Pose,
    world: &[Mat4],
    node: usize,
    model_from_mesh: Mat4,
) -> Option<Deformed> {
    let mesh = model.nodes.nodes.get(node)?.mesh?;
    let primitives = &model.meshes.get(mesh)?.primitives;
    let skinned = model.nodes.nodes[node].skin.is_some();
    let mesh_from_model = model_from_mesh.inverse();
    let mut out = Deformed::default();
    let (mut normals, mut tangents) = (Vec::new(), Vec::new());
    let (mut all_normals, mut all_tangents) = (true, true);
    for (index, primitive) in primitives.iter().enumerate() {
        if !primitive.is_triangles() {
            continue;
        }
        let at = PrimitiveRef {
            mesh,
            node,
            primitive: index,
        };
        let part = if skinned && primitive.influences.is_some() {
            let world_space = deform_primitive(model, pose, world, at)?;
            transform(&world_space, mesh_from_model)
        } else {
            morphed(model, pose, at)?
        };
        let count = part.positions.len();
        all_normals &= part.normals.is_some();
        all_tangents &= part.tangents.is_some();
        normals.extend(part.normals.unwrap_or_else(|| vec![Vec3::ZERO; count]));
        tangents.extend(
            part.tangents
                .unwrap_or_else(|| vec![Vec4::new(0.0, 0.0, 0.0, 1.0); count]),
        );
        out.positions.extend(part.positions);
    }
    out.normals = all_normals.then_some(normals);
    out.tangents = all_tangents.then_some(tangents);
    Some(out)
}
