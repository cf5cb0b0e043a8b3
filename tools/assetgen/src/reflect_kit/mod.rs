//! The art kit of the game Reflect, made by code: modular chamber pieces (walls, floors,
//! ceilings with light strips, trims, panels, glass, devices, props, signs) as glTF 2.0 files
//! with their textures, written by `assetgen reflect-kit` to `assets/reflect/kit/`.
//!
//! Conventions (the contract with the chamber levels, `docs/LEVELS.md` "The Reflect kit"):
//! metres, right-handed, +Y up; unless a piece says otherwise its origin is at its bottom
//! centre and its visible face looks towards +Z. Materials are baked into each piece.
//! [`kit_files`] gives every file's bytes, deterministic (a test compares them with the
//! committed files). Files: `mesh` (shape building), `materials` (palette), `textures`
//! and `signs` (images), then one file per group of pieces (`machines`: fans, crate, piston).
//! Must not: read anything from disk.

mod devices;
mod machines;
pub mod materials;
pub(crate) mod mesh;
mod panels;
mod props;
pub mod signs;
mod structure;
pub mod textures;

use crate::gltf_writer::{MaterialSpec, MeshData, write_gltf};
use mesh::Builder;

/// One kit piece: its file stem, materials (glTF order) and geometry.
pub struct Piece {
    pub name: &'static str,
    pub materials: Vec<MaterialSpec>,
    pub mesh: MeshData,
}

impl Piece {
    fn new(name: &'static str, materials: Vec<MaterialSpec>, builder: Builder) -> Self {
        Self {
            name,
            materials,
            mesh: builder.finish(),
        }
    }

    /// Triangles of the piece, all materials together.
    pub fn triangle_count(&self) -> usize {
        self.mesh.indices.iter().map(|i| i.len() / 3).sum()
    }

    /// Triangles whose material emits light.
    pub fn emissive_triangle_count(&self) -> usize {
        self.materials
            .iter()
            .zip(&self.mesh.indices)
            .filter(|(m, _)| m.emissive != [0.0; 3])
            .map(|(_, i)| i.len() / 3)
            .sum()
    }
}

/// Every piece of the kit, in a fixed order.
pub fn pieces() -> Vec<Piece> {
    let mut all = vec![
        structure::wall("wall_8x4", 8.0),
        structure::wall("wall_4x4", 4.0),
        structure::wall_door(),
        structure::floor(),
        structure::ceiling(),
        structure::trim(),
        structure::light_bar(),
        panels::mirror_panel(),
        panels::curved_panel(),
        panels::glass_cube(),
        panels::glass_pane(),
        panels::door(),
        devices::dispenser(),
        devices::plate(),
        devices::receiver(),
        devices::emitter(),
        props::elevator(),
        props::railing(),
        props::pillar(),
        props::pipe(),
        machines::fan_frame(),
        machines::fan_rotor(),
        machines::cargo_crate(),
        machines::piston_sleeve(),
        machines::piston_rod(),
    ];
    const SIGNS: [&str; signs::SIGN_COUNT as usize] =
        ["sign_1", "sign_2", "sign_3", "sign_4", "sign_5"];
    for (i, name) in SIGNS.iter().enumerate() {
        all.push(signs::sign(i as u32 + 1, name));
    }
    all
}

/// Every file of the kit as `(path relative to the kit folder, bytes)`, sorted by path:
/// `<piece>.gltf` and `<piece>.bin` per piece, `textures/<name>.png` per texture.
pub fn kit_files() -> anyhow::Result<Vec<(String, Vec<u8>)>> {
    let mut files = Vec::new();
    for piece in pieces() {
        let bin_name = format!("{}.bin", piece.name);
        let written = write_gltf(piece.name, &bin_name, &piece.mesh, &piece.materials)?;
        files.push((format!("{}.gltf", piece.name), written.gltf));
        files.push((bin_name, written.bin));
    }
    for (name, image) in textures::surface_textures() {
        files.push((format!("textures/{name}.png"), textures::png_bytes(&image)?));
    }
    for number in 1..=signs::SIGN_COUNT {
        let (color, glow) = signs::sign_textures(number);
        files.push((
            format!("textures/sign_{number}.png"),
            textures::png_bytes(&color)?,
        ));
        files.push((
            format!("textures/sign_{number}_glow.png"),
            textures::png_bytes(&glow)?,
        ));
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    Ok(files)
}
