//! The moon's position and phase: Paul Schlyter's low-precision series ("How to compute
//! planetary positions": mean elements of date, Kepler's equation, the twelve largest
//! longitude and five latitude perturbations; about 2′ geocentric), moved to the observer
//! (topocentric: the parallax reaches 1°).
//!
//! Any thread; pure functions. Owns [`MoonState`]. Must not: know the atmosphere or the
//! engine's renderer.

use super::calendar::UtcInstant;
use super::horizon::{Horizontal, Observer, observer_vector, to_horizontal};
use super::solar::ecliptic;

/// Earth's equatorial radius in astronomical units (6378.14 km / 149 597 870.7 km).
const EARTH_RADIUS_AU: f64 = 6378.14 / 149_597_870.7;

/// Where the moon is and how it is lit, seen from one observer at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoonState {
    /// Topocentric geometric elevation (no refraction) and azimuth from north towards east.
    pub horizontal: Horizontal,
    /// Sun–moon–Earth angle in degrees: 0 at full moon, 180 at new moon.
    pub phase_angle_deg: f64,
    /// Share of the disc that is lit, (1 + cos phase angle) / 2.
    pub illuminated_fraction: f64,
    /// Whether the lit part grows (new → full).
    pub waxing: bool,
    /// Earth–moon distance in Earth radii (geocentric).
    pub distance_earth_radii: f64,
}

fn sin_d(x: f64) -> f64 {
    x.to_radians().sin()
}

fn cos_d(x: f64) -> f64 {
    x.to_radians().cos()
}

/// Geocentric ecliptic longitude and latitude of date (degrees) and distance (Earth radii).
fn geocentric(jd: f64) -> (f64, f64, f64) {
    let d = jd - 2451543.5;
    let node = 125.1228 - 0.0529538083 * d;
    let incl = 5.1454;
    let perigee = 318.0634 + 0.1643573223 * d;
    let a = 60.2666;
    let e: f64 = 0.0549;
    let m = (115.3654 + 13.0649929509 * d).rem_euclid(360.0);
    let mut ecc = m + e.to_degrees() * sin_d(m) * (1.0 + e * cos_d(m));
    for _ in 0..8 {
        ecc -= (ecc - e.to_degrees() * sin_d(ecc) - m) / (1.0 - e * cos_d(ecc));
    }
    let (xv, yv) = (a * (cos_d(ecc) - e), a * (1.0 - e * e).sqrt() * sin_d(ecc));
    let v = yv.atan2(xv).to_degrees();
    let mut r = (xv * xv + yv * yv).sqrt();
    let (vw, n, i) = (v + perigee, node, incl);
    let xh = r * (cos_d(n) * cos_d(vw) - sin_d(n) * sin_d(vw) * cos_d(i));
    let yh = r * (sin_d(n) * cos_d(vw) + cos_d(n) * sin_d(vw) * cos_d(i));
    let zh = r * sin_d(vw) * sin_d(i);
    let mut lon = yh.atan2(xh).to_degrees();
    let mut lat = zh.atan2((xh * xh + yh * yh).sqrt()).to_degrees();
    // Perturbations (Schlyter §"Perturbations of the Moon").
    let ms = 356.0470 + 0.9856002585 * d;
    let ws = 282.9404 + 4.70935e-5 * d;
    let ls = ms + ws;
    let lm = m + perigee + node;
    let dd = lm - ls;
    let f = lm - node;
    lon += -1.274 * sin_d(m - 2.0 * dd) + 0.658 * sin_d(2.0 * dd)
        - 0.186 * sin_d(ms)
        - 0.059 * sin_d(2.0 * m - 2.0 * dd)
        - 0.057 * sin_d(m - 2.0 * dd + ms)
        + 0.053 * sin_d(m + 2.0 * dd)
        + 0.046 * sin_d(2.0 * dd - ms)
        + 0.041 * sin_d(m - ms)
        - 0.035 * sin_d(dd)
        - 0.031 * sin_d(m + ms)
        - 0.015 * sin_d(2.0 * f - 2.0 * dd)
        + 0.011 * sin_d(m - 4.0 * dd);
    lat += -0.173 * sin_d(f - 2.0 * dd)
        - 0.055 * sin_d(m - f - 2.0 * dd)
        - 0.046 * sin_d(m + f - 2.0 * dd)
        + 0.033 * sin_d(f + 2.0 * dd)
        + 0.017 * sin_d(2.0 * m + f);
    r += -0.58 * cos_d(m - 2.0 * dd) - 0.46 * cos_d(2.0 * dd);
    (lon.rem_euclid(360.0), lat, r)
}

/// The moon seen by `observer` at `when`.
pub fn moon_position(observer: &Observer, when: &UtcInstant) -> MoonState {
    let jd = when.julian_day();
    let (lon, lat, r) = geocentric(jd);
    let (sun_lon, sun_distance_au, obliquity) = ecliptic(jd);
    // Ecliptic → equatorial (of date), geocentric, in Earth radii.
    let ecl = [
        r * cos_d(lat) * cos_d(lon),
        r * cos_d(lat) * sin_d(lon),
        r * sin_d(lat),
    ];
    let (ce, se) = (cos_d(obliquity), sin_d(obliquity));
    let geo = [ecl[0], ecl[1] * ce - ecl[2] * se, ecl[1] * se + ecl[2] * ce];
    let o = observer_vector(observer, jd);
    let topo = [geo[0] - o[0], geo[1] - o[1], geo[2] - o[2]];
    // Phase angle from the geocentric elongation ψ and the two distances (Meeus eq. 48.3).
    let cos_psi = (cos_d(lat) * cos_d(lon - sun_lon)).clamp(-1.0, 1.0);
    let psi = cos_psi.acos();
    let moon_au = r * EARTH_RADIUS_AU;
    let phase = (sun_distance_au * psi.sin()).atan2(moon_au - sun_distance_au * cos_psi);
    MoonState {
        horizontal: to_horizontal(topo, observer, jd),
        phase_angle_deg: phase.to_degrees(),
        illuminated_fraction: (1.0 + phase.cos()) / 2.0,
        waxing: (lon - sun_lon).rem_euclid(360.0) < 180.0,
        distance_earth_radii: r,
    }
}
