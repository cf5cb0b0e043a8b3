//! Loads one glTF file into a [`Model`]: opens it, converts its materials and meshes, and
//! expands its scene into placements.
//!
//! Model layout: `materials` are the file's materials in glTF order, then the glTF default
//! material if some primitive has none; `meshes` are the file's meshes in glTF order, leaving
//! out those without triangles (so every mesh is checked, placed or not: a mesh library without
//! nodes still loads); `placements` follow the scene's depth-first node order, a node with
//! `EXT_mesh_gpu_instancing` giving one placement per instance. Every mesh goes through
//! `mesh_check` and, when it is normal-mapped without tangents, `tangents`.
//! Must not: parse JSON or read accessors itself.

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::limits::MAX_PLACEMENTS;
use super::super::mesh_check::check_mesh;
use super::super::model::{Model, Placement};
use super::super::tangents::ensure_tangents;
use super::super::texture::TextureSet;
use super::accessor::Reader;
use super::document::open;
use super::instancing::instance_transforms;
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
    let mut meshes = Vec::new();
    let mut model_mesh_of: Vec<Option<usize>> = Vec::new();
    let mut placements: Vec<Placement> = Vec::new();
    {
        let reader = Reader {
            context,
            file: &file,
        };
        for gltf_mesh in file.document.meshes() {
            let converted = convert_mesh(
                &reader,
                &mut notes,
                &mut budget,
                &gltf_mesh,
                &mut material_for,
            )?;
            model_mesh_of.push(converted.map(|mesh| {
                meshes.push(mesh);
                meshes.len() - 1
            }));
        }
        for (gltf_index, model_from_mesh, node) in node_placements {
            let Some(mesh) = model_mesh_of.get(gltf_index).copied().flatten() else {
                continue;
            };
            match instance_transforms(&reader, node)? {
                Some(instances) => placements.extend(instances.iter().map(|instance| Placement {
                    mesh,
                    model_from_mesh: model_from_mesh * *instance,
                })),
                None => placements.push(Placement {
                    mesh,
                    model_from_mesh,
                }),
            }
            if placements.len() > MAX_PLACEMENTS {
                return Err(context.too_large(
                    "scene (placed meshes)",
                    placements.len() as u64,
                    MAX_PLACEMENTS as u64,
                ));
            }
        }
    }
    let mut placed = vec![false; meshes.len()];
    for placement in &placements {
        placed[placement.mesh] = true;
    }
    let unplaced = placed.iter().filter(|&&p| !p).count();
    if unplaced > 0 {
        notes.push(format!(
            "{unplaced} mesh(es) not placed by the scene (loaded, without placement)"
        ));
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
