//! The It's About Time art kit (`assets/its_about_time/kit/`): the committed files are exactly
//! what `tools/assetgen` makes; every piece loads through the engine's glTF loader with finite
//! bounds, triangles and its materials (normal maps included); only the flames and glyph
//! inlays emit; the brittle wall's pieces tile the wall's box; the textures have their sizes
//! (docs/LEVELS.md, "The It's About Time kit").

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use assetgen::ruins_kit::{self, textures, wall};
use candela::assets::{AssetRoot, Model, load_model};
use glam::Vec3;

const REGENERATE: &str = "cargo run --release -p assetgen -- ruins-kit";

/// The triangle budget of one piece (the terrain tile is the biggest, 12,800).
const MAX_TRIANGLES: usize = 13_000;

fn assets() -> PathBuf {
    candela_tests::repo().join("assets")
}

fn kit_dir() -> PathBuf {
    assets().join("its_about_time/kit")
}

fn files_under(dir: &Path, prefix: &str, out: &mut BTreeSet<String>) -> anyhow::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let relative = format!("{prefix}{name}");
        if entry.file_type()?.is_dir() {
            files_under(&entry.path(), &format!("{relative}/"), out)?;
        } else {
            out.insert(relative);
        }
    }
    Ok(())
}

#[test]
fn committed_kit_is_what_assetgen_makes() -> anyhow::Result<()> {
    let made = ruins_kit::kit_files()?;
    let mut committed = BTreeSet::new();
    if kit_dir().is_dir() {
        files_under(&kit_dir(), "", &mut committed)?;
    }
    let made_names: BTreeSet<String> = made.iter().map(|(name, _)| name.clone()).collect();
    let missing: Vec<_> = made_names.difference(&committed).collect();
    let extra: Vec<_> = committed.difference(&made_names).collect();
    let mut stale = Vec::new();
    for (name, bytes) in &made {
        if committed.contains(name) && std::fs::read(kit_dir().join(name))? != *bytes {
            stale.push(name.clone());
        }
    }
    assert!(
        missing.is_empty() && extra.is_empty() && stale.is_empty(),
        "assets/its_about_time/kit differs from what assetgen makes: missing {missing:?}, extra \
         {extra:?}, stale {stale:?}; run `{REGENERATE}` (and delete the extra files)"
    );
    Ok(())
}

fn load(piece: &str) -> anyhow::Result<Model> {
    let root = AssetRoot::new(assets())?;
    let referrer = Path::new("tests/cross/ruins_kit.rs");
    Ok(load_model(
        &root,
        referrer,
        &format!("its_about_time/kit/{piece}.gltf"),
    )?)
}

/// The bounds of every placed vertex, in the model's space.
fn bounds(model: &Model) -> (Vec3, Vec3) {
    let (mut min, mut max) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for placement in &model.placements {
        for p in &model.meshes[placement.mesh].positions {
            let q = placement.model_from_mesh.transform_point3(*p);
            min = min.min(q);
            max = max.max(q);
        }
    }
    (min, max)
}

fn triangles(model: &Model) -> usize {
    model.meshes.iter().map(|m| m.triangles.len()).sum()
}

fn emissive_triangles(model: &Model) -> usize {
    model
        .meshes
        .iter()
        .flat_map(|m| &m.triangle_materials)
        .filter(|&&material| model.materials[material as usize].emission.max_element() > 0.0)
        .count()
}

fn is_emissive_piece(name: &str) -> bool {
    name == "torch_flame" || name.starts_with("glyph_glow_")
}

#[test]
fn every_piece_loads_with_finite_bounds_and_triangles() -> anyhow::Result<()> {
    let pieces = ruins_kit::pieces();
    for required in [
        "block_small",
        "steps",
        "column_drum",
        "column_capital",
        "carved_panel",
        "lintel",
        "temple_tier",
        "torch",
        "torch_flame",
        "sun_altar",
        "lever_base",
        "lever_handle",
        "glyph_tile",
        "glyph_glow_0",
        "pressure_plate",
        "push_block",
        "boulder",
        "brittle_wall_piece_0",
        "sand_terrain",
    ] {
        assert!(
            pieces.iter().any(|p| p.name == required),
            "the kit has no {required}"
        );
    }
    for piece in &pieces {
        let name = piece.name;
        let model = load(name)?;
        let unexpected: Vec<&String> = model
            .notes
            .iter()
            .filter(|n| !n.starts_with("generated tangents"))
            .collect();
        assert!(
            unexpected.is_empty(),
            "{name}: the loader noted {unexpected:?}"
        );
        assert_eq!(model.placements.len(), 1, "{name}: one placed mesh");
        let (min, max) = bounds(&model);
        assert!(
            min.is_finite() && max.is_finite() && (max - min).min_element() >= 0.0,
            "{name}: bounds {min}..{max}"
        );
        let count = triangles(&model);
        assert!(
            count > 0 && count <= MAX_TRIANGLES,
            "{name}: {count} triangles (budget {MAX_TRIANGLES})"
        );
        assert_eq!(
            count,
            piece.triangle_count(),
            "{name}: triangles written = loaded"
        );
        for material in &model.materials {
            assert!(
                material.name != "glTF default",
                "{name}: a primitive without material"
            );
        }
        let emissive = emissive_triangles(&model);
        if is_emissive_piece(name) {
            assert_eq!(emissive, count, "{name}: every triangle emits");
        } else {
            assert_eq!(emissive, 0, "{name}: does not emit");
        }
        // Pieces sit on y = 0 except those centred on their pivot, the inlays on their tile
        // and the wall's pieces (the whole wall does).
        let off_ground = ["boulder", "sun_disc", "lever_handle"].contains(&name)
            || name.starts_with("glyph_glow_")
            || name.starts_with("brittle_wall_piece_");
        if !off_ground {
            assert!(min.y.abs() < 1e-3, "{name}: its foot is at y = {}", min.y);
        }
    }
    Ok(())
}

