//! Multiple scattering by iterated orders (Bruneton & Neyret 2008's scheme, solved on a
//! discrete-ordinates grid): the in-scattering that second and higher orders add, per unit
//! scattering coefficient, as a table over altitude, the local sun elevation and the view's
//! direction in the local frame (elevation, azimuth from the sun), and the sky's irradiance on
//! the ground. It replaces Hillaire's Ψms (isotropic phase, a geometric series, the ground lit
//! by the sun alone), which left the sky 3.5–19 % (median) too dark against brute force
//! (`docs/ACCURACY.md`, "Brute force against the tables").
//!
//! Each order n ≥ 1 is a radiance field L⁽ⁿ⁾ at the grid's nodes, marched along each node's
//! ray: order 1 is the sun's single scattering (and the sunlit ground), order n ≥ 2 the
//! scattering density of order n − 1 (σ_R·S_R + σ_A·S_A, read back from the table at each
//! point) plus the ground lit by order n − 1's sky (Lambertian, the level's albedo). The next
//! scattering's phase integrals S = ∫ p(ω_o·ω_i) L(ω_i) dω_i are one matrix product per node
//! (the phases averaged over each direction cell, rows normalised to 1 so no energy is made or
//! lost). Orders are added until one adds less than [`CONVERGED`] of the sum; the rest of the
//! series is added as a geometric tail at the last two orders' ratio.
//!
//! Any thread; built once per atmosphere (the sun enters only through the local sun
//! elevation), its nodes on the rayon pool, and kept in a small cache of the latest
//! atmospheres ([`ScatteringOrders::shared`]). Kilometres, as in `atmosphere`; radiance per
//! unit solar irradiance. Local frame: z up, the sun in the x–z plane. Must not: know about the
//! view table's layout or the engine.

use std::sync::{Arc, Mutex};

use glam::Vec3;
use rayon::prelude::*;

use super::atmosphere::{
    Atmosphere, GROUND_RADIUS_KM, Medium, TOP_RADIUS_KM, march_pieces, ray_sphere, rayleigh_phase,
    shadow_edges,
};
use super::orders_grid::*;
use super::transmittance::TransmittanceLut;

use std::f32::consts::PI;

/// Steps along each node's ray (quadratic spacing; the single-scattering order, which reads
/// no table, takes more, cut at the planet shadow's edge).
const STEPS: usize = 32;
const SUN_STEPS: usize = 96;
/// Sub-samples per direction cell side for the cell-averaged phase functions.
const SUB: usize = 4;
/// Scattering orders: the sum stops when an order adds less than this share of it (or at the
/// last), and the rest of the series is added as a geometric tail.
pub const CONVERGED: f32 = 0.02;
const MAX_ORDER: usize = 8;
/// The phase integrals of orders ≥ 2 per node and the sky's irradiance on the ground.
pub struct ScatteringOrders {
    /// S_R, S_A per (altitude, sun, direction) node: in-scattering per unit Rayleigh and
    /// aerosol scattering coefficient, sr⁻¹-weighted radiance per unit solar irradiance.
    rayleigh: Vec<Vec3>,
    aerosol: Vec<Vec3>,
    /// The sky's irradiance (orders ≥ 1, the sun's direct light excluded) on the ground per
    /// sun node, per unit solar irradiance.
    ground: Vec<Vec3>,
    /// How many orders were summed (the highest order n of S⁽ⁿ⁾).
    orders: usize,
}

/// Where one order's light comes from when its radiance field is marched.
enum Source<'a> {
    /// The sun (single scattering; the ground lit by the sun).
    Sun,
    /// The previous order's phase integrals and its sky's irradiance on the ground.
    Field(&'a ScatteringOrders),
}

struct Context<'a> {
    atmosphere: &'a Atmosphere,
    transmittance: &'a TransmittanceLut,
}

