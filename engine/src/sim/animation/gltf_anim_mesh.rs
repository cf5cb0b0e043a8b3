//! Per-primitive vertex data for animation from glTF meshes: base POSITION / NORMAL /
//! TANGENT, JOINTS_0 / WEIGHTS_0 as four influences, and morph targets; plus the check that
//! every vertex of a skinned node names a joint its skin has.
//!
//! Every primitive is kept, whatever its mode, with vertex `i` = element `i` of its POSITION
//! accessor (no welding, no de-indexing; a primitive without POSITION has no vertices).
//! Attribute and morph-target accessors must have the position count.
//! Owns: [`read_meshes`], [`check_joints`]. Must not: place or sample anything.

use std::path::Path;

use glam::{Vec3, Vec4};
use gltf::json;
use gltf::json::accessor::Type;
use gltf::json::mesh::Semantic;
use gltf::json::validation::Checked;

use super::error::{AnimError, AnimResult};
use super::model::{AnimMesh, AnimPrimitive};
use super::morph::MorphTarget;
use super::pose::NodeTree;
use super::skin::{Influence, Skin};
use crate::assets::gltf::accessor::Reader;

/// Reads every mesh of the file (see the module doc).
pub(crate) fn read_meshes(
    reader: &Reader,
    json: &json::Root,
    notes: &mut Vec<String>,
) -> AnimResult<Vec<AnimMesh>> {
    let file = &reader.context.file;
    let mut meshes = Vec::with_capacity(json.meshes.len());
    for (mesh_index, mesh) in json.meshes.iter().enumerate() {
        let label = mesh
            .name
            .clone()
            .unwrap_or_else(|| format!("mesh #{mesh_index}"));
        let mut primitives = Vec::with_capacity(mesh.primitives.len());
        for (index, primitive) in mesh.primitives.iter().enumerate() {
            let bad = |message: String| AnimError::BadPrimitive {
                file: file.clone(),
                mesh: label.clone(),
                primitive: index,
                message,
            };
            primitives.push(read_primitive(reader, primitive, &bad)?);
        }
        let target_count = primitives
            .iter()
            .map(|p| p.morph_targets.len())
            .max()
            .unwrap_or(0);
        if primitives
            .iter()
            .any(|p| p.morph_targets.len() != target_count)
        {
            notes.push(format!(
                "mesh {label:?}: primitives have different morph target counts"
            ));
        }
        let mut default_weights = mesh.weights.clone().unwrap_or_default();
        default_weights.resize(target_count, 0.0);
        if default_weights.iter().any(|w| !w.is_finite()) {
            return Err(AnimError::BadPrimitive {
                file: file.clone(),
                mesh: label,
                primitive: 0,
                message: "the mesh's default morph weights are not finite".to_string(),
            });
        }
        meshes.push(AnimMesh {
            name: mesh.name.clone(),
            primitives,
            default_weights,
        });
    }
    Ok(meshes)
}

