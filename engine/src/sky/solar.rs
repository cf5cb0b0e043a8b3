//! The sun's position: NOAA's solar calculator (Meeus, *Astronomical Algorithms*, ch. 25, low
//! accuracy: about 0.01° from 1800 to 2200).
//!
//! Any thread; pure functions. Owns [`SunState`]. Must not: know the engine's axes beyond
//! [`Horizontal::direction`] or anything of the atmosphere.

use super::calendar::UtcInstant;
use super::horizon::{Horizontal, Observer, equatorial_vector, to_horizontal};

/// Where the sun is, seen from one observer at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SunState {
    /// Geometric elevation (no refraction) and azimuth from north towards east.
    pub horizontal: Horizontal,
    /// Apparent ecliptic longitude of date, degrees (the moon's phase uses it).
    pub ecliptic_longitude_deg: f64,
    /// Earth–sun distance in astronomical units.
    pub distance_au: f64,
}

/// Julian centuries since J2000.0.
fn centuries(jd: f64) -> f64 {
    (jd - 2451545.0) / 36525.0
}

/// Apparent ecliptic longitude (degrees), distance (au) and obliquity (degrees) at `jd`.
pub(super) fn ecliptic(jd: f64) -> (f64, f64, f64) {
    let t = centuries(jd);
    let l0 = (280.46646 + t * (36000.76983 + 0.0003032 * t)).rem_euclid(360.0);
    let m = 357.52911 + t * (35999.05029 - 0.0001537 * t);
    let e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    let mr = m.to_radians();
    let c = mr.sin() * (1.914602 - t * (0.004817 + 0.000014 * t))
        + (2.0 * mr).sin() * (0.019993 - 0.000101 * t)
        + (3.0 * mr).sin() * 0.000289;
    let true_longitude = l0 + c;
    let anomaly = (m + c).to_radians();
    let distance = 1.000001018 * (1.0 - e * e) / (1.0 + e * anomaly.cos());
    let omega = (125.04 - 1934.136 * t).to_radians();
    let apparent = true_longitude - 0.00569 - 0.00478 * omega.sin();
    let eps0 = 23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
    let obliquity = eps0 + 0.00256 * omega.cos();
    (apparent, distance, obliquity)
}

/// The sun seen by `observer` at `when`.
pub fn sun_position(observer: &Observer, when: &UtcInstant) -> SunState {
    let jd = when.julian_day();
    let (longitude, distance, obliquity) = ecliptic(jd);
    let (l, eps) = (longitude.to_radians(), obliquity.to_radians());
    let ra = (eps.cos() * l.sin()).atan2(l.cos());
    let dec = (eps.sin() * l.sin()).asin();
    SunState {
        horizontal: to_horizontal(equatorial_vector(ra, dec), observer, jd),
        ecliptic_longitude_deg: longitude.rem_euclid(360.0),
        distance_au: distance,
    }
}