impl ScatteringOrders {
    /// The table for `atmosphere`, from a cache of the latest four atmospheres (built on a miss:
    /// about 4 s on two loaded cores, `docs/PERFORMANCE.md`).
    pub fn shared(atmosphere: &Atmosphere, transmittance: &TransmittanceLut) -> Arc<Self> {
        static CACHE: Mutex<Vec<(Atmosphere, Arc<ScatteringOrders>)>> = Mutex::new(Vec::new());
        if let Ok(cache) = CACHE.lock()
            && let Some((_, t)) = cache.iter().find(|(a, _)| a == atmosphere)
        {
            return t.clone();
        }
        let table = Arc::new(Self::build(atmosphere, transmittance, MAX_ORDER));
        if let Ok(mut cache) = CACHE.lock() {
            if cache.len() >= 4 {
                cache.remove(0);
            }
            cache.push((*atmosphere, table.clone()));
        }
        table
    }

    /// Iterates the orders 2..=`max_order` (fewer when converged).
    pub fn build(
        atmosphere: &Atmosphere,
        transmittance: &TransmittanceLut,
        max_order: usize,
    ) -> Self {
        let cx = Context {
            atmosphere,
            transmittance,
        };
        // One pair of phase matrices per altitude node (the cells follow the local horizon).
        let phases: Vec<(Vec<f32>, Vec<f32>)> = (0..ALTITUDES)
            .map(|k| {
                let e_h = horizon(radius(k));
                (
                    phase_matrix(&rayleigh_phase, e_h),
                    phase_matrix(&|c| atmosphere.aerosol.phase(c), e_h),
                )
            })
            .collect();
        let mut total = Self::zeros();
        let mut radiance = transport(&cx, &Source::Sun);
        let mut previous_sum = Vec3::ZERO;
        for order in 2..=max_order {
            let next = scatter(&radiance, &phases);
            let added = next.sum();
            total.add(&next, Vec3::ONE);
            total.orders = order;
            let share = (added / total.sum().max(Vec3::splat(1e-30))).max_element();
            if order == max_order || share <= CONVERGED {
                // The rest of the series, geometric at the last two orders' ratio per channel
                // (by then each order has the shape of the one before).
                if order > 2 {
                    let q = (added / previous_sum.max(Vec3::splat(1e-30))).min(Vec3::splat(0.9));
                    total.add(&next, q / (Vec3::ONE - q));
                }
                break;
            }
            previous_sum = added;
            radiance = transport(&cx, &Source::Field(&next));
        }
        total
    }

    /// Adds `other` × `weight` (per channel).
    fn add(&mut self, other: &Self, weight: Vec3) {
        for (t, n) in self.rayleigh.iter_mut().zip(&other.rayleigh) {
            *t += *n * weight;
        }
        for (t, n) in self.aerosol.iter_mut().zip(&other.aerosol) {
            *t += *n * weight;
        }
        for (t, n) in self.ground.iter_mut().zip(&other.ground) {
            *t += *n * weight;
        }
    }

    /// The phase integrals summed over every node, per channel (a measure of an order's size).
    fn sum(&self) -> Vec3 {
        self.rayleigh.iter().chain(&self.aerosol).copied().sum()
    }

    fn zeros() -> Self {
        Self {
            rayleigh: vec![Vec3::ZERO; ALTITUDES * SUNS * DIRECTIONS],
            aerosol: vec![Vec3::ZERO; ALTITUDES * SUNS * DIRECTIONS],
            ground: vec![Vec3::ZERO; SUNS],
            orders: 1,
        }
    }

    /// The highest scattering order summed.
    #[cfg(test)]
    pub fn orders(&self) -> usize {
        self.orders
    }

    /// Radiance per unit solar irradiance per km that orders ≥ 2 scatter at radius `r` (km),
    /// media `m`, towards a viewer looking along a direction of zenith cosine `mu` whose
    /// scattering-angle cosine with the sun (zenith cosine `mu_s`) is `nu`.
    pub fn source(&self, r: f32, mu_s: f32, mu: f32, nu: f32, m: &Medium) -> Vec3 {
        let (sr, sa) = self.lookup(r, mu_s, mu, local_azimuth(nu, mu, mu_s));
        m.rayleigh * sr + m.mie * sa
    }

