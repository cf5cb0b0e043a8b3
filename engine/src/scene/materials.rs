//! Materials and textures in the form the tracers read.
//!
//! Owns: converting engine [`Material`]s into `GpuMaterial` (roughness, absorption coefficients,
//! light-picking weight) and packing every model's textures into one texel buffer with a
//! `GpuTexture` table. Must not: decode images (the loaders did) or sample textures.

use glam::Vec3;
use half::f16;

use crate::assets::{Material, MaterialKind, Model, Texture, Wrap};
use crate::layout::{
    GpuMaterial, GpuTexture, INVALID, MATERIAL_CONDUCTOR, MATERIAL_DIELECTRIC, MATERIAL_DIFFUSE,
    MATERIAL_FLAG_LINE, MATERIAL_FLAG_TWO_SIDED_EMISSION, MATERIAL_METAL_ROUGH,
    TEXTURE_FLAG_NEAREST, TEXTURE_LEVELS_SHIFT, WRAP_CLAMP, WRAP_MIRROR, WRAP_REPEAT,
};
use crate::scene::mips;

fn wrap_bits(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => WRAP_REPEAT,
        Wrap::Clamp => WRAP_CLAMP,
        Wrap::Mirror => WRAP_MIRROR,
    }
}

/// Packs two f16 pairs: `[r | g << 16, b | a << 16]` (WGSL `unpack2x16float` order).
pub fn pack_texel(t: [f16; 4]) -> [u32; 2] {
    let bits = t.map(|c| c.to_bits() as u32);
    [bits[0] | (bits[1] << 16), bits[2] | (bits[3] << 16)]
}

/// Most texels all textures together may hold, mip chains included: 16 Mi texels of 8 bytes =
/// 128 MiB, the largest storage binding WebGPU guarantees and what lavapipe offers. Scenes over
/// budget have their largest textures halved (box filter) until they fit, with a warning.
pub const TEXEL_BUDGET: usize = 16 << 20;

/// `t` halved in each dimension (2×2 box filter; odd edges repeat the last texel).
fn halve(t: &Texture) -> Texture {
    let (w, h) = (t.width.div_ceil(2).max(1), t.height.div_ceil(2).max(1));
    let at =
        |x: u32, y: u32| t.texels[(y.min(t.height - 1) * t.width + x.min(t.width - 1)) as usize];
    let mut texels = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0.0f32; 4];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let p = at(2 * x + dx, 2 * y + dy);
                for c in 0..4 {
                    sum[c] += p[c].to_f32() * 0.25;
                }
            }
            texels.push(sum.map(f16::from_f32));
        }
    }
    Texture {
        width: w,
        height: h,
        texels,
        ..t.clone()
    }
}

/// Every model's textures, halving the largest until the total fits [`TEXEL_BUDGET`].
fn textures_within_budget(models: &[Model]) -> Vec<Vec<std::borrow::Cow<'_, Texture>>> {
    let mut all: Vec<Vec<std::borrow::Cow<'_, Texture>>> = models
        .iter()
        .map(|m| m.textures.iter().map(std::borrow::Cow::Borrowed).collect())
        .collect();
    let total = |all: &Vec<Vec<std::borrow::Cow<'_, Texture>>>| -> usize {
        all.iter()
            .flatten()
            .map(|t| mips::chain_len(t.width, t.height))
            .sum()
    };
    while total(&all) > TEXEL_BUDGET {
        let Some((m, i)) = all
            .iter()
            .enumerate()
            .flat_map(|(m, ts)| {
                ts.iter()
                    .enumerate()
                    .map(move |(i, t)| ((m, i), t.texels.len()))
            })
            .max_by_key(|&(_, n)| n)
            .map(|(at, _)| at)
        else {
            break;
        };
        let halved = halve(&all[m][i]);
        log::warn!(
            "textures exceed the budget of {TEXEL_BUDGET} texels: {} halved to {}×{}",
            halved.name,
            halved.width,
            halved.height
        );
        all[m][i] = std::borrow::Cow::Owned(halved);
    }
    all
}

