//! The night's lights of a [`PhysicalSky`]: the moon's irradiance by its phase, the night-sky
//! floor (airglow), the star field's brightness and the celestial frame the stars turn with.
//!
//! Any thread; pure functions. Units as the rest of the sky (linear RGB, W·m⁻²·nm⁻¹ for
//! irradiance, W·m⁻²·sr⁻¹·nm⁻¹ for radiance; × [`super::LUX_PER_Y`] for lux and cd/m²);
//! directions in engine space (north = −Z, east = +X, up = +Y). Must not: know the tracers or
//! their uniforms (`scene/discs.rs` writes those).
//!
//! - **Phase law**: the standard astronomical one for the moon's visual magnitude,
//!   m(α) = −12.73 + 0.026 |α| + 4·10⁻⁹ α⁴ (α the phase angle in degrees; Allen's
//!   *Astrophysical Quantities*, used by Krisciunas & Schaefer 1991, "A model of the
//!   brightness of moonlight"). It is a fit to measured lunar photometry (the opposition
//!   surge included), which a Lommel–Seeliger disc lacks; a quarter moon (α = 90°) gives
//!   10^(−0.4·2.602) = 0.091 of the full moon.
//! - **Full moon**: 2.5·10⁻⁶ of the sun's irradiance at the top of the atmosphere
//!   (−12.73 against the sun's −26.74 is 10^(−0.4·14.01) = 2.5·10⁻⁶), with the sun's colour.
//! - **Airglow**: the natural night-sky brightness at the zenith, 174 µcd/m² (≈ 22.0 mag per
//!   square arcsecond; Falchi et al. 2016, "The new world atlas of artificial night sky
//!   brightness", their natural background), slightly green, brightening towards the horizon
//!   as a thin layer at 90 km (van Rhijn) and dimmed by the air's extinction.
//! - **Stars**: a magnitude-0 star gives 2.54·10⁻⁶ lx (Allen); the field's magnitudes follow
//!   N(< m) ∝ 10^(0.48 m) up to 6.5 (about 9000 stars on the sphere).
//! - **The moonlit sky** ([`MoonSky`]): the air scatters the moon's light as it scatters the
//!   sun's (the moon's light has the sun's colour here), so the moon's sky is the sun's
//!   sky-view table built for the moon's elevation, seen in the moon's azimuth frame and scaled
//!   by the moon's share of the sun's irradiance ([`MOON_FULL_RATIO`] × the phase law). It is
//!   left out while the sun stands above [`MOON_SKY_SUN_ABOVE_DEG`] (the sun's twilight outshines
//!   a full moon's sky by more than 100 times there) or the moon below
//!   [`MOON_SKY_MOON_BELOW_DEG`] (its sky is then under 5 % of the airglow): no second table is
//!   built nor read by day.

use glam::Vec3;

use super::atmosphere::{GROUND_RADIUS_KM, SOLAR_IRRADIANCE, VIEW_ALTITUDE_KM};
use super::error::SkyError;
use super::exposure::LUX_PER_Y;
use super::horizon::{Horizontal, Observer, sidereal_deg};
use super::physical::PhysicalSky;
use super::transmittance::transmittance_exact;

/// The full moon's irradiance as a share of the sun's (both above the atmosphere).
pub const MOON_FULL_RATIO: f32 = 2.5e-6;
/// Natural night-sky luminance at the zenith, cd/m² (Falchi et al. 2016).
pub const AIRGLOW_ZENITH_CD_M2: f32 = 174e-6;
/// Airglow colour, linear RGB of luminance 1 (the green 557.7 nm line over a grey floor).
pub const AIRGLOW_COLOUR: Vec3 = Vec3::new(0.85, 1.05, 0.95);
/// Illuminance of a magnitude-0 star outside the atmosphere, lux.
pub const STAR_ZERO_MAGNITUDE_LUX: f32 = 2.54e-6;
/// Angular radius of a star's disc in the renderer, degrees: small beside a pixel of a usual
/// view (0.08°), large enough that escaping rays find it; its irradiance does not depend on it.
pub const STAR_ANGULAR_RADIUS_DEG: f32 = 0.04;

/// Above this sun elevation (degrees) the moon's scattered light is left out of the sky.
pub const MOON_SKY_SUN_ABOVE_DEG: f64 = -6.0;
/// Below this moon elevation (degrees) the moon's scattered light is left out of the sky.
pub const MOON_SKY_MOON_BELOW_DEG: f64 = -6.0;

/// The moon's share of the sky: the second sky-view table both tracers read at night (built by
/// `SkyBaker` and `SkyTables` after the sun's, `VIEW_WIDTH × VIEW_HEIGHT` texels more).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoonSky {
    /// The moon's elevation rounded to the table step (`table_elevation_deg`), degrees: the
    /// elevation the moon's table is built for (as the sun's table, per unit solar irradiance ×
    /// the solar irradiance).
    pub table_elevation_deg: f64,
    /// Unit horizontal vector towards the moon's azimuth, engine space.
    pub azimuth: Vec3,
    /// The moon's irradiance above the air as a share of the sun's: [`MOON_FULL_RATIO`] ×
    /// [`moon_phase_factor`]. The moon's table is multiplied by it when read, so a change of
    /// phase rebuilds nothing.
    pub scale: f32,
}

/// The moon's brightness relative to full at phase angle `phase_angle_deg` (0: full, 180: new).
pub fn moon_phase_factor(phase_angle_deg: f64) -> f64 {
    let a = phase_angle_deg.abs().min(180.0);
    10f64.powf(-0.4 * (0.026 * a + 4e-9 * a.powi(4)))
}

