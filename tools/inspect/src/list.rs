//! Printing what a glTF file holds: nodes, meshes, materials, skins and clips.
//!
//! Owns: [`print`]. Materials come from the engine's model loader (the animation loader
//! does not read them); if that loader refuses the file, the reason is printed instead.

use std::path::Path;

use candela::sim::animation::{AnimatedModel, Interpolation};

fn name(name: Option<&str>) -> String {
    name.map_or_else(|| "(unnamed)".to_string(), |n| format!("{n:?}"))
}

/// Prints the listing of `model`, loaded from `file`, to stdout.
pub fn print(file: &Path, model: &AnimatedModel) {
    println!("{}", file.display());
    let nodes = &model.nodes.nodes;
    println!("nodes ({}):", nodes.len());
    for (i, node) in nodes.iter().enumerate() {
        let mut parts = vec![format!("  #{i} {}", name(node.name.as_deref()))];
        if let Some(mesh) = node.mesh {
            parts.push(format!("mesh {mesh}"));
        }
        if let Some(skin) = node.skin {
            parts.push(format!("skin {skin}"));
        }
        if !node.children.is_empty() {
            parts.push(format!("children {:?}", node.children));
        }
        if !model.nodes.in_scene[i] {
            parts.push("(not in the default scene)".to_string());
        }
        println!("{}", parts.join(", "));
    }
    println!("meshes ({}):", model.meshes.len());
    for (i, mesh) in model.meshes.iter().enumerate() {
        let vertices: usize = mesh.primitives.iter().map(|p| p.positions.len()).sum();
        let skinned = mesh.primitives.iter().any(|p| p.influences.is_some());
        println!(
            "  #{i} {}: {} primitive(s), {vertices} vertices, {} morph target(s){}",
            name(mesh.name.as_deref()),
            mesh.primitives.len(),
            mesh.default_weights.len(),
            if skinned { ", skinned" } else { "" }
        );
    }
    match candela::assets::load_model_file(file) {
        Ok(loaded) => {
            println!("materials ({}):", loaded.materials.len());
            for (i, material) in loaded.materials.iter().enumerate() {
                println!("  #{i} {:?} ({:?})", material.name, material.kind);
            }
        }
        Err(error) => println!("materials: not read ({error})"),
    }
    println!("skins ({}):", model.skins.len());
    for (i, skin) in model.skins.iter().enumerate() {
        println!(
            "  #{i} {}: {} joint(s)",
            name(skin.name.as_deref()),
            skin.joints.len()
        );
    }
    println!("clips ({}):", model.clips.len());
    for (i, clip) in model.clips.iter().enumerate() {
        let mut kinds: Vec<String> = clip
            .channels
            .iter()
            .map(|c| {
                let interpolation = match c.interpolation {
                    Interpolation::Step => "STEP",
                    Interpolation::Linear => "LINEAR",
                    Interpolation::CubicSpline => "CUBICSPLINE",
                };
                format!("{interpolation} {}", c.property.name())
            })
            .collect();
        kinds.sort();
        kinds.dedup();
        let label = if clip.name.is_empty() {
            "(unnamed)".to_string()
        } else {
            format!("{:?}", clip.name)
        };
        println!(
            "  #{i} {label}: {:.4} s, {} channel(s) ({})",
            clip.duration_seconds,
            clip.channels.len(),
            kinds.join(", ")
        );
    }
    for note in &model.notes {
        println!("note: {note}");
    }
}
