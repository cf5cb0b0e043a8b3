//! A deterministic writer of skinned, animated glTF 2.0 binaries (`.glb`): one skinned mesh
//! (one primitive per material, each with its own vertices), one skin over a joint tree, and
//! animations of the joints' translation and rotation with LINEAR samplers.
//!
//! Inputs: [`SkinnedPart`]s (positions in metres in the bind pose, right-handed, +Y up; unit
//! normals; TEXCOORD_0; up to four joint influences per vertex), [`JointSpec`]s (parents
//! before children; rest translation in metres and rotation as an (x, y, z, w) unit
//! quaternion, relative to the parent) and [`ClipSpec`]s (key times in seconds). The inverse
//! bind matrices are the inverses of the joints' rest world matrices, so the file at rest
//! shows the mesh as given. Output: the `.glb` bytes.
//!
//! File layout: node 0 is the mesh node (mesh 0, skin 0, no transform: glTF ignores a skinned
//! node's own transform), node `1 + j` is joint `j`; the scene lists node 0 and the root
//! joints. JOINTS_0 is `u8` when there are at most 256 joints, else `u16`; WEIGHTS_0 is
//! `f32`. The buffer holds, in order: each part's positions, normals, texture coordinates,
//! joints, weights and indices, then the inverse bind matrices, then each clip's key times
//! and each channel's values; `gltf_skin_bin` packs it and the GLB container.
//!
//! Deterministic bytes: the JSON comes from the `derive(Serialize)` structs of
//! `gltf_skin_json`, written compact by `serde_json`; the buffer is little-endian. Must not:
//! read files, or write textures, glass or emission strength (the hero has none; a
//! [`MaterialSpec`] asking for them is refused).

use glam::{Mat4, Quat, Vec3};

use crate::gltf_json::{Asset, Material, MaterialExtensions, Pbr, Scene};
use crate::gltf_skin_bin::{
    ARRAY_BUFFER, Bin, ELEMENT_ARRAY_BUFFER, FLOAT, UNSIGNED_BYTE, UNSIGNED_INT, UNSIGNED_SHORT,
    bounds, floats, glb,
};
use crate::gltf_skin_json::{
    AnimationJson, ChannelJson, GlbBuffer, SamplerJson, SkinAttributes, SkinJson, SkinMesh,
    SkinNode, SkinPrimitive, SkinRoot, TargetJson,
};
use crate::gltf_writer::MaterialSpec;

/// The vertices and triangles of one material of the skinned mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SkinnedPart {
    /// Index into the materials given to [`write_skinned_glb`].
    pub material: usize,
    /// Metres, bind pose.
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub uvs: Vec<[f32; 2]>,
    /// Joint indices (into the joint list) of each vertex.
    pub joints: Vec<[u16; 4]>,
    /// Their weights, summing to 1.
    pub weights: Vec<[f32; 4]>,
    /// Triangles, three indices each, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
}

/// One joint of the skeleton.
#[derive(Clone, Debug, PartialEq)]
pub struct JointSpec {
    pub name: String,
    /// An earlier joint, or `None` for a root.
    pub parent: Option<usize>,
    /// Rest translation relative to the parent, metres.
    pub translation: [f32; 3],
    /// Rest rotation relative to the parent, (x, y, z, w).
    pub rotation: [f32; 4],
}

/// What a channel animates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChannelPath {
    /// Metres, three values per key.
    Translation,
    /// (x, y, z, w) unit quaternions, four values per key.
    Rotation,
}

/// One animated property of one joint; one value per key of its clip.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelSpec {
    pub joint: usize,
    pub path: ChannelPath,
    /// Flat: 3 (translation) or 4 (rotation) values per key.
    pub values: Vec<f32>,
}

/// One animation: its key times (seconds, increasing, shared by every channel) and channels.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipSpec {
    pub name: String,
    pub times: Vec<f32>,
    pub channels: Vec<ChannelSpec>,
}

