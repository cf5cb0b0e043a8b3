//! The hero of It's About Time (../shared/games/ITS_ABOUT_TIME.md), made by code: a stylised
//! low-poly humanoid about 1.8 m tall (`body`) on a 21-joint skeleton (`skeleton`) with eight
//! clips (`clips`: `idle`, `walk`, `run`, `jump`, `fall`; `actions`: `push`, `pick_up`,
//! `celebrate`), written by `assetgen hero`
//! as one skinned glTF binary, `assets/common/hero/hero.glb`.
//!
//! Conventions: metres, right-handed, +Y up; feet at y = 0, facing +Z (a level turns it with
//! `model_yaw_deg: 180` to face −Z). Materials: an orange jacket, dark blue trousers, skin,
//! dark leather (boots, belt, hair). [`hero_files`] gives the file's bytes, deterministic (a
//! test compares them with the committed file). Must not: read anything from disk.

mod actions;
mod body;
mod clips;
pub mod skeleton;
mod weights;

use crate::gltf_skin::write_skinned_glb;
use crate::gltf_writer::MaterialSpec;

/// The file name under the hero folder (`assets/common/hero/`).
pub const FILE: &str = "hero.glb";
/// The clip names, in file order: locomotion first, then the explorer's actions (`push`
/// loops; `pick_up` and `celebrate` are one-shots that start and end at rest).
pub const CLIPS: [&str; 8] = [
    "idle",
    "walk",
    "run",
    "jump",
    "fall",
    "push",
    "pick_up",
    "celebrate",
];
/// The hero's height, metres (feet to the top of the hair).
pub const HEIGHT_M: f32 = 1.8;

fn plain(name: &str, base: [f32; 3], roughness: f32) -> MaterialSpec {
    MaterialSpec {
        name: name.to_string(),
        base_color: [base[0], base[1], base[2], 1.0],
        base_color_texture: None,
        metallic: 0.0,
        roughness,
        emissive: [0.0; 3],
        emissive_strength: 1.0,
        emissive_texture: None,
        normal_texture: None,
        glass_ior: None,
    }
}

/// The materials, in `body::material` order (linear colours).
fn materials() -> Vec<MaterialSpec> {
    vec![
        plain("jacket", [0.72, 0.20, 0.04], 0.65),
        plain("cloth", [0.04, 0.07, 0.17], 0.9),
        plain("skin", [0.60, 0.38, 0.26], 0.6),
        plain("leather", [0.10, 0.055, 0.03], 0.45),
    ]
}

/// The hero as GLB bytes.
pub fn hero_glb() -> anyhow::Result<Vec<u8>> {
    write_skinned_glb(
        "hero",
        &body::parts(),
        &materials(),
        &skeleton::joints(),
        &clips::clips(),
    )
}

/// Every file of the hero folder as `(path relative to it, bytes)`.
pub fn hero_files() -> anyhow::Result<Vec<(String, Vec<u8>)>> {
    Ok(vec![(FILE.to_string(), hero_glb()?)])
}

/// Triangles of the mesh, all materials together.
pub fn triangle_count() -> usize {
    body::parts().iter().map(|p| p.indices.len() / 3).sum()
}
