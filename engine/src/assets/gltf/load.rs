//! Loads one glTF file into a [`Model`]: opens it, converts its materials, expands its scene
//! and converts the meshes the scene places (meshes no node of the scene uses are not loaded).
//!
//! Model layout: `materials` are the file's materials in glTF order, then the glTF default
//! material if some primitive has none; `meshes` are the placed glTF meshes in order of first
//! placement; `placements` follow the scene's depth-first node order. Every mesh goes through
//! `mesh_check` and, when it is normal-mapped without tangents, `tangents`.
//! Must not: parse JSON or read accessors itself.

use std::collections::HashMap;

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::mesh_check::check_mesh;
use super::super::model::{Model, Placement};
use super::super::tangents::ensure_tangents;
use super::super::texture::TextureSet;
use super::accessor::Reader;
use super::document::open;
use super::material::{convert_materials, default_material};
use super::mesh::{Budget, convert_mesh};
use super::nodes::place_meshes;

/// Loads the glTF or GLB file of `context`.
pub(crate) fn load(context: &mut LoadContext) -> AssetResult<Model> {
    let file = open(context)?;
    let mut textures = TextureSet::default();
    let mut materials = convert_materials(context, &file, &mut textures)?;
    let node_placements = place_meshes(context, &file.document)?;

    let material_count = materials.len();
    let mut default_index: Option<u32> = None;
    let mut material_for = |index: Option<usize>| -> u32 {
        match index {
            Some(index) if index < material_count => index as u32,
            _ => *default_index.get_or_insert(material_count as u32),
        }
    };
    let mut notes = Vec::new();
    let mut budget = Budget::default();
    let mut model_mesh_of: HashMap<usize, Option<usize>> = HashMap::new();
    let mut meshes = Vec::new();
    let mut placements = Vec::new();
    {
        let reader = Reader {
            context,
            file: &file,
        };
        for (gltf_index, model_from_mesh) in node_placements {
            let mesh = match model_mesh_of.get(&gltf_index) {
                Some(&known) => known,
                None => {
                    let converted = match file.document.meshes().nth(gltf_index) {
                        Some(gltf_mesh) => convert_mesh(
                            &reader,
                            &mut notes,
                            &mut budget,
                            &gltf_mesh,
                            &mut material_for,
                        )?,
                        None => None,
                    };
                    let index = converted.map(|mesh| {
                        meshes.push(mesh);
                        meshes.len() - 1
                    });
                    model_mesh_of.insert(gltf_index, index);
                    index
                }
            };
            if let Some(mesh) = mesh {
                placements.push(Placement {
                    mesh,
                    model_from_mesh,
                });
            }
        }
    }
    for note in notes {
        context.note(note);
    }
    if default_index.is_some() {
        materials.push(default_material());
        context.note("some primitives have no material: the glTF default material is used");
    }
    for mesh in &mut meshes {
        check_mesh(context, mesh, materials.len())?;
        ensure_tangents(context, mesh, &materials);
    }
    Ok(Model {
        name: String::new(),
        meshes,
        materials,
        textures: textures.into_textures(),
        placements,
        notes: Vec::new(),
    })
}
