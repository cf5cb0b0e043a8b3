//! glTF textures: a material's texture reference to a deduplicated engine texture.
//!
//! The image comes from a buffer view (GLB, embedded), a `data:` URI, or a file resolved
//! inside the asset root relative to the glTF file. The format is recognised from the bytes
//! (the declared `mimeType` is not trusted). The sampler's wrap modes map to [`Wrap`]
//! (`CLAMP_TO_EDGE` → Clamp, `MIRRORED_REPEAT` → Mirror, `REPEAT` → Repeat) and
//! `magFilter` `NEAREST` to nearest filtering; `minFilter` (mipmapping) is not used.
//! Texture coordinate sets other than 0 and `KHR_texture_transform` are not supported: the
//! texture is sampled with TEXCOORD_0, untransformed, and a note says so.
//! Must not: decode images itself (`assets::texture` does).

use gltf::texture::{MagFilter, WrappingMode};

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::model::{TextureRef, Wrap};
use super::super::texture::{Sampling, TextureSet, Usage};
use super::accessor::Reader;
use super::document::GltfFile;
use super::uri::{UriTarget, parse_uri};

/// What a material's texture reference says besides the texture.
pub(crate) struct TextureUse<'a> {
    pub texture: gltf::Texture<'a>,
    pub tex_coord: u32,
    pub transformed: bool,
}

/// Loads the texture of `texture_use` for `usage`; `what` names the material slot for notes.
/// A texture without an image source (glTF leaves that case to extensions) gives `None`.
pub(crate) fn load_texture(
    context: &mut LoadContext,
    file: &GltfFile,
    textures: &mut TextureSet,
    texture_use: &TextureUse,
    usage: Usage,
    what: &str,
) -> AssetResult<Option<TextureRef>> {
    if texture_use.tex_coord != 0 {
        context.warn(format!(
            "{what} uses TEXCOORD_{}, which is not supported: TEXCOORD_0 used",
            texture_use.tex_coord
        ));
    }
    if texture_use.transformed {
        context.warn(format!(
            "{what}: KHR_texture_transform is not supported: ignored"
        ));
    }
    let texture = &texture_use.texture;
    let sampler = texture.sampler();
    let wrap = |mode: WrappingMode| match mode {
        WrappingMode::ClampToEdge => Wrap::Clamp,
        WrappingMode::MirroredRepeat => Wrap::Mirror,
        WrappingMode::Repeat => Wrap::Repeat,
    };
    let sampling = Sampling {
        wrap_u: wrap(sampler.wrap_s()),
        wrap_v: wrap(sampler.wrap_t()),
        nearest: sampler.mag_filter() == Some(MagFilter::Nearest),
    };
    let json = file.document.as_json();
    let image_index = json.textures.get(texture.index()).map(|t| t.source.value());
    let Some((image_index, image)) =
        image_index.and_then(|i| json.images.get(i).map(|image| (i, image)))
    else {
        context.warn(format!(
            "{what}: texture {} has no image source Candela can read: texture not used",
            texture.index()
        ));
        return Ok(None);
    };
    let name = image
        .uri
        .as_deref()
        .filter(|uri| !uri.starts_with("data:"))
        .map(str::to_string)
        .or_else(|| image.name.clone())
        .map_or_else(
            || format!("image #{image_index}"),
            |n| format!("image #{image_index} ({n})"),
        );
    let source = format!("image #{image_index}");
    textures
        .get_or_load(context, &source, &name, usage, sampling, |context| {
            image_bytes(context, file, image_index)
        })
        .map(Some)
}

/// The encoded bytes of image `index`.
fn image_bytes(context: &mut LoadContext, file: &GltfFile, index: usize) -> AssetResult<Vec<u8>> {
    let json = file.document.as_json();
    let Some(image) = json.images.get(index) else {
        return Err(context.gltf_error(format!("image {index} does not exist")));
    };
    if let Some(view) = image.buffer_view {
        let reader = Reader { context, file };
        let (bytes, _) = reader.view_bytes(view.value())?;
        return Ok(bytes.to_vec());
    }
    let Some(uri) = image.uri.as_deref() else {
        return Err(context.gltf_error(format!("image {index} has neither a uri nor a bufferView")));
    };
    match parse_uri(uri).map_err(|m| context.gltf_error(format!("image {index}: {m}")))? {
        UriTarget::Embedded(bytes) => Ok(bytes),
        UriTarget::Relative(path) => {
            let path = context.resolve(&context.folder, &path)?;
            context.read_referenced(&path)
        }
    }
}
