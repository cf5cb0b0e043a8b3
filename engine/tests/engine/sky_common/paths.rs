//! The brute-force reference's second and higher scattering orders: Monte Carlo volumetric
//! path tracing in the spherical shell, all orders, no tables.
//!
//! One path: the first scattering point on the view ray sampled in proportion to σ_t·T (the
//! view's optical depth from `single::ViewRay`, forced to scatter and weighted by 1 − T), a
//! direction from the phase functions (one-sample mixture of Rayleigh, uniform proposal, and
//! the aerosol lobes, Henyey–Greenstein proposals), then free flights by spectral delta
//! tracking against one majorant (Kutz et al. 2017: one walk carries R, G and B with
//! per-channel weights), next-event estimation to the sun (a directional source, f64
//! transmittance by quadrature, zero in the planet's shadow) at every later scattering point
//! and at the ground (Lambertian, the level's albedo, cosine-sampled bounce), Russian roulette
//! from the third order on. The first point gets no next-event estimate: single scattering is
//! `single::single_scattering`'s, deterministic. Seeded splitmix64: the same seed gives the
//! same figures on any thread.
//!
//! [`higher_orders_next_flight`] is the same walk with the next-flight estimator instead of the
//! collision's next-event estimate: at every vertex, once its outgoing direction is drawn, the
//! light that reaches the vertex along it by one more scattering of sunlight (in the air, or at
//! the ground at the ray's end) is integrated deterministically (`single::single_scattering`
//! from the vertex); the walk then goes on with no estimate at the next vertex. Same mean, far
//! less variance in twilight, where sunlit air is thin and high and a collision rarely lands in
//! it; each vertex costs a march.
//!
//! Test thread (rayon workers). Frame, units: as `single`. Must not: use the engine's tables.

use std::f64::consts::PI;

use glam::DVec3;

use super::air::{Air, Media, ground_radius, henyey_greenstein, ray_sphere, top_radius};
use super::single::{Fineness, ViewRay, single_scattering};

/// splitmix64 (Steele et al. 2014): small, seeded, reproducible.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn mean(v: DVec3) -> f64 {
    (v.x + v.y + v.z) / 3.0
}

/// A unit vector at `cos_theta` from unit `axis`, turned by `phi` about it.
fn around(axis: DVec3, cos_theta: f64, phi: f64) -> DVec3 {
    let helper = if axis.x.abs() > 0.9 {
        DVec3::Y
    } else {
        DVec3::X
    };
    let a = axis.cross(helper).normalize();
    let b = axis.cross(a);
    let s = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    (a * phi.cos() + b * phi.sin()) * s + axis * cos_theta
}

/// Samples a new direction after scattering at media `m` while travelling along `incoming`;
/// returns it with the per-channel weight p_c(cos θ) / pdf(cos θ) (p_c the channel's phase
/// function, normalised).
pub fn sample_phase(air: &Air, m: &Media, incoming: DVec3, rng: &mut Rng) -> (DVec3, DVec3) {
    let (rayleigh, aerosol) = (mean(m.rayleigh), mean(m.aerosol));
    let total = rayleigh + aerosol;
    let lobes = air.aerosol_lobes();
    let shares = [
        (rayleigh / total, 0.0),
        (aerosol / total * lobes[0].0, lobes[0].1),
        (aerosol / total * lobes[1].0, lobes[1].1),
    ];
    let pick = rng.next();
    let mut acc = 0.0;
    let mut g = shares[2].1;
    for (share, lobe_g) in shares {
        acc += share;
        if pick < acc {
            g = lobe_g;
            break;
        }
    }
    let u = rng.next();
    let cos_theta = if g.abs() < 1e-6 {
        1.0 - 2.0 * u
    } else {
        let sq = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
        ((1.0 + g * g - sq * sq) / (2.0 * g)).clamp(-1.0, 1.0)
    };
    let pdf: f64 = shares
        .iter()
        .map(|&(share, lobe_g)| share * henyey_greenstein(cos_theta, lobe_g))
        .sum();
    let dir = around(incoming, cos_theta, 2.0 * PI * rng.next());
    let weight = air.phase_scattering(m, cos_theta) / (m.scattering() * pdf);
    (dir, weight)
}

