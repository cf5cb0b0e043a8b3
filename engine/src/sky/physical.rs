//! [`PhysicalSky`]: what a level writes to get the physically based sky (the sun's place, by
//! angles or by a time and place, and the atmosphere's knobs), its checks, the sun it gives
//! (direction and direct normal irradiance through the air) and [`SkyTables`], the
//! precomputed sky-view texels both tracers read.
//!
//! Any thread. Building the tables costs about 0.3 s on one core, plus the scattering orders
//! once per atmosphere (`orders`, cached): done when the sky changes, never per frame. Directions are in engine space (north = −Z, east = +X, up = +Y);
//! radiance and irradiance in linear RGB, W·m⁻²·sr⁻¹·nm⁻¹ and W·m⁻²·nm⁻¹ (the spectral units of
//! Mitsuba's sunsky, which `docs/ACCURACY.md` compares against). Must not: know levels, scenes
//! or tracers (the level loader names the file beside a [`SkyError`]).

use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::atmosphere::{
    Aerosol, Atmosphere, GROUND_RADIUS_KM, SOLAR_IRRADIANCE, VIEW_ALTITUDE_KM,
};
use super::calendar::UtcInstant;
use super::error::SkyError;
use super::horizon::{Horizontal, Observer};
use super::orders::ScatteringOrders;
use super::sky_view::{build_view, lookup_view};
use super::solar::sun_position;
use super::transmittance::{TransmittanceLut, transmittance_exact};

/// The sun placed by a time and place instead of angles (the ephemeris, `sky::sun_position`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SkyTime {
    /// Degrees, north positive, −90..=90.
    pub latitude_deg: f64,
    /// Degrees, east positive, −180..=180.
    pub longitude_deg: f64,
    pub year: i32,
    pub month: u32,
    pub day: u32,
    /// Hours since midnight UTC, 0 ≤ h < 24.
    pub utc_hours: f64,
    /// How fast the day flows in play: seconds of day per simulated second (the fixed steps
    /// advance it; `app/runner/time_of_day.rs`), 0..=1e6; 0 (the default): the time stands
    /// still unless the game turns it.
    #[serde(default)]
    pub time_rate: f64,
}

/// A physically based sky (Hillaire 2020, Earth preset) with its sun.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhysicalSky {
    /// Sun elevation above the horizon, degrees, −90..=90 (ignored when `time` is set).
    #[serde(default = "default_elevation")]
    pub sun_elevation_deg: f32,
    /// Sun azimuth from north (−Z) towards east (+X), degrees (ignored when `time` is set).
    #[serde(default)]
    pub sun_azimuth_deg: f32,
    /// Place the sun by date, time and place instead.
    #[serde(default)]
    pub time: Option<SkyTime>,
    /// Aerosol density relative to Hillaire's clear preset (1), 0..=100. Mitsuba's
    /// Hosek–Wilkie turbidity 3 corresponds to [`HAZE_TURBIDITY_3`] with
    /// [`Aerosol::TURBIDITY_3`].
    #[serde(default = "one")]
    pub haze: f32,
    /// What the aerosols are (per unit `haze`); the default is Hillaire's Earth preset.
    /// [`Aerosol::TURBIDITY_3`] with [`HAZE_TURBIDITY_3`] matches Hosek–Wilkie's turbidity 3.
    #[serde(default, skip_serializing_if = "Aerosol::is_earth")]
    pub aerosol: Aerosol,
    /// Ozone density relative to the preset, 0..=10.
    #[serde(default = "one")]
    pub ozone: f32,
    /// Lambertian ground reflectance, linear RGB, each 0..=1.
    #[serde(default = "default_albedo")]
    pub ground_albedo: [f32; 3],
    /// Multiplier of the sun disc's radiance, 0..=1000 (0: the sky alone, as Mitsuba's
    /// `sun_scale`; the sky itself is not changed).
    #[serde(default = "one")]
    pub sun_scale: f32,
    /// Multiplier of the stars and the airglow (`sky/night.rs`), 0..=1000 (0: none; the moon
    /// is not changed).
    #[serde(default = "one")]
    pub night_sky: f32,
    /// A cloud layer moved by the wind (`sky/clouds.rs`); `None` (the default): a clear sky.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clouds: Option<super::clouds::CloudLayer>,
}

/// The haze that, with [`Aerosol::TURBIDITY_3`], gives the diffuse-to-global horizontal ratio
/// of Mitsuba's Hosek–Wilkie sky at turbidity 3, albedo 0.3, at 60° sun elevation (0.1894;
/// calibrated once by bisection, checked by `engine/tests/engine/sky_reference.rs`). With
/// Hillaire's [`Aerosol::EARTH`] it is only a thicker haze.
pub const HAZE_TURBIDITY_3: f32 = 5.949;

