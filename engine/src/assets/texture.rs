//! Texture decoding and deduplication: image bytes (PNG, JPEG, and the other formats the
//! `image` crate is built with) in, linear RGBA f16 [`Texture`]s out.
//!
//! Colour textures (base colour, emission) are stored sRGB-encoded in files and decoded here
//! with the exact sRGB EOTF (IEC 61966-2-1): `c ≤ 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055)^2.4`.
//! Data textures (normal maps, metallic-roughness) are taken as they are (identity). Alpha is
//! always linear. Floating-point images (Radiance HDR) are linear already and never re-encoded.
//! OBJ bump maps are decoded as data and handed to `bump` (height map → normal map).
//!
//! Within one model a texture is decoded once per (source, usage) and stored once per
//! (source, usage, sampler). Sizes over [`MAX_TEXTURE_SIDE`] per side or
//! [`MAX_TEXTURE_TEXELS`] in all are refused before decoding.
//! Must not: know which file format referenced the texture, or upload anything.

use std::collections::HashMap;
use std::io::Cursor;
use std::sync::Arc;

use half::f16;
use image::{DynamicImage, ImageReader};

use super::bump;
use super::context::LoadContext;
use super::error::{AssetError, AssetResult};
use super::limits::{MAX_DECODE_ALLOC_BYTES, MAX_TEXTURE_SIDE, MAX_TEXTURE_TEXELS};
use super::model::{Texture, TextureRef, Wrap};

/// What a texture is used for, which decides its decoding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Usage {
    /// sRGB-encoded colour (base colour, emission): decoded with the sRGB EOTF.
    Color,
    /// Linear data (normal maps, metallic-roughness): taken as is.
    Data,
    /// An OBJ `bump` map: a greyscale image is a height map and becomes a tangent-space
    /// normal map (see `bump`); a coloured one is taken as a normal map.
    Bump,
}

/// How a texture is sampled (part of the deduplication key).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct Sampling {
    pub wrap_u: Wrap,
    pub wrap_v: Wrap,
    pub nearest: bool,
}

/// Decoded texels shared by the textures that sample one source with different samplers.
struct Decoded {
    width: u32,
    height: u32,
    texels: Vec<[f16; 4]>,
}

/// The textures of one model, deduplicated.
#[derive(Default)]
pub(crate) struct TextureSet {
    textures: Vec<Texture>,
    by_key: HashMap<(String, Usage, Sampling), usize>,
    decoded: HashMap<(String, Usage), Arc<Decoded>>,
}

impl TextureSet {
    /// Returns the texture for `source` (a key unique within the model: a canonical path or an
    /// image index) with `usage` and `sampling`, decoding the bytes from `read` on first use.
    /// `name` is shown in messages and stored as [`Texture::name`].
    pub fn get_or_load(
        &mut self,
        context: &mut LoadContext,
        source: &str,
        name: &str,
        usage: Usage,
        sampling: Sampling,
        read: impl FnOnce(&mut LoadContext) -> AssetResult<Vec<u8>>,
    ) -> AssetResult<TextureRef> {
        let key = (source.to_string(), usage, sampling);
        if let Some(&index) = self.by_key.get(&key) {
            return Ok(TextureRef(index));
        }
        let decoded_key = (source.to_string(), usage);
        let decoded = match self.decoded.get(&decoded_key) {
            Some(decoded) => Arc::clone(decoded),
            None => {
                let bytes = read(context)?;
                let decoded = Arc::new(decode(context, name, &bytes, usage)?);
                self.decoded.insert(decoded_key, Arc::clone(&decoded));
                decoded
            }
        };
        let index = self.textures.len();
        self.textures.push(Texture {
            name: name.to_string(),
            width: decoded.width,
            height: decoded.height,
            texels: decoded.texels.clone(),
            wrap_u: sampling.wrap_u,
            wrap_v: sampling.wrap_v,
            nearest: sampling.nearest,
        });
        self.by_key.insert(key, index);
        Ok(TextureRef(index))
    }

    /// The textures, in [`TextureRef`] order.
    pub fn into_textures(self) -> Vec<Texture> {
        self.textures
    }
}