    /// The sky's irradiance on the ground (per unit solar irradiance) where the sun's zenith
    /// cosine is `mu_s`.
    pub fn ground_irradiance(&self, mu_s: f32) -> Vec3 {
        let (j0, j1, t) = sun_position(mu_s);
        sun_blend(self.ground[j0], self.ground[j1], t)
    }

    /// (S_R, S_A) interpolated over the four coordinates.
    fn lookup(&self, r: f32, mu_s: f32, mu: f32, azimuth: f32) -> (Vec3, Vec3) {
        let h = ((r - GROUND_RADIUS_KM) / (TOP_RADIUS_KM - GROUND_RADIUS_KM)).clamp(0.0, 1.0);
        let k = position(h.sqrt() * (ALTITUDES - 1) as f32, ALTITUDES);
        let j = sun_position(mu_s);
        let e = mu.clamp(-1.0, 1.0).asin();
        // The elevation's cell coordinate about each altitude node's own horizon.
        let m_at = |k: usize| {
            let c = cell_c(e, horizon(radius(k)));
            position((c + 1.0) * 0.5 * ELEVATIONS as f32 - 0.5, ELEVATIONS)
        };
        let n = position(azimuth / PI * AZIMUTHS as f32 - 0.5, AZIMUTHS);
        // Trilinear over altitude and direction at each of the two sun nodes, then between them.
        let mut at_sun = [(Vec3::ZERO, Vec3::ZERO); 2];
        for (ki, kw) in [(k.0, 1.0 - k.2), (k.1, k.2)] {
            let m = m_at(ki);
            for (s, ji) in [j.0, j.1].into_iter().enumerate() {
                let base = (ki * SUNS + ji) * DIRECTIONS;
                for (mi, mw) in [(m.0, 1.0 - m.2), (m.1, m.2)] {
                    for (ni, nw) in [(n.0, 1.0 - n.2), (n.1, n.2)] {
                        let w = kw * mw * nw;
                        let i = base + mi * AZIMUTHS + ni;
                        at_sun[s].0 += self.rayleigh[i] * w;
                        at_sun[s].1 += self.aerosol[i] * w;
                    }
                }
            }
        }
        (
            sun_blend(at_sun[0].0, at_sun[1].0, j.2),
            sun_blend(at_sun[0].1, at_sun[1].1, j.2),
        )
    }
}

fn sun_position(mu_s: f32) -> (usize, usize, f32) {
    let c0 = sun_c0();
    let c = angle_to_c(mu_s.clamp(-1.0, 1.0).asin());
    position((c - c0) / (1.0 - c0) * (SUNS - 1) as f32, SUNS)
}

/// Cell-averaged phase matrix: entry [o][i] = ∫ p(ω_o·ω) dω over direction cell i and its
/// mirror image (azimuth −a), ω_o cell o's centre, the cells about a horizon at `e_h`; rows
/// normalised to sum to 1.
fn phase_matrix(phase: &(dyn Fn(f32) -> f32 + Sync), e_h: f32) -> Vec<f32> {
    (0..DIRECTIONS)
        .into_par_iter()
        .flat_map_iter(|o| {
            let (eo, _, _) = elevation_cell(o / AZIMUTHS, e_h);
            let wo = direction(eo, azimuth_cell(o % AZIMUTHS));
            let mut row: Vec<f32> = (0..DIRECTIONS)
                .map(|i| {
                    let (_, z0, z1) = elevation_cell(i / AZIMUTHS, e_h);
                    let a0 = PI * (i % AZIMUTHS) as f32 / AZIMUTHS as f32;
                    let (dz, da) = ((z1 - z0) / SUB as f32, PI / (AZIMUTHS * SUB) as f32);
                    let mut sum = 0.0;
                    for s in 0..SUB {
                        let z: f32 = z0 + (s as f32 + 0.5) * dz;
                        let e = z.clamp(-1.0, 1.0).asin();
                        for t in 0..SUB {
                            let a = a0 + (t as f32 + 0.5) * da;
                            let w = direction(e, a);
                            let mirror = Vec3::new(w.x, -w.y, w.z);
                            sum += phase(wo.dot(w)) + phase(wo.dot(mirror));
                        }
                    }
                    sum * dz * da
                })
                .collect();
            let total: f32 = row.iter().sum();
            for v in &mut row {
                *v /= total.max(1e-12);
            }
            row
        })
        .collect()
}

