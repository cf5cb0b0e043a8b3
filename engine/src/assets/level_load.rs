//! Loading what a level renders: the RON file and every model it names, into a [`SceneDesc`].
//!
//! Owns: resolving model paths through the [`AssetRoot`], loading each model once, turning
//! level materials into engine materials, marking instances that move (bodies, clips) as
//! dynamic, and checking every name the scene uses (models, materials) with an error that
//! names the level and the item. Main thread or a loader thread.
//! Must not: build BVHs, colliders or gameplay (`level::load_level` does), or touch the GPU.

use std::collections::HashMap;
use std::path::Path;

use glam::Vec3;
use rayon::prelude::*;

use super::error::{AssetError, AssetResult};
use super::level::{Level, LevelMaterial, SkyDesc};
use super::level_body::BodyEntry;
use super::model::Material;
use super::root::AssetRoot;
use super::scene_desc::{SceneDesc, SceneInstance};

/// Reads `level_path` and loads what it renders from `root` (models in parallel): its
/// models, materials, instances, camera, sun, sky and render settings. Its bodies and gameplay
/// are checked and built by `level::load_level`, which a game uses.
pub fn load_scene(level_path: &Path, root: &AssetRoot) -> AssetResult<SceneDesc> {
    let level = Level::read(level_path)?;
    scene_from_level(level_path, &level, root)
}

/// Loads the models of an already parsed `level` (read from `level_path`).
pub fn scene_from_level(
    level_path: &Path,
    level: &Level,
    root: &AssetRoot,
) -> AssetResult<SceneDesc> {
    let level_error = |message: String| AssetError::Level {
        path: level_path.to_path_buf(),
        message,
    };
    let mut model_index = HashMap::new();
    let names = level
        .models
        .iter()
        .map(|m| m.name.as_str())
        .chain(level.grids.iter().map(|g| g.name.as_str()))
        .chain(level.boxes.iter().map(|b| b.name.as_str()))
        .chain(level.terrains.iter().map(|t| t.name.as_str()))
        .chain(level.cities.iter().map(|c| c.name.as_str()));
    for (i, name) in names.enumerate() {
        if model_index.insert(name, i).is_some() {
            return Err(level_error(format!("model name {name:?} is used twice")));
        }
    }
    let mut material_index = HashMap::new();
    for (i, m) in level.materials.iter().enumerate() {
        if material_index.insert(m.name.as_str(), i).is_some() {
            return Err(level_error(format!(
                "material name {:?} is used twice",
                m.name
            )));
        }
    }
    let material_of = |kind: &str, name: &str, material: &str| {
        material_index
            .get(material)
            .map(|&m| level_material(&level.materials[m]))
            .ok_or_else(|| {
                level_error(format!(
                    "{kind} {name:?} uses the material {material:?}, which the level does not define"
                ))
            })
    };
    let mut grids = Vec::with_capacity(level.grids.len());
    for grid in &level.grids {
        let material = material_of("grid", &grid.name, &grid.material)?;
        let [nx, nz] = grid.divisions;
        let sizes_ok = grid.size.iter().all(|s| *s > 0.0 && s.is_finite());
        if nx == 0 || nz == 0 || nx > 2048 || nz > 2048 || !sizes_ok {
            return Err(level_error(format!(
                "grid {:?}: size must be positive and divisions within 1..=2048",
                grid.name
            )));
        }
        grids.push(super::grid::grid_model(grid, material));
    }
    grids.extend(super::level_shapes::generated_models(
        level,
        &material_of,
        &level_error,
    )?);
    let mut instances = Vec::with_capacity(level.instances.len());
    for (i, instance) in level.instances.iter().enumerate() {
        let Some(&model) = model_index.get(instance.model.as_str()) else {
            return Err(level_error(format!(
                "instance {i} uses the model {:?}, which the level does not define",
                instance.model
            )));
        };
        let material_override = match &instance.material {
            None => None,
            Some(name) => Some(*material_index.get(name.as_str()).ok_or_else(|| {
                level_error(format!(
                    "instance {i} uses the material {name:?}, which the level does not define"
                ))
            })?),
        };
        let world_from_model = instance.transform.world_from_model();
        if !world_from_model.is_finite() || world_from_model.determinant() == 0.0 {
            return Err(level_error(format!(
                "instance {i} ({:?}) has a degenerate or non-finite transform",
                instance.model
            )));
        }
        super::level_water::check_simulated_water(level, i, instance).map_err(level_error)?;
        instances.push(SceneInstance {
            model,
            world_from_model,
            material_override,
            name: instance.name.clone(),
            dynamic: instance.dynamic || instance.waves.is_some(),
            light_group: instance.light_group,
            waves: instance.waves,
        });
    }
    let camera = &level.camera;
    if !(camera.vertical_fov_deg > 0.0 && camera.vertical_fov_deg < 180.0) {
        return Err(level_error(format!(
            "camera.vertical_fov_deg must be in (0, 180), not {}",
            camera.vertical_fov_deg
        )));
    }
    if Vec3::from(camera.look_at) == Vec3::from(camera.position) {
        return Err(level_error("camera.look_at equals camera.position".into()));
    }
    if let SkyDesc::Physical(sky) = &level.sky {
        if level.sun.is_some() {
            return Err(level_error(
                "sun must be None with sky: Physical (the physical sky places and colours the sun)"
                    .into(),
            ));
        }
        if let Err(e) = sky.validate() {
            return Err(level_error(format!("sky.Physical: {e}")));
        }
    }
    let mut models = level
        .models
        .par_iter()
        .map(|entry| {
            super::load_model(root, level_path, &entry.path).map_err(|e| AssetError::InLevel {
                level: level_path.to_path_buf(),
                model: entry.name.clone(),
                source: Box::new(e),
            })
        })
        .collect::<AssetResult<Vec<_>>>()?;
    for (model, entry) in models.iter().zip(&level.models) {
        for note in &model.notes {
            log::info!("{}: {}: {note}", level_path.display(), entry.path);
        }
    }
    models.extend(grids);
    for (entry, scene_instance) in level.instances.iter().zip(&mut instances) {
        // A body that moves, or a clip that moves the instance: compared every frame, never
        // written once and forgotten.
        let moving_body = matches!(
            entry.body,
            Some(BodyEntry::Dynamic { .. } | BodyEntry::Kinematic { .. })
        );
        let clip_target = entry.name.as_deref().is_some_and(|name| {
            level
                .gameplay
                .animations
                .iter()
                .flat_map(|clip| &clip.tracks)
                .any(|track| track.target == name)
        });
        // A breakable's piece stands still until it falls.
        let piece = entry.name.as_deref().is_some_and(|name| {
            (level.gameplay.breakables.iter()).any(|b| b.pieces.iter().any(|p| p == name))
        });
        scene_instance.dynamic |= moving_body || clip_target || piece;
    }
    Ok(SceneDesc {
        source: level_path.to_path_buf(),
        models,
        level_materials: level.materials.iter().map(level_material).collect(),
        instances,
        camera: level.camera,
        sun: level.sun,
        sky: level.sky,
        render: level.render,
    })
}

fn level_material(m: &LevelMaterial) -> Material {
    Material {
        name: m.name.clone(),
        kind: m.kind,
        base_color: Vec3::from(m.base_color),
        emission: Vec3::from(m.emission),
        two_sided_emission: m.two_sided_emission,
        roughness: m.roughness,
        metallic: m.metallic,
        ior: m.ior,
        attenuation_color: Vec3::from(m.attenuation_color),
        attenuation_distance: m.attenuation_distance.unwrap_or(f32::INFINITY),
        ..Material::default()
    }
}
