//! The Reflect art kit (`assets/reflect/kit/`): the committed files are exactly what
//! `tools/assetgen` makes, and every piece loads through the engine's glTF loader with the
//! size, origin and materials the chamber levels rely on (docs/LEVELS.md, "The Reflect kit").

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use candela::assets::{AssetRoot, Model, load_model};
use glam::Vec3;

const REGENERATE: &str = "cargo run --release -p assetgen -- reflect-kit";

/// Each piece's bounds (metres, the piece's own space), from the kit's specification.
const BOUNDS: [(&str, [f32; 3], [f32; 3]); 30] = [
    ("wall_8x4", [-4.0, 0.0, -0.2], [4.0, 4.0, 0.0]),
    ("wall_4x4", [-2.0, 0.0, -0.2], [2.0, 4.0, 0.0]),
    ("wall_4x4_door", [-2.0, 0.0, -0.2], [2.0, 4.0, 0.0]),
    ("floor_8x8", [-4.0, -0.2, -4.0], [4.0, 0.0, 4.0]),
    ("ceiling_8x8", [-4.0, 0.0, -4.0], [4.0, 0.2, 4.0]),
    ("trim_8", [-4.0, 0.0, 0.0], [4.0, 0.3, 0.08]),
    ("light_strip_4", [-0.075, 0.0, 0.0], [0.075, 4.0, 0.08]),
    ("mirror_panel", [-1.0, 0.0, -0.06], [1.0, 2.0, 0.0]),
    // Radius 3 about (0, ·, 3), 60° wide, 0.06 m thick: the back reaches x = ±3.06 sin 30°,
    // the arc's ends come forward to z = 3 − 3 cos 30°.
    ("curved_panel", [-1.53, 0.0, -0.06], [1.53, 2.0, 0.401_924]),
    ("glass_cube", [-0.25, -0.25, -0.25], [0.25, 0.25, 0.25]),
    ("glass_pane_4x4", [-2.0, 0.0, -0.12], [2.0, 4.0, 0.0]),
    ("door", [-1.2, 0.0, -0.075], [1.2, 3.0, 0.075]),
    ("dispenser", [-0.5, 0.0, -0.5], [0.5, 3.0, 0.5]),
    ("plate", [-0.7, 0.0, -0.7], [0.7, 0.08, 0.7]),
    ("receiver", [-0.3, 0.0, 0.0], [0.3, 0.6, 0.25]),
    ("emitter", [-0.3, 0.0, 0.0], [0.3, 0.6, 0.3]),
    ("elevator", [-1.5, -0.3, -1.5], [1.5, 0.0, 1.5]),
    ("railing_3", [-1.5, 0.0, -0.03], [1.5, 1.0, 0.03]),
    ("pillar", [-0.5, 0.0, -0.5], [0.5, 8.0, 0.5]),
    ("pipe_8", [-4.0, -0.14, -0.14], [4.0, 0.14, 0.14]),
    ("fan_frame", [-0.7, -0.7, 0.0], [0.7, 0.7, 0.34]),
    // Four blades to radius 0.55 on the X and Y axes; the hub is 0.14 m deep.
    ("fan_rotor", [-0.55, -0.55, -0.07], [0.55, 0.55, 0.07]),
    ("crate", [-0.25, -0.25, -0.25], [0.25, 0.25, 0.25]),
    ("piston_sleeve", [-0.25, -0.25, 0.0], [0.25, 0.25, 0.6]),
    ("piston_rod", [-0.18, -0.18, 0.1], [0.18, 0.18, 1.08]),
    ("sign_1", [-0.5, 0.0, -0.05], [0.5, 1.0, 0.0]),
    ("sign_2", [-0.5, 0.0, -0.05], [0.5, 1.0, 0.0]),
    ("sign_3", [-0.5, 0.0, -0.05], [0.5, 1.0, 0.0]),
    ("sign_4", [-0.5, 0.0, -0.05], [0.5, 1.0, 0.0]),
    ("sign_5", [-0.5, 0.0, -0.05], [0.5, 1.0, 0.0]),
];

/// Pieces the game turns into mirrors or carries as glass: one material each.
const SINGLE_MATERIAL: [&str; 3] = ["mirror_panel", "curved_panel", "glass_cube"];

/// The triangle budget of one piece.
const MAX_TRIANGLES: usize = 5_000;

