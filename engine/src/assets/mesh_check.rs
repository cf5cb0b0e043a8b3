//! The checks every loader runs on every mesh before handing it out, and the repairs that
//! are safe to make.
//!
//! Refused (an [`AssetError::BadMesh`] naming the file, the mesh and the element):
//! non-finite positions (NaN or ±∞), vertex indices out of range, per-vertex arrays whose
//! length differs from the position count, per-triangle material indices out of range, and
//! meshes over [`MAX_MESH_ELEMENTS`] vertices or triangles.
//! Repaired (and noted):
//! - a normal that is non-finite or zero becomes the zero vector, which means "flat here"
//!   (the tracers use the geometric normal); other normals are renormalised to unit length;
//! - a non-finite texture coordinate becomes (0, 0);
//! - a tangent that is non-finite or zero becomes zero (no normal mapping at that vertex);
//!   a `w` other than ±1 becomes the sign of `w` (+1 for 0).
//!
//! Kept: zero-area triangles (the tracers never hit them), counted in a note.
//! Must not: reorder, weld or otherwise change valid geometry.

use super::context::LoadContext;
use super::error::{AssetError, AssetResult};
use super::limits::MAX_MESH_ELEMENTS;
use super::model::Mesh;

/// Checks `mesh` (one of a model with `material_count` materials) and repairs what is safe.
pub(crate) fn check_mesh(
    context: &mut LoadContext,
    mesh: &mut Mesh,
    material_count: usize,
) -> AssetResult<()> {
    let bad = |message: String| AssetError::BadMesh {
        path: context.file.clone(),
        mesh: mesh.name.clone(),
        message,
    };
    let vertex_count = mesh.positions.len();
    let larger = vertex_count.max(mesh.triangles.len()) as u64;
    if larger > MAX_MESH_ELEMENTS {
        return Err(context.too_large(
            format!("mesh {:?} (vertices or triangles)", mesh.name),
            larger,
            MAX_MESH_ELEMENTS,
        ));
    }
    if let Some(vertex) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(bad(format!(
            "vertex {vertex} has a non-finite position {:?}",
            mesh.positions[vertex]
        )));
    }
    for (what, length) in [
        ("normals", mesh.normals.as_ref().map(Vec::len)),
        ("texture coordinates", mesh.uvs.as_ref().map(Vec::len)),
        ("tangents", mesh.tangents.as_ref().map(Vec::len)),
    ] {
        if let Some(length) = length.filter(|&length| length != vertex_count) {
            return Err(bad(format!("{length} {what} for {vertex_count} vertices")));
        }
    }
    if mesh.triangle_materials.len() != mesh.triangles.len() {
        return Err(bad(format!(
            "{} triangle materials for {} triangles",
            mesh.triangle_materials.len(),
            mesh.triangles.len()
        )));
    }
    for (triangle, indices) in mesh.triangles.iter().enumerate() {
        if let Some(&index) = indices.iter().find(|&&i| i as usize >= vertex_count) {
            return Err(bad(format!(
                "triangle {triangle} uses vertex {index}, but the mesh has {vertex_count} vertices"
            )));
        }
    }
    if let Some(triangle) = mesh
        .triangle_materials
        .iter()
        .position(|&m| m as usize >= material_count)
    {
        return Err(bad(format!(
            "triangle {triangle} uses material {}, but the model has {material_count}",
            mesh.triangle_materials[triangle]
        )));
    }
    let name = mesh.name.clone();
    repair_attributes(context, mesh, &name);
    let degenerate = mesh
        .triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            (b - a).cross(c - a).length_squared() == 0.0
        })
        .count();
    if degenerate > 0 {
        context.note(format!(
            "mesh {name:?}: {degenerate} zero-area triangle(s) kept (never hit by rays)"
        ));
    }
    Ok(())
}

/// Normalises normals and fixes non-finite normals, texture coordinates and tangents.
fn repair_attributes(context: &mut LoadContext, mesh: &mut Mesh, name: &str) {
    if let Some(normals) = mesh.normals.as_mut() {
        let mut flat = 0;
        for normal in normals.iter_mut() {
            let length = normal.length();
            if length.is_finite() && length > 0.0 {
                *normal /= length;
            } else {
                *normal = glam::Vec3::ZERO;
                flat += 1;
            }
        }
        if flat > 0 {
            context.warn(format!(
                "mesh {name:?}: {flat} normal(s) zero or non-finite, set to zero (flat shading there)"
            ));
        }
    }
    if let Some(uvs) = mesh.uvs.as_mut() {
        let mut fixed = 0;
        for uv in uvs.iter_mut().filter(|uv| !uv.is_finite()) {
            *uv = glam::Vec2::ZERO;
            fixed += 1;
        }
        if fixed > 0 {
            context.warn(format!(
                "mesh {name:?}: {fixed} non-finite texture coordinate(s) set to (0, 0)"
            ));
        }
    }
    if let Some(tangents) = mesh.tangents.as_mut() {
        let mut fixed = 0;
        for tangent in tangents.iter_mut() {
            let xyz = tangent.truncate();
            let length = xyz.length();
            let sign = if tangent.w < 0.0 { -1.0 } else { 1.0 };
            if length.is_finite() && length > 0.0 && tangent.w.is_finite() {
                *tangent = (xyz / length).extend(sign);
            } else {
                *tangent = glam::Vec4::new(0.0, 0.0, 0.0, 1.0);
                fixed += 1;
            }
        }
        if fixed > 0 {
            context.warn(format!(
                "mesh {name:?}: {fixed} tangent(s) zero or non-finite, set to zero (no normal mapping there)"
            ));
        }
    }
}