/// The sRGB EOTF (IEC 61966-2-1): an encoded value in [0, 1] to linear.
pub(crate) fn srgb_to_linear(encoded: f32) -> f32 {
    if encoded <= 0.04045 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// Decodes `bytes` (the texture `name` of the model being loaded) for `usage`.
fn decode(
    context: &mut LoadContext,
    name: &str,
    bytes: &[u8],
    usage: Usage,
) -> AssetResult<Decoded> {
    let image = decode_image(context, name, bytes)?;
    let (width, height) = (image.width(), image.height());
    let grey = matches!(
        image.color(),
        image::ColorType::L8
            | image::ColorType::La8
            | image::ColorType::L16
            | image::ColorType::La16
    );
    let texels = to_linear_f16(image, usage == Usage::Color);
    let texels = if usage == Usage::Bump {
        if grey || texels.iter().all(|t| t[0] == t[1] && t[1] == t[2]) {
            context.note(format!(
                "bump map {name:?} is greyscale: taken as a height map and converted to a \
                 tangent-space normal map (slope = height difference per texel × bump multiplier)"
            ));
            bump::height_to_normal(width, height, &texels)
        } else {
            context.note(format!(
                "bump map {name:?} has colour: taken as a tangent-space normal map"
            ));
            texels
        }
    } else {
        texels
    };
    Ok(Decoded {
        width,
        height,
        texels,
    })
}

/// Reads the header, refuses absurd sizes, then decodes with allocation limits.
fn decode_image(context: &LoadContext, name: &str, bytes: &[u8]) -> AssetResult<DynamicImage> {
    let error = |message: String| AssetError::Texture {
        path: context.file.clone(),
        texture: name.to_string(),
        message,
    };
    let reader = || -> AssetResult<ImageReader<Cursor<&[u8]>>> {
        let mut reader = ImageReader::new(Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| error(e.to_string()))?;
        if reader.format().is_none() {
            // Formats without a magic number (TGA) are known by the file's extension.
            match image::ImageFormat::from_path(name) {
                Ok(format) => reader.set_format(format),
                Err(_) => return Err(error("unknown image format".to_string())),
            }
        }
        Ok(reader)
    };
    let (width, height) = reader()?
        .into_dimensions()
        .map_err(|e| error(e.to_string()))?;
    let texels = u64::from(width) * u64::from(height);
    if width > MAX_TEXTURE_SIDE || height > MAX_TEXTURE_SIDE || texels > MAX_TEXTURE_TEXELS {
        return Err(context.too_large(
            format!(
                "texture {name:?} ({width} × {height} texels; at most {MAX_TEXTURE_SIDE} per side)"
            ),
            texels,
            MAX_TEXTURE_TEXELS,
        ));
    }
    if texels == 0 {
        return Err(error("the image has no texels".to_string()));
    }
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_TEXTURE_SIDE);
    limits.max_image_height = Some(MAX_TEXTURE_SIDE);
    limits.max_alloc = Some(MAX_DECODE_ALLOC_BYTES);
    let mut reader = reader()?;
    reader.limits(limits);
    reader.decode().map_err(|e| error(e.to_string()))
}

/// Converts to linear RGBA f16, applying the sRGB EOTF to integer colour channels when `srgb`.
fn to_linear_f16(image: DynamicImage, srgb: bool) -> Vec<[f16; 4]> {
    use image::ColorType as C;
    match image.color() {
        C::L8 | C::La8 | C::Rgb8 | C::Rgba8 => {
            let table: [f16; 256] = std::array::from_fn(|i| {
                let encoded = i as f32 / 255.0;
                f16::from_f32(if srgb {
                    srgb_to_linear(encoded)
                } else {
                    encoded
                })
            });
            let alpha: [f16; 256] = std::array::from_fn(|i| f16::from_f32(i as f32 / 255.0));
            image
                .to_rgba8()
                .pixels()
                .map(|p| {
                    let [r, g, b, a] = p.0;
                    [
                        table[usize::from(r)],
                        table[usize::from(g)],
                        table[usize::from(b)],
                        alpha[usize::from(a)],
                    ]
                })
                .collect()
        }
        C::L16 | C::La16 | C::Rgb16 | C::Rgba16 => {
            let channel = |value: u16| {
                let encoded = f32::from(value) / 65535.0;
                f16::from_f32(if srgb {
                    srgb_to_linear(encoded)
                } else {
                    encoded
                })
            };
            image
                .to_rgba16()
                .pixels()
                .map(|p| {
                    let [r, g, b, a] = p.0;
                    [
                        channel(r),
                        channel(g),
                        channel(b),
                        f16::from_f32(f32::from(a) / 65535.0),
                    ]
                })
                .collect()
        }
        // Floating-point images hold linear values already; clamp into the f16 range.
        _ => {
            let channel = |value: f32| {
                if value.is_finite() {
                    f16::from_f32(value.clamp(-65504.0, 65504.0))
                } else {
                    f16::ZERO
                }
            };
            image
                .to_rgba32f()
                .pixels()
                .map(|p| {
                    let [r, g, b, a] = p.0;
                    [channel(r), channel(g), channel(b), channel(a)]
                })
                .collect()
        }
    }
}
