//! [`SkyBaker`]: keeps a physical sky's sky-view table up to date while the sun moves, at the
//! cost of what the sun changes only. The transmittance and multiple-scattering tables depend
//! on the atmosphere alone (haze, ozone, ground albedo): they are built once per atmosphere and
//! kept. The sky-view table depends on the sun's elevation alone (the azimuth is the lookup's
//! frame, `sky_view_radiance`), and it is built for the elevation rounded to
//! [`TABLE_ELEVATION_STEP_DEG`] ([`table_elevation_deg`]): it is rebuilt only when the sun
//! crosses into another step, and the table is a function of the sky alone (not of the path
//! the sun took), so replays and screenshots repeat. After each rebuild the next step's table
//! in the direction the sun moves is built ahead on a thread of its own; when the sun gets
//! there the update takes it (waiting for it if it is not done), so a steadily moving sun does
//! not stall the caller — and the bits are those of a build on the spot. The sun disc's own
//! direction is not the table's: the tracers take it from the sky's description every frame,
//! exactly.
//!
//! At night the moon's table ([`super::MoonSky`]: the same table built for the moon's
//! elevation) follows the sun's in the texels, under the same rule: rebuilt only when the
//! moon crosses into another elevation step; the moon's phase is a factor the tracers apply,
//! so it rebuilds nothing. By day (or with the moon down) there is no moon's table: nothing
//! is built or read for it.
//!
//! Any thread (the render thread's `scene::SkyTable` holds one). Must not: know scenes, commits
//! or tracers.

use std::sync::mpsc::{Receiver, channel};
use std::sync::{Arc, Mutex};

use glam::Vec3;

use super::atmosphere::Atmosphere;
use super::error::SkyError;
use super::orders::ScatteringOrders;
use super::physical::PhysicalSky;
use super::sky_view::{VIEW_HEIGHT, VIEW_WIDTH, build_view};
use super::transmittance::TransmittanceLut;

/// The step (degrees of sun elevation) the sky-view table's elevation is rounded to. 0.1° is
/// under half the sun's radius; at a day rate of 60 (a day in 24 minutes) the sun climbs at
/// most 0.25° a second, so the table is rebuilt at most about every 0.4 s.
pub const TABLE_ELEVATION_STEP_DEG: f64 = 0.1;

/// The sun elevation (degrees) the sky-view table is built for: `elevation_deg` rounded to
/// [`TABLE_ELEVATION_STEP_DEG`] (so 10°, 30°, 60° stay exact).
pub fn table_elevation_deg(elevation_deg: f64) -> f64 {
    (elevation_deg / TABLE_ELEVATION_STEP_DEG).round() * TABLE_ELEVATION_STEP_DEG
}

/// The atmosphere's fields the sun-independent tables are built from.
type AtmosphereKey = (u32, u32, [u32; 3], [u32; 7]);

fn key(sky: &PhysicalSky) -> AtmosphereKey {
    let a = &sky.aerosol;
    (
        sky.haze.to_bits(),
        sky.ozone.to_bits(),
        sky.ground_albedo.map(f32::to_bits),
        [
            a.scattering_per_km,
            a.absorption_per_km,
            a.angstrom,
            a.scale_height_km,
            a.g,
            a.forward_share,
            a.forward_g,
        ]
        .map(f32::to_bits),
    )
}

/// The sun-independent tables of one atmosphere.
struct Luts {
    key: AtmosphereKey,
    atmosphere: Atmosphere,
    transmittance: TransmittanceLut,
    multiple: Arc<ScatteringOrders>,
}

/// What [`SkyBaker::update`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Baked {
    /// The table held is still good (same atmosphere, sun within the rebuild angle).
    Kept,
    /// The sky-view table was rebuilt on the kept transmittance and multiple-scattering tables.
    View,
    /// The sky-view table built ahead for this step was taken (the sun moved on steadily).
    Ahead,
    /// Everything was rebuilt (a new atmosphere).
    All,
}

/// A sky-view table being built ahead on a thread of its own.
struct Ahead {
    key: AtmosphereKey,
    elevation_deg: f64,
    texels: Receiver<Vec<[f32; 4]>>,
}