/// The moon as the renderer sees it: where it is, its irradiance at the viewer (phase law and
/// the air's transmittance along its direction; zero below the horizon) and the sun's
/// direction that lights it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoonLight {
    /// Unit vector towards the moon's centre.
    pub direction: Vec3,
    /// Irradiance normal to `direction` at the viewer, W·m⁻²·nm⁻¹ per channel.
    pub irradiance: Vec3,
    /// Unit vector towards the sun (the terminator's orientation on the disc).
    pub sun_direction: Vec3,
    /// Sun–moon–Earth angle, degrees.
    pub phase_angle_deg: f64,
}

impl PhysicalSky {
    /// The moon's light; `None` when the sky is placed by angles (no date: no moon).
    pub fn moon_light(&self) -> Result<Option<MoonLight>, SkyError> {
        let now = self.now()?;
        let Some(moon) = now.moon else {
            return Ok(None);
        };
        let r = GROUND_RADIUS_KM + VIEW_ALTITUDE_KM;
        let mu = moon.horizontal.elevation_deg.to_radians().sin() as f32;
        let transmittance = transmittance_exact(&self.atmosphere(), r, mu);
        let factor = moon_phase_factor(moon.phase_angle_deg) as f32;
        Ok(Some(MoonLight {
            direction: moon.horizontal.direction(),
            irradiance: SOLAR_IRRADIANCE * (MOON_FULL_RATIO * factor) * transmittance,
            sun_direction: now.sun_direction,
            phase_angle_deg: moon.phase_angle_deg,
        }))
    }

    /// The moon's share of the sky ([`MoonSky`]); `None` without a date, by day (the sun above
    /// [`MOON_SKY_SUN_ABOVE_DEG`]) or with the moon below [`MOON_SKY_MOON_BELOW_DEG`].
    pub fn moon_sky(&self) -> Result<Option<MoonSky>, SkyError> {
        let now = self.now()?;
        let Some(moon) = now.moon else {
            return Ok(None);
        };
        if now.sun.elevation_deg > MOON_SKY_SUN_ABOVE_DEG
            || moon.horizontal.elevation_deg < MOON_SKY_MOON_BELOW_DEG
        {
            return Ok(None);
        }
        let flat = Horizontal {
            elevation_deg: 0.0,
            azimuth_deg: moon.horizontal.azimuth_deg,
        };
        Ok(Some(MoonSky {
            table_elevation_deg: super::baker::table_elevation_deg(moon.horizontal.elevation_deg),
            azimuth: flat.direction(),
            scale: MOON_FULL_RATIO * moon_phase_factor(moon.phase_angle_deg) as f32,
        }))
    }

    /// The air's transmittance straight up (the stars' extinction is this to the air mass).
    pub fn zenith_transmittance(&self) -> Vec3 {
        transmittance_exact(&self.atmosphere(), GROUND_RADIUS_KM + VIEW_ALTITUDE_KM, 1.0)
    }

    /// The night-sky floor's radiance at the zenith outside the air's extinction (× `night_sky`).
    pub fn airglow_zenith(&self) -> Vec3 {
        AIRGLOW_COLOUR * (AIRGLOW_ZENITH_CD_M2 / LUX_PER_Y * self.night_sky)
    }

    /// Irradiance of a magnitude-0 star (grey, luminance units; × `night_sky`).
    pub fn star_zero_irradiance(&self) -> f32 {
        STAR_ZERO_MAGNITUDE_LUX / LUX_PER_Y * self.night_sky
    }

    /// The celestial frame in engine space, as rows: x towards the equinox (right ascension 0
    /// on the equator), y towards right ascension 6 h, z towards the north celestial pole. A
    /// sky placed by angles uses latitude 45° and local sidereal time 0 (the stars stand still).
    pub fn celestial_frame(&self) -> Result<[Vec3; 3], SkyError> {
        let (latitude, lst) = match &self.time {
            Some(t) => {
                let observer = Observer::new(t.latitude_deg, t.longitude_deg)?;
                let jd = t.instant()?.julian_day();
                (
                    observer.latitude_deg(),
                    sidereal_deg(jd) + observer.longitude_deg(),
                )
            }
            None => (45.0, 0.0),
        };
        Ok(celestial_frame(latitude, lst))
    }
}

/// The celestial frame (rows x, y, z as [`PhysicalSky::celestial_frame`]) for a latitude and a
/// local sidereal time, degrees. The equator's point at hour angle H is
/// cos H · (its meridian point in the south) + sin H · west.
pub fn celestial_frame(latitude_deg: f64, local_sidereal_deg: f64) -> [Vec3; 3] {
    let pole = Horizontal {
        elevation_deg: latitude_deg,
        azimuth_deg: 0.0,
    }
    .direction();
    let south = Horizontal {
        elevation_deg: 90.0 - latitude_deg,
        azimuth_deg: 180.0,
    }
    .direction();
    let west = Vec3::NEG_X;
    let h = local_sidereal_deg.to_radians();
    let (s, c) = (h.sin() as f32, h.cos() as f32);
    [south * c + west * s, south * s - west * c, pole]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_moon_is_a_tenth_of_full_and_the_frame_is_right_handed() {
        assert_eq!(moon_phase_factor(0.0), 1.0);
        let quarter = moon_phase_factor(90.0);
        assert!((quarter - 0.091).abs() < 0.002, "{quarter}");
        let [x, y, z] = celestial_frame(48.0, 37.0);
        assert!((x.cross(y) - z).length() < 1e-5);
        assert!(x.dot(y).abs() < 1e-6 && (x.length() - 1.0).abs() < 1e-6);
    }
}
