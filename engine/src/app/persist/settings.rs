//! The player's settings: picture (resolution scale, target frame rate, vsync, fullscreen),
//! sound (master, effects and music volume), look (mouse sensitivity, invert Y) and rebound
//! actions, kept as RON in `<config>/settings.ron` (see `user_dirs.rs`).
//!
//! Loading never fails: a missing file gives [`Settings::default`]; bad RON, an unknown field,
//! a value out of range (NaN included) or an unknown action gives the defaults, a warning
//! naming the file and the problem, and the bad file kept as `settings.ron.corrupt`. Every
//! field has a default (`#[serde(default)]`), so files from older versions load. Saving is
//! atomic and refuses values that would not load again.
//!
//! Owns: the settings values and their ranges. Main thread. Must not: apply them (the runner
//! does: window, tracer scaling, audio buses, the player controller).

use std::path::Path;

use serde::{Deserialize, Serialize};

use super::bindings::Bindings;
use super::stored::{Loaded, StoreError, load_or_default, save_ron};
use crate::app::input::ActionSet;
use crate::app::input::InputMap;

/// The player's settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Settings {
    /// Render resolution per axis as a fraction of the window's, in [0.1, 1]. Workload scaling
    /// may go lower to hold `target_fps`; it never goes above this.
    pub resolution_scale: f32,
    /// Frames per second the runner aims for, in [10, 1000]; `None`: as fast as they come.
    /// The default, 30, is a rate the CPU tracer holds on two cores (at a lowered resolution);
    /// at 60 workload scaling would sit at its floor and still miss it.
    pub target_fps: Option<f32>,
    /// Present on vertical blank.
    pub vsync: bool,
    /// Borderless fullscreen.
    pub fullscreen: bool,
    /// Linear gain in [0, 1] of everything.
    pub master_volume: f32,
    /// Linear gain in [0, 1] of sound effects (on top of the master).
    pub effects_volume: f32,
    /// Linear gain in [0, 1] of music (on top of the master).
    pub music_volume: f32,
    /// Multiplier in [0.05, 20] on the controller's base look rate (mouse and stick).
    pub mouse_sensitivity: f32,
    /// Pushing the mouse or stick up looks down.
    pub invert_y: bool,
    /// Actions the player rebound (the rest keep the game's defaults).
    pub bindings: Bindings,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            resolution_scale: 1.0,
            target_fps: Some(30.0),
            vsync: true,
            fullscreen: false,
            master_volume: 1.0,
            effects_volume: 1.0,
            music_volume: 0.8,
            mouse_sensitivity: 1.0,
            invert_y: false,
            bindings: Bindings::default(),
        }
    }
}

/// `value` within [lo, hi] (false for NaN).
fn check_range(name: &str, value: f32, lo: f32, hi: f32) -> Result<(), String> {
    if value >= lo && value <= hi {
        Ok(())
    } else {
        Err(format!("{name} is {value}, outside [{lo}, {hi}]"))
    }
}

impl Settings {
    /// The first value out of range or binding `set` does not know, if any.
    pub fn check(&self, set: &ActionSet) -> Result<(), String> {
        check_range("resolution_scale", self.resolution_scale, 0.1, 1.0)?;
        if let Some(fps) = self.target_fps {
            check_range("target_fps", fps, 10.0, 1000.0)?;
        }
        check_range("master_volume", self.master_volume, 0.0, 1.0)?;
        check_range("effects_volume", self.effects_volume, 0.0, 1.0)?;
        check_range("music_volume", self.music_volume, 0.0, 1.0)?;
        check_range("mouse_sensitivity", self.mouse_sensitivity, 0.05, 20.0)?;
        self.bindings
            .check(set)
            .map_err(|p| format!("bindings: {p}"))
    }

    /// Reads the settings file (see the module doc: never fails, warns instead).
    pub fn load(path: &Path, set: &ActionSet) -> Loaded<Settings> {
        load_or_default(path, |s: &Settings| s.check(set))
    }

    /// Writes the settings file atomically; values that would not load again are refused and
    /// the previous file is kept.
    pub fn save(&self, path: &Path, set: &ActionSet) -> Result<(), StoreError> {
        self.check(set).map_err(|problem| StoreError::Invalid {
            path: path.to_path_buf(),
            problem,
        })?;
        save_ron(path, self)
    }

    /// The input map: `set`'s defaults with the player's rebinding in place.
    pub fn input_map(&self, set: &ActionSet) -> InputMap {
        self.bindings.input_map(set)
    }

    /// Gain of the effects bus including the master (linear).
    pub fn effects_gain(&self) -> f32 {
        self.master_volume * self.effects_volume
    }

    /// Gain of the music bus including the master (linear).
    pub fn music_gain(&self) -> f32 {
        self.master_volume * self.music_volume
    }

    /// Factor on vertical look input: −1 with `invert_y`, else 1.
    pub fn look_y_sign(&self) -> f32 {
        if self.invert_y { -1.0 } else { 1.0 }
    }
}
