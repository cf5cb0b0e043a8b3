//! The ruins kit's material palette: every material a piece bakes into its glTF, by name.
//!
//! Colours are linear Rec.709 factors (textures carry sRGB colour and multiply them); emission
//! is `emissive` × `emissive_strength` in W·sr⁻¹·m⁻². Texture URIs are relative to the kit
//! folder (`textures/<name>.png`). Must not: build geometry.

use crate::gltf_writer::MaterialSpec;

/// Radiance of a torch flame, W·sr⁻¹·m⁻² per unit of `FLAME_COLOR`: a flame of about
/// 0.1 m² lights the ground around its torch at night.
pub const FLAME_STRENGTH: f32 = 2.0;
/// Flame colour (linear): deep orange.
pub const FLAME_COLOR: [f32; 3] = [1.0, 0.38, 0.08];
/// Radiance of a glowing glyph, W·sr⁻¹·m⁻² per unit of `GLYPH_COLOR`.
pub const GLYPH_STRENGTH: f32 = 0.6;
/// Glyph glow colour (linear): turquoise, the ruins' magic.
pub const GLYPH_COLOR: [f32; 3] = [0.2, 0.85, 0.75];

fn plain(name: &str, base: [f32; 3], metallic: f32, roughness: f32) -> MaterialSpec {
    MaterialSpec {
        name: name.to_string(),
        base_color: [base[0], base[1], base[2], 1.0],
        base_color_texture: None,
        metallic,
        roughness,
        emissive: [0.0; 3],
        emissive_strength: 1.0,
        emissive_texture: None,
        normal_texture: None,
        glass_ior: None,
    }
}

fn textured(name: &str, texture: &str, tint: [f32; 3], roughness: f32) -> MaterialSpec {
    MaterialSpec {
        base_color_texture: Some(format!("textures/{texture}.png")),
        normal_texture: Some(format!("textures/{texture}_normal.png")),
        ..plain(name, tint, 0.0, roughness)
    }
}

fn glowing(name: &str, color: [f32; 3], strength: f32) -> MaterialSpec {
    MaterialSpec {
        emissive: color,
        emissive_strength: strength,
        // Dark, so that sunlight on the glow does not wash its colour out.
        ..plain(name, [0.05, 0.04, 0.03], 0.0, 0.6)
    }
}

/// Warm weathered sandstone: blocks, steps, columns, the temple.
pub fn sandstone() -> MaterialSpec {
    textured("sandstone", "sandstone", [1.0; 3], 0.9)
}

/// Sandstone a little more yellow and worn smooth by feet: step treads, plates.
pub fn sandstone_worn() -> MaterialSpec {
    textured("sandstone_worn", "sandstone", [1.0, 0.95, 0.88], 0.8)
}

/// Darker carved stone with glyph reliefs: panels, lintels, altars, glyph tiles.
pub fn carved() -> MaterialSpec {
    textured("carved", "carved", [1.0; 3], 0.85)
}

/// Sand: the terrain.
pub fn sand() -> MaterialSpec {
    textured("sand", "sand", [1.0; 3], 0.95)
}

/// Old bronze: the sun disc, the lever's handle, the torch bowl's rim.
pub fn bronze() -> MaterialSpec {
    plain("bronze", [0.55, 0.36, 0.18], 1.0, 0.45)
}

/// Charred dark wood: the lever's grip, the torch's fuel.
pub fn charred_wood() -> MaterialSpec {
    plain("charred_wood", [0.06, 0.04, 0.03], 0.0, 0.9)
}

/// A torch flame (emits; the flame is its own piece so light groups can switch it).
pub fn flame() -> MaterialSpec {
    glowing("flame", FLAME_COLOR, FLAME_STRENGTH)
}

/// A glowing glyph inlay.
pub fn glyph_glow() -> MaterialSpec {
    glowing("glyph_glow", GLYPH_COLOR, GLYPH_STRENGTH)
}