/// A cosine-distributed direction about unit `normal`.
fn cosine_sample(normal: DVec3, rng: &mut Rng) -> DVec3 {
    let u = rng.next();
    around(normal, u.sqrt(), 2.0 * PI * rng.next())
}

/// The first scattering point on the view ray, sampled with pdf(t) = σ_g e^{−τ_g} /
/// (1 − e^{−τ_g,max}), τ_g the channels' mean optical depth (piecewise linear between the
/// view's nodes): the point, its media and the weight T_c σ_s,c / pdf per channel.
pub fn first_point(air: &Air, view: &ViewRay, rng: &mut Rng) -> (DVec3, Media, DVec3) {
    let last = view.depth.len() - 1;
    let reach = 1.0 - (-mean(view.depth[last])).exp();
    let target = -(1.0 - rng.next() * reach).ln();
    let i = view
        .depth
        .partition_point(|d| mean(*d) <= target)
        .clamp(1, last);
    let (g0, g1) = (mean(view.depth[i - 1]), mean(view.depth[i]));
    let (t0, t1) = (view.t[i - 1], view.t[i]);
    let f = ((target - g0) / (g1 - g0)).clamp(0.0, 1.0);
    let t = t0 + f * (t1 - t0);
    let pdf = (g1 - g0) / (t1 - t0) * (-target).exp() / reach;
    let depth = view.depth[i - 1].lerp(view.depth[i], f);
    let x = view.point(t);
    let m = air.media(x.length() - ground_radius());
    let w = (-depth).exp() * m.scattering() / pdf;
    (x, m, w)
}

/// Spectral delta tracking from `x` along unit `dir` over `boundary` km: the first real
/// collision (point and media; `w` times σ_s,c / σ̄_mean) or `None` when the flight passes the
/// boundary; each null collision multiplies `w` by (σ̄ − σ_t,c) / (σ̄ − σ̄_mean).
pub fn track(
    air: &Air,
    x: DVec3,
    dir: DVec3,
    boundary: f64,
    w: &mut DVec3,
    rng: &mut Rng,
) -> Option<(DVec3, Media)> {
    let mut t = 0.0;
    loop {
        t -= (1.0 - rng.next()).ln() / air.majorant;
        if t >= boundary {
            return None;
        }
        let p = x + dir * t;
        let m = air.media(p.length() - ground_radius());
        let sigma = mean(m.extinction);
        if rng.next() * air.majorant < sigma {
            *w *= m.scattering() / sigma;
            return Some((p, m));
        }
        *w *= (DVec3::splat(air.majorant) - m.extinction) / (air.majorant - sigma);
    }
}

/// One path's estimate of single scattering (the first point's next-event estimate): a check
/// of [`first_point`] against `single::single_scattering`.
pub fn single_by_paths(
    air: &Air,
    view: &ViewRay,
    sun: DVec3,
    fine: Fineness,
    rng: &mut Rng,
) -> DVec3 {
    let (x, m, w) = first_point(air, view, rng);
    let r = x.length();
    let sun_t = air.transmittance(r, x.dot(sun) / r, fine.sun_intervals);
    w * air.phase_scattering(&m, view.direction.dot(sun)) / m.scattering() * sun_t
}