impl Default for PhysicalSky {
    /// `sky: Physical(())`: a clear sky (Earth preset), the sun 45° high in the north.
    fn default() -> Self {
        Self {
            sun_elevation_deg: default_elevation(),
            sun_azimuth_deg: 0.0,
            time: None,
            haze: 1.0,
            aerosol: Aerosol::EARTH,
            ozone: 1.0,
            ground_albedo: default_albedo(),
            sun_scale: 1.0,
            night_sky: 1.0,
            clouds: None,
        }
    }
}

fn default_elevation() -> f32 {
    45.0
}

fn one() -> f32 {
    1.0
}

fn default_albedo() -> [f32; 3] {
    [0.3; 3]
}

pub(super) fn check(
    field: &'static str,
    value: f32,
    lo: f32,
    hi: f32,
    range: &'static str,
) -> Result<(), SkyError> {
    if value.is_finite() && (lo..=hi).contains(&value) {
        Ok(())
    } else {
        Err(SkyError::Parameter {
            field,
            value: value as f64,
            range,
        })
    }
}

impl PhysicalSky {
    /// Checks every field; the error names the field (`haze`, `sun_elevation_deg`, …).
    pub fn validate(&self) -> Result<(), SkyError> {
        check(
            "sun_elevation_deg",
            self.sun_elevation_deg,
            -90.0,
            90.0,
            "-90..=90",
        )?;
        check(
            "sun_azimuth_deg",
            self.sun_azimuth_deg,
            -360.0,
            360.0,
            "-360..=360",
        )?;
        check("haze", self.haze, 0.0, 100.0, "0..=100")?;
        check("ozone", self.ozone, 0.0, 10.0, "0..=10")?;
        self.aerosol.validate()?;
        check("sun_scale", self.sun_scale, 0.0, 1000.0, "0..=1000")?;
        check("night_sky", self.night_sky, 0.0, 1000.0, "0..=1000")?;
        for a in self.ground_albedo {
            check("ground_albedo", a, 0.0, 1.0, "0..=1")?;
        }
        if let Some(time) = &self.time {
            time.instant()?;
            time.check_rate()?;
            Observer::new(time.latitude_deg, time.longitude_deg)?;
        }
        if let Some(clouds) = &self.clouds {
            clouds.validate()?;
        }
        Ok(())
    }

    /// Where the sun stands (elevation, azimuth from north towards east).
    pub fn sun_horizontal(&self) -> Result<Horizontal, SkyError> {
        self.validate()?;
        Ok(match &self.time {
            Some(time) => {
                let observer = Observer::new(time.latitude_deg, time.longitude_deg)?;
                sun_position(&observer, &time.instant()?).horizontal
            }
            None => Horizontal {
                elevation_deg: self.sun_elevation_deg as f64,
                azimuth_deg: self.sun_azimuth_deg as f64,
            },
        })
    }

    pub(super) fn atmosphere(&self) -> Atmosphere {
        Atmosphere {
            haze: self.haze,
            ozone: self.ozone,
            ground_albedo: Vec3::from(self.ground_albedo),
            aerosol: self.aerosol,
        }
    }

    /// Direct normal irradiance of the sun at the viewer (solar irradiance × transmittance
    /// along the sun's direction; zero below the horizon), W·m⁻²·nm⁻¹ per channel.
    pub fn sun_irradiance(&self) -> Result<Vec3, SkyError> {
        let h = self.sun_horizontal()?;
        let r = GROUND_RADIUS_KM + VIEW_ALTITUDE_KM;
        let mu = (h.elevation_deg.to_radians().sin()) as f32;
        Ok(SOLAR_IRRADIANCE * transmittance_exact(&self.atmosphere(), r, mu))
    }
}

impl SkyTime {
    pub(super) fn instant(&self) -> Result<UtcInstant, SkyError> {
        if !self.utc_hours.is_finite() || !(0.0..24.0).contains(&self.utc_hours) {
            return Err(SkyError::Parameter {
                field: "time.utc_hours",
                value: self.utc_hours,
                range: "0 <= h < 24",
            });
        }
        let seconds = self.utc_hours * 3600.0;
        let (hour, minute) = (
            (seconds / 3600.0) as u32,
            ((seconds % 3600.0) / 60.0) as u32,
        );
        UtcInstant::new(
            self.year,
            self.month,
            self.day,
            hour,
            minute,
            seconds % 60.0,
        )
    }
}

/// The precomputed sky for one [`PhysicalSky`]: the sky-view texels (layout in `sky_view`)
/// and the frame they are seen in; at night the moon's table follows the sun's
/// ([`super::MoonSky`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SkyTables {
    /// `VIEW_WIDTH × VIEW_HEIGHT` RGB + padding texels, radiance; twice that with the moon's
    /// table after the sun's.
    pub texels: Vec<[f32; 4]>,
    /// Unit vector towards the sun, engine space.
    pub sun_direction: Vec3,
    /// Unit horizontal vector towards the sun's azimuth (engine space; +X·… when the sun is at
    /// the zenith the azimuth still gives it).
    pub sun_azimuth: Vec3,
    /// The moon's table's frame and scale as the tracers' uniforms hold them (`moon_sky`):
    /// xyz the unit horizontal vector towards the moon's azimuth, w the moon's share of the
    /// sun's irradiance (0: no moon's table).
    pub moon_sky: [f32; 4],
}

