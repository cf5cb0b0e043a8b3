//! Tangent generation: MikkTSpace tangents for meshes whose material has a normal map but
//! whose file gave no tangents (glTF 2.0 asks for exactly this).
//!
//! Uses `bevy_mikktspace` (Bevy's safe Rust port, byte-identical to Mikkelsen's reference C
//! code). Texture coordinates are handed over as `(u, 1 - v)`: MikkTSpace and the tools that
//! bake normal maps work with v pointing up the image, while [`Mesh::uvs`] use glTF's v down.
//! With this, tangents match those that glTF exporters store (checked against
//! NormalTangentMirrorTest in the tests below). Output: [`Mesh::tangents`], unit `xyz` with
//! `w` = ±1 the bitangent sign (bitangent = `w · normal × tangent`).
//! Must not: change positions, normals or texture coordinates.

use bevy_mikktspace::{Geometry, TangentSpace, generate_tangents};
use glam::Vec4;

use super::context::LoadContext;
use super::model::{Material, Mesh};

/// Generates tangents for `mesh` when it has none, one of its triangles uses a material with
/// a normal texture, and it has normals and texture coordinates; notes what it did or why not.
pub(crate) fn ensure_tangents(context: &mut LoadContext, mesh: &mut Mesh, materials: &[Material]) {
    if mesh.tangents.is_some() {
        return;
    }
    let normal_mapped = mesh.triangle_materials.iter().any(|&m| {
        materials
            .get(m as usize)
            .is_some_and(|material| material.normal_texture.is_some())
    });
    if !normal_mapped {
        return;
    }
    if mesh.normals.is_none() || mesh.uvs.is_none() {
        context.warn(format!(
            "mesh {:?} uses a normal map but has no {}: the normal map has no effect",
            mesh.name,
            if mesh.normals.is_none() {
                "normals"
            } else {
                "texture coordinates"
            }
        ));
        return;
    }
    mesh.tangents = Some(mikktspace_tangents(mesh));
    context.note(format!("generated tangents for mesh {:?}", mesh.name));
}

/// MikkTSpace tangents for a mesh with normals and texture coordinates (zero where MikkTSpace
/// gives none, e.g. isolated degenerate triangles).
pub(crate) fn mikktspace_tangents(mesh: &Mesh) -> Vec<Vec4> {
    let mut geometry = MikkGeometry {
        mesh,
        tangents: vec![Vec4::new(0.0, 0.0, 0.0, 1.0); mesh.positions.len()],
    };
    // The error type of bevy_mikktspace 1.0 has no variants: generation cannot fail.
    if generate_tangents(&mut geometry).is_err() {
        log::warn!("mesh {:?}: MikkTSpace failed", mesh.name);
    }
    geometry.tangents
}

/// The view of a [`Mesh`] that MikkTSpace reads and writes.
struct MikkGeometry<'a> {
    mesh: &'a Mesh,
    tangents: Vec<Vec4>,
}

impl MikkGeometry<'_> {
    fn vertex(&self, face: usize, vert: usize) -> usize {
        self.mesh.triangles[face][vert] as usize
    }
}

impl Geometry for MikkGeometry<'_> {
    fn num_faces(&self) -> usize {
        self.mesh.triangles.len()
    }

    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }

    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.mesh.positions[self.vertex(face, vert)].to_array()
    }

    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        let vertex = self.vertex(face, vert);
        self.mesh
            .normals
            .as_ref()
            .map_or([0.0; 3], |normals| normals[vertex].to_array())
    }

    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        let vertex = self.vertex(face, vert);
        self.mesh
            .uvs
            .as_ref()
            .map_or([0.0; 2], |uvs| [uvs[vertex].x, 1.0 - uvs[vertex].y])
    }

    fn set_tangent(&mut self, tangent_space: Option<TangentSpace>, face: usize, vert: usize) {
        if let Some(tangent_space) = tangent_space {
            let vertex = self.vertex(face, vert);
            self.tangents[vertex] = Vec4::from_array(tangent_space.tangent_encoded());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regenerates the tangents NormalTangentMirrorTest ships and compares: same direction
    /// (within a few degrees) and the same bitangent sign on nearly every vertex.
    #[test]
    fn generated_tangents_match_the_ones_gltf_exporters_store()
    -> Result<(), Box<dyn std::error::Error>> {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../shared/external/gltf/NormalTangentMirrorTest/glTF-Binary/NormalTangentMirrorTest.glb"
        );
        let model = crate::assets::load_model_file(std::path::Path::new(path))?;
        let (mut compared, mut agree) = (0usize, 0usize);
        for mesh in &model.meshes {
            let Some(shipped) = mesh.tangents.as_ref() else {
                continue;
            };
            let generated = mikktspace_tangents(mesh);
            for (s, g) in shipped.iter().zip(&generated) {
                compared += 1;
                if s.w == g.w && s.truncate().dot(g.truncate()) > 0.99 {
                    agree += 1;
                }
            }
        }
        assert!(compared > 1000, "only {compared} tangents compared");
        assert!(
            agree as f64 >= 0.95 * compared as f64,
            "{agree} of {compared} generated tangents agree with the shipped ones"
        );
        Ok(())
    }
}
