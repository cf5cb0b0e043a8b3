//! Opening a glTF file: the bytes of a `.gltf` or `.glb` in, a validated `gltf::Document` and
//! its buffers out.
//!
//! - GLB files are split by `glb`; the JSON is parsed and validated by the `gltf` crate
//!   (indices in range, enum values known, required fields present), except for the few
//!   errors listed in [`tolerated`].
//! - The asset version must be 2.x. `extensionsRequired` may name only extensions the engine
//!   reads or can safely ignore (`SUPPORTED_REQUIRED`); anything else (Draco, meshopt, WebP,
//!   Basis) is refused with [`AssetError::Unsupported`](crate::assets::AssetError::Unsupported).
//!   Extensions that are used but not required and not read are noted.
//! - Buffers: the GLB BIN chunk, `data:` URIs, or files resolved inside the asset root relative
//!   to the glTF file (a buffer with neither is kept empty: an error only when read). Each must
//!   hold at least its `byteLength` (over [`MAX_BUFFER_BYTES`] is refused before reading) and
//!   is cut to it, so that later bounds checks use the declared size.
//!
//! Must not: read accessors or images (`accessor`, `texture` do).

use gltf::json;

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::limits::MAX_BUFFER_BYTES;
use super::glb::{is_glb, split_glb};
use super::uri::{UriTarget, parse_uri};

/// Required extensions the engine loads (or, for `KHR_texture_transform`, ignores with a note).
const SUPPORTED_REQUIRED: &[&str] = &[
    "EXT_mesh_gpu_instancing",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_texture_transform",
];

/// Extensions whose data the engine reads.
const READ_EXTENSIONS: &[&str] = &[
    "EXT_mesh_gpu_instancing",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
];

/// A parsed glTF file and its buffers (each exactly `byteLength` bytes; `None` for a buffer
/// without data: no `uri` and not the GLB's BIN chunk, an error only when something reads it).
pub(crate) struct GltfFile {
    pub document: gltf::Document,
    pub buffers: Vec<Option<Vec<u8>>>,
}

/// Reads, parses and validates the glTF file of `context`, and loads its buffers.
pub(crate) fn open(context: &mut LoadContext) -> AssetResult<GltfFile> {
    let bytes = context.read_model_file()?;
    let (json_bytes, bin) = if is_glb(&bytes) {
        let glb = split_glb(&bytes).map_err(|message| context.gltf_error(message))?;
        for note in &glb.notes {
            context.warn(note.clone());
        }
        (glb.json, glb.bin)
    } else {
        (&bytes[..], None)
    };
    let mut root: json::Root = json::deserialize::from_slice(json_bytes)
        .map_err(|e| context.gltf_error(format!("invalid JSON: {e}")))?;
    check_version(context, &root)?;
    check_attribute_indices(context, &root)?;
    check_extensions(context, &root)?;
    // Checked above; the `gltf` crate would refuse those it does not enable itself.
    root.extensions_required.clear();
    validate(context, &root)?;
    let document = gltf::Document::from_json_without_validation(root);
    let buffers = load_buffers(context, &document, bin)?;
    Ok(GltfFile { document, buffers })
}

/// Refuses glTF versions other than 2.x.
fn check_version(context: &LoadContext, root: &json::Root) -> AssetResult<()> {
    let major = |version: &str| version.split('.').next().map(str::to_string);
    if major(&root.asset.version).as_deref() != Some("2") {
        return Err(context.unsupported(format!(
            "glTF version {:?} (only 2.x is supported)",
            root.asset.version
        )));
    }
    if let Some(min) = &root.asset.min_version
        && major(min).as_deref() != Some("2")
    {
        return Err(context.unsupported(format!("glTF minVersion {min:?} (only 2.x is supported)")));
    }
    Ok(())
}

/// Runs the `gltf` crate's validation and refuses the file on any error except those the
/// engine handles itself (see [`tolerated`]).
fn validate(context: &mut LoadContext, root: &json::Root) -> AssetResult<()> {
    use json::validation::Validate;
    let mut errors = Vec::new();
    root.validate(root, json::Path::new, &mut |path, error| {
        errors.push((path(), error));
    });
    let (tolerated, refused): (Vec<_>, Vec<_>) = errors
        .into_iter()
        .partition(|(path, error)| tolerated(path.as_str(), error));
    if !refused.is_empty() {
        let message = refused
            .iter()
            .take(5)
            .map(|(path, error)| format!("{path}: {error}"))
            .collect::<Vec<_>>()
            .join("; ");
        return Err(context.gltf_error(format!("invalid glTF: {message}")));
    }
    for (path, error) in tolerated {
        context.note(format!("{path}: {error} (tolerated)"));
    }
    Ok(())
}