/// One path's estimate of the radiance per unit solar irradiance that orders ≥ 2 (air and
/// ground) send to the viewer along `view`, for a sun towards unit `sun`.
pub fn higher_orders(
    air: &Air,
    view: &ViewRay,
    sun: DVec3,
    fine: Fineness,
    rng: &mut Rng,
) -> DVec3 {
    let (mut x, m, mut w) = first_point(air, view, rng);
    let (mut dir, phase_weight) = sample_phase(air, &m, view.direction, rng);
    w *= phase_weight;

    let mut radiance = DVec3::ZERO;
    for order in 2..1000 {
        let r = x.length();
        let mu = x.dot(dir) / r;
        let ground = ray_sphere(r, mu, ground_radius(), true);
        let Some(boundary) = ground.or(ray_sphere(r, mu, top_radius(), false)) else {
            break;
        };
        let collision = track(air, x, dir, boundary, &mut w, rng);
        if let Some((p, m)) = collision {
            let rp = p.length();
            let sun_t = air.transmittance(rp, p.dot(sun) / rp, fine.sun_intervals);
            radiance += w * air.phase_scattering(&m, dir.dot(sun)) / m.scattering() * sun_t;
            let (next, phase_weight) = sample_phase(air, &m, dir, rng);
            x = p;
            dir = next;
            w *= phase_weight;
        } else if ground.is_some() {
            let normal = (x + dir * boundary).normalize();
            x = normal * ground_radius();
            let cos_sun = normal.dot(sun);
            if cos_sun > 0.0 {
                let sun_t = air.transmittance(ground_radius(), cos_sun, fine.sun_intervals);
                radiance += w * air.albedo / PI * cos_sun * sun_t;
            }
            dir = cosine_sample(normal, rng);
            w *= air.albedo;
        } else {
            break; // out through the top
        }
        if order >= 3 {
            let survive = w.max_element().min(1.0);
            if survive <= 0.0 || rng.next() >= survive {
                break;
            }
            w /= survive;
        }
    }
    radiance
}

/// Radiance per unit solar irradiance reaching `x` from unit direction `dir` by one scattering
/// of sunlight: in the air along the ray (`single_scattering` on `fine`'s nodes) and, where the
/// ray ends on the ground, the sunlit Lambertian ground seen through the ray's transmittance.
pub fn next_flight(air: &Air, x: DVec3, dir: DVec3, sun: DVec3, fine: Fineness) -> DVec3 {
    let ray = ViewRay::from(air, x, dir, fine.view_intervals);
    let mut radiance = single_scattering(air, &ray, sun, fine);
    if let (true, Some(&end), Some(&depth)) = (ray.ground, ray.t.last(), ray.depth.last()) {
        let normal = ray.point(end).normalize();
        let cos_sun = normal.dot(sun);
        if cos_sun > 0.0 {
            let sun_t = air.transmittance(ground_radius(), cos_sun, fine.sun_intervals);
            radiance += (-depth).exp() * air.albedo / PI * cos_sun * sun_t;
        }
    }
    radiance
}

/// [`higher_orders`] with the next-flight estimator (module doc): the same walk, the light of
/// every vertex's next scattering integrated along its outgoing ray on `flight`'s nodes.
pub fn higher_orders_next_flight(
    air: &Air,
    view: &ViewRay,
    sun: DVec3,
    flight: Fineness,
    rng: &mut Rng,
) -> DVec3 {
    let (mut x, m, mut w) = first_point(air, view, rng);
    let (mut dir, phase_weight) = sample_phase(air, &m, view.direction, rng);
    w *= phase_weight;

    let mut radiance = DVec3::ZERO;
    for order in 2..1000 {
        radiance += w * next_flight(air, x, dir, sun, flight);
        let r = x.length();
        let mu = x.dot(dir) / r;
        let ground = ray_sphere(r, mu, ground_radius(), true);
        let Some(boundary) = ground.or(ray_sphere(r, mu, top_radius(), false)) else {
            break;
        };
        if let Some((p, m)) = track(air, x, dir, boundary, &mut w, rng) {
            let (next, phase_weight) = sample_phase(air, &m, dir, rng);
            x = p;
            dir = next;
            w *= phase_weight;
        } else if ground.is_some() {
            let normal = (x + dir * boundary).normalize();
            x = normal * ground_radius();
            dir = cosine_sample(normal, rng);
            w *= air.albedo;
        } else {
            break; // out through the top
        }
        if order >= 3 {
            let survive = w.max_element().min(1.0);
            if survive <= 0.0 || rng.next() >= survive {
                break;
            }
            w /= survive;
        }
    }
    radiance
}
