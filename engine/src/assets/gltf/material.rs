//! glTF materials to engine [`Material`]s (metallic-roughness PBR plus the KHR extensions the
//! engine reads).
//!
//! - base colour = `baseColorFactor.rgb` × texture (sRGB); alpha, `alphaMode` and
//!   `alphaCutoff` are ignored (surfaces are opaque), with a note when not OPAQUE.
//! - `metallicFactor`, `roughnessFactor` × metallic-roughness texture (linear; G = roughness,
//!   B = metallic). Normal texture (linear) with its `scale`. Occlusion maps are not used (a
//!   path tracer computes occlusion).
//! - emission = `emissiveFactor` × `KHR_materials_emissive_strength` × texture (sRGB), in
//!   W·sr⁻¹·m⁻² as the engine reads it; `doubleSided` → emission from both faces.
//! - `KHR_materials_transmission` factor, `KHR_materials_ior` (1.5 by default) and
//!   `KHR_materials_volume` attenuation colour and distance (thickness is not used): a
//!   material with transmission 1 and metallic 0 becomes a [`MaterialKind::Dielectric`] (tinted
//!   by the base colour, roughness kept), any other a [`MaterialKind::MetalRough`] with its
//!   `transmission` factor. The transmission texture is not used (noted).
//! - factors are clamped to their glTF ranges; non-finite values are refused.
//! - The default material (for primitives without one) is glTF's: white, metallic 1, roughness 1.
//!
//! Must not: read mesh data.

use glam::Vec3;

use super::super::context::LoadContext;
use super::super::error::AssetResult;
use super::super::model::{Material, MaterialKind};
use super::super::texture::{TextureSet, Usage};
use super::document::GltfFile;
use super::texture::{TextureUse, load_texture};

/// The glTF default material (glTF 2.0 §3.9.6).
pub(crate) fn default_material() -> Material {
    Material {
        name: "glTF default".to_string(),
        kind: MaterialKind::MetalRough,
        base_color: Vec3::ONE,
        metallic: 1.0,
        roughness: 1.0,
        ..Material::default()
    }
}

/// Converts every material of the file, in glTF order.
pub(crate) fn convert_materials(
    context: &mut LoadContext,
    file: &GltfFile,
    textures: &mut TextureSet,
) -> AssetResult<Vec<Material>> {
    file.document
        .materials()
        .map(|material| convert(context, file, textures, &material))
        .collect()
}

/// Converts one material.
fn convert(
    context: &mut LoadContext,
    file: &GltfFile,
    textures: &mut TextureSet,
    gltf_material: &gltf::Material,
) -> AssetResult<Material> {
    let index = gltf_material.index().unwrap_or(usize::MAX);
    let name = gltf_material
        .name()
        .map_or_else(|| format!("material #{index}"), str::to_string);
    let finite = |values: &[f32], what: &str| {
        if values.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(context.gltf_error(format!("material {name:?}: {what} is not finite")))
        }
    };
    let pbr = gltf_material.pbr_metallic_roughness();
    let base_color_factor = pbr.base_color_factor();
    finite(&base_color_factor, "baseColorFactor")?;
    let emissive = gltf_material.emissive_factor();
    finite(&emissive, "emissiveFactor")?;
    let strength = gltf_material.emissive_strength().unwrap_or(1.0);
    let ior = gltf_material.ior().unwrap_or(1.5);
    let transmission = gltf_material.transmission();
    let transmission_factor = transmission
        .as_ref()
        .map_or(0.0, |t| t.transmission_factor());
    let volume = gltf_material.volume();
    let attenuation_color = volume.as_ref().map_or([1.0; 3], |v| v.attenuation_color());
    let attenuation_distance = volume
        .as_ref()
        .map_or(f32::INFINITY, |v| v.attenuation_distance());
    finite(
        &[
            pbr.metallic_factor(),
            pbr.roughness_factor(),
            strength,
            ior,
            transmission_factor,
        ],
        "a factor",
    )?;
    finite(&attenuation_color, "attenuationColor")?;

    let metallic = pbr.metallic_factor().clamp(0.0, 1.0);
    let transmission_factor = transmission_factor.clamp(0.0, 1.0);
    let mut material = Material {
        name: name.clone(),
        kind: MaterialKind::MetalRough,
        base_color: Vec3::from_slice(&base_color_factor[..3]).clamp(Vec3::ZERO, Vec3::ONE),
        emission: Vec3::from(emissive).max(Vec3::ZERO) * strength.max(0.0),
        two_sided_emission: gltf_material.double_sided(),
        roughness: pbr.roughness_factor().clamp(0.0, 1.0),
        metallic,
        ior: if ior > 0.0 { ior } else { 1.5 },
        transmission: transmission_factor,
        attenuation_color: Vec3::from(attenuation_color).clamp(Vec3::ZERO, Vec3::ONE),
        attenuation_distance: if attenuation_distance > 0.0 {
            attenuation_distance
        } else {
            f32::INFINITY
        },
        ..Material::default()
    };
    if transmission_factor >= 1.0 && metallic == 0.0 {
        material.kind = MaterialKind::Dielectric;
    }

    if let Some(info) = pbr.base_color_texture() {
        let slot = texture_use(
            info.texture(),
            info.tex_coord(),
            info.texture_transform().is_some(),
        );
        let what = format!("material {name:?} base colour texture");
        material.base_color_texture =
            load_texture(context, file, textures, &slot, Usage::Color, &what)?;
    }
    if let Some(info) = pbr.metallic_roughness_texture() {
        let slot = texture_use(
            info.texture(),
            info.tex_coord(),
            info.texture_transform().is_some(),
        );
        let what = format!("material {name:?} metallic-roughness texture");
        material.metal_rough_texture =
            load_texture(context, file, textures, &slot, Usage::Data, &what)?;
    }
    if let Some(normal) = gltf_material.normal_texture() {
        let slot = texture_use(normal.texture(), normal.tex_coord(), false);
        let what = format!("material {name:?} normal texture");
        material.normal_texture = load_texture(context, file, textures, &slot, Usage::Data, &what)?;
        material.normal_scale = if normal.scale().is_finite() {
            normal.scale()
        } else {
            1.0
        };
    }
    if let Some(info) = gltf_material.emissive_texture() {
        let slot = texture_use(
            info.texture(),
            info.tex_coord(),
            info.texture_transform().is_some(),
        );
        let what = format!("material {name:?} emissive texture");
        material.emission_texture =
            load_texture(context, file, textures, &slot, Usage::Color, &what)?;
    }

    if gltf_material.alpha_mode() != gltf::material::AlphaMode::Opaque {
        context.note(format!(
            "material {name:?}: alpha mode {:?} is not supported: opaque",
            gltf_material.alpha_mode()
        ));
    }
    if transmission
        .as_ref()
        .is_some_and(|t| t.transmission_texture().is_some())
    {
        context.note(format!(
            "material {name:?}: transmission texture not supported: factor used"
        ));
    }
    Ok(material)
}

/// Bundles a texture reference's parts.
fn texture_use(texture: gltf::Texture<'_>, tex_coord: u32, transformed: bool) -> TextureUse<'_> {
    TextureUse {
        texture,
        tex_coord,
        transformed,
    }
}
