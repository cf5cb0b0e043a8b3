//! Joins the parts `tobj` returns for one OBJ object or group (it splits a group at every
//! `usemtl`) into one engine [`Mesh`] with a material per triangle.
//!
//! Inputs: `tobj` meshes (single-indexed, triangulated) with their model material index.
//! Output: a [`Mesh`], positions as written, texture coordinates flipped to the glTF
//! convention (`v' = 1 - v`), normals `None` when no part has `vn` (flat shading), zeros for
//! the vertices of parts without them (flat there); each case noted.
//! Must not: read files or materials.

use glam::{Vec2, Vec3};

use super::context::LoadContext;
use super::model::Mesh;

/// Joins the `tobj` parts of one object or group into one mesh.
pub(crate) struct MeshBuilder {
    /// The object or group name.
    pub name: String,
    mesh: Mesh,
    normals: Vec<Vec3>,
    uvs: Vec<Vec2>,
    parts_with_normals: usize,
    parts_with_uvs: usize,
    parts: usize,
}

impl MeshBuilder {
    /// An empty mesh named after the object or group.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_string(),
            mesh: Mesh {
                name: name.to_string(),
                ..Mesh::default()
            },
            normals: Vec::new(),
            uvs: Vec::new(),
            parts_with_normals: 0,
            parts_with_uvs: 0,
            parts: 0,
        }
    }

    /// Appends one `tobj` part (single-indexed, triangulated) using material `material`.
    pub fn add(&mut self, context: &mut LoadContext, part: &tobj::Mesh, material: u32) {
        let base = self.mesh.positions.len() as u32;
        let count = part.positions.len() / 3;
        self.parts += 1;
        self.mesh.positions.extend(
            part.positions
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0], p[1], p[2])),
        );
        if part.normals.len() == count * 3 && count > 0 {
            self.parts_with_normals += 1;
            self.normals.extend(
                part.normals
                    .chunks_exact(3)
                    .map(|n| Vec3::new(n[0], n[1], n[2])),
            );
        } else {
            if !part.normals.is_empty() {
                context.warn(format!(
                    "object {:?}: only some face corners have a normal (vn): flat shading for this part",
                    self.name
                ));
            }
            self.normals.extend(std::iter::repeat_n(Vec3::ZERO, count));
        }
        if part.texcoords.len() == count * 2 && count > 0 {
            self.parts_with_uvs += 1;
            self.uvs.extend(
                part.texcoords
                    .chunks_exact(2)
                    .map(|t| Vec2::new(t[0], 1.0 - t[1])),
            );
        } else {
            if !part.texcoords.is_empty() {
                context.warn(format!(
                    "object {:?}: only some face corners have texture coordinates (vt): (0, 0) used",
                    self.name
                ));
            }
            self.uvs.extend(std::iter::repeat_n(Vec2::ZERO, count));
        }
        for triangle in part.indices.chunks_exact(3) {
            self.mesh
                .triangles
                .push([triangle[0] + base, triangle[1] + base, triangle[2] + base]);
            self.mesh.triangle_materials.push(material);
        }
    }

    /// The joined mesh, or `None` when it has no triangles (only lines, points or nothing).
    pub fn finish(mut self, context: &mut LoadContext) -> Option<Mesh> {
        if self.mesh.triangles.is_empty() {
            return None;
        }
        if self.parts_with_normals == 0 {
            context.note(format!(
                "mesh {:?} has no normals (vn): flat shading",
                self.name
            ));
        } else {
            if self.parts_with_normals < self.parts {
                context.warn(format!(
                    "mesh {:?}: parts without normals (vn) get zero normals (flat there)",
                    self.name
                ));
            }
            self.mesh.normals = Some(self.normals);
        }
        if self.parts_with_uvs > 0 {
            self.mesh.uvs = Some(self.uvs);
        }
        Some(self.mesh)
    }
}
