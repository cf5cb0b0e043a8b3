//! The brute-force reference's own checks (`sky_common`, used by `sky_brute_force`): its
//! quadrature converged, and its Monte Carlo pieces unbiased against what they estimate.

use candela::sky::{Aerosol, HAZE_TURBIDITY_3, PhysicalSky};
use glam::DVec3;

use crate::sky_brute_force::{FINE, FLIGHT, worst};
use crate::sky_common::air::{self, Air};
use crate::sky_common::paths::{Rng, next_flight, sample_phase, single_by_paths, track};
use crate::sky_common::single::{Fineness, ViewRay, direction, single_scattering};

fn sky() -> PhysicalSky {
    PhysicalSky {
        sun_elevation_deg: 10.0,
        haze: HAZE_TURBIDITY_3,
        aerosol: Aerosol::TURBIDITY_3,
        ground_albedo: [0.3; 3],
        ..PhysicalSky::default()
    }
}

/// The reference's own quadrature: its single scattering changes by less than 1e-4 (relative,
/// a hundredth of the 1 % band) with 4× the nodes, at the lowest views and suns (long grazing
/// paths, the planet's shadow), and its transmittance to space by less than 1e-4 with 8× the
/// Simpson intervals.
#[test]
fn brute_force_quadrature_is_converged() {
    let s = sky();
    let air = Air::new(&s);
    let finer = Fineness {
        view_intervals: 4 * FINE.view_intervals,
        sun_intervals: 4 * FINE.sun_intervals,
    };
    for sun_deg in [10.0f64, 2.0, -6.0] {
        let sun = direction(sun_deg.to_radians(), 0.0);
        for (e, a) in [(0.6f64, 0.0f64), (0.6, 180.0), (5.0, 90.0), (40.0, 0.0)] {
            let d = direction(e.to_radians(), a.to_radians());
            let coarse =
                single_scattering(&air, &ViewRay::new(&air, d, FINE.view_intervals), sun, FINE);
            let fine = single_scattering(
                &air,
                &ViewRay::new(&air, d, finer.view_intervals),
                sun,
                finer,
            );
            let off = worst(coarse, fine);
            println!(
                "sun {sun_deg}°, view {e}°/{a}°: single {coarse:?} vs 4× finer {fine:?} ({off:.1e})"
            );
            assert!(
                off < 1e-4,
                "sun {sun_deg}°, view {e}°/{a}°: {coarse} vs {fine}"
            );
        }
    }
    for (h, mu) in [
        (0.01f64, 0.02f64),
        (30.0, -0.05),
        (60.0, -0.12),
        (0.01, 1.0),
    ] {
        let r = air::ground_radius() + h;
        let (Some(a), Some(b)) = (
            air.optical_depth(r, mu, FINE.sun_intervals),
            air.optical_depth(r, mu, 8 * FINE.sun_intervals),
        ) else {
            panic!("h {h} km, μ {mu}: in the shadow");
        };
        let (ta, tb) = ((-a).exp(), (-b).exp());
        assert!(
            worst(ta, tb) < 1e-4,
            "h {h} km, μ {mu}: transmittance {ta} vs {tb}"
        );
    }
}

/// Mean and standard error of `n` draws of `f`.
fn mean_and_stderr(n: usize, mut f: impl FnMut() -> DVec3) -> (DVec3, DVec3) {
    let (mut sum, mut squares) = (DVec3::ZERO, DVec3::ZERO);
    for _ in 0..n {
        let x = f();
        sum += x;
        squares += x * x;
    }
    let mean = sum / n as f64;
    let variance = (squares / n as f64 - mean * mean).max(DVec3::ZERO);
    (mean, (variance / (n as f64 - 1.0)).sqrt())
}

