//! The glTF 2.0 JSON that `gltf_skin` writes for a skinned, animated GLB, as `Serialize`
//! structs: field order is fixed by the declarations (no maps), so the text is the same on
//! every run. Materials, accessors, the asset and the scene are `gltf_json`'s; what is here
//! is what a skinned file adds (joint nodes with rest transforms, skins, JOINTS_0 /
//! WEIGHTS_0 attributes, animations) or writes differently (a buffer with no URI, buffer
//! views without a target). Must not: hold logic beyond `skip_serializing_if` helpers.

use serde::Serialize;

use crate::gltf_json::{Accessor, Asset, Material, Scene};

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct SkinRoot {
    pub(crate) asset: Asset,
    pub(crate) scene: usize,
    pub(crate) scenes: Vec<Scene>,
    pub(crate) nodes: Vec<SkinNode>,
    pub(crate) meshes: Vec<SkinMesh>,
    pub(crate) materials: Vec<Material>,
    pub(crate) skins: Vec<SkinJson>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) animations: Vec<AnimationJson>,
    pub(crate) accessors: Vec<Accessor>,
    pub(crate) buffer_views: Vec<View>,
    pub(crate) buffers: Vec<GlbBuffer>,
}

/// A node: the skinned mesh's (mesh + skin, no transform) or a joint's (rest transform,
/// children).
#[derive(Serialize)]
pub(crate) struct SkinNode {
    pub(crate) name: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) mesh: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) skin: Option<usize>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) children: Vec<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) translation: Option<[f32; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) rotation: Option<[f32; 4]>,
}

#[derive(Serialize)]
pub(crate) struct SkinMesh {
    pub(crate) name: String,
    pub(crate) primitives: Vec<SkinPrimitive>,
}

#[derive(Serialize)]
pub(crate) struct SkinPrimitive {
    pub(crate) attributes: SkinAttributes,
    pub(crate) indices: usize,
    pub(crate) material: usize,
}

#[derive(Serialize)]
pub(crate) struct SkinAttributes {
    #[serde(rename = "POSITION")]
    pub(crate) position: usize,
    #[serde(rename = "NORMAL")]
    pub(crate) normal: usize,
    #[serde(rename = "TEXCOORD_0")]
    pub(crate) texcoord_0: usize,
    #[serde(rename = "JOINTS_0")]
    pub(crate) joints_0: usize,
    #[serde(rename = "WEIGHTS_0")]
    pub(crate) weights_0: usize,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct SkinJson {
    pub(crate) name: String,
    pub(crate) inverse_bind_matrices: usize,
    pub(crate) joints: Vec<usize>,
}

#[derive(Serialize)]
pub(crate) struct AnimationJson {
    pub(crate) name: String,
    pub(crate) channels: Vec<ChannelJson>,
    pub(crate) samplers: Vec<SamplerJson>,
}

#[derive(Serialize)]
pub(crate) struct ChannelJson {
    pub(crate) sampler: usize,
    pub(crate) target: TargetJson,
}

#[derive(Serialize)]
pub(crate) struct TargetJson {
    pub(crate) node: usize,
    pub(crate) path: &'static str,
}

#[derive(Serialize)]
pub(crate) struct SamplerJson {
    pub(crate) input: usize,
    pub(crate) interpolation: &'static str,
    pub(crate) output: usize,
}

/// A buffer view; `target` only for vertex and index data (glTF leaves it out for inverse
/// bind matrices and animation keys).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct View {
    pub(crate) buffer: usize,
    pub(crate) byte_offset: usize,
    pub(crate) byte_length: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) target: Option<u32>,
}

/// The GLB's own binary chunk: no URI.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
pub(crate) struct GlbBuffer {
    pub(crate) byte_length: usize,
}
