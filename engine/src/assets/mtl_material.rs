//! MTL records to engine [`Material`]s: the one place that says how Wavefront's Phong-era
//! parameters map onto the path tracer's materials.
//!
//! The mapping (all colours taken as linear RGB, as MTL files written for renderers are):
//! - `illum` 4, 6 or 7 (refraction) → [`MaterialKind::Dielectric`], IOR `Ni` (1.5 when
//!   absent or not positive), tint `Tf` (white when absent), no absorption; smooth unless
//!   `Ns` is given (then roughness from `Ns`, below).
//! - `illum` 3 or 5 (ray-traced reflection) with a non-zero `Ks` → [`MaterialKind::Conductor`]
//!   with F0 = `Ks`: a perfect mirror when `Ns` is absent or ≥ 1000, else roughness from `Ns`.
//! - `Pr`/`Pm` (the PBR extension) → [`MaterialKind::MetalRough`] with those values.
//! - any other `illum` ≥ 2 with a non-zero `Ks` → [`MaterialKind::MetalRough`], metallic 0,
//!   base colour `Kd`, roughness from `Ns` (0.5 when absent): a diffuse base under a glossy
//!   dielectric coat. Only whether `Ks` is non-zero matters; its colour is not kept (the coat's
//!   reflectance follows from its IOR, `Ni` or 1.5).
//! - otherwise (`illum` 0, 1, or no `Ks`) → [`MaterialKind::Diffuse`] with albedo `Kd`.
//! - roughness from the Phong exponent: α = √(2 / (Ns + 2)) (Walter et al. 2007, the Beckmann
//!   width of the same lobe), perceptual roughness = √α, clamped to [0, 1].
//! - `Ke` → emission (radiance, W·sr⁻¹·m⁻²), one-sided (along the geometric normal).
//! - `d` < 1 or `Tr` > 0 → `transmission` = 1 − `d` (or `Tr`) on a non-dielectric material,
//!   which then becomes MetalRough (the only kind with a transmission factor). `Tf` alone
//!   does not make a material transmissive (many exporters write `Tf 1 1 1` on every
//!   material); it is the tint of refractive (`illum` 4/6/7) materials.
//! - `map_Kd`, `map_Ke`: sRGB colour textures multiplied by `Kd`/`Ke` (white when absent).
//!   `norm`: a tangent-space normal map; `bump`/`map_bump`: a height map converted to a normal
//!   map, or a normal map if the image has colour (see `texture`); `-bm` → `normal_scale`.
//! - albedos and `Ks` are clamped to [0, 1], emission to ≥ 0, with a note.
//!
//! Must not: parse text (`mtl` does) or decode images (`texture` does).

use std::path::Path;

use glam::Vec3;

use super::context::LoadContext;
use super::error::AssetResult;
use super::model::{Material, MaterialKind, TextureRef, Wrap};
use super::mtl::{MtlMaterial, MtlTexture};
use super::texture::{Sampling, TextureSet, Usage};

/// `Ns` at and above which a mirror (`illum` 3/5) is perfectly smooth. Blender's exporters
/// write at most 900 (its roughness 0) or 1000.
const MIRROR_NS: f32 = 1000.0;

/// Perceptual GGX roughness for a Phong exponent `ns` (see the module doc).
pub(crate) fn roughness_from_ns(ns: f32) -> f32 {
    let alpha = (2.0 / (ns.max(0.0) + 2.0)).sqrt();
    alpha.sqrt().clamp(0.0, 1.0)
}

