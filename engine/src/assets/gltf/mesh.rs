//! glTF meshes to engine [`Mesh`]es: one engine mesh per glTF mesh, its primitives joined,
//! each triangle keeping its primitive's material.
//!
//! - Modes TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become triangles (strip and fan
//!   winding as glTF 2.0 §3.7.2.1 defines); POINTS and LINES* primitives are skipped (noted).
//! - Indexed and non-indexed primitives; accessors are read by `accessor` (dense, sparse,
//!   normalized or quantized integers).
//! - Attributes: POSITION (VEC3; a primitive without it is skipped), NORMAL (VEC3), TEXCOORD_0
//!   (VEC2, glTF convention already), TANGENT (VEC4). Each must have the position count.
//!   When only some primitives of a mesh have normals, texture coordinates or tangents, the
//!   others get zeros (normals: flat; tangents: none) and a note. Other sets (TEXCOORD_1+,
//!   COLOR_0, JOINTS/WEIGHTS) and morph targets are not used (noted).
//!
//! Must not: place meshes (`nodes`) or check them (`mesh_check` runs afterwards).

use glam::{Vec2, Vec3, Vec4};
use gltf::Semantic;
use gltf::json::accessor::Type;
use gltf::mesh::Mode;

use super::super::context::LoadContext;
use super::super::error::{AssetError, AssetResult};
use super::super::limits::MAX_MODEL_ELEMENTS;
use super::super::model::Mesh;
use super::accessor::Reader;

/// Counts elements against [`MAX_MODEL_ELEMENTS`] across the meshes of one model.
#[derive(Default)]
pub(crate) struct Budget {
    used: u64,
}