fn material_json(m: &MaterialSpec) -> anyhow::Result<Material> {
    anyhow::ensure!(
        m.base_color_texture.is_none()
            && m.emissive_texture.is_none()
            && m.normal_texture.is_none()
            && m.glass_ior.is_none()
            && m.emissive_strength == 1.0,
        "material {}: the skinned writer writes factors only",
        m.name
    );
    Ok(Material {
        name: m.name.clone(),
        pbr_metallic_roughness: Pbr {
            base_color_factor: m.base_color,
            base_color_texture: None,
            metallic_factor: m.metallic,
            roughness_factor: m.roughness,
        },
        normal_texture: None,
        emissive_factor: (m.emissive != [0.0; 3]).then_some(m.emissive),
        emissive_texture: None,
        extensions: MaterialExtensions {
            emissive_strength: None,
            ior: None,
            transmission: None,
        },
    })
}

/// Rest world matrices of `joints` (parents come first).
pub fn rest_world(joints: &[JointSpec]) -> anyhow::Result<Vec<Mat4>> {
    let mut world: Vec<Mat4> = Vec::with_capacity(joints.len());
    for (j, joint) in joints.iter().enumerate() {
        let local = Mat4::from_rotation_translation(
            Quat::from_array(joint.rotation),
            Vec3::from(joint.translation),
        );
        world.push(match joint.parent {
            None => local,
            Some(p) if p < j => world[p] * local,
            Some(p) => anyhow::bail!("joint {}: parent {p} does not come first", joint.name),
        });
    }
    Ok(world)
}

/// Checks one part's attribute lengths, indices and joint references.
fn check_part(p: usize, part: &SkinnedPart, joints: usize, materials: usize) -> anyhow::Result<()> {
    let n = part.positions.len();
    anyhow::ensure!(
        [
            part.normals.len(),
            part.uvs.len(),
            part.joints.len(),
            part.weights.len()
        ]
        .iter()
        .all(|&len| len == n),
        "part {p}: attribute lengths differ"
    );
    anyhow::ensure!(part.material < materials, "part {p}: no such material");
    anyhow::ensure!(
        !part.indices.is_empty() && part.indices.len().is_multiple_of(3),
        "part {p}: no triangles, or an index list not in triangles"
    );
    anyhow::ensure!(
        part.indices.iter().all(|&i| (i as usize) < n),
        "part {p}: an index out of range"
    );
    anyhow::ensure!(
        part.joints
            .iter()
            .flatten()
            .all(|&j| usize::from(j) < joints),
        "part {p}: a joint index out of range"
    );
    Ok(())
}