/// Maps one MTL material (from an MTL file in `mtl_folder`) to an engine material, loading
/// its textures into `textures`.
pub(crate) fn to_material(
    context: &mut LoadContext,
    mtl: &MtlMaterial,
    mtl_folder: &Path,
    textures: &mut TextureSet,
) -> AssetResult<Material> {
    let name = &mtl.name;
    let mut material = Material {
        name: name.clone(),
        ..Material::default()
    };
    let kd = clamp_unit(context, name, "Kd", mtl.kd);
    let ks = clamp_unit(context, name, "Ks", mtl.ks).unwrap_or(Vec3::ZERO);
    let has_ks = ks.max_element() > 0.0;
    let ior = match mtl.ni {
        Some(ni) if ni > 0.0 => ni,
        _ => 1.5,
    };
    let illum = mtl.illum.unwrap_or(if has_ks { 2 } else { 1 });
    material.ior = ior;
    match illum {
        4 | 6 | 7 => {
            material.kind = MaterialKind::Dielectric;
            material.base_color = clamp_unit(context, name, "Tf", mtl.tf).unwrap_or(Vec3::ONE);
            material.roughness = mtl.ns.map_or(0.0, roughness_from_ns);
        }
        3 | 5 if has_ks => {
            material.kind = MaterialKind::Conductor;
            material.base_color = ks;
            material.metallic = 1.0;
            material.roughness = match mtl.ns {
                Some(ns) if ns < MIRROR_NS => roughness_from_ns(ns),
                _ => 0.0,
            };
        }
        _ if mtl.pr.is_some() || mtl.pm.is_some() => {
            material.kind = MaterialKind::MetalRough;
            material.base_color = kd.unwrap_or(Vec3::ONE);
            material.roughness = mtl.pr.unwrap_or(1.0).clamp(0.0, 1.0);
            material.metallic = mtl.pm.unwrap_or(0.0).clamp(0.0, 1.0);
        }
        2.. if has_ks => {
            material.kind = MaterialKind::MetalRough;
            material.base_color = kd.unwrap_or(Vec3::splat(0.8));
            material.metallic = 0.0;
            material.roughness = mtl.ns.map_or(0.5, roughness_from_ns);
        }
        _ => {
            material.kind = MaterialKind::Diffuse;
            material.base_color = kd.unwrap_or(Vec3::splat(0.8));
        }
    }
    let transmission = mtl
        .d
        .map(|d| 1.0 - d)
        .or(mtl.tr)
        .unwrap_or(0.0)
        .clamp(0.0, 1.0);
    if transmission > 0.0 && material.kind != MaterialKind::Dielectric {
        if material.kind != MaterialKind::MetalRough {
            material.kind = MaterialKind::MetalRough;
            material.metallic = 0.0;
        }
        material.transmission = transmission;
        context.note(format!(
            "material {name:?}: dissolve d/Tr taken as transmission {transmission}"
        ));
    }
    if let Some(ke) = mtl.ke {
        if ke.min_element() < 0.0 {
            context.warn(format!("material {name:?}: negative Ke clamped to 0"));
        }
        material.emission = ke.max(Vec3::ZERO);
    }
    if let Some(map) = &mtl.map_kd {
        material.base_color_texture = Some(load_texture(
            context,
            map,
            mtl_folder,
            Usage::Color,
            textures,
        )?);
        if kd.is_none() && material.kind != MaterialKind::Dielectric {
            material.base_color = Vec3::ONE;
        }
    }
    if let Some(map) = &mtl.map_ke {
        material.emission_texture = Some(load_texture(
            context,
            map,
            mtl_folder,
            Usage::Color,
            textures,
        )?);
        if mtl.ke.is_none() {
            material.emission = Vec3::ONE;
        }
    }
    let normal_map = match (&mtl.norm, &mtl.bump) {
        (Some(norm), Some(_)) => {
            context.note(format!("material {name:?}: has norm and bump; norm used"));
            Some((norm, Usage::Data))
        }
        (Some(norm), None) => Some((norm, Usage::Data)),
        (None, Some(bump)) => Some((bump, Usage::Bump)),
        (None, None) => None,
    };
    if let Some((map, usage)) = normal_map {
        material.normal_texture = Some(load_texture(context, map, mtl_folder, usage, textures)?);
        material.normal_scale = map.bump_multiplier;
    }
    if !mtl.ignored.is_empty() {
        context.note(format!(
            "material {name:?}: ignored MTL statements: {}",
            mtl.ignored.join(", ")
        ));
    }
    Ok(material)
}

/// Clamps a colour to [0, 1] with a note when it was outside.
fn clamp_unit(
    context: &mut LoadContext,
    name: &str,
    what: &str,
    color: Option<Vec3>,
) -> Option<Vec3> {
    let color = color?;
    let clamped = color.clamp(Vec3::ZERO, Vec3::ONE);
    if clamped != color {
        context.warn(format!(
            "material {name:?}: {what} {color} clamped to [0, 1]"
        ));
    }
    Some(clamped)
}

/// Resolves (relative to the MTL file's folder, inside the root) and loads one texture.
fn load_texture(
    context: &mut LoadContext,
    map: &MtlTexture,
    mtl_folder: &Path,
    usage: Usage,
    textures: &mut TextureSet,
) -> AssetResult<TextureRef> {
    let path = context.resolve(mtl_folder, &map.file)?;
    let wrap = if map.clamp { Wrap::Clamp } else { Wrap::Repeat };
    let sampling = Sampling {
        wrap_u: wrap,
        wrap_v: wrap,
        nearest: false,
    };
    let source = path.to_string_lossy().into_owned();
    textures.get_or_load(context, &source, &map.file, usage, sampling, |context| {
        context.read_referenced(&path)
    })
}
