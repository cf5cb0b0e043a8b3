//! The brute-force reference of the physical sky (issue 34, "Brute force against the tables"):
//! the engine's spherical atmosphere rewritten in f64 (`air`), its single scattering by a
//! deterministic fine march (`single`) and all higher orders by Monte Carlo volumetric path
//! tracing (`paths`), with no table anywhere. `sky_brute_force` compares the engine's sky-view
//! tables against it.
//!
//! Test thread; [`reference`] spreads its paths over rayon's workers, seeded per direction so
//! the figures do not depend on the threads. Must not: use the engine's transmittance,
//! multiple-scattering or sky-view code, only the atmosphere's parameters.
#![allow(dead_code)]

pub mod air;
pub mod paths;
pub mod single;

use candela::sky::PhysicalSky;
use glam::DVec3;

use air::Air;
use paths::{Rng, higher_orders, higher_orders_next_flight};
use single::{Fineness, ViewRay, direction, single_scattering};

/// The reference radiance towards one view, per unit solar irradiance.
#[derive(Clone, Copy, Debug)]
pub struct Reference {
    /// Single scattering (deterministic quadrature).
    pub single: DVec3,
    /// All orders: single + the Monte Carlo mean of orders ≥ 2 (air and ground).
    pub total: DVec3,
    /// Standard error of `total` (from the spread of the paths), per channel.
    pub stderr: DVec3,
}

/// The reference towards a view at `elevation` and `azimuth` from the sun (radians) for a sun
/// at `sun_elevation` radians, with `paths` Monte Carlo paths seeded by `seed`: the collision
/// estimator (`paths::higher_orders`), or with `flight` the next-flight estimator on its nodes
/// (`paths::higher_orders_next_flight`; twilight).
#[allow(clippy::too_many_arguments)]
pub fn reference(
    sky: &PhysicalSky,
    sun_elevation: f64,
    elevation: f64,
    azimuth: f64,
    paths: usize,
    seed: u64,
    fine: Fineness,
    flight: Option<Fineness>,
) -> Reference {
    let air = Air::new(sky);
    let sun = direction(sun_elevation, 0.0);
    let view = ViewRay::new(&air, direction(elevation, azimuth), fine.view_intervals);
    let single = single_scattering(&air, &view, sun, fine);
    let mut rng = Rng::new(seed);
    let (mut sum, mut squares) = (DVec3::ZERO, DVec3::ZERO);
    for _ in 0..paths {
        let l = match flight {
            Some(f) => higher_orders_next_flight(&air, &view, sun, f, &mut rng),
            None => higher_orders(&air, &view, sun, fine, &mut rng),
        };
        sum += l;
        squares += l * l;
    }
    let n = paths.max(2) as f64;
    let mean = sum / n;
    let variance = (squares / n - mean * mean).max(DVec3::ZERO) * (n / (n - 1.0));
    Reference {
        single,
        total: single + mean,
        stderr: (variance / n).sqrt(),
    }
}
