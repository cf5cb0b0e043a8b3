//! The Wavefront OBJ loader: an `.obj` file and its MTL libraries in, a [`Model`] out.
//!
//! OBJ has no units or axes of its own; the engine reads it as right-handed, +Y up, metres
//! (what Blender and most tools write), with no conversion.
//! - Parsing is `tobj` 4 (after `obj_scan` validated indices and removed lines and points),
//!   triangulating polygons as a fan from the first corner: a quad (v0, v1, v2, v3) becomes
//!   (v0, v1, v2) and (v0, v2, v3), exactly as Mitsuba splits it.
//! - One [`Mesh`] per object or group (`o`/`g`; `tobj` splits a group at each `usemtl`, those
//!   parts are joined again), with a material per triangle, and one identity placement each.
//! - Texture coordinates are flipped to the glTF convention (`v' = 1 - v`).
//! - A mesh without `vn` gets `normals: None` (flat shading), with a note. Parts of a mesh
//!   without `vn` get zero normals (flat there), also noted.
//! - `mtllib` files and the textures they name resolve relative to the OBJ's and the MTL's
//!   folders, inside the asset root. A missing MTL is an error, except in an `mtllib`
//!   statement naming several files of which at least one exists (the others are noted).
//! - Faces whose `usemtl` names no known material, or that come before any `usemtl`, get a
//!   default diffuse material (albedo 0.8), with a note.
//!
//! Must not: interpret MTL parameters (`mtl_material` does) or decode images (`texture` does).

use std::cell::RefCell;
use std::collections::HashMap;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use glam::Mat4;

use super::context::LoadContext;
use super::error::{AssetError, AssetResult};
use super::mesh_check::check_mesh;
use super::model::{Material, Mesh, Model, Placement};
use super::mtl::{MtlMaterial, parse_mtl};
use super::mtl_material::to_material;
use super::obj_mesh::MeshBuilder;
use super::obj_scan::scan_obj;
use super::tangents::ensure_tangents;
use super::texture::TextureSet;

/// Loads the OBJ file of `context`.
pub(crate) fn load(context: &mut LoadContext) -> AssetResult<Model> {
    let bytes = context.read_model_file()?;
    let text = String::from_utf8_lossy(&bytes);
    let scan = scan_obj(&text).map_err(|message| context.obj_error(message))?;
    if scan.skipped_lines_and_points > 0 {
        context.note(format!(
            "skipped {} line (l) and point (p) statement(s): only faces are loaded",
            scan.skipped_lines_and_points
        ));
    }
    if scan.short_faces > 0 {
        context.warn(format!(
            "skipped {} face(s) with fewer than three vertices",
            scan.short_faces
        ));
    }
    if scan.dangling_indices > 0 {
        context.warn(format!(
            "{} face corner(s) name a normal or texture coordinate, but the file has none: ignored",
            scan.dangling_indices
        ));
    }
    let libraries = RefCell::new(Libraries::default());
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let parsed = tobj::load_obj_buf(
        &mut Cursor::new(scan.text.as_bytes()),
        &options,
        |requested| load_library(context, &libraries, requested),
    );
    let libraries = libraries.into_inner();
    if let Some(error) = libraries.error {
        return Err(error);
    }
    for note in libraries.notes {
        context.warn(note);
    }
    let (objects, _) = parsed.map_err(|error| context.obj_error(error.to_string()))?;
    for name in &scan.used_materials {
        if !libraries.materials.iter().any(|(m, _)| &m.name == name) {
            context.warn(format!(
                "usemtl {name:?} names no material of the MTL files: default material used"
            ));
        }
    }

    let mut materials = MaterialTable::default();
    let mut textures = TextureSet::default();
    let mut meshes: Vec<Mesh> = Vec::new();
    let mut builder: Option<MeshBuilder> = None;
    for object in &objects {
        let material = materials.index_for(
            context,
            object.mesh.material_id,
            &libraries.materials,
            &mut textures,
        )?;
        if builder.as_ref().is_some_and(|b| b.name != object.name) {
            meshes.extend(builder.take().and_then(|b| b.finish(context)));
        }
        builder
            .get_or_insert_with(|| MeshBuilder::new(&object.name))
            .add(context, &object.mesh, material);
    }
    meshes.extend(builder.take().and_then(|b| b.finish(context)));
    if meshes.is_empty() {
        context.note("the file has no faces");
    }
    let materials = materials.finish(context);
    for mesh in &mut meshes {
        check_mesh(context, mesh, materials.len())?;
        ensure_tangents(context, mesh, &materials);
    }
    let placements = (0..meshes.len())
        .map(|mesh| Placement {
            mesh,
            model_from_mesh: Mat4::IDENTITY,
        })
        .collect();
    Ok(Model {
        name: String::new(),
        meshes,
        materials,
        textures: textures.into_textures(),
        placements,
        notes: Vec::new(),
    })
}

/// The MTL libraries read while `tobj` parses, in `tobj`'s material id order.
#[derive(Default)]
struct Libraries {
    /// Each material with the folder of its MTL file (textures resolve from there).
    materials: Vec<(MtlMaterial, PathBuf)>,
    /// The first error; returned once `tobj` is done.
    error: Option<AssetError>,
    notes: Vec<String>,
}

