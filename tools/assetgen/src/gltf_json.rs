//! The glTF 2.0 JSON schema subset that `gltf_writer` writes, as `Serialize` structs: field
//! order is fixed by the declarations (no maps), so the JSON text is the same on every run.
//! Names follow the glTF spec (camelCase on the wire). Must not: hold logic beyond
//! `skip_serializing_if` helpers.

use serde::Serialize;

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Root {
    pub(crate) asset: Asset,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) extensions_used: Vec<&'static str>,
    pub(crate) scene: usize,
    pub(crate) scenes: Vec<Scene>,
    pub(crate) nodes: Vec<Node>,
    pub(crate) meshes: Vec<Mesh>,
    pub(crate) materials: Vec<Material>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) samplers: Vec<Sampler>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) images: Vec<Image>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) textures: Vec<Texture>,
    pub(crate) accessors: Vec<Accessor>,
    pub(crate) buffer_views: Vec<BufferView>,
    pub(crate) buffers: Vec<Buffer>,
}

#[derive(Serialize)]
pub(crate) struct Asset {
    pub(crate) version: &'static str,
    pub(crate) generator: &'static str,
}

#[derive(Serialize)]
pub(crate) struct Scene {
    pub(crate) nodes: Vec<usize>,
}

#[derive(Serialize)]
pub(crate) struct Node {
    pub(crate) name: String,
    pub(crate) mesh: usize,
}

#[derive(Serialize)]
pub(crate) struct Mesh {
    pub(crate) name: String,
    pub(crate) primitives: Vec<Primitive>,
}

#[derive(Serialize)]
pub(crate) struct Primitive {
    pub(crate) attributes: Attributes,
    pub(crate) indices: usize,
    pub(crate) material: usize,
}

#[derive(Serialize)]
pub(crate) struct Attributes {
    #[serde(rename = "POSITION")]
    pub(crate) position: usize,
    #[serde(rename = "NORMAL")]
    pub(crate) normal: usize,
    #[serde(rename = "TEXCOORD_0")]
    pub(crate) texcoord_0: usize,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Material {
    pub(crate) name: String,
    pub(crate) pbr_metallic_roughness: Pbr,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) normal_texture: Option<TextureInfo>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) emissive_factor: Option<[f32; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) emissive_texture: Option<TextureInfo>,
    #[serde(skip_serializing_if = "MaterialExtensions::is_empty")]
    pub(crate) extensions: MaterialExtensions,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Pbr {
    pub(crate) base_color_factor: [f32; 4],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) base_color_texture: Option<TextureInfo>,
    pub(crate) metallic_factor: f32,
    pub(crate) roughness_factor: f32,
}

#[derive(Serialize)]
pub(crate) struct TextureInfo {
    pub(crate) index: usize,
}

#[derive(Serialize)]
pub(crate) struct MaterialExtensions {
    #[serde(
        rename = "KHR_materials_emissive_strength",
        skip_serializing_if = "Option::is_none"
    )]
    pub(crate) emissive_strength: Option<EmissiveStrength>,
    #[serde(rename = "KHR_materials_ior", skip_serializing_if = "Option::is_none")]
    pub(crate) ior: Option<Ior>,
    #[serde(
        rename = "KHR_materials_transmission",
        skip_serializing_if = "Option::is_none"
    )]
    pub(crate) transmission: Option<Transmission>,
}

impl MaterialExtensions {
    pub(crate) fn is_empty(&self) -> bool {
        self.emissive_strength.is_none() && self.ior.is_none() && self.transmission.is_none()
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct EmissiveStrength {
    pub(crate) emissive_strength: f32,
}

#[derive(Serialize)]
pub(crate) struct Ior {
    pub(crate) ior: f32,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Transmission {
    pub(crate) transmission_factor: f32,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Sampler {
    pub(crate) mag_filter: u32,
    pub(crate) min_filter: u32,
    pub(crate) wrap_s: u32,
    pub(crate) wrap_t: u32,
}

#[derive(Serialize)]
pub(crate) struct Image {
    pub(crate) uri: String,
}

#[derive(Serialize)]
pub(crate) struct Texture {
    pub(crate) sampler: usize,
    pub(crate) source: usize,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Accessor {
    pub(crate) buffer_view: usize,
    pub(crate) component_type: u32,
    pub(crate) count: usize,
    #[serde(rename = "type")]
    pub(crate) kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) min: Option<Vec<f32>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) max: Option<Vec<f32>>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct BufferView {
    pub(crate) buffer: usize,
    pub(crate) byte_offset: usize,
    pub(crate) byte_length: usize,
    pub(crate) target: u32,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct Buffer {
    pub(crate) uri: String,
    pub(crate) byte_length: usize,
}
