//! Render areas a level declares: boxes in world space, each naming the light groups visible
//! from it (`render_areas: [(name: "sun_gate", min: (8, -1, -7), max: (27, 12, 7),
//! light_groups: [2])]`), and their checks. While the camera is inside an area, emitters whose
//! light group it does not name leave next-event estimation's light table (they still emit when
//! a path hits them: `layout::INSTANCE_FLAG_UNSAMPLED`); inside several areas, the groups any of
//! them names are sampled; outside every area, every group is, as in a level without areas.
//! Emitters in no light group are always sampled.
//!
//! Owns: [`RenderArea`], [`sampled_groups`] (which groups the camera's position samples) and
//! [`check_render_areas`] (called by `Level::parse`, so a bad area never reaches a game). Any
//! thread, pure. Must not: touch the light table (the upkeep does, from [`sampled_groups`]).
//!
//! Units: metres, world space (right-handed, Y up).

use std::collections::HashSet;
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::error::{AssetError, AssetResult};
use super::level::Level;

/// One render area: an axis-aligned box in world space (metres) and the light groups
/// (`InstanceEntry::light_group`) whose emitters can light what the camera sees from it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderArea {
    /// Unique among the level's areas, not empty (messages and the bench name it).
    pub name: String,
    /// The box's lowest corner, metres, world space.
    pub min: [f32; 3],
    /// The box's highest corner, metres, world space (each axis ≥ `min`'s).
    pub max: [f32; 3],
    /// The light groups sampled while the camera is inside; each must be a group some instance
    /// (or laser beam) of the level belongs to.
    pub light_groups: Vec<u32>,
}

impl RenderArea {
    /// Whether `point` (metres, world space) lies in the box, faces included.
    pub fn contains(&self, point: [f32; 3]) -> bool {
        (0..3).all(|k| self.min[k] <= point[k] && point[k] <= self.max[k])
    }
}

/// The light groups next-event estimation samples with the camera at `camera` (metres, world
/// space): `None` outside every area (every group); inside, the groups any containing area names,
/// sorted and without repeats.
pub fn sampled_groups(areas: &[RenderArea], camera: [f32; 3]) -> Option<Vec<u32>> {
    let mut groups: Option<Vec<u32>> = None;
    for area in areas.iter().filter(|a| a.contains(camera)) {
        groups
            .get_or_insert_with(Vec::new)
            .extend(&area.light_groups);
    }
    groups.map(|mut g| {
        g.sort_unstable();
        g.dedup();
        g
    })
}

/// The first area `level` (read from `path`) may not declare, naming the file and the field: an
/// empty name, a name used twice, a `min` above `max` on some axis (or not finite), a light
/// group no instance or laser beam of the level belongs to.
pub fn check_render_areas(level: &Level, path: &Path) -> AssetResult<()> {
    let bad = |i: usize, area: &RenderArea, message: String| {
        Err(AssetError::Level {
            path: path.to_path_buf(),
            message: format!("render_areas[{i}] ({:?}): {message}", area.name),
        })
    };
    let groups: HashSet<u32> = (level.instances.iter().filter_map(|i| i.light_group))
        .chain((level.gameplay.lasers.iter()).filter_map(|l| l.beam.as_ref()?.light_group))
        .collect();
    let mut names = HashSet::new();
    for (i, area) in level.render_areas.iter().enumerate() {
        if area.name.trim().is_empty() {
            return bad(i, area, "name is empty; every area needs a name".into());
        }
        if !names.insert(area.name.as_str()) {
            return bad(
                i,
                area,
                format!(
                    "name {:?} is used by an earlier area; names must be unique",
                    area.name
                ),
            );
        }
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            let (lo, hi) = (area.min[k], area.max[k]);
            if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
                return bad(
                    i,
                    area,
                    format!("min.{axis} is {lo} and max.{axis} is {hi}; min must not be above max"),
                );
            }
        }
        if let Some(g) = area.light_groups.iter().find(|g| !groups.contains(g)) {
            return bad(
                i,
                area,
                format!("light_groups names group {g}, which no instance belongs to"),
            );
        }
    }
    Ok(())
}
