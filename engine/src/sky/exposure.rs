//! The exposure the sky calls for: the horizontal illuminance under a physical sky (sun and
//! sky, from the sky-view table and the sun's direct irradiance) and the exposure, in stops,
//! that a deterministic meter sets for it — a function of the sky (so of the time of day),
//! never of the rendered picture, so replays and screenshots reproduce.
//!
//! Any thread; pure functions. Units: the illuminance is the luminance-weighted (Rec.709 Y)
//! irradiance in the sky's units (W·m⁻²·nm⁻¹, CIE-Y normalised as Mitsuba's sunsky), and
//! [`LUX_PER_Y`] turns it into lux. Must not: know the tonemapper or the engine's settings.

use glam::Vec3;

use super::sky_view::lookup_view;

/// Lux per unit of the sky's luminance-weighted irradiance: 683 lm/W × ∫ȳ(λ) dλ (106.857 nm).
/// The sun's top-of-atmosphere 1.6836 is then 123 000 lx.
pub const LUX_PER_Y: f32 = 683.0 * 106.857;
/// The darkest night the meter exposes for, lux (a quarter moon's light): below it the picture
/// darkens one stop per stop.
pub const NIGHT_FLOOR_LUX: f32 = 0.01;
/// Illuminance at which the meter exposes a mid grey to mid grey, lux (an overcast day).
pub const DAYLIGHT_LUX: f32 = 10_000.0;
/// Share of the stops below [`DAYLIGHT_LUX`] that the picture darkens (twilight and night
/// read darker than the day, as the eye sees them, without going black).
pub const NIGHT_DARKENING: f32 = 0.25;

const LUMINANCE: Vec3 = Vec3::new(0.2126, 0.7152, 0.0722);
const QUADRATURE: usize = 64;

/// Luminance-weighted irradiance on a horizontal surface (sky units, × [`LUX_PER_Y`] for lux)
/// from a sky-view table (`texels`, sun disc excluded) and the sun's direct normal irradiance
/// `sun_irradiance` at elevation `sun_elevation_deg` (none below the horizon).
pub fn horizontal_illuminance(
    texels: &[[f32; 4]],
    sun_irradiance: Vec3,
    sun_elevation_deg: f64,
) -> f32 {
    if texels.is_empty() {
        return 0.0;
    }
    // E = ∫∫ L(e, φ) sin e cos e de dφ over the upper hemisphere; the table is symmetric about
    // the sun's vertical plane, so φ runs over 0..π and counts twice.
    let (de, dphi) = (
        std::f32::consts::FRAC_PI_2 / QUADRATURE as f32,
        std::f32::consts::PI / QUADRATURE as f32,
    );
    let mut sky = 0.0f32;
    for i in 0..QUADRATURE {
        let e = (i as f32 + 0.5) * de;
        let weight = e.sin() * e.cos() * de * dphi * 2.0;
        for j in 0..QUADRATURE {
            let phi = (j as f32 + 0.5) * dphi;
            sky += weight * lookup_view(texels, e, phi).dot(LUMINANCE);
        }
    }
    let sun =
        sun_irradiance.dot(LUMINANCE) * (sun_elevation_deg.to_radians().sin() as f32).max(0.0);
    sky + sun
}

/// The exposure in stops (the radiance multiplier is 2^ev, as `TonemapSettings::exposure_ev`)
/// for a horizontal illuminance `illuminance` in sky units: a mid-grey diffuse surface under
/// it is shown at mid grey (2^ev = π / E) by day, and the picture darkens by
/// [`NIGHT_DARKENING`] of the stops below [`DAYLIGHT_LUX`]; nights darker than
/// [`NIGHT_FLOOR_LUX`] are exposed as that. Decreases as the illuminance grows.
pub fn exposure_ev(illuminance: f32) -> f32 {
    let lux = (illuminance.max(0.0) * LUX_PER_Y).max(NIGHT_FLOOR_LUX);
    let metered = (std::f32::consts::PI * LUX_PER_Y / lux).log2();
    metered - NIGHT_DARKENING * (DAYLIGHT_LUX / lux).log2().max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exposure_falls_as_the_light_grows_and_stays_finite_in_the_dark() {
        let mut last = f32::INFINITY;
        for lux in [0.0f32, 0.001, 0.01, 1.0, 100.0, 10_000.0, 120_000.0] {
            let ev = exposure_ev(lux / LUX_PER_Y);
            assert!(ev.is_finite() && ev <= last, "{lux} lx: {ev}");
            last = ev;
        }
        // A uniform sky of radiance 1 gives E = π.
        let table =
            vec![[1.0, 1.0, 1.0, 0.0]; super::super::VIEW_WIDTH * super::super::VIEW_HEIGHT];
        let e = horizontal_illuminance(&table, Vec3::ZERO, 30.0);
        assert!((e - std::f32::consts::PI).abs() < 1e-3, "{e}");
        let e = horizontal_illuminance(&table, Vec3::ONE, 30.0);
        assert!((e - std::f32::consts::PI - 0.5).abs() < 1e-3, "{e}");
    }
}