/// Writes `name` (the mesh, its skin and the GLB's generator text) as a `.glb`.
pub fn write_skinned_glb(
    name: &str,
    parts: &[SkinnedPart],
    materials: &[MaterialSpec],
    joints: &[JointSpec],
    clips: &[ClipSpec],
) -> anyhow::Result<Vec<u8>> {
    anyhow::ensure!(!joints.is_empty(), "{name}: a skin needs joints");
    let world = rest_world(joints)?;
    let mut bin = Bin::default();
    let mut primitives = Vec::with_capacity(parts.len());
    for (p, part) in parts.iter().enumerate() {
        check_part(p, part, joints.len(), materials.len())?;
        let n = part.positions.len();
        let flat: Vec<f32> = part.positions.iter().flatten().copied().collect();
        let position = bin.push(
            floats(flat.iter().copied()),
            Some(ARRAY_BUFFER),
            (FLOAT, n, "VEC3"),
            Some(bounds(&flat, 3)),
        );
        let normals = floats(part.normals.iter().flatten().copied());
        let normal = bin.push(normals, Some(ARRAY_BUFFER), (FLOAT, n, "VEC3"), None);
        let uvs = floats(part.uvs.iter().flatten().copied());
        let texcoord_0 = bin.push(uvs, Some(ARRAY_BUFFER), (FLOAT, n, "VEC2"), None);
        let (joint_bytes, joint_type): (Vec<u8>, u32) = if joints.len() <= 256 {
            let bytes = part.joints.iter().flatten().map(|&j| j as u8).collect();
            (bytes, UNSIGNED_BYTE)
        } else {
            let bytes = part.joints.iter().flatten().flat_map(|j| j.to_le_bytes());
            (bytes.collect(), UNSIGNED_SHORT)
        };
        let joints_0 = bin.push(
            joint_bytes,
            Some(ARRAY_BUFFER),
            (joint_type, n, "VEC4"),
            None,
        );
        let weights = floats(part.weights.iter().flatten().copied());
        let weights_0 = bin.push(weights, Some(ARRAY_BUFFER), (FLOAT, n, "VEC4"), None);
        let index_bytes = part.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let indices = bin.push(
            index_bytes,
            Some(ELEMENT_ARRAY_BUFFER),
            (UNSIGNED_INT, part.indices.len(), "SCALAR"),
            None,
        );
        primitives.push(SkinPrimitive {
            attributes: SkinAttributes {
                position,
                normal,
                texcoord_0,
                joints_0,
                weights_0,
            },
            indices,
            material: part.material,
        });
    }
    let inverse_binds = floats(world.iter().flat_map(|m| m.inverse().to_cols_array()));
    let inverse_bind_matrices = bin.push(inverse_binds, None, (FLOAT, joints.len(), "MAT4"), None);

    let mut animations = Vec::with_capacity(clips.len());
    for clip in clips {
        let keys = clip.times.len();
        anyhow::ensure!(
            keys > 0 && clip.times.windows(2).all(|w| w[0] < w[1]),
            "clip {}: key times must increase",
            clip.name
        );
        let input = bin.push(
            floats(clip.times.iter().copied()),
            None,
            (FLOAT, keys, "SCALAR"),
            Some(bounds(&clip.times, 1)),
        );
        let mut channels = Vec::with_capacity(clip.channels.len());
        let mut samplers = Vec::with_capacity(clip.channels.len());
        for channel in &clip.channels {
            let (width, kind, path) = match channel.path {
                ChannelPath::Translation => (3, "VEC3", "translation"),
                ChannelPath::Rotation => (4, "VEC4", "rotation"),
            };
            anyhow::ensure!(
                channel.joint < joints.len() && channel.values.len() == keys * width,
                "clip {}: a channel on joint {} with {} values for {keys} keys",
                clip.name,
                channel.joint,
                channel.values.len()
            );
            let output = bin.push(
                floats(channel.values.iter().copied()),
                None,
                (FLOAT, keys, kind),
                None,
            );
            channels.push(ChannelJson {
                sampler: samplers.len(),
                target: TargetJson {
                    node: 1 + channel.joint,
                    path,
                },
            });
            samplers.push(SamplerJson {
                input,
                interpolation: "LINEAR",
                output,
            });
        }
        animations.push(AnimationJson {
            name: clip.name.clone(),
            channels,
            samplers,
        });
    }

    let mut nodes = vec![SkinNode {
        name: name.to_string(),
        mesh: Some(0),
        skin: Some(0),
        children: Vec::new(),
        translation: None,
        rotation: None,
    }];
    for (j, joint) in joints.iter().enumerate() {
        let children = (0..joints.len())
            .filter(|&c| joints[c].parent == Some(j))
            .map(|c| 1 + c)
            .collect();
        nodes.push(SkinNode {
            name: joint.name.clone(),
            mesh: None,
            skin: None,
            children,
            translation: Some(joint.translation),
            rotation: (joint.rotation != [0.0, 0.0, 0.0, 1.0]).then_some(joint.rotation),
        });
    }
    let mut scene_nodes = vec![0];
    scene_nodes.extend(
        (0..joints.len())
            .filter(|&j| joints[j].parent.is_none())
            .map(|j| 1 + j),
    );
    let root = SkinRoot {
        asset: Asset {
            version: "2.0",
            generator: "candela assetgen (skinned)",
        },
        scene: 0,
        scenes: vec![Scene { nodes: scene_nodes }],
        nodes,
        meshes: vec![SkinMesh {
            name: name.to_string(),
            primitives,
        }],
        materials: materials
            .iter()
            .map(material_json)
            .collect::<Result<_, _>>()?,
        skins: vec![SkinJson {
            name: name.to_string(),
            inverse_bind_matrices,
            joints: (1..=joints.len()).collect(),
        }],
        animations,
        accessors: bin.accessors,
        buffer_views: bin.views,
        buffers: vec![GlbBuffer {
            byte_length: bin.bytes.len(),
        }],
    };
    Ok(glb(serde_json::to_vec(&root)?, bin.bytes))
}
