//! The art kit of the game It's About Time, made by code: weathered sandstone ruins pieces
//! (blocks, steps, a column, carved panels, a lintel, a temple tier), puzzle props (torch and
//! flame, sun altar and disc, lever, glowing glyphs, pressure plate, pushable block, boulder,
//! a pre-fractured brittle wall) and a sand terrain tile, as glTF 2.0 files with their colour
//! and normal-map textures, written by `assetgen ruins-kit` to `assets/its_about_time/kit/`.
//!
//! Conventions (the contract with the levels, `docs/LEVELS.md` "The It's About Time kit"):
//! metres, right-handed, +Y up; a piece sits on y = 0 centred on the Y axis unless its doc
//! says otherwise (the boulder and the sun disc are centred at their origin so they turn about
//! it; the lever handle's origin is its pivot). Parts that move or switch (flame, disc, lever
//! handle, glyph glow, pressure plate, wall pieces) are separate pieces. Materials are baked
//! into each piece. [`kit_files`] gives every file's bytes, deterministic (a test compares
//! them with the committed files). Files: `noise`, `glyphs`, `textures` (images), `materials`
//! (palette), `stone` and `shapes` (shape building, on the Reflect kit's mesh builder), then
//! one file per group of pieces (`structure`, `props`, `wall`, `terrain`).
//! Must not: read anything from disk.

pub mod glyphs;
pub mod materials;
pub mod noise;
pub mod props;
mod shapes;
mod stone;
pub mod structure;
pub mod terrain;
pub mod textures;
pub mod wall;

use glam::Vec3;

use crate::gltf_writer::{MaterialSpec, write_gltf_by};
use crate::reflect_kit::Piece;
use crate::reflect_kit::mesh::Builder;

/// The generator string written into every piece.
const GENERATOR: &str = "candela assetgen (ruins-kit)";

fn piece(name: &'static str, materials: Vec<MaterialSpec>, builder: Builder) -> Piece {
    Piece {
        name,
        materials,
        mesh: builder.finish(),
    }
}

/// Every piece of the kit, in a fixed order.
pub fn pieces() -> Vec<Piece> {
    let mut all = vec![
        structure::block("block_small", Vec3::new(1.0, 0.5, 0.6), 1),
        structure::block("block_medium", Vec3::new(1.6, 0.8, 0.8), 2),
        structure::block("block_large", Vec3::new(2.4, 1.2, 1.2), 3),
        structure::steps(),
        structure::column_drum(),
        structure::column_capital(),
        structure::carved_panel(),
        structure::lintel(),
        structure::temple_tier(),
        props::torch(),
        props::torch_flame(),
        props::sun_altar(),
        props::sun_disc(),
        props::lever_base(),
        props::lever_handle(),
        props::glyph_tile(),
    ];
    const GLOWS: [&str; glyphs::GLYPH_COUNT] = [
        "glyph_glow_0",
        "glyph_glow_1",
        "glyph_glow_2",
        "glyph_glow_3",
    ];
    for (glyph, name) in GLOWS.iter().enumerate() {
        all.push(props::glyph_glow(name, glyph));
    }
    all.extend([
        props::pressure_plate_frame(),
        props::pressure_plate(),
        props::push_block(),
        props::boulder(),
    ]);
    for index in 0..wall::WALL_PIECES {
        all.push(wall::wall_piece(index));
    }
    all.push(terrain::sand_terrain());
    all
}

/// Every file of the kit as `(path relative to the kit folder, bytes)`, sorted by path:
/// `<piece>.gltf` and `<piece>.bin` per piece, `textures/<name>.png` per texture.
pub fn kit_files() -> anyhow::Result<Vec<(String, Vec<u8>)>> {
    let mut files = Vec::new();
    for piece in pieces() {
        let bin_name = format!("{}.bin", piece.name);
        let written = write_gltf_by(
            GENERATOR,
            piece.name,
            &bin_name,
            &piece.mesh,
            &piece.materials,
        )?;
        files.push((format!("{}.gltf", piece.name), written.gltf));
        files.push((bin_name, written.bin));
    }
    for (name, image) in textures::textures() {
        files.push((
            format!("textures/{name}.png"),
            crate::reflect_kit::textures::png_bytes(&image)?,
        ));
    }
    files.sort_by(|a, b| a.0.cmp(&b.0));
    Ok(files)
}