/// Texture table, texels, the first global texture index of each model, and the mean RGB
/// luminance of every (global) texture.
pub fn pack_textures(models: &[Model]) -> (Vec<GpuTexture>, Vec<[u32; 2]>, Vec<u32>, Vec<f32>) {
    let mut table = Vec::new();
    let mut texels = Vec::new();
    let mut bases = Vec::with_capacity(models.len());
    let mut means = Vec::new();
    for model_textures in textures_within_budget(models) {
        bases.push(table.len() as u32);
        for texture in &model_textures {
            let mut flags = wrap_bits(texture.wrap_u) | (wrap_bits(texture.wrap_v) << 2);
            if texture.nearest {
                flags |= TEXTURE_FLAG_NEAREST;
            }
            // Nearest (pixel-art) textures are read on level 0 only: no chain.
            let lower = if texture.nearest {
                Vec::new()
            } else {
                mips::lower_levels(texture.width, texture.height, &texture.texels)
            };
            let levels = if lower.is_empty() {
                1
            } else {
                mips::level_count(texture.width, texture.height)
            };
            flags |= levels << TEXTURE_LEVELS_SHIFT;
            table.push(GpuTexture {
                texel_offset: texels.len() as u32,
                width: texture.width,
                height: texture.height,
                flags,
            });
            let mut sum = 0.0f64;
            for t in &texture.texels {
                texels.push(pack_texel(*t));
                sum += luminance(Vec3::new(t[0].to_f32(), t[1].to_f32(), t[2].to_f32())) as f64;
            }
            texels.extend(lower.iter().map(|t| pack_texel(*t)));
            means.push((sum / texture.texels.len().max(1) as f64) as f32);
        }
    }
    if texels.is_empty() {
        // Storage buffers may not be empty.
        texels.push([0, 0]);
    }
    (table, texels, bases, means)
}

/// Converts one material; `texture_base` is the global index of its model's first texture and
/// `texture_means` the mean luminance of each global texture.
pub fn to_gpu_material(m: &Material, texture_base: u32, texture_means: &[f32]) -> GpuMaterial {
    let tex = |t: Option<crate::assets::TextureRef>| {
        t.map(|t| texture_base + t.0 as u32).unwrap_or(INVALID)
    };
    let kind = match m.kind {
        MaterialKind::Diffuse => MATERIAL_DIFFUSE,
        MaterialKind::Conductor => MATERIAL_CONDUCTOR,
        MaterialKind::Dielectric => MATERIAL_DIELECTRIC,
        MaterialKind::MetalRough => MATERIAL_METAL_ROUGH,
    };
    let emission_texture = tex(m.emission_texture);
    let texture_mean = if emission_texture == INVALID {
        1.0
    } else {
        texture_means
            .get(emission_texture as usize)
            .copied()
            .unwrap_or(1.0)
    };
    let emission = m.emission.max(Vec3::ZERO);
    let emission_weight = if emission.is_finite() {
        luminance(emission) * texture_mean
    } else {
        0.0
    };
    // Beer–Lambert: colour c left after distance d ⇒ σ = −ln(c) / d per channel.
    let absorption = if m.attenuation_distance.is_finite() && m.attenuation_distance > 0.0 {
        let c = m.attenuation_color.clamp(Vec3::splat(1e-6), Vec3::ONE);
        Vec3::new(-c.x.ln(), -c.y.ln(), -c.z.ln()) / m.attenuation_distance
    } else {
        Vec3::ZERO
    };
    GpuMaterial {
        base_color: m
            .base_color
            .clamp(Vec3::ZERO, Vec3::ONE)
            .extend(1.0)
            .to_array(),
        emission: emission.extend(emission_weight.max(0.0)).to_array(),
        absorption: absorption.extend(0.0).to_array(),
        kind,
        roughness: m.roughness.clamp(0.0, 1.0),
        metallic: m.metallic.clamp(0.0, 1.0),
        ior: if m.ior.is_finite() && m.ior > 1e-3 {
            m.ior
        } else {
            1.5
        },
        transmission: m.transmission.clamp(0.0, 1.0),
        normal_scale: m.normal_scale,
        flags: if m.two_sided_emission {
            MATERIAL_FLAG_TWO_SIDED_EMISSION
        } else {
            0
        } | if m.line { MATERIAL_FLAG_LINE } else { 0 },
        base_color_texture: tex(m.base_color_texture),
        normal_texture: tex(m.normal_texture),
        emission_texture,
        metal_rough_texture: tex(m.metal_rough_texture),
        _padding: 0,
    }
}

/// Rec.709 luminance of a linear RGB colour (light power for the light table, texture means;
/// the integrators' sampling uses the same weights: twin `luminance` in
/// `shaders/shared/sampling.wgsl`).
#[inline]
pub fn luminance(c: Vec3) -> f32 {
    c.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}