/// Reads one primitive; `bad` makes an error naming it.
fn read_primitive(
    reader: &Reader,
    primitive: &json::mesh::Primitive,
    bad: &dyn Fn(String) -> AnimError,
) -> AnimResult<AnimPrimitive> {
    let attribute = |semantic: Semantic| primitive.attributes.get(&Checked::Valid(semantic));
    let mode = match primitive.mode {
        Checked::Valid(mode) => mode.as_gl_enum(),
        Checked::Invalid => return Err(bad("has an unknown mode".to_string())),
    };
    let Some(position_accessor) = attribute(Semantic::Positions) else {
        return Ok(AnimPrimitive {
            mode,
            ..AnimPrimitive::default()
        });
    };
    let (positions, _) =
        reader.read_floats(position_accessor.value(), &[Type::Vec3], "POSITION")?;
    let count = positions.len() / 3;
    // Reads accessor `index` as `kind`, checking the count and finiteness.
    let read = |index: usize, kind: Type, what: &str| -> AnimResult<Vec<f32>> {
        let (values, components) = reader.read_floats(index, &[kind], what)?;
        if values.len() / components != count {
            return Err(bad(format!(
                "{what} has {} elements for {count} positions",
                values.len() / components
            )));
        }
        if let Some(at) = values.iter().position(|v| !v.is_finite()) {
            return Err(bad(format!(
                "{what} element {} is not finite",
                at / components
            )));
        }
        Ok(values)
    };
    let vec3s = |values: Vec<f32>| values.chunks_exact(3).map(Vec3::from_slice).collect();
    let normals = match attribute(Semantic::Normals) {
        Some(a) => Some(vec3s(read(a.value(), Type::Vec3, "NORMAL")?)),
        None => None,
    };
    let tangents = match attribute(Semantic::Tangents) {
        Some(a) => Some(
            read(a.value(), Type::Vec4, "TANGENT")?
                .chunks_exact(4)
                .map(Vec4::from_slice)
                .collect(),
        ),
        None => None,
    };
    let influences = match (
        attribute(Semantic::Joints(0)),
        attribute(Semantic::Weights(0)),
    ) {
        (Some(joints), Some(weights)) => {
            let joints = read(joints.value(), Type::Vec4, "JOINTS_0")?;
            let weights = read(weights.value(), Type::Vec4, "WEIGHTS_0")?;
            let mut influences = Vec::with_capacity(count);
            for (vertex, (j, w)) in joints
                .chunks_exact(4)
                .zip(weights.chunks_exact(4))
                .enumerate()
            {
                if let Some(&joint) = j
                    .iter()
                    .find(|&&j| j < 0.0 || j.fract() != 0.0 || j > f32::from(u16::MAX))
                {
                    return Err(bad(format!(
                        "vertex {vertex}: joint index {joint} is not an integer in 0..=65535"
                    )));
                }
                if let Some(&weight) = w.iter().find(|&&w| w < 0.0) {
                    return Err(bad(format!("vertex {vertex}: negative weight {weight}")));
                }
                influences.push(Influence::normalized(
                    [j[0] as u16, j[1] as u16, j[2] as u16, j[3] as u16],
                    [w[0], w[1], w[2], w[3]],
                ));
            }
            Some(influences)
        }
        (None, None) => None,
        _ => {
            return Err(bad(
                "has JOINTS_0 without WEIGHTS_0 or the reverse".to_string()
            ));
        }
    };
    let mut morph_targets = Vec::new();
    for (k, target) in primitive.targets.iter().flatten().enumerate() {
        let read3 = |index: Option<json::Index<json::Accessor>>, what: &str| {
            index
                .map(|i| {
                    read(i.value(), Type::Vec3, &format!("morph target {k} {what}")).map(vec3s)
                })
                .transpose()
        };
        morph_targets.push(MorphTarget {
            positions: read3(target.positions, "POSITION")?,
            normals: read3(target.normals, "NORMAL")?,
            tangents: read3(target.tangents, "TANGENT")?,
        });
    }
    Ok(AnimPrimitive {
        mode,
        positions: vec3s(positions),
        normals,
        tangents,
        influences,
        morph_targets,
    })
}

/// Refuses a skinned node whose mesh has a vertex that puts weight on a joint its skin does
/// not have. A zero-weight influence is never read, so its index is not checked.
pub(crate) fn check_joints(
    file: &Path,
    nodes: &NodeTree,
    skins: &[Skin],
    meshes: &[AnimMesh],
) -> AnimResult<()> {
    for node in &nodes.nodes {
        let (Some(skin_index), Some(mesh_index)) = (node.skin, node.mesh) else {
            continue;
        };
        let Some(skin) = skins.get(skin_index) else {
            return Err(AnimError::BadSkin {
                file: file.to_path_buf(),
                skin: skin_index,
                message: "is used by a node but does not exist".to_string(),
            });
        };
        let Some(mesh) = meshes.get(mesh_index) else {
            continue;
        };
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            for (vertex, influence) in primitive.influences.iter().flatten().enumerate() {
                for (&joint, &weight) in influence.joints.iter().zip(&influence.weights) {
                    if weight != 0.0 && usize::from(joint) >= skin.joints.len() {
                        return Err(AnimError::JointOutOfRange {
                            file: file.to_path_buf(),
                            mesh: mesh
                                .name
                                .clone()
                                .unwrap_or_else(|| format!("mesh #{mesh_index}")),
                            primitive: p,
                            vertex,
                            joint: u32::from(joint),
                            skin: skin_index,
                            joint_count: skin.joints.len(),
                        });
                    }
                }
            }
        }
    }
    Ok(())
}