/// The sky-view table of the latest physical sky, and the tables it was built from.
#[derive(Default)]
pub struct SkyBaker {
    luts: Option<Arc<Luts>>,
    /// The sun elevation (degrees) the sky-view table was built for.
    built_elevation_deg: Option<f64>,
    /// The moon elevation (degrees) the moon's table was built for; `None`: no moon's table.
    moon_elevation_deg: Option<f64>,
    /// `VIEW_WIDTH × VIEW_HEIGHT` texels (layout in `sky_view`), twice that with the moon's
    /// table after the sun's.
    texels: Arc<Vec<[f32; 4]>>,
    /// The next step's table, being built (a mutex only so that the baker is `Sync`).
    ahead: Mutex<Option<Ahead>>,
}

impl Clone for SkyBaker {
    /// A copy without the table being built ahead (the copy builds its own when it needs it).
    fn clone(&self) -> Self {
        Self {
            luts: self.luts.clone(),
            built_elevation_deg: self.built_elevation_deg,
            moon_elevation_deg: self.moon_elevation_deg,
            texels: self.texels.clone(),
            ahead: Mutex::new(None),
        }
    }
}

/// The sky-view texels for a sun at `elevation_deg` on `luts`.
fn view(luts: &Luts, elevation_deg: f64) -> Vec<[f32; 4]> {
    build_view(
        &luts.atmosphere,
        &luts.transmittance,
        Some(&luts.multiple),
        (elevation_deg as f32).to_radians(),
    )
}

impl std::fmt::Debug for SkyBaker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SkyBaker")
            .field("built_elevation_deg", &self.built_elevation_deg)
            .field("moon_elevation_deg", &self.moon_elevation_deg)
            .field("texels", &self.texels.len())
            .finish()
    }
}

impl SkyBaker {
    /// Brings the table up to `sky`: keeps it when the atmosphere is the same and the sun's
    /// [`table_elevation_deg`] is the one it was built for; rebuilds the sky-view table alone
    /// when only the sun moved (`docs/PERFORMANCE.md`, "Sky tables"); everything when the
    /// atmosphere changed.
    pub fn update(&mut self, sky: &PhysicalSky) -> Result<Baked, SkyError> {
        let elevation = table_elevation_deg(sky.sun_horizontal()?.elevation_deg);
        let moon = sky.moon_sky()?.map(|m| m.table_elevation_deg);
        let k = key(sky);
        let mut baked = Baked::View;
        let luts = match &self.luts {
            Some(l) if l.key == k => {
                if self.built_elevation_deg == Some(elevation) && self.moon_elevation_deg == moon {
                    return Ok(Baked::Kept);
                }
                l.clone()
            }
            _ => {
                baked = Baked::All;
                let atmosphere = sky.atmosphere();
                let transmittance = TransmittanceLut::build(&atmosphere);
                let multiple = ScatteringOrders::shared(&atmosphere, &transmittance);
                let l = Arc::new(Luts {
                    key: k,
                    atmosphere,
                    transmittance,
                    multiple,
                });
                self.luts = Some(l.clone());
                l
            }
        };
        let n = VIEW_WIDTH * VIEW_HEIGHT;
        let sun_moved = baked == Baked::All || self.built_elevation_deg != Some(elevation);
        let mut texels = if !sun_moved && self.texels.len() >= n {
            self.texels[..n].to_vec()
        } else {
            match self.take_ahead(k, elevation) {
                Some(texels) => {
                    baked = Baked::Ahead;
                    texels
                }
                None => view(&luts, elevation),
            }
        };
        if let Some(m) = moon {
            let moon_kept = baked != Baked::All
                && self.moon_elevation_deg == Some(m)
                && self.texels.len() == 2 * n;
            if moon_kept {
                texels.extend_from_slice(&self.texels[n..]);
            } else {
                texels.extend(view(&luts, m));
            }
        }
        self.texels = Arc::new(texels);
        self.moon_elevation_deg = moon;
        let previous = self.built_elevation_deg.replace(elevation);
        if baked != Baked::All
            && let Some(previous) = previous
            && previous != elevation
        {
            let next = table_elevation_deg(
                elevation + TABLE_ELEVATION_STEP_DEG * (elevation - previous).signum(),
            );
            self.build_ahead(luts, next);
        }
        Ok(baked)
    }