/// The next order's phase integrals from radiance field `radiance` (per node), and the ground's
/// irradiance from that field's sky (the ground nodes, cells above the horizon).
fn scatter(radiance: &[Vec3], phases: &[(Vec<f32>, Vec<f32>)]) -> ScatteringOrders {
    let nodes: Vec<(Vec<Vec3>, Vec<Vec3>)> = radiance
        .par_chunks(DIRECTIONS)
        .enumerate()
        .map(|(node, field)| {
            let (phase_r, phase_a) = &phases[node / SUNS];
            let apply = |matrix: &[f32]| -> Vec<Vec3> {
                matrix
                    .chunks(DIRECTIONS)
                    .map(|row| row.iter().zip(field).map(|(p, l)| *l * *p).sum())
                    .collect()
            };
            (apply(phase_r), apply(phase_a))
        })
        .collect();
    let mut out = ScatteringOrders::zeros();
    for (i, (r, a)) in nodes.into_iter().enumerate() {
        out.rayleigh[i * DIRECTIONS..(i + 1) * DIRECTIONS].copy_from_slice(&r);
        out.aerosol[i * DIRECTIONS..(i + 1) * DIRECTIONS].copy_from_slice(&a);
    }
    // Irradiance on the ground: the altitude-0 nodes, Σ L cos θ dω over the upper cells (×2:
    // the mirror half of the azimuths).
    for j in 0..SUNS {
        let field = &radiance[j * DIRECTIONS..(j + 1) * DIRECTIONS];
        let mut e = Vec3::ZERO;
        for m in ELEVATIONS / 2..ELEVATIONS {
            let (_, z0, z1) = elevation_cell(m, 0.0);
            let cell = 0.5 * (z1 * z1 - z0 * z0) * (PI / AZIMUTHS as f32) * 2.0;
            for n in 0..AZIMUTHS {
                e += field[m * AZIMUTHS + n] * cell;
            }
        }
        out.ground[j] = e;
    }
    out
}

/// One order's radiance field at every node and direction cell centre.
fn transport(cx: &Context, source: &Source) -> Vec<Vec3> {
    (0..ALTITUDES * SUNS)
        .into_par_iter()
        .flat_map_iter(|node| {
            let (k, j) = (node / SUNS, node % SUNS);
            (0..DIRECTIONS).map(move |d| {
                let (e, _, _) = elevation_cell(d / AZIMUTHS, horizon(radius(k)));
                let dir = direction(e, azimuth_cell(d % AZIMUTHS));
                march(cx, source, radius(k), sun_elevation(j), dir)
            })
        })
        .collect()
}

