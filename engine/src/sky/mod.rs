//! The sky above a level: where the sun and moon stand at a time and place (the ephemeris),
//! and a physically based atmosphere precomputed into tables the tracers read (Hillaire 2020,
//! "A Scalable and Production Ready Sky and Atmosphere Rendering Technique").
//!
//! Owns: [`UtcInstant`] and [`Observer`] (checked inputs), [`sun_position`] (NOAA / Meeus
//! ch. 25), [`moon_position`] (Schlyter's series, topocentric, with the phase), and the mapping
//! from the local horizon to engine space (north = −Z, east = +X, up = +Y, azimuth from north
//! towards east; [`Horizontal::direction`]), and the physical sky: the Earth preset's media
//! (`atmosphere`), the transmittance table, the scattering orders' table (multiple scattering, `orders`, its grid `orders_grid`), the sky-view table and
//! its lookup (`sky_view`), and [`PhysicalSky`] / [`SkyTables`] that a level's sky turns into;
//! turning the time of day ([`SkyTime::advanced`], [`SkyNow`], `day`), the tables kept while
//! the sun moves ([`SkyBaker`]), the exposure the sky calls for (`exposure`) and the night's
//! lights: the moon's phase law, the moonlit sky, airglow, stars and the celestial frame (`night`); the cloud
//! layer the wind moves and its transmittance (`clouds`).
//! Runs on any thread: plain data and pure functions.
//! Must not: know about levels, scenes, the ECS or either tracer; it sits below `assets` in
//! the layers and uses no engine module (only glam, rayon, serde and thiserror).

mod atmosphere;
mod baker;
mod calendar;
mod clouds;
mod day;
mod error;
mod exposure;
mod horizon;
mod lunar;
mod night;
mod orders;
mod orders_grid;
mod physical;
mod sky_view;
mod solar;
mod transmittance;

pub use atmosphere::{
    Aerosol, GROUND_RADIUS_KM, OZONE_ABSORPTION, RAYLEIGH_SCALE_HEIGHT_KM, RAYLEIGH_SCATTERING,
    SOLAR_IRRADIANCE, TOP_RADIUS_KM, VIEW_ALTITUDE_KM,
};
pub use baker::{Baked, SkyBaker, TABLE_ELEVATION_STEP_DEG, table_elevation_deg};
pub use calendar::UtcInstant;
pub use clouds::{
    CloudLayer, CloudPlane, CloudShape, MAX_CLOUD_TEXELS, cloud_seconds, cloud_transmittance,
};
pub use day::SkyNow;
pub use error::SkyError;
pub use exposure::{
    DAYLIGHT_LUX, LUX_PER_Y, NIGHT_DARKENING, NIGHT_FLOOR_LUX, exposure_ev, horizontal_illuminance,
};
pub use horizon::{Horizontal, Observer};
pub use lunar::{MoonState, moon_position};
pub use night::{
    AIRGLOW_COLOUR, AIRGLOW_ZENITH_CD_M2, MOON_FULL_RATIO, MOON_SKY_MOON_BELOW_DEG,
    MOON_SKY_SUN_ABOVE_DEG, MoonLight, MoonSky, STAR_ANGULAR_RADIUS_DEG, STAR_ZERO_MAGNITUDE_LUX,
    celestial_frame, moon_phase_factor,
};
pub use physical::{
    HAZE_TURBIDITY_3, PhysicalSky, SkyTables, SkyTime, moon_uniform, moon_view_radiance,
    sky_view_radiance,
};
pub use sky_view::{VIEW_HEIGHT, VIEW_WIDTH};
pub use solar::{SunState, sun_position};

/// The sun's angular radius in degrees (mean, as seen from the Earth).
pub const SUN_ANGULAR_RADIUS_DEG: f32 = 0.2665;
/// The moon's angular radius in degrees (mean).
pub const MOON_ANGULAR_RADIUS_DEG: f32 = 0.259;