    /// The table built ahead for `elevation` under atmosphere `key`, waiting for it if it is not
    /// done; `None` when none was built for it (one built for another step is dropped).
    fn take_ahead(&self, key: AtmosphereKey, elevation: f64) -> Option<Vec<[f32; 4]>> {
        let ahead = self.ahead.lock().ok()?.take()?;
        (ahead.key == key && ahead.elevation_deg == elevation)
            .then(|| ahead.texels.recv().ok())
            .flatten()
    }

    /// Starts building the sky-view table for `elevation` on a thread of its own.
    fn build_ahead(&self, luts: Arc<Luts>, elevation: f64) {
        if !(-90.0..=90.0).contains(&elevation) {
            return;
        }
        let (send, texels) = channel();
        let key = luts.key;
        let started = std::thread::Builder::new()
            .name("sky ahead".into())
            .spawn(move || {
                // The receiver may be gone (the sun went elsewhere): nothing to do then.
                let _ = send.send(view(&luts, elevation));
            });
        if started.is_ok()
            && let Ok(mut slot) = self.ahead.lock()
        {
            *slot = Some(Ahead {
                key,
                elevation_deg: elevation,
                texels,
            });
        }
    }

    /// The luminance-weighted horizontal illuminance under `sky` (sky units; `exposure`): the
    /// table as last built (the moonlit sky's too) plus the sun's and the moon's direct light
    /// at their exact elevations. Call after
    /// [`SkyBaker::update`] with the same sky.
    pub fn horizontal_illuminance(&self, sky: &PhysicalSky) -> Result<f32, SkyError> {
        let h = sky.sun_horizontal()?;
        let sun = sky.sun_irradiance()? * sky.sun_scale;
        // The moon's direct light (`night`), luminance-weighted as the rest.
        let moon = sky.moon_light()?.map_or(0.0, |m| {
            m.irradiance.dot(Vec3::new(0.2126, 0.7152, 0.0722)) * m.direction.y.max(0.0)
        });
        // The moonlit sky (its table after the sun's), scaled by the moon's share.
        let n = VIEW_WIDTH * VIEW_HEIGHT;
        let moon_sky = match sky.moon_sky()? {
            Some(m) if self.texels.len() == 2 * n => {
                super::exposure::horizontal_illuminance(&self.texels[n..], Vec3::ZERO, -90.0)
                    * m.scale
            }
            _ => 0.0,
        };
        let sun_sky = &self.texels[..n.min(self.texels.len())];
        Ok(
            super::exposure::horizontal_illuminance(sun_sky, sun, h.elevation_deg)
                + moon
                + moon_sky,
        )
    }

    /// The sky-view texels as last built (empty before the first [`SkyBaker::update`]).
    pub fn texels(&self) -> &Arc<Vec<[f32; 4]>> {
        &self.texels
    }

    /// The sun elevation (degrees) the table was built for.
    pub fn built_elevation_deg(&self) -> Option<f64> {
        self.built_elevation_deg
    }

    /// Whether the tables held were built for `sky`'s atmosphere (haze, ozone, ground albedo, aerosol):
    /// an update for it rebuilds at most the sky-view table.
    pub fn holds_atmosphere_of(&self, sky: &PhysicalSky) -> bool {
        self.luts.as_ref().is_some_and(|l| l.key == key(sky))
    }

    /// Whether [`SkyBaker::update`] for `sky` would build anything (another atmosphere, the
    /// sun or the moon in another elevation step than the tables', the moon's table
    /// appearing or going); a sky whose sun fails its checks needs
    /// nothing built.
    pub fn needs_update(&self, sky: &PhysicalSky) -> bool {
        let Ok(h) = sky.sun_horizontal() else {
            return false;
        };
        let moon = sky.moon_sky().ok().flatten().map(|m| m.table_elevation_deg);
        !self.holds_atmosphere_of(sky)
            || self.built_elevation_deg != Some(table_elevation_deg(h.elevation_deg))
            || self.moon_elevation_deg != moon
    }

    /// Forgets everything (the next update rebuilds all).
    pub fn clear(&mut self) {
        *self = Self::default();
    }
}