/// Radiance per unit solar irradiance arriving at radius `r` looking along `dir` (local frame)
/// from `source`'s light, for a sun at `sun_elevation` radians.
fn march(cx: &Context, source: &Source, r: f32, sun_elevation: f32, dir: Vec3) -> Vec3 {
    let sun = direction(sun_elevation, 0.0);
    let origin = Vec3::new(0.0, 0.0, r);
    // A ray that meets the ground: decided in f64 (at the ground node the near root is 0 and
    // f32 rounding may miss it, sending the ray through the planet).
    let (r64, mu64) = (r as f64, dir.z as f64);
    let meets = mu64 < 0.0 && r64 * r64 * (1.0 - mu64 * mu64) <= (GROUND_RADIUS_KM as f64).powi(2);
    let ground = meets.then(|| ray_sphere(r, dir.z, GROUND_RADIUS_KM, true).unwrap_or(0.0));
    let length = ground
        .or(ray_sphere(r, dir.z, TOP_RADIUS_KM, false))
        .unwrap_or(0.0);
    let nu = dir.dot(sun);
    let a = cx.atmosphere;
    let (phase_r, phase_m) = (rayleigh_phase(nu), a.aerosol.phase(nu));
    let (mut radiance, mut throughput) = (Vec3::ZERO, Vec3::ONE);
    let (steps, edges) = match source {
        Source::Sun => (SUN_STEPS, shadow_edges(origin, dir, sun, length)),
        Source::Field(_) => (STEPS, Vec::new()),
    };
    for (t, dt) in march_pieces(length, steps, &edges) {
        let p = origin + dir * t;
        let rp = p.length();
        let (mu_s, mu) = (p.dot(sun) / rp, p.dot(dir) / rp);
        let m = a.medium(rp - GROUND_RADIUS_KM);
        let light = match source {
            Source::Sun => {
                cx.transmittance.lookup(rp, mu_s) * (m.rayleigh * phase_r + m.mie * phase_m)
            }
            Source::Field(f) => f.source(rp, mu_s, mu, nu, &m),
        };
        let step = (-m.extinction * dt).exp();
        radiance += throughput * (light - light * step) / m.extinction.max(Vec3::splat(1e-9));
        throughput *= step;
    }
    if let Some(t) = ground {
        let normal = (origin + dir * t).normalize();
        let mu_s = normal.dot(sun);
        let irradiance = match source {
            Source::Sun => cx.transmittance.lookup(GROUND_RADIUS_KM, mu_s) * mu_s.max(0.0),
            Source::Field(f) => f.ground_irradiance(mu_s),
        };
        radiance += throughput * irradiance * a.ground_albedo / PI;
    }
    radiance
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sky::Aerosol;

    #[test]
    fn direction_cells_tile_the_sphere() {
        let mut solid = 0.0;
        let e_h = horizon(TOP_RADIUS_KM);
        for m in 0..ELEVATIONS {
            let (e, z0, z1) = elevation_cell(m, e_h);
            assert!(z0 < e.sin() && e.sin() < z1, "cell {m}'s centre inside it");
            solid += (z1 - z0) * PI * 2.0;
        }
        assert!((solid - 4.0 * PI).abs() < 1e-4, "{solid}");
        // The Rayleigh phase integrates to 1 over the cells before normalising.
        assert!(cell_c(e_h, e_h).abs() < 1e-6);
        assert!((cell_elevation(cell_c(0.3, e_h), e_h) - 0.3).abs() < 1e-5);
        let isotropic = phase_matrix(&|_| 1.0 / (4.0 * PI), e_h);
        let row: f32 = isotropic[..DIRECTIONS].iter().sum();
        assert!((row - 1.0).abs() < 1e-5, "{row}");
    }

    #[test]
    fn orders_add_light_and_converge() {
        let atmosphere = Atmosphere {
            haze: 1.0,
            ozone: 1.0,
            ground_albedo: Vec3::splat(0.3),
            aerosol: Aerosol::EARTH,
        };
        let transmittance = TransmittanceLut::build(&atmosphere);
        let two = ScatteringOrders::build(&atmosphere, &transmittance, 2);
        let all = ScatteringOrders::build(&atmosphere, &transmittance, MAX_ORDER);
        assert!(
            all.orders() > 2 && all.orders() < MAX_ORDER,
            "{}",
            all.orders()
        );
        let r = GROUND_RADIUS_KM + 0.01;
        let (s2, _) = two.lookup(r, 0.5, 0.3, 1.0);
        let (s, _) = all.lookup(r, 0.5, 0.3, 1.0);
        // Higher orders add light, blue most, and less than the second order itself.
        let ratio = s / s2;
        assert!(
            ratio.min_element() > 1.0 && ratio.max_element() < 2.0,
            "{ratio}"
        );
        assert!(ratio.z > ratio.x, "{ratio}");
        // The sky's irradiance on the ground under a high sun: a tenth to a third of the sun's.
        let e = all.ground_irradiance(1.0);
        let sun = transmittance.lookup(GROUND_RADIUS_KM, 1.0);
        let share = e / sun;
        assert!(
            share.min_element() > 0.02 && share.max_element() < 0.4,
            "{share}"
        );
    }
}