/// The `tobj` material loader: resolves and parses the files of one `mtllib` statement.
fn load_library(
    context: &LoadContext,
    libraries: &RefCell<Libraries>,
    requested: &Path,
) -> tobj::MTLLoadResult {
    let requested = requested.to_string_lossy();
    match read_libraries(context, &requested) {
        Ok((found, notes)) => {
            let mut libraries = libraries.borrow_mut();
            libraries.notes.extend(notes);
            let names = found
                .iter()
                .map(|(m, _)| tobj::Material {
                    name: m.name.clone(),
                    ..Default::default()
                })
                .collect::<Vec<_>>();
            // `tobj`'s map type (an `AHashMap`) is inferred from its result type.
            let map = names
                .iter()
                .enumerate()
                .map(|(i, m)| (m.name.clone(), i))
                .collect();
            libraries.materials.extend(found);
            Ok((names, map))
        }
        Err(error) => {
            libraries.borrow_mut().error.get_or_insert(error);
            Err(tobj::LoadError::OpenFileFailed)
        }
    }
}

/// Reads the MTL file(s) named by one `mtllib` value: the whole value as one file name, or
/// else its (backslash-escaped) whitespace-separated names.
type Found = (Vec<(MtlMaterial, PathBuf)>, Vec<String>);
fn read_libraries(context: &LoadContext, value: &str) -> AssetResult<Found> {
    let whole = unescape(value.trim());
    if whole.is_empty() {
        return Ok((
            Vec::new(),
            vec!["an mtllib statement names no file".to_string()],
        ));
    }
    let first_try = context.resolve(&context.folder, &whole);
    let names = split_names(value);
    if first_try.is_ok() || names.len() < 2 {
        return Ok((read_library(context, &first_try?, &whole)?, Vec::new()));
    }
    let (mut found, mut notes) = (Vec::new(), Vec::new());
    let mut last_missing = None;
    for name in &names {
        match context.resolve(&context.folder, name) {
            Ok(path) => found.extend(read_library(context, &path, name)?),
            Err(error @ AssetError::MissingFile { .. }) => {
                notes.push(format!(
                    "MTL file {name:?} not found (other files of its mtllib are used)"
                ));
                last_missing = Some(error);
            }
            Err(error) => return Err(error),
        }
    }
    match last_missing {
        Some(error) if found.is_empty() => Err(error),
        _ => Ok((found, notes)),
    }
}

/// Reads and parses one MTL file.
fn read_library(
    context: &LoadContext,
    path: &Path,
    name: &str,
) -> AssetResult<Vec<(MtlMaterial, PathBuf)>> {
    let bytes = context.read_referenced(path)?;
    let materials = parse_mtl(&String::from_utf8_lossy(&bytes))
        .map_err(|message| context.obj_error(format!("MTL file {name:?}: {message}")))?;
    let folder = path
        .parent()
        .map_or_else(|| context.folder.clone(), Path::to_path_buf);
    Ok(materials.into_iter().map(|m| (m, folder.clone())).collect())
}

/// Splits at whitespace not escaped by a backslash, and unescapes.
fn split_names(value: &str) -> Vec<String> {
    let mut names = vec![String::new()];
    let mut chars = value.chars();
    while let Some(c) = chars.next() {
        match c {
            '\\' => match chars.next() {
                Some(next) if next.is_whitespace() => {
                    names.last_mut().into_iter().for_each(|n| n.push(next))
                }
                Some(next) => names.last_mut().into_iter().for_each(|n| {
                    n.push('\\');
                    n.push(next);
                }),
                None => {}
            },
            c if c.is_whitespace() => names.push(String::new()),
            c => names.last_mut().into_iter().for_each(|n| n.push(c)),
        }
    }
    names.retain(|n| !n.is_empty());
    names
}

/// Removes the backslashes that escape whitespace.
fn unescape(value: &str) -> String {
    value.replace("\\ ", " ").replace("\\\t", "\t")
}

/// `tobj` material ids to model material indices, converting each MTL material on first use.
#[derive(Default)]
struct MaterialTable {
    materials: Vec<Material>,
    by_id: HashMap<usize, u32>,
    default: Option<u32>,
    default_uses: usize,
}

impl MaterialTable {
    fn index_for(
        &mut self,
        context: &mut LoadContext,
        id: Option<usize>,
        libraries: &[(MtlMaterial, PathBuf)],
        textures: &mut TextureSet,
    ) -> AssetResult<u32> {
        let known = id.and_then(|id| libraries.get(id).map(|entry| (id, entry)));
        let Some((id, (mtl, folder))) = known else {
            self.default_uses += 1;
            let next = self.materials.len() as u32;
            return Ok(*self.default.get_or_insert_with(|| {
                self.materials.push(Material {
                    name: "default".to_string(),
                    ..Material::default()
                });
                next
            }));
        };
        if let Some(&index) = self.by_id.get(&id) {
            return Ok(index);
        }
        let material = to_material(context, mtl, folder, textures)?;
        let index = self.materials.len() as u32;
        self.materials.push(material);
        self.by_id.insert(id, index);
        Ok(index)
    }

    fn finish(self, context: &mut LoadContext) -> Vec<Material> {
        if self.default.is_some() {
            context.note(format!(
                "{} object part(s) have no known material: default diffuse material (albedo 0.8) used",
                self.default_uses
            ));
        }
        self.materials
    }
}
