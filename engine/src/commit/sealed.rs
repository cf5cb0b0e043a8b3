//! [`Commit`]: one frame's deltas for the render thread (Brigade §4.4, Figure 7).
//!
//! Owns: the sealed frame — buffer writes (instances, refitted or rebuilt BLAS data, deformed
//! vertices, materials, light table, TLAS) with the header they leave behind, the view (a
//! `RenderCamera`, never the level file's `CameraDesc`), sun, sky
//! and render settings, how much moved (for converging), and in a window what to present (with
//! the stats overlay). Static data travels once, in the first commit after it is loaded.
//! Must not: reference the ECS (the render thread never sees game state) or carry the main
//! thread's telemetry (timers and upkeep counts stay in its `FrameReport`).

use super::present::PresentRequest;
use crate::assets::{RenderSettings, SkyDesc, SunDesc};
use crate::extract::RenderCamera;
use crate::scene::{SceneHeader, SceneWrite};

/// What moved since the previous commit, for the converging policy.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    /// A camera cut (teleport, level change): forget the accumulated image.
    pub cut: bool,
    /// How far the camera moved: metres of translation plus radians of rotation.
    pub camera: f32,
    /// Whether any rendered object moved, deformed, changed material or light.
    pub objects: bool,
    /// How far the sky's lighting moved: degrees the sun turned (a time of day, a moved sun),
    /// infinity for any other change of the sun or sky, 0 for none
    /// (`app::lighting_change`).
    pub lighting: f32,
}

/// One frame, sealed.
#[derive(Clone, Debug)]
pub struct Commit {
    pub frame: u64,
    pub writes: Vec<SceneWrite>,
    pub header: SceneHeader,
    /// The view, built once by the extractor (world space: eye, camera-to-world basis, field
    /// of view, lens); the render side reads it as is.
    pub camera: RenderCamera,
    pub sun: Option<SunDesc>,
    pub sky: SkyDesc,
    pub render: RenderSettings,
    pub motion: Motion,
    /// Read the converged film back after rendering this frame (screenshots, captures).
    pub capture: bool,
    /// What to show in the window after rendering (`None` headless: nothing is presented).
    pub present: Option<PresentRequest>,
}

impl Commit {
    /// Bytes of scene data this commit carries.
    pub fn bytes(&self) -> usize {
        self.writes.iter().map(SceneWrite::bytes).sum()
    }
}
