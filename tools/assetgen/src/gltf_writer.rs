//! A small deterministic glTF 2.0 writer: one mesh (one primitive per material) in one node,
//! written as a `.gltf` JSON file plus one `.bin` buffer.
//!
//! Inputs: a [`MeshData`] (positions in metres, right-handed, +Y up; unit normals; TEXCOORD_0
//! with glTF's top-left origin; `u32` triangle lists, one per material) and its
//! [`MaterialSpec`]s. Output: the two files' bytes ([`GltfFiles`]).
//!
//! What the engine's loader (`engine/src/assets/gltf/material.rs`) reads is all that is written:
//! `baseColorFactor` (+ base colour texture, sRGB), metallic and roughness factors,
//! `normalTexture`, `emissiveFactor` (+ emissive texture) with `KHR_materials_emissive_strength` (radiance
//! W·sr⁻¹·m⁻² = factor × strength), `KHR_materials_transmission` and `KHR_materials_ior` for
//! glass. Textures are referenced by URI relative to the `.gltf` file, sampled REPEAT/LINEAR.
//!
//! Deterministic bytes: the JSON comes from the `derive(Serialize)` structs of `gltf_json`
//! (field order fixed, no map iteration), floats are printed by `serde_json` (shortest
//! round-trip form, the same on every machine), and the buffer is little-endian `f32`/`u32` in a fixed layout: positions,
//! normals, texture coordinates, then each primitive's indices. Must not: read files or know
//! about any particular piece.

use crate::gltf_json::{
    Accessor, Asset, Attributes, Buffer, BufferView, EmissiveStrength, Image, Ior, Material,
    MaterialExtensions, Mesh, Node, Pbr, Primitive, Root, Sampler, Scene, Texture, TextureInfo,
    Transmission,
};

/// One material as written to glTF. Colours are linear; `emissive_strength` multiplies
/// `emissive` (so radiance = `emissive` × `emissive_strength`, W·sr⁻¹·m⁻²).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialSpec {
    pub name: String,
    pub base_color: [f32; 4],
    pub base_color_texture: Option<String>,
    pub metallic: f32,
    pub roughness: f32,
    pub emissive: [f32; 3],
    pub emissive_strength: f32,
    pub emissive_texture: Option<String>,
    /// A tangent-space normal map (glTF convention: +X towards +u, +Y towards the top of the
    /// image, stored as `n * 0.5 + 0.5`); the engine generates MikkTSpace tangents for it.
    pub normal_texture: Option<String>,
    /// `Some(ior)`: transmissive glass (transmission 1, metallic must be 0).
    pub glass_ior: Option<f32>,
}

/// Triangle geometry with per-vertex attributes and one index list per material.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub uvs: Vec<[f32; 2]>,
    /// `indices[m]`: the triangles (3 indices each) of material `m`.
    pub indices: Vec<Vec<u32>>,
}

/// The bytes of a written piece.
pub struct GltfFiles {
    pub gltf: Vec<u8>,
    pub bin: Vec<u8>,
}

/// Writes `mesh` with `materials` as `<name>.gltf` (referring to `bin_uri`) and its buffer,
/// naming the Reflect kit as the generator (see [`write_gltf_by`]).
pub fn write_gltf(
    name: &str,
    bin_uri: &str,
    mesh: &MeshData,
    materials: &[MaterialSpec],
) -> anyhow::Result<GltfFiles> {
    write_gltf_by(
        "candela assetgen (reflect-kit)",
        name,
        bin_uri,
        mesh,
        materials,
    )
}