/// The reference's Monte Carlo pieces against what they estimate, within 4.5 standard errors
/// per channel: spectral delta tracking's escape weight against the quadrature's transmittance
/// (three view elevations), the phase sampling's weight p/pdf averaging 1 (the phase functions
/// normalised, the sampling unbiased), and single scattering by the first point's next-event
/// estimate against the deterministic march, and the next-flight estimate (`FLIGHT`'s nodes)
/// against the collision's next-event estimate it replaces, from a point 1 km up along rays to
/// the sky and to the ground, the sun above and below the horizon.
#[test]
fn brute_force_paths_are_unbiased() {
    let s = sky();
    let air = Air::new(&s);
    let mut rng = Rng::new(0x5EED);
    let n = 100_000;
    let within = |what: &str, estimate: (DVec3, DVec3), expected: DVec3| {
        // An exact 0 ± 0 (a ray wholly in the planet's shadow) counts as 0 σ.
        let off = (estimate.0 - expected).abs();
        let sigmas =
            DVec3::select(off.cmpeq(DVec3::ZERO), DVec3::ZERO, off / estimate.1).max_element();
        println!(
            "{what}: {:?} ± {:?} vs {expected:?} ({sigmas:.2} σ)",
            estimate.0, estimate.1
        );
        assert!(
            sigmas < 4.5,
            "{what}: {:?} ± {:?} vs {expected:?}",
            estimate.0,
            estimate.1
        );
    };
    let r0 = air::ground_radius() + candela::sky::VIEW_ALTITUDE_KM as f64;
    let origin = DVec3::new(0.0, 0.0, r0);
    for e in [2.0f64, 10.0, 45.0] {
        let d = direction(e.to_radians(), 0.0);
        let boundary = air::ray_sphere(r0, d.z, air::top_radius(), false).unwrap_or(0.0);
        let estimate = mean_and_stderr(n, || {
            let mut w = DVec3::ONE;
            match track(&air, origin, d, boundary, &mut w, &mut rng) {
                None => w,
                Some(_) => DVec3::ZERO,
            }
        });
        within(
            &format!("transmittance at {e}°"),
            estimate,
            air.transmittance(r0, d.z, 64),
        );
    }
    let m = air.media(1.0);
    let estimate = mean_and_stderr(n, || sample_phase(&air, &m, DVec3::Z, &mut rng).1);
    within("phase weight", estimate, DVec3::ONE);
    let x = DVec3::new(0.0, 0.0, air::ground_radius() + 1.0);
    // Below the horizon, rays that see sunlit air (a collision rarely lands in it elsewhere).
    for (sun_deg, rays) in [
        (10.0f64, [(20.0f64, 0.0f64), (5.0, 160.0), (-10.0, 30.0)]),
        (-6.0, [(20.0, 0.0), (45.0, 90.0), (5.0, 20.0)]),
    ] {
        let sun = direction(sun_deg.to_radians(), 0.0);
        for (e, a) in rays {
            let d = direction(e.to_radians(), a.to_radians());
            let r = x.length();
            let ground = air::ray_sphere(r, d.z, air::ground_radius(), true);
            let boundary = ground
                .or(air::ray_sphere(r, d.z, air::top_radius(), false))
                .unwrap_or(0.0);
            let estimate = mean_and_stderr(n, || {
                let mut w = DVec3::ONE;
                match track(&air, x, d, boundary, &mut w, &mut rng) {
                    Some((p, m)) => {
                        let rp = p.length();
                        let sun_t = air.transmittance(rp, p.dot(sun) / rp, FINE.sun_intervals);
                        w * air.phase_scattering(&m, d.dot(sun)) / m.scattering() * sun_t
                    }
                    None if ground.is_some() => {
                        let normal = (x + d * boundary).normalize();
                        let cos_sun = normal.dot(sun).max(0.0);
                        let sun_t = air.transmittance(air::ground_radius(), cos_sun, 16);
                        w * air.albedo / std::f64::consts::PI * cos_sun * sun_t
                    }
                    None => DVec3::ZERO,
                }
            });
            within(
                &format!("next flight, sun {sun_deg}°, ray {e}°/{a}°"),
                estimate,
                next_flight(&air, x, d, sun, FLIGHT),
            );
        }
    }
    let sun = direction(10f64.to_radians(), 0.0);
    for (e, a) in [(2.0f64, 30.0f64), (20.0, 150.0)] {
        let view = ViewRay::new(
            &air,
            direction(e.to_radians(), a.to_radians()),
            FINE.view_intervals,
        );
        let estimate = mean_and_stderr(n, || single_by_paths(&air, &view, sun, FINE, &mut rng));
        within(
            &format!("single at {e}°/{a}°"),
            estimate,
            single_scattering(&air, &view, sun, FINE),
        );
    }
}
