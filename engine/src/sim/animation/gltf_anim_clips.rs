//! glTF animations to [`Clip`]s: one clip per glTF animation, one channel per glTF channel,
//! each checked by `clip::check_channel` (target exists, key counts match, finite increasing
//! times, finite values) with errors naming the file, the clip and the channel.
//!
//! Morph-weight channels take their width from the target node's mesh (its morph target
//! count). Channels on a node given by a `matrix` (glTF forbids it) animate its
//! decomposition, with a note. Owns: [`read_clips`]. Must not: sample or apply clips.

use gltf::json;
use gltf::json::accessor::Type;
use gltf::json::animation::{Interpolation as GltfInterpolation, Property as GltfProperty};
use gltf::json::validation::Checked;

use super::clip::{Channel, Clip, Interpolation, Property, check_channel};
use super::error::{AnimError, AnimResult};
use super::model::AnimMesh;
use super::pose::NodeTree;
use crate::assets::gltf::accessor::Reader;

/// Reads and checks every animation of the file.
pub(crate) fn read_clips(
    reader: &Reader,
    json: &json::Root,
    nodes: &NodeTree,
    meshes: &[AnimMesh],
    notes: &mut Vec<String>,
) -> AnimResult<Vec<Clip>> {
    let file = &reader.context.file;
    let mut clips = Vec::with_capacity(json.animations.len());
    for (clip_index, animation) in json.animations.iter().enumerate() {
        let name = animation.name.clone().unwrap_or_default();
        let label = if name.is_empty() {
            format!("#{clip_index}")
        } else {
            name.clone()
        };
        let mut channels = Vec::with_capacity(animation.channels.len());
        for (index, channel) in animation.channels.iter().enumerate() {
            let bad = |message: String| AnimError::BadChannel {
                file: file.clone(),
                clip: label.clone(),
                channel: index,
                message,
            };
            let node = channel.target.node.value();
            let Some(target) = nodes.nodes.get(node) else {
                return Err(AnimError::MissingNode {
                    file: file.clone(),
                    clip: label.clone(),
                    channel: index,
                    node,
                    node_count: nodes.nodes.len(),
                });
            };
            let Some(sampler) = animation.samplers.get(channel.sampler.value()) else {
                return Err(bad(format!(
                    "sampler {} does not exist",
                    channel.sampler.value()
                )));
            };
            let property = match channel.target.path {
                Checked::Valid(GltfProperty::Translation) => Property::Translation,
                Checked::Valid(GltfProperty::Rotation) => Property::Rotation,
                Checked::Valid(GltfProperty::Scale) => Property::Scale,
                Checked::Valid(GltfProperty::MorphTargetWeights) => Property::Weights,
                Checked::Invalid => return Err(bad("has an unknown target path".to_string())),
            };
            let interpolation = match sampler.interpolation {
                Checked::Valid(GltfInterpolation::Step) => Interpolation::Step,
                Checked::Valid(GltfInterpolation::Linear) => Interpolation::Linear,
                Checked::Valid(GltfInterpolation::CubicSpline) => Interpolation::CubicSpline,
                Checked::Invalid => return Err(bad("has an unknown interpolation".to_string())),
            };
            let (width, kind) = match property {
                Property::Translation | Property::Scale => (3, Type::Vec3),
                Property::Rotation => (4, Type::Vec4),
                Property::Weights => {
                    let targets = target
                        .mesh
                        .and_then(|m| meshes.get(m))
                        .map_or(0, |m| m.default_weights.len());
                    if targets == 0 {
                        return Err(bad(format!(
                            "animates the morph weights of node {node}, whose mesh has no morph targets"
                        )));
                    }
                    (targets, Type::Scalar)
                }
            };
            if target.matrix.is_some() && property != Property::Weights {
                notes.push(format!(
                    "clip {label:?}: node {node} is given by a matrix but animated (glTF forbids it); its decomposition is animated"
                ));
            }
            let (times_seconds, _) =
                reader.read_floats(sampler.input.value(), &[Type::Scalar], "animation input")?;
            let (values, _) =
                reader.read_floats(sampler.output.value(), &[kind], "animation output")?;
            let channel = Channel {
                target: node,
                property,
                interpolation,
                times_seconds,
                values,
                width,
            };
            check_channel(file, &label, index, &channel, nodes.nodes.len())?;
            channels.push(channel);
        }
        clips.push(Clip::new(name, channels));
    }
    Ok(clips)
}
