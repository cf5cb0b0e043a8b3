//! The observer and the step from equatorial coordinates to the engine's axes.
//!
//! Any thread; pure functions. Owns [`Observer`], [`Horizontal`] (elevation and azimuth) and
//! the one mapping from the local horizon to engine space: **north = −Z, east = +X, up = +Y**
//! (right-handed, Y up). Azimuth is measured from north towards east (clockwise seen from
//! above), as pvlib, ephem and the NOAA tables do. Must not: know calendars or series.

use glam::Vec3;

use super::error::SkyError;

/// Where the sky is seen from: geodetic latitude and longitude in degrees (north and east
/// positive). The Earth is taken as a sphere (the lunar parallax ignores flattening: < 0.01°).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Observer {
    latitude_deg: f64,
    longitude_deg: f64,
}

impl Observer {
    /// Checks latitude ∈ [−90°, 90°] and longitude ∈ [−180°, 180°].
    pub fn new(latitude_deg: f64, longitude_deg: f64) -> Result<Self, SkyError> {
        if !latitude_deg.is_finite() || latitude_deg.abs() > 90.0 {
            return Err(SkyError::Latitude(latitude_deg));
        }
        if !longitude_deg.is_finite() || longitude_deg.abs() > 180.0 {
            return Err(SkyError::Longitude(longitude_deg));
        }
        Ok(Self {
            latitude_deg,
            longitude_deg,
        })
    }

    pub fn latitude_deg(&self) -> f64 {
        self.latitude_deg
    }

    pub fn longitude_deg(&self) -> f64 {
        self.longitude_deg
    }
}

/// A direction on the local sky: elevation above the geometric horizon (no refraction) and
/// azimuth from north towards east, both in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Horizontal {
    pub elevation_deg: f64,
    pub azimuth_deg: f64,
}

impl Horizontal {
    /// Unit vector towards this direction in engine space (north = −Z, east = +X, up = +Y).
    pub fn direction(&self) -> Vec3 {
        let (h, a) = (
            self.elevation_deg.to_radians(),
            self.azimuth_deg.to_radians(),
        );
        Vec3::new(
            (h.cos() * a.sin()) as f32,
            h.sin() as f32,
            (-h.cos() * a.cos()) as f32,
        )
    }

    /// Unit vector in f64 as (east, north, up): used by tests that compare angles finely.
    pub fn enu(&self) -> [f64; 3] {
        let (h, a) = (
            self.elevation_deg.to_radians(),
            self.azimuth_deg.to_radians(),
        );
        [h.cos() * a.sin(), h.cos() * a.cos(), h.sin()]
    }
}

/// Greenwich mean sidereal time in degrees for the Julian day `jd` (UT), Meeus eq. 12.4.
pub fn sidereal_deg(jd: f64) -> f64 {
    let t = (jd - 2451545.0) / 36525.0;
    let g = 280.46061837 + 360.98564736629 * (jd - 2451545.0) + 0.000387933 * t * t
        - t * t * t / 38710000.0;
    g.rem_euclid(360.0)
}

/// Equatorial unit vector (x towards the equinox, z towards the celestial north pole) from
/// right ascension and declination in radians.
pub fn equatorial_vector(ra: f64, dec: f64) -> [f64; 3] {
    [dec.cos() * ra.cos(), dec.cos() * ra.sin(), dec.sin()]
}

/// Local horizontal coordinates of an equatorial vector `v` (any length, geocentric or
/// topocentric, x towards the equinox) seen by `observer` at Julian day `jd` (UT).
pub fn to_horizontal(v: [f64; 3], observer: &Observer, jd: f64) -> Horizontal {
    let lst = (sidereal_deg(jd) + observer.longitude_deg).to_radians();
    let lat = observer.latitude_deg.to_radians();
    let ra = v[1].atan2(v[0]);
    let dec = v[2].atan2((v[0] * v[0] + v[1] * v[1]).sqrt());
    let hour = lst - ra;
    // East, north, up components (Meeus ch. 13 rewritten as a rotation).
    let east = -dec.cos() * hour.sin();
    let north = dec.sin() * lat.cos() - dec.cos() * hour.cos() * lat.sin();
    let up = dec.sin() * lat.sin() + dec.cos() * hour.cos() * lat.cos();
    Horizontal {
        elevation_deg: up.atan2((east * east + north * north).sqrt()).to_degrees(),
        azimuth_deg: east.atan2(north).to_degrees().rem_euclid(360.0),
    }
}

/// The observer's position in the equatorial frame in Earth radii (spherical Earth).
pub fn observer_vector(observer: &Observer, jd: f64) -> [f64; 3] {
    let lst = (sidereal_deg(jd) + observer.longitude_deg).to_radians();
    let lat = observer.latitude_deg.to_radians();
    [lat.cos() * lst.cos(), lat.cos() * lst.sin(), lat.sin()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn azimuth_maps_to_engine_axes() {
        let d = |a: f64| {
            Horizontal {
                elevation_deg: 0.0,
                azimuth_deg: a,
            }
            .direction()
        };
        assert!((d(0.0) - Vec3::NEG_Z).length() < 1e-6, "north is -Z");
        assert!((d(90.0) - Vec3::X).length() < 1e-6, "east is +X");
        let up = Horizontal {
            elevation_deg: 90.0,
            azimuth_deg: 10.0,
        }
        .direction();
        assert!((up - Vec3::Y).length() < 1e-6);
    }

    #[test]
    fn bad_observers_are_refused() {
        assert_eq!(Observer::new(91.0, 0.0), Err(SkyError::Latitude(91.0)));
        assert!(Observer::new(f64::NAN, 0.0).is_err());
        assert_eq!(Observer::new(0.0, -181.0), Err(SkyError::Longitude(-181.0)));
        assert!(Observer::new(-90.0, 180.0).is_ok());
    }
}
