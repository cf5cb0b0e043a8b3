//! `EXT_mesh_gpu_instancing`: a node that draws its mesh once per instance, with per-instance
//! TRANSLATION (VEC3), ROTATION (VEC4 quaternion, float or normalized integers) and SCALE
//! (VEC3) accessors. Each instance becomes its own placement, `node_global · T · R · S`.
//!
//! Input: the node's extension JSON and an accessor [`Reader`]. Output: the per-instance
//! transforms in the node's space. All attributes must have the same count (bounded by
//! [`MAX_PLACEMENTS`]); a missing attribute is the identity.
//! Must not: walk the node hierarchy (`nodes` does).

use glam::{Mat4, Quat, Vec3};
use gltf::json::accessor::Type;

use super::super::error::AssetResult;
use super::super::limits::MAX_PLACEMENTS;
use super::accessor::Reader;

/// The instance transforms of node `node`, or `None` when it does not use the extension.
pub(crate) fn instance_transforms(reader: &Reader, node: usize) -> AssetResult<Option<Vec<Mat4>>> {
    let Some(extension) = reader
        .file
        .document
        .as_json()
        .nodes
        .get(node)
        .and_then(|n| n.extensions.as_ref())
        .and_then(|e| e.others.get("EXT_mesh_gpu_instancing"))
    else {
        return Ok(None);
    };
    let context = reader.context;
    let error = |m: &str| context.gltf_error(format!("node {node}: EXT_mesh_gpu_instancing: {m}"));
    let attributes = extension
        .get("attributes")
        .and_then(|a| a.as_object())
        .ok_or_else(|| error("no attributes object"))?;
    let read = |name: &str, kind: Type| -> AssetResult<Option<(Vec<f32>, usize)>> {
        let Some(value) = attributes.get(name) else {
            return Ok(None);
        };
        let index = value
            .as_u64()
            .ok_or_else(|| error(&format!("{name} is not an accessor index")))?;
        let (values, components) = reader.read_floats(index as usize, &[kind], name)?;
        let count = values.len() / components.max(1);
        Ok(Some((values, count)))
    };
    let translation = read("TRANSLATION", Type::Vec3)?;
    let rotation = read("ROTATION", Type::Vec4)?;
    let scale = read("SCALE", Type::Vec3)?;
    let counts: Vec<usize> = [&translation, &rotation, &scale]
        .iter()
        .filter_map(|a| a.as_ref().map(|(_, count)| *count))
        .collect();
    let Some(&count) = counts.first() else {
        return Err(error("no TRANSLATION, ROTATION or SCALE"));
    };
    if counts.iter().any(|&c| c != count) {
        return Err(error("attributes have different counts"));
    }
    if count > MAX_PLACEMENTS {
        return Err(context.too_large(
            format!("node {node} instances"),
            count as u64,
            MAX_PLACEMENTS as u64,
        ));
    }
    let mut transforms = Vec::with_capacity(count);
    for i in 0..count {
        let t = translation
            .as_ref()
            .map_or(Vec3::ZERO, |(v, _)| Vec3::from_slice(&v[i * 3..]));
        let r = rotation.as_ref().map_or(Quat::IDENTITY, |(v, _)| {
            let q = Quat::from_slice(&v[i * 4..]);
            if q.length_squared() > 0.0 {
                q.normalize()
            } else {
                Quat::IDENTITY
            }
        });
        let s = scale
            .as_ref()
            .map_or(Vec3::ONE, |(v, _)| Vec3::from_slice(&v[i * 3..]));
        let transform = Mat4::from_scale_rotation_translation(s, r, t);
        if !transform.is_finite() {
            return Err(error(&format!("instance {i} has a non-finite transform")));
        }
        transforms.push(transform);
    }
    Ok(Some(transforms))
}