impl SkyTables {
    /// Precomputes the transmittance, scattering-orders and sky-view tables (the sky-view one
    /// for the sun's elevation rounded to `TABLE_ELEVATION_STEP_DEG`, as [`super::SkyBaker`]).
    pub fn build(sky: &PhysicalSky) -> Result<Self, SkyError> {
        let h = sky.sun_horizontal()?;
        let atmosphere = sky.atmosphere();
        let transmittance = TransmittanceLut::build(&atmosphere);
        let multiple = ScatteringOrders::shared(&atmosphere, &transmittance);
        // The table's elevation step (`baker`), so a table built here equals the render side's.
        let elevation = (super::baker::table_elevation_deg(h.elevation_deg) as f32).to_radians();
        let mut texels = build_view(&atmosphere, &transmittance, Some(&multiple), elevation);
        let moon = sky.moon_sky()?;
        if let Some(m) = moon {
            let e = (m.table_elevation_deg as f32).to_radians();
            texels.extend(build_view(&atmosphere, &transmittance, Some(&multiple), e));
        }
        let flat = Horizontal {
            elevation_deg: 0.0,
            azimuth_deg: h.azimuth_deg,
        };
        Ok(Self {
            texels,
            sun_direction: h.direction(),
            sun_azimuth: flat.direction(),
            moon_sky: moon_uniform(moon),
        })
    }

    /// The sun's sky-view table of [`SkyTables::build`] with the second and higher scattering
    /// orders left out (`sky/orders.rs`): single scattering alone above the horizon (below it,
    /// also the ground lit by the sun alone). No moon's table. A check of the tables against a reference
    /// (`engine/tests/engine/sky_brute_force.rs`); the tracers never read it.
    pub fn build_single_scattering(sky: &PhysicalSky) -> Result<Self, SkyError> {
        let h = sky.sun_horizontal()?;
        let atmosphere = sky.atmosphere();
        let transmittance = TransmittanceLut::build(&atmosphere);
        let elevation = (super::baker::table_elevation_deg(h.elevation_deg) as f32).to_radians();
        let flat = Horizontal {
            elevation_deg: 0.0,
            azimuth_deg: h.azimuth_deg,
        };
        Ok(Self {
            texels: build_view(&atmosphere, &transmittance, None, elevation),
            sun_direction: h.direction(),
            sun_azimuth: flat.direction(),
            moon_sky: [0.0; 4],
        })
    }

    /// Sky radiance towards unit engine-space direction `d` (sun and moon discs excluded; the
    /// moonlit sky included).
    pub fn radiance(&self, d: Vec3) -> Vec3 {
        sky_view_radiance(&self.texels, self.sun_azimuth, d)
            + moon_view_radiance(&self.texels, self.moon_sky, d)
    }
}

/// The lookup both tracers do: elevation from `d.y`, azimuth from the sun's horizontal
/// direction `sun_azimuth` (unit, engine space).
pub fn sky_view_radiance(texels: &[[f32; 4]], sun_azimuth: Vec3, d: Vec3) -> Vec3 {
    let elevation = d.y.clamp(-1.0, 1.0).asin();
    let side = Vec3::Y.cross(sun_azimuth);
    let azimuth = d.dot(side).atan2(d.dot(sun_azimuth));
    lookup_view(texels, elevation, azimuth)
}

/// The moon's table's frame and scale as the uniforms' `moon_sky` holds them (zero: none).
pub fn moon_uniform(moon: Option<super::MoonSky>) -> [f32; 4] {
    moon.map_or([0.0; 4], |m| m.azimuth.extend(m.scale).to_array())
}

/// The moonlit sky towards unit engine-space direction `d`: the moon's table (the second
/// `VIEW_WIDTH × VIEW_HEIGHT` texels of `texels`) seen in the frame of `moon_sky.xyz` and
/// multiplied by `moon_sky.w`; zero when `w` is 0 or the table is not there (a table still
/// being rebuilt). Twin: `moon_view_radiance` in `shaders/shared/sky_view.wgsl`.
pub fn moon_view_radiance(texels: &[[f32; 4]], moon_sky: [f32; 4], d: Vec3) -> Vec3 {
    let n = super::VIEW_WIDTH * super::VIEW_HEIGHT;
    if moon_sky[3] <= 0.0 || texels.len() < 2 * n {
        return Vec3::ZERO;
    }
    sky_view_radiance(&texels[n..2 * n], Vec3::from_slice(&moon_sky[..3]), d) * moon_sky[3]
}
