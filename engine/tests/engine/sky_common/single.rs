//! Single scattering of the brute-force reference, without Monte Carlo: one view ray from the
//! viewer (10 m up) marched on fine nodes, the view's optical depth accumulated in f64, and at
//! every node the sun's transmittance integrated to space (`Air::optical_depth`). Also keeps the
//! view ray's optical depth per node, from which `paths` samples the first scattering point.
//!
//! Test thread (rayon workers). Frame: the planet's centre at the origin, z up through the
//! viewer, the sun in the x–z plane; kilometres; radiance per unit solar irradiance (the sun a
//! directional source). Must not: use the engine's tables.

use candela::sky::VIEW_ALTITUDE_KM;
use glam::DVec3;

use super::air::{Air, ground_radius, ray_sphere, top_radius};

/// How finely the reference integrates (nodes on the view ray, Simpson intervals per piece of
/// a sun ray).
#[derive(Clone, Copy, Debug)]
pub struct Fineness {
    pub view_intervals: usize,
    pub sun_intervals: usize,
}

/// A view ray from the viewer through the air to the top, marched.
pub struct ViewRay {
    pub origin: DVec3,
    pub direction: DVec3,
    /// Node distances, km (0 first, the exit last; dense near the viewer).
    pub t: Vec<f64>,
    /// Optical depth from the viewer to each node, per channel.
    pub depth: Vec<DVec3>,
    /// Whether the ray ends on the ground (else at the atmosphere's top).
    pub ground: bool,
}

/// Unit vector at `elevation` and `azimuth` (from the sun's vertical plane), radians, z up.
pub fn direction(elevation: f64, azimuth: f64) -> DVec3 {
    DVec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
    )
}

impl ViewRay {
    /// The ray from the viewer towards `direction` (unit, above the horizon) with `intervals`
    /// steps.
    pub fn new(air: &Air, direction: DVec3, intervals: usize) -> Self {
        let r0 = ground_radius() + VIEW_ALTITUDE_KM as f64;
        Self::from(air, DVec3::new(0.0, 0.0, r0), direction, intervals)
    }

    /// The ray from `origin` (in the shell) towards unit `direction` to the ground or the top,
    /// with `intervals` steps (the paths' next-flight estimate, `paths::next_flight`).
    pub fn from(air: &Air, origin: DVec3, direction: DVec3, intervals: usize) -> Self {
        let r0 = origin.length();
        let mu = origin.dot(direction) / r0;
        let ground = ray_sphere(r0, mu, ground_radius(), true);
        let length = ground
            .or(ray_sphere(r0, mu, top_radius(), false))
            .unwrap_or(0.0);
        let t: Vec<f64> = (0..=intervals)
            .map(|i| length * (i as f64 / intervals as f64).powi(2))
            .collect();
        let extinction = |t: f64| air.media((origin + direction * t).length() - ground_radius());
        let mut depth = Vec::with_capacity(t.len());
        let mut tau = DVec3::ZERO;
        let mut previous = extinction(0.0).extinction;
        depth.push(tau);
        for w in t.windows(2) {
            // Simpson on each interval (the midpoint evaluated once more).
            let mid = extinction(0.5 * (w[0] + w[1])).extinction;
            let next = extinction(w[1]).extinction;
            tau += (previous + 4.0 * mid + next) * ((w[1] - w[0]) / 6.0);
            depth.push(tau);
            previous = next;
        }
        Self {
            origin,
            direction,
            t,
            depth,
            ground: ground.is_some(),
        }
    }

    pub fn point(&self, t: f64) -> DVec3 {
        self.origin + self.direction * t
    }

    /// Optical depth from the viewer to distance `t`, linear between nodes.
    pub fn depth_at(&self, t: f64) -> DVec3 {
        let i = self
            .t
            .partition_point(|&x| x <= t)
            .clamp(1, self.t.len() - 1);
        let (t0, t1) = (self.t[i - 1], self.t[i]);
        let f = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        self.depth[i - 1].lerp(self.depth[i], f.clamp(0.0, 1.0))
    }
}

/// Single-scattered radiance per unit solar irradiance towards the viewer along `view`, for a
/// sun towards unit `sun`: ∫ T_view σ_s p T_sun dt, trapezoid on the view's nodes; an interval
/// that crosses the edge of the planet's shadow is split at the edge (found by bisection).
pub fn single_scattering(air: &Air, view: &ViewRay, sun: DVec3, fine: Fineness) -> DVec3 {
    let cos_theta = view.direction.dot(sun);
    let lit = |t: f64| {
        let p = view.point(t);
        let r = p.length();
        ray_sphere(r, p.dot(sun) / r, ground_radius(), true).is_none()
    };
    let integrand = |t: f64, depth: DVec3| {
        let p = view.point(t);
        let r = p.length();
        let m = air.media(r - ground_radius());
        let sun_t = air.transmittance(r, p.dot(sun) / r, fine.sun_intervals);
        (-depth).exp() * air.phase_scattering(&m, cos_theta) * sun_t
    };
    let values: Vec<DVec3> = view
        .t
        .iter()
        .zip(&view.depth)
        .map(|(&t, &d)| integrand(t, d))
        .collect();
    let mut sum = DVec3::ZERO;
    for i in 1..view.t.len() {
        let (t0, t1) = (view.t[i - 1], view.t[i]);
        let (lit0, lit1) = (lit(t0), lit(t1));
        if lit0 == lit1 {
            sum += (values[i - 1] + values[i]) * (0.5 * (t1 - t0));
            continue;
        }
        // The shadow's edge: bisect, then integrate the lit part from the edge.
        let (mut dark, mut light) = if lit0 { (t1, t0) } else { (t0, t1) };
        for _ in 0..60 {
            let mid = 0.5 * (dark + light);
            if lit(mid) {
                light = mid;
            } else {
                dark = mid;
            }
        }
        let edge = integrand(light, view.depth_at(light));
        let end = if lit0 { values[i - 1] } else { values[i] };
        let far = if lit0 { t0 } else { t1 };
        sum += (edge + end) * (0.5 * (far - light).abs());
    }
    sum
}