#[test]
fn stone_materials_have_colour_and_normal_maps() -> anyhow::Result<()> {
    for (piece, material) in [
        ("block_large", "sandstone"),
        ("carved_panel", "carved"),
        ("steps", "sandstone_worn"),
        ("sand_terrain", "sand"),
    ] {
        let model = load(piece)?;
        let m = model
            .materials
            .iter()
            .find(|m| m.name == material)
            .ok_or_else(|| anyhow::anyhow!("{piece}: no material {material}"))?;
        assert!(
            m.base_color_texture.is_some() && m.normal_texture.is_some(),
            "{piece}: {material} has a colour texture and a normal map"
        );
        let tangents = model.meshes.iter().all(|mesh| mesh.tangents.is_some());
        assert!(tangents, "{piece}: tangents for the normal map");
    }
    Ok(())
}

#[test]
fn brittle_wall_pieces_tile_the_wall_box() -> anyhow::Result<()> {
    let [w, h, d] = wall::WALL_SIZE;
    let (want_min, want_max) = (
        Vec3::new(-w / 2.0, 0.0, -d / 2.0),
        Vec3::new(w / 2.0, h, d / 2.0),
    );
    let (mut min, mut max) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    let mut front_area = 0.0f64;
    assert!(
        wall::WALL_PIECES >= 4,
        "a wall of {} pieces",
        wall::WALL_PIECES
    );
    for (index, name) in wall::WALL_PIECE_NAMES.iter().enumerate() {
        assert_eq!(*name, format!("brittle_wall_piece_{index}"));
        let model = load(name)?;
        let (lo, hi) = bounds(&model);
        assert!(
            lo.cmpge(want_min - 1e-3).all() && hi.cmple(want_max + 1e-3).all(),
            "{name}: bounds {lo}..{hi} leave the wall's box {want_min}..{want_max}"
        );
        min = min.min(lo);
        max = max.max(hi);
        // The piece's share of the wall's front face (z = +d/2, facing +Z).
        for mesh in &model.meshes {
            for t in &mesh.triangles {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                let n = (b - a).cross(c - a);
                if n.z > 0.0 && (a.z - d / 2.0).abs() < 1e-4 && (b.z - a.z).abs() < 1e-4 {
                    front_area += 0.5 * f64::from(n.length());
                }
            }
        }
    }
    assert!(
        min.abs_diff_eq(want_min, 1e-3) && max.abs_diff_eq(want_max, 1e-3),
        "the pieces' bounds {min}..{max}, the wall's box {want_min}..{want_max}"
    );
    // No gap and no overlap: the front faces add up to the wall's face.
    let want_area = f64::from(w * h);
    assert!(
        (front_area - want_area).abs() < 1e-3,
        "the pieces' front faces cover {front_area} m², the wall's face is {want_area} m²"
    );
    Ok(())
}

#[test]
fn textures_have_their_sizes() -> anyhow::Result<()> {
    let expected = [
        ("sandstone", textures::STONE_SIZE),
        ("sandstone_normal", textures::STONE_SIZE),
        ("carved", textures::STONE_SIZE),
        ("carved_normal", textures::STONE_SIZE),
        ("sand", textures::SAND_SIZE),
        ("sand_normal", textures::SAND_SIZE),
    ];
    for (name, size) in expected {
        let path = kit_dir().join(format!("textures/{name}.png"));
        let (w, h) = image::image_dimensions(&path)
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        assert_eq!(
            (w, h),
            (size, size),
            "{name}.png is {w} × {h}, want {size}²"
        );
        assert!(size == 256 || size == 512, "{name}: small textures only");
    }
    let mut total = 0u64;
    let mut all = BTreeSet::new();
    files_under(&kit_dir(), "", &mut all)?;
    for file in &all {
        total += std::fs::metadata(kit_dir().join(file))?.len();
    }
    assert!(total < 5_000_000, "the kit is {total} bytes, budget 5 MB");
    Ok(())
}
