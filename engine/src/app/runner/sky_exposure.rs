//! [`Engine::sky_exposure_ev`]: the exposure a physical sky calls for now, from its horizontal
//! illuminance (sun and sky; `sky::exposure_ev`). A function of the sky's description (so of
//! the time of day), never of the rendered picture: replays and screenshots reproduce it.
//!
//! Main thread. The tables it integrates are the main thread's own ([`SkyMeter`], a
//! [`SkyTable`]: built once per atmosphere, the sky-view table again only when the sun crosses
//! an elevation step, on a worker thread when the engine's render configuration asks for
//! `SkyRebuild::Background` — a window's sun turned fast at an altar must not stall its frames
//! — and on this thread otherwise, so captures repeat). Must not: touch the render thread or
//! the tonemapper (callers pass the value on).

use super::engine::Engine;
use crate::assets::SkyDesc;
use crate::scene::{SkyRebuild, SkyTable};
use crate::sky::exposure_ev;

/// The main thread's sky table for the exposure, and how it follows a moving sun (as the
/// render thread's: `RenderConfig::sky_rebuild`).
#[derive(Debug, Default)]
pub(in crate::app) struct SkyMeter {
    table: SkyTable,
    how: SkyRebuild,
}

impl SkyMeter {
    pub(in crate::app) fn new(how: SkyRebuild) -> Self {
        Self {
            table: SkyTable::default(),
            how,
        }
    }
}

impl Engine {
    /// The exposure in stops (radiance × 2^ev, as `TonemapSettings::exposure_ev`) that the
    /// physical sky's horizontal illuminance calls for now; `None` for other skies (manual
    /// exposure then) or a sky that fails its checks.
    pub fn sky_exposure_ev(&mut self) -> Option<f32> {
        let SkyDesc::Physical(sky) = &self.environment.sky else {
            return None;
        };
        let meter = &mut self.sky_meter;
        meter.table.update_with(&self.environment.sky, meter.how);
        let e = meter.table.horizontal_illuminance(sky).ok()?;
        Some(exposure_ev(e))
    }
}
