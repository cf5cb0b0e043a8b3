//! The game file (`assets/reflect/reflect.ron`): which level files make the world (a base file
//! shared by all chambers, then one file per chamber), the chambers in play order with their
//! name, objective, start, mirror cap and bounds, and which models the mirror gun may turn into
//! mirrors.
//!
//! Owns: [`GameFile`], [`Chamber`] and their checks. Main thread, at start.
//! Must not: load levels (`world` does).
//!
//! Units: metres (world space, +Y up), degrees where the field says `_deg`.
//!
//! ```ron
//! Reflect(
//!     base: "reflect/levels/common.ron",
//!     mirror_material: "mirror",
//!     mirrorable_models: ["mirror_panel", "curved_panel"],
//!     chambers: [(id: "chamber_1", name: "Plate", file: "reflect/levels/chamber_1.ron",
//!                 objective: "Put a cube on the plate", start: (0, 0, -2), yaw_deg: 0,
//!                 mirrors: 0, bounds: ((-8, -1, -16), (8, 9, 0)))],
//! )
//! ```

use std::path::{Path, PathBuf};

use glam::Vec3;
use serde::Deserialize;

/// A problem with the game file, naming it and the item.
#[derive(Debug, thiserror::Error)]
pub enum GameFileError {
    #[error("{path}: cannot read: {source}")]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: {message}")]
    Invalid { path: PathBuf, message: String },
}

/// The game file as written.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "Reflect", deny_unknown_fields)]
pub struct GameFile {
    /// Level file every chamber shares (models, materials, camera, sky, render settings),
    /// relative to the asset root.
    pub base: String,
    /// The level material the mirror gun gives a panel (a smooth conductor).
    pub mirror_material: String,
    /// Models whose instances the mirror gun may turn into mirrors.
    pub mirrorable_models: Vec<String>,
    /// The chambers in play order.
    pub chambers: Vec<ChamberEntry>,
}

/// One chamber as written.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChamberEntry {
    /// Stable id: the progress save's key, the replay's level id.
    pub id: String,
    /// What menus show.
    pub name: String,
    /// Its level file, relative to the asset root.
    pub file: String,
    /// The HUD's objective line while the player is in it.
    pub objective: String,
    /// Where the player's feet start (and return to when a laser crosses them), metres.
    pub start: [f32; 3],
    /// Which way the player looks there: 0 looks along −Z, 90 along −X.
    pub yaw_deg: f32,
    /// How many mirrors may be active at once in the chamber.
    pub mirrors: i64,
    /// The chamber's box (min, max corners): the player is in the chamber whose box holds
    /// their feet; a panel belongs to the chamber whose box holds it.
    pub bounds: ([f32; 3], [f32; 3]),
}

/// A checked chamber.
#[derive(Clone, Debug, PartialEq)]
pub struct Chamber {
    pub id: String,
    pub name: String,
    pub file: String,
    pub objective: String,
    pub start: Vec3,
    /// Radians, the player's yaw convention (0 looks along −Z).
    pub yaw: f32,
    pub mirror_cap: u32,
    pub min: Vec3,
    pub max: Vec3,
}

impl Chamber {
    /// Whether `p` lies in the chamber's box.
    pub fn contains(&self, p: Vec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }
}

impl GameFile {
    /// Reads and parses `path`.
    pub fn read(path: &Path) -> Result<Self, GameFileError> {
        let text = std::fs::read_to_string(path).map_err(|source| GameFileError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        ron::Options::default()
            .from_str::<GameFile>(&text)
            .map_err(|e| GameFileError::Invalid {
                path: path.to_path_buf(),
                message: e.to_string(),
            })
    }

    /// The chambers, checked: unique ids, a cap of zero or more, finite numbers, a box with
    /// its start inside.
    pub fn chambers(&self, path: &Path) -> Result<Vec<Chamber>, GameFileError> {
        let invalid = |message: String| GameFileError::Invalid {
            path: path.to_path_buf(),
            message,
        };
        if self.chambers.is_empty() {
            return Err(invalid("chambers: the game has no chamber".into()));
        }
        let mut out: Vec<Chamber> = Vec::with_capacity(self.chambers.len());
        for c in &self.chambers {
            let item = |m: &str| invalid(format!("chamber {:?}: {m}", c.id));
            if c.id.is_empty() {
                return Err(invalid("a chamber has an empty id".into()));
            }
            if out.iter().any(|o| o.id == c.id) {
                return Err(item("the id is used twice"));
            }
            let cap = u32::try_from(c.mirrors).map_err(|_| {
                item(&format!(
                    "mirrors: {} is not a mirror count (0 or more)",
                    c.mirrors
                ))
            })?;
            let (min, max) = (Vec3::from(c.bounds.0), Vec3::from(c.bounds.1));
            let start = Vec3::from(c.start);
            if !(min.is_finite() && max.is_finite() && start.is_finite() && c.yaw_deg.is_finite()) {
                return Err(item("a number is not finite"));
            }
            if !min.cmplt(max).all() {
                return Err(item("bounds: the min corner is not below the max corner"));
            }
            let chamber = Chamber {
                id: c.id.clone(),
                name: c.name.clone(),
                file: c.file.clone(),
                objective: c.objective.clone(),
                start,
                yaw: c.yaw_deg.to_radians(),
                mirror_cap: cap,
                min,
                max,
            };
            if !chamber.contains(start + Vec3::Y * 0.1) {
                return Err(item("start: the start is outside the chamber's bounds"));
            }
            out.push(chamber);
        }
        Ok(out)
    }
}
