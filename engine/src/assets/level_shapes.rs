//! The engine-made models of a level besides grids — boxes, terrains, cities — checked and
//! generated in that order (after the grids; level loading appends them to the models in the
//! same order it registered their names).
//!
//! Owns: the size checks of those entries, each failing with a message that names the entry.
//! Must not: read files.

use super::city::city_model;
use super::error::{AssetError, AssetResult};
use super::level::Level;
use super::model::{Material, Model};
use super::shapes::{box_model, terrain_model};

/// Largest divisions per axis of a terrain (as for grids).
const MAX_DIVISIONS: u32 = 2048;
/// Most blocks per axis of a city, and lots per block edge.
const MAX_BLOCKS: u32 = 256;
const MAX_LOTS: u32 = 16;

fn positive(values: &[f32]) -> bool {
    values.iter().all(|v| v.is_finite() && *v > 0.0)
}

/// Boxes, terrains and cities of `level`, in that order. `material_of(kind, name, material)`
/// resolves a level material; `invalid` makes the error for a bad entry.
pub(super) fn generated_models(
    level: &Level,
    material_of: &dyn Fn(&str, &str, &str) -> AssetResult<Material>,
    invalid: &dyn Fn(String) -> AssetError,
) -> AssetResult<Vec<Model>> {
    let mut models = Vec::new();
    for b in &level.boxes {
        let material = material_of("box", &b.name, &b.material)?;
        if !positive(&b.size) {
            return Err(invalid(format!(
                "box {:?}: every size must be positive",
                b.name
            )));
        }
        models.push(box_model(b, material));
    }
    for t in &level.terrains {
        let material = material_of("terrain", &t.name, &t.material)?;
        let [nx, nz] = t.divisions;
        let ok = positive(&t.size)
            && positive(&[t.feature_size])
            && t.height.is_finite()
            && t.flat_radius.is_finite()
            && t.ramp.is_finite()
            && (1..=MAX_DIVISIONS).contains(&nx)
            && (1..=MAX_DIVISIONS).contains(&nz);
        if !ok {
            return Err(invalid(format!(
                "terrain {:?}: size and feature_size must be positive, divisions within \
                 1..={MAX_DIVISIONS}, heights finite",
                t.name
            )));
        }
        models.push(terrain_model(t, material));
    }
    for c in &level.cities {
        let walls = material_of("city", &c.name, &c.wall_material)?;
        let roofs = material_of("city", &c.name, &c.roof_material)?;
        let [nx, nz] = c.blocks;
        let ok = positive(&[c.block_size, c.height[0], c.height[1]])
            && c.height[0] <= c.height[1]
            && c.street_width.is_finite()
            && c.street_width >= 0.0
            && c.plaza_radius.is_finite()
            && (1..=MAX_BLOCKS).contains(&nx)
            && (1..=MAX_BLOCKS).contains(&nz)
            && (1..=MAX_LOTS).contains(&c.lots);
        if !ok {
            return Err(invalid(format!(
                "city {:?}: blocks within 1..={MAX_BLOCKS}, lots within 1..={MAX_LOTS}, \
                 block_size and heights positive (lowest first), street_width not negative",
                c.name
            )));
        }
        models.push(city_model(c, walls, roofs));
    }
    Ok(models)
}
