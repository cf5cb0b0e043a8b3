//! The Reflect kit's material palette: every material a piece bakes into its glTF, by name.
//!
//! Colours are linear Rec.709 factors (textures carry sRGB colour and multiply them); emission
//! is `emissive` × `emissive_strength` in W·sr⁻¹·m⁻². Texture URIs are relative to the kit
//! folder (`textures/<name>.png`). Must not: build geometry.

use crate::gltf_writer::MaterialSpec;

/// Radiance of the ceiling light strips and the wall light bars, W·sr⁻¹·m⁻² per unit of
/// `LIGHT_STRIP_COLOR`. Chosen so a 16 × 16 × 8 m chamber with four ceilings (8 strips of
/// 8 × 0.2 m each) is lit comfortably; the lead tunes it in the levels if needed.
pub const LIGHT_STRIP_STRENGTH: f32 = 12.0;

/// Warm white of the light strips (linear).
pub const LIGHT_STRIP_COLOR: [f32; 3] = [1.0, 0.9, 0.76];

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

fn textured(name: &str, texture: &str, metallic: f32, roughness: f32) -> MaterialSpec {
    MaterialSpec {
        base_color_texture: Some(format!("textures/{texture}.png")),
        ..plain(name, [1.0; 3], metallic, roughness)
    }
}

fn glowing(name: &str, color: [f32; 3], strength: f32) -> MaterialSpec {
    MaterialSpec {
        emissive: color,
        emissive_strength: strength,
        ..plain(name, [0.9; 3], 0.0, 0.5)
    }
}

/// Dark grey metal wall panels (not mirrorable by look).
pub fn panel_dark() -> MaterialSpec {
    textured("panel_dark", "panel_dark", 0.35, 0.5)
}

/// The recessed seams between panels: near-black metal.
pub fn seam() -> MaterialSpec {
    plain("seam_dark", [0.015, 0.016, 0.018], 0.5, 0.55)
}

/// Brushed dark metal: trims, frames, housings, rings.
pub fn metal_dark() -> MaterialSpec {
    textured("metal_dark", "metal_dark", 0.7, 0.38)
}

/// The floor tiles.
pub fn floor_tile() -> MaterialSpec {
    textured("floor_tile", "floor_tile", 0.0, 0.72)
}

/// White-grey ceiling panels.
pub fn ceiling_white() -> MaterialSpec {
    MaterialSpec {
        base_color: [0.86, 0.87, 0.88, 1.0],
        ..textured("ceiling_white", "panel_white", 0.0, 0.8)
    }
}

/// The mirrorable panel's white (also the curved panel's and the door's).
pub fn panel_white() -> MaterialSpec {
    textured("panel_white", "panel_white", 0.0, 0.45)
}

/// Ceiling strip and wall bar light: warm white.
pub fn light_strip() -> MaterialSpec {
    glowing("light_strip", LIGHT_STRIP_COLOR, LIGHT_STRIP_STRENGTH)
}

/// The thin blue accent lines of trims and pillars.
pub fn trim_light() -> MaterialSpec {
    glowing("trim_light", [0.2, 0.55, 1.0], 5.0)
}

/// Orange accent paint (stripes, bands, rings).
pub fn accent_orange() -> MaterialSpec {
    plain("accent_orange", [0.85, 0.3, 0.03], 0.0, 0.45)
}

/// An orange light line (doors).
pub fn orange_light() -> MaterialSpec {
    glowing("orange_light", [1.0, 0.42, 0.08], 5.0)
}

/// The pressure plate's top.
pub fn plate_top() -> MaterialSpec {
    plain("plate_top", [0.9, 0.32, 0.04], 0.0, 0.4)
}

/// Clear glass with a faint blue tint (transmission 1, IOR 1.5).
pub fn glass() -> MaterialSpec {
    MaterialSpec {
        glass_ior: Some(1.5),
        ..plain("glass", [0.9, 0.96, 1.0], 0.0, 0.0)
    }
}

/// The receiver's lens: milky white, slightly glossy.
pub fn lens_white() -> MaterialSpec {
    plain("lens_white", [0.85, 0.88, 0.9], 0.0, 0.25)
}

/// The emitter's red-tinted metal nozzle.
pub fn nozzle_red() -> MaterialSpec {
    plain("nozzle_red", [0.55, 0.04, 0.03], 0.6, 0.3)
}

/// The emitter nozzle's glowing red tip.
pub fn emitter_glow() -> MaterialSpec {
    glowing("emitter_glow", [1.0, 0.08, 0.04], 6.0)
}

/// The elevator deck: hazard border and grate.
pub fn hazard_deck() -> MaterialSpec {
    textured("hazard_deck", "hazard_deck", 0.3, 0.55)
}

/// The elevator's ring of small lights: cool white.
pub fn elevator_light() -> MaterialSpec {
    glowing("elevator_light", [0.7, 0.88, 1.0], 8.0)
}

/// Pipes: lighter grey metal.
pub fn pipe_grey() -> MaterialSpec {
    plain("pipe_grey", [0.45, 0.47, 0.5], 0.8, 0.35)
}

/// The cargo crate's painted steel: a muted teal.
pub fn crate_paint() -> MaterialSpec {
    plain("crate_paint", [0.06, 0.16, 0.19], 0.2, 0.55)
}

/// The face of chamber sign `number`: its base colour texture, and its digit glowing
/// through the emissive texture.
pub fn sign_face(number: u32) -> MaterialSpec {
    MaterialSpec {
        emissive: [1.0, 0.97, 0.92],
        emissive_strength: 4.0,
        emissive_texture: Some(format!("textures/sign_{number}_glow.png")),
        ..textured(
            &format!("sign_{number}_face"),
            &format!("sign_{number}"),
            0.0,
            0.5,
        )
    }
}