/// Writes `mesh` with `materials` as `<name>.gltf` (referring to `bin_uri`) and its buffer,
/// with `generator` as the asset's generator string.
/// Materials without triangles are still written (their index is kept); primitives are only
/// written for materials that have triangles.
pub fn write_gltf_by(
    generator: &'static str,
    name: &str,
    bin_uri: &str,
    mesh: &MeshData,
    materials: &[MaterialSpec],
) -> anyhow::Result<GltfFiles> {
    let vertex_count = mesh.positions.len();
    anyhow::ensure!(
        mesh.normals.len() == vertex_count && mesh.uvs.len() == vertex_count,
        "{name}: attribute lengths differ"
    );
    anyhow::ensure!(
        mesh.indices.len() == materials.len(),
        "{name}: one index list per material"
    );
    let mut bin = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();

    let mut push_view = |bin: &mut Vec<u8>, bytes: Vec<u8>, target: u32| {
        let offset = bin.len();
        bin.extend_from_slice(&bytes);
        views.push(BufferView {
            buffer: 0,
            byte_offset: offset,
            byte_length: bytes.len(),
            target,
        });
        views.len() - 1
    };
    const ARRAY_BUFFER: u32 = 34962;
    const ELEMENT_ARRAY_BUFFER: u32 = 34963;
    const FLOAT: u32 = 5126;
    const UNSIGNED_INT: u32 = 5125;

    let (min, max) = bounds(&mesh.positions);
    let position_view = push_view(
        &mut bin,
        floats(mesh.positions.iter().flatten()),
        ARRAY_BUFFER,
    );
    accessors.push(Accessor {
        buffer_view: position_view,
        component_type: FLOAT,
        count: vertex_count,
        kind: "VEC3",
        min: Some(min.to_vec()),
        max: Some(max.to_vec()),
    });
    let normal_view = push_view(
        &mut bin,
        floats(mesh.normals.iter().flatten()),
        ARRAY_BUFFER,
    );
    accessors.push(Accessor {
        buffer_view: normal_view,
        component_type: FLOAT,
        count: vertex_count,
        kind: "VEC3",
        min: None,
        max: None,
    });
    let uv_view = push_view(&mut bin, floats(mesh.uvs.iter().flatten()), ARRAY_BUFFER);
    accessors.push(Accessor {
        buffer_view: uv_view,
        component_type: FLOAT,
        count: vertex_count,
        kind: "VEC2",
        min: None,
        max: None,
    });
    let mut primitives = Vec::new();
    for (material, indices) in mesh.indices.iter().enumerate() {
        if indices.is_empty() {
            continue;
        }
        anyhow::ensure!(
            indices.len() % 3 == 0,
            "{name}: index list not in triangles"
        );
        if let Some(bad) = indices.iter().find(|&&i| i as usize >= vertex_count) {
            anyhow::bail!("{name}: index {bad} out of range ({vertex_count} vertices)");
        }
        let bytes = indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = push_view(&mut bin, bytes, ELEMENT_ARRAY_BUFFER);
        accessors.push(Accessor {
            buffer_view: view,
            component_type: UNSIGNED_INT,
            count: indices.len(),
            kind: "SCALAR",
            min: None,
            max: None,
        });
        primitives.push(Primitive {
            attributes: Attributes {
                position: 0,
                normal: 1,
                texcoord_0: 2,
            },
            indices: accessors.len() - 1,
            material,
        });
    }

    // Textures: one image per distinct URI, in first-use order.
    let mut image_uris: Vec<String> = Vec::new();
    let mut texture_of = |uri: &Option<String>| {
        uri.as_ref().map(|uri| {
            let index = image_uris.iter().position(|u| u == uri).unwrap_or_else(|| {
                image_uris.push(uri.clone());
                image_uris.len() - 1
            });
            TextureInfo { index }
        })
    };
    let mut uses_strength = false;
    let mut uses_glass = false;
    let json_materials: Vec<Material> = materials
        .iter()
        .map(|m| {
            let strength = (m.emissive_strength != 1.0).then_some(m.emissive_strength);
            uses_strength |= strength.is_some();
            uses_glass |= m.glass_ior.is_some();
            let emissive = m.emissive != [0.0; 3];
            Material {
                name: m.name.clone(),
                pbr_metallic_roughness: Pbr {
                    base_color_factor: m.base_color,
                    base_color_texture: texture_of(&m.base_color_texture),
                    metallic_factor: m.metallic,
                    roughness_factor: m.roughness,
                },
                normal_texture: texture_of(&m.normal_texture),
                emissive_factor: emissive.then_some(m.emissive),
                emissive_texture: texture_of(&m.emissive_texture),
                extensions: MaterialExtensions {
                    emissive_strength: strength.map(|s| EmissiveStrength {
                        emissive_strength: s,
                    }),
                    transmission: m.glass_ior.map(|_| Transmission {
                        transmission_factor: 1.0,
                    }),
                    ior: m.glass_ior.map(|ior| Ior { ior }),
                },
            }
        })
        .collect();
    let mut extensions_used = Vec::new();
    if uses_strength {
        extensions_used.push("KHR_materials_emissive_strength");
    }
    if uses_glass {
        extensions_used.push("KHR_materials_ior");
        extensions_used.push("KHR_materials_transmission");
    }
    let textures = (0..image_uris.len())
        .map(|source| Texture { sampler: 0, source })
        .collect::<Vec<_>>();
    let root = Root {
        asset: Asset {
            version: "2.0",
            generator,
        },
        extensions_used,
        scene: 0,
        scenes: vec![Scene { nodes: vec![0] }],
        nodes: vec![Node {
            name: name.to_string(),
            mesh: 0,
        }],
        meshes: vec![Mesh {
            name: name.to_string(),
            primitives,
        }],
        materials: json_materials,
        samplers: if textures.is_empty() {
            Vec::new()
        } else {
            vec![Sampler {
                mag_filter: 9729,
                min_filter: 9729,
                wrap_s: 10497,
                wrap_t: 10497,
            }]
        },
        images: image_uris.into_iter().map(|uri| Image { uri }).collect(),
        textures,
        accessors,
        buffer_views: views,
        buffers: vec![Buffer {
            uri: bin_uri.to_string(),
            byte_length: bin.len(),
        }],
    };
    let mut gltf = serde_json::to_vec_pretty(&root)?;
    gltf.push(b'\n');
    Ok(GltfFiles { gltf, bin })
}

fn floats<'a>(values: impl Iterator<Item = &'a f32>) -> Vec<u8> {
    values.flat_map(|v| v.to_le_bytes()).collect()
}

fn bounds(positions: &[[f32; 3]]) -> ([f32; 3], [f32; 3]) {
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for p in positions {
        for k in 0..3 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    if positions.is_empty() {
        return ([0.0; 3], [0.0; 3]);
    }
    (min, max)
}