/// Converts glTF mesh `gltf_mesh`. `material_for` maps a primitive's material index (`None`
/// for none) to the model's material index. Returns `None` when no primitive has triangles.
pub(crate) fn convert_mesh(
    reader: &Reader,
    notes: &mut Vec<String>,
    budget: &mut Budget,
    gltf_mesh: &gltf::Mesh,
    mut material_for: impl FnMut(Option<usize>) -> u32,
) -> AssetResult<Option<Mesh>> {
    let context: &LoadContext = reader.context;
    let name = gltf_mesh
        .name()
        .map_or_else(|| format!("mesh #{}", gltf_mesh.index()), str::to_string);
    let mut mesh = Mesh {
        name: name.clone(),
        ..Mesh::default()
    };
    let (mut normals, mut uvs, mut tangents) = (Vec::new(), Vec::new(), Vec::new());
    let (mut with_normals, mut with_uvs, mut with_tangents, mut parts) = (0, 0, 0, 0);
    let mut unused = Vec::new();
    for primitive in gltf_mesh.primitives() {
        let mode = primitive.mode();
        if !matches!(
            mode,
            Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
        ) {
            notes.push(format!(
                "mesh {name:?}: a {mode:?} primitive skipped (only triangles are loaded)"
            ));
            continue;
        }
        let Some(position_accessor) = primitive.get(&Semantic::Positions) else {
            notes.push(format!(
                "mesh {name:?}: a primitive without POSITION skipped"
            ));
            continue;
        };
        let (positions, _) =
            reader.read_floats(position_accessor.index(), &[Type::Vec3], "POSITION")?;
        let count = positions.len() / 3;
        let read = |semantic: Semantic, kind: Type, what: &str| -> AssetResult<Option<Vec<f32>>> {
            let Some(accessor) = primitive.get(&semantic) else {
                return Ok(None);
            };
            let (values, components) = reader.read_floats(accessor.index(), &[kind], what)?;
            if values.len() / components != count {
                return Err(context.gltf_error(format!(
                    "mesh {name:?}: {what} has {} elements for {count} positions",
                    values.len() / components
                )));
            }
            Ok(Some(values))
        };
        let primitive_normals = read(Semantic::Normals, Type::Vec3, "NORMAL")?;
        let primitive_uvs = read(Semantic::TexCoords(0), Type::Vec2, "TEXCOORD_0")?;
        let primitive_tangents = read(Semantic::Tangents, Type::Vec4, "TANGENT")?;
        let indices = match primitive.indices() {
            Some(accessor) => reader.read_indices(accessor.index())?,
            None => (0..count as u32).collect(),
        };
        // Checked per primitive: after joining, a bad index could name another primitive's vertex.
        if let Some(&bad) = indices.iter().find(|&&i| i as usize >= count) {
            return Err(AssetError::BadMesh {
                path: context.file.clone(),
                mesh: name,
                message: format!("index {bad} is out of range ({count} vertices in the primitive)"),
            });
        }
        let triangles = assemble(mode, &indices);
        budget.used += (count + triangles.len()) as u64;
        if budget.used > MAX_MODEL_ELEMENTS {
            return Err(context.too_large(
                "model (vertices + triangles)",
                budget.used,
                MAX_MODEL_ELEMENTS,
            ));
        }
        for (semantic, _) in primitive.attributes() {
            let label = semantic.to_string();
            if !matches!(
                label.as_str(),
                "POSITION" | "NORMAL" | "TEXCOORD_0" | "TANGENT"
            ) && !unused.contains(&label)
            {
                unused.push(label);
            }
        }
        if primitive.morph_targets().len() > 0 && !unused.iter().any(|u| u == "morph targets") {
            unused.push("morph targets".to_string());
        }

        parts += 1;
        let base = mesh.positions.len() as u32;
        mesh.positions
            .extend(positions.chunks_exact(3).map(Vec3::from_slice));
        match primitive_normals {
            Some(values) => {
                with_normals += 1;
                normals.extend(values.chunks_exact(3).map(Vec3::from_slice));
            }
            None => normals.extend(std::iter::repeat_n(Vec3::ZERO, count)),
        }
        match primitive_uvs {
            Some(values) => {
                with_uvs += 1;
                uvs.extend(values.chunks_exact(2).map(Vec2::from_slice));
            }
            None => uvs.extend(std::iter::repeat_n(Vec2::ZERO, count)),
        }
        match primitive_tangents {
            Some(values) => {
                with_tangents += 1;
                tangents.extend(values.chunks_exact(4).map(Vec4::from_slice));
            }
            None => tangents.extend(std::iter::repeat_n(Vec4::new(0.0, 0.0, 0.0, 1.0), count)),
        }
        let material = material_for(primitive.material().index());
        mesh.triangles
            .extend(triangles.iter().map(|t| t.map(|i| i + base)));
        mesh.triangle_materials
            .extend(std::iter::repeat_n(material, triangles.len()));
    }
    if !unused.is_empty() {
        notes.push(format!("mesh {name:?}: not used: {}", unused.join(", ")));
    }
    if mesh.triangles.is_empty() {
        return Ok(None);
    }
    for (with, what) in [
        (with_normals, "normals"),
        (with_uvs, "texture coordinates"),
        (with_tangents, "tangents"),
    ] {
        if with > 0 && with < parts {
            notes.push(format!(
                "mesh {name:?}: {with} of {parts} primitives have {what}; the others get zeros"
            ));
        }
    }
    mesh.normals = (with_normals > 0).then_some(normals);
    mesh.uvs = (with_uvs > 0).then_some(uvs);
    mesh.tangents = (with_tangents == parts).then_some(tangents);
    if mesh.normals.is_none() {
        notes.push(format!("mesh {name:?} has no normals: flat shading"));
    }
    Ok(Some(mesh))
}

/// Triangles from a primitive's index list.
fn assemble(mode: Mode, indices: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        Mode::TriangleStrip => (0..indices.len().saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [indices[i], indices[i + 1], indices[i + 2]]
                } else {
                    [indices[i], indices[i + 2], indices[i + 1]]
                }
            })
            .collect(),
        Mode::TriangleFan => (1..indices.len().saturating_sub(1))
            .map(|i| [indices[i], indices[i + 1], indices[0]])
            .collect(),
        _ => indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect(),
    }
}
