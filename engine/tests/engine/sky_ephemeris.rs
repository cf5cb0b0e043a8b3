//! The ephemeris (`candela::sky`) against reference positions from pvlib (NREL SPA, sun) and
//! PyEphem (moon), made by `tools/skyref/gen.py` into `tools/skyref/ephemeris.csv`: 48 places
//! and instants from 1950 to 2080, latitudes from −55° to 78°.
//!
//! Tolerances (the issue's): sun direction within 0.05°, moon direction within 0.5°, moon
//! phase angle within 1°. Directions are compared as the angle between unit vectors, so an
//! azimuth near the zenith cannot inflate the error.

use std::path::Path;

use candela::sky::{Horizontal, Observer, UtcInstant, moon_position, sun_position};

fn angle_deg(a: [f64; 3], b: [f64; 3]) -> f64 {
    let dot: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
    dot.clamp(-1.0, 1.0).acos().to_degrees()
}

fn horizontal(elevation_deg: f64, azimuth_deg: f64) -> Horizontal {
    Horizontal {
        elevation_deg,
        azimuth_deg,
    }
}

#[test]
fn sun_and_moon_match_the_reference_ephemerides() -> anyhow::Result<()> {
    let csv = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tools/skyref/ephemeris.csv");
    let text = std::fs::read_to_string(&csv)?;
    let (mut worst_sun, mut worst_moon, mut worst_phase, mut worst_lit) = (0f64, 0f64, 0f64, 0f64);
    let mut rows = 0;
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<f64> = line.split(',').map(str::parse).collect::<Result<_, _>>()?;
        let observer = Observer::new(f[0], f[1])?;
        let when = UtcInstant::new(
            f[2] as i32,
            f[3] as u32,
            f[4] as u32,
            f[5] as u32,
            f[6] as u32,
            f[7],
        )?;
        let sun = sun_position(&observer, &when);
        let moon = moon_position(&observer, &when);
        worst_sun = worst_sun.max(angle_deg(
            sun.horizontal.enu(),
            horizontal(f[8], f[9]).enu(),
        ));
        worst_moon = worst_moon.max(angle_deg(
            moon.horizontal.enu(),
            horizontal(f[10], f[11]).enu(),
        ));
        worst_phase = worst_phase.max((moon.phase_angle_deg - f[12]).abs());
        worst_lit = worst_lit.max((moon.illuminated_fraction - f[13]).abs());
        rows += 1;
    }
    println!(
        "{rows} rows: sun {worst_sun:.4}°, moon {worst_moon:.4}°, phase angle {worst_phase:.4}°, \
         lit fraction {worst_lit:.4} (worst)"
    );
    assert_eq!(rows, 48, "the reference table lost rows");
    assert!(worst_sun <= 0.05, "sun off by {worst_sun}°");
    assert!(worst_moon <= 0.5, "moon off by {worst_moon}°");
    assert!(worst_phase <= 1.0, "moon phase angle off by {worst_phase}°");
    assert!(worst_lit <= 0.01, "lit fraction off by {worst_lit}");
    Ok(())
}

#[test]
fn bad_places_and_times_are_typed_errors() {
    use candela::sky::SkyError;
    assert_eq!(Observer::new(-90.5, 0.0), Err(SkyError::Latitude(-90.5)));
    assert!(matches!(
        UtcInstant::new(2026, 2, 30, 12, 0, 0.0),
        Err(SkyError::Date {
            month: 2,
            day: 30,
            ..
        })
    ));
    let message = Observer::new(123.0, 0.0).unwrap_err().to_string();
    assert!(message.contains("time.latitude_deg = 123"), "{message}");
}