fn assets() -> PathBuf {
    candela_tests::repo().join("assets")
}

fn kit_dir() -> PathBuf {
    assets().join("reflect/kit")
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
    let made = assetgen::reflect_kit::kit_files()?;
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
        "assets/reflect/kit differs from what assetgen makes: missing {missing:?}, extra \
         {extra:?}, stale {stale:?}; run `{REGENERATE}` (and delete the extra files)"
    );
    Ok(())
}

fn load(piece: &str) -> anyhow::Result<Model> {
    let root = AssetRoot::new(assets())?;
    let referrer = Path::new("tests/cross/reflect_kit.rs");
    Ok(load_model(
        &root,
        referrer,
        &format!("reflect/kit/{piece}.gltf"),
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

#[test]
fn every_piece_loads_with_its_specified_bounds() -> anyhow::Result<()> {
    let pieces: Vec<&str> = assetgen::reflect_kit::pieces()
        .iter()
        .map(|p| p.name)
        .collect();
    let listed: Vec<&str> = BOUNDS.iter().map(|(name, _, _)| *name).collect();
    assert_eq!(
        pieces, listed,
        "the bounds table lists every piece, in kit order"
    );
    for (piece, min, max) in BOUNDS {
        let model = load(piece)?;
        assert!(
            model.notes.is_empty(),
            "{piece}: the loader noted {:?}",
            model.notes
        );
        assert_eq!(model.placements.len(), 1, "{piece}: one placed mesh");
        let (got_min, got_max) = bounds(&model);
        let (want_min, want_max) = (Vec3::from(min), Vec3::from(max));
        // 1 mm: the kit's stated tolerance; positions are written on a 10 µm grid.
        assert!(
            got_min.abs_diff_eq(want_min, 1e-3) && got_max.abs_diff_eq(want_max, 1e-3),
            "{piece}: bounds {got_min}..{got_max}, specified {want_min}..{want_max}"
        );
        let count = triangles(&model);
        assert!(
            count > 0 && count <= MAX_TRIANGLES,
            "{piece}: {count} triangles (budget {MAX_TRIANGLES})"
        );
        for material in &model.materials {
            assert!(
                material.name != "glTF default",
                "{piece}: a primitive without material"
            );
        }
    }
    Ok(())
}

#[test]
fn mirrorable_and_glass_pieces_have_one_material() -> anyhow::Result<()> {
    for piece in SINGLE_MATERIAL {
        let model = load(piece)?;
        let names: Vec<&str> = model.materials.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names.len(), 1, "{piece}: materials {names:?}");
    }
    for piece in ["mirror_panel", "curved_panel"] {
        let model = load(piece)?;
        assert_eq!(model.materials[0].name, "panel_white", "{piece}");
        assert!(
            model.materials[0].base_color_texture.is_some(),
            "{piece}: textured"
        );
    }
    let cube = load("glass_cube")?;
    assert_eq!(
        cube.materials[0].kind,
        candela::assets::MaterialKind::Dielectric
    );
    assert!((cube.materials[0].ior - 1.5).abs() < 1e-6);
    Ok(())
}

#[test]
fn ceilings_and_lights_emit() -> anyhow::Result<()> {
    let ceiling = load("ceiling_8x8")?;
    let emissive = emissive_triangles(&ceiling);
    assert!(
        emissive >= 400,
        "ceiling_8x8: {emissive} emissive triangles, the game needs at least 400 per ceiling"
    );
    for piece in [
        "light_strip_4",
        "trim_8",
        "elevator",
        "pillar",
        "door",
        "emitter",
    ] {
        assert!(emissive_triangles(&load(piece)?) > 0, "{piece} emits");
    }
    for piece in [
        "mirror_panel",
        "curved_panel",
        "glass_cube",
        "wall_8x4",
        "floor_8x8",
        "fan_rotor",
        "crate",
        "piston_rod",
    ] {
        assert_eq!(
            emissive_triangles(&load(piece)?),
            0,
            "{piece} does not emit"
        );
    }
    for number in 1..=5 {
        let sign = load(&format!("sign_{number}"))?;
        let face = &sign.materials[0];
        assert!(
            face.emission_texture.is_some() && face.base_color_texture.is_some(),
            "sign_{number}: the face has its colour and glow textures"
        );
    }
    Ok(())
}