/// Validation errors that the `gltf` crate reports but glTF 2.0 allows or the engine does not
/// depend on: an accessor without `bufferView` (all zeros, glTF 2.0 §3.6.2.1), a texture
/// without `source` (allowed when an extension provides the image; such a texture is
/// skipped), a primitive without POSITION (skipped), POSITION bounds (`min`/`max`, which
/// the engine does not use) and an accessor type or component type unknown to glTF 2.0
/// (`accessor` refuses to read such an accessor, so only unused ones pass).
fn tolerated(path: &str, error: &json::validation::Error) -> bool {
    use json::validation::Error;
    let field = |prefix: &str, suffix: &str| path.starts_with(prefix) && path.ends_with(suffix);
    match error {
        Error::Missing => {
            field("accessors[", "].bufferView")
                || field("textures[", "].source")
                || field("meshes[", ".attributes[\"POSITION\"]")
                || field("meshes[", "[\"POSITION\"].min")
                || field("meshes[", "[\"POSITION\"].max")
        }
        Error::Invalid => {
            field("meshes[", "[\"POSITION\"].min")
                || field("meshes[", "[\"POSITION\"].max")
                || field("accessors[", "].type")
                || field("accessors[", "].componentType")
        }
        _ => false,
    }
}

/// Refuses attribute accessor indices out of range. The `gltf` crate's own validation
/// indexes the POSITION accessor unchecked (gltf-json 1.4.1, `primitive_validate_hook`).
fn check_attribute_indices(context: &LoadContext, root: &json::Root) -> AssetResult<()> {
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            for accessor in primitive.attributes.values() {
                if accessor.value() >= root.accessors.len() {
                    return Err(context.gltf_error(format!(
                        "mesh {m} primitive {p}: attribute accessor {} does not exist",
                        accessor.value()
                    )));
                }
            }
        }
    }
    Ok(())
}

/// Refuses unsupported required extensions; notes used extensions that are not read.
fn check_extensions(context: &mut LoadContext, root: &json::Root) -> AssetResult<()> {
    if let Some(required) = root
        .extensions_required
        .iter()
        .find(|e| !SUPPORTED_REQUIRED.contains(&e.as_str()))
    {
        return Err(context.unsupported(format!(
            "requires the glTF extension {required}, which Candela does not support"
        )));
    }
    for used in &root.extensions_used {
        if !READ_EXTENSIONS.contains(&used.as_str()) {
            context.note(format!("glTF extension {used} is not supported: ignored"));
        }
    }
    Ok(())
}

/// Loads every buffer, checking its size against `byteLength`.
fn load_buffers(
    context: &mut LoadContext,
    document: &gltf::Document,
    bin: Option<&[u8]>,
) -> AssetResult<Vec<Option<Vec<u8>>>> {
    let mut buffers: Vec<Option<Vec<u8>>> = Vec::new();
    for (index, buffer) in document.as_json().buffers.iter().enumerate() {
        let declared = buffer.byte_length.0;
        if declared > MAX_BUFFER_BYTES {
            return Err(context.too_large(format!("buffer {index}"), declared, MAX_BUFFER_BYTES));
        }
        let mut data = match buffer.uri.as_deref() {
            None => match bin {
                Some(bin) if index == 0 => bin.to_vec(),
                _ => {
                    buffers.push(None);
                    continue;
                }
            },
            Some(uri) => match parse_uri(uri)
                .map_err(|m| context.gltf_error(format!("buffer {index}: {m}")))?
            {
                UriTarget::Embedded(bytes) => bytes,
                UriTarget::Relative(path) => {
                    let file = context.resolve(&context.folder, &path)?;
                    context.read_referenced(&file)?
                }
            },
        };
        if (data.len() as u64) < declared {
            return Err(context.gltf_error(format!(
                "buffer {index} declares byteLength {declared} but holds only {} bytes",
                data.len()
            )));
        }
        data.truncate(declared as usize);
        buffers.push(Some(data));
    }
    Ok(buffers)
}
