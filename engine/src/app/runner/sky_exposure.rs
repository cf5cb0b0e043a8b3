//! [`Engine::sky_exposure_ev`]: the exposure a physical sky calls for now, from its horizontal
//! illuminance (sun and sky; `sky::exposure_ev`). A function of the sky's description (so of
//! the time of day), never of the rendered picture: replays and screenshots reproduce it.
//!
//! Main thread. The tables it integrates are the main thread's own ([`crate::sky::SkyBaker`]:
//! built once per atmosphere, the sky-view table again only when the sun crosses an elevation
//! step). Must not: touch the render thread or the tonemapper (callers pass the value on).

use super::engine::Engine;
use crate::assets::SkyDesc;
use crate::sky::exposure_ev;

impl Engine {
    /// The exposure in stops (radiance × 2^ev, as `TonemapSettings::exposure_ev`) that the
    /// physical sky's horizontal illuminance calls for now; `None` for other skies (manual
    /// exposure then) or a sky that fails its checks.
    pub fn sky_exposure_ev(&mut self) -> Option<f32> {
        let SkyDesc::Physical(sky) = &self.environment.sky else {
            return None;
        };
        self.sky_meter.update(sky).ok()?;
        let e = self.sky_meter.horizontal_illuminance(sky).ok()?;
        Some(exposure_ev(e))
    }
}
