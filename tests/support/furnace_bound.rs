//! The lower bound of the stability furnace (`tests/cross/stability.rs`): a smooth-shaded unit
//! icosphere of one rough material under a constant white sky of radiance 1, seen by the
//! furnace camera. Light that scatters once off a convex surface escapes to the sky, so a
//! pixel is at least the single-scatter albedo of the lobe it sees (rough conductor,
//! metal-rough); for rough glass, at least reflection plus the light refracted in and out
//! again (two refractions through the sphere: at the exit the incidence equals the entry's
//! refracted angle, by the chord's symmetry). All from `reference_albedo` (quadrature, not the
//! code under test).
//!
//! Conservative for the mesh: `spread` is the largest angle between a shading (vertex) normal
//! and its face normal; directions within it of the horizon are not counted, and each pixel's
//! bound is the smallest over its footprint's viewing angles widened by `spread` (2 × at the
//! exit of the glass). Bounds are tabulated on 64 cosines; a range takes the smallest node in it
//! and its two neighbours. Only pixels whose whole footprint sees the sphere at cos θ ≥ 0.2 are
//! bounded (towards the silhouette the facets' deviation grows).
//! Must not: render (the caller compares its render with these numbers).

use crate::reference_albedo as reference;
use candela::assets::{Material, MaterialKind, Mesh};
use glam::{DVec3, Vec3};

/// Largest angle (radians) between a vertex normal and the face normal of its triangle.
pub fn normal_spread(mesh: &Mesh) -> f64 {
    let normals = mesh.normals.as_ref().expect("smooth normals");
    let mut spread = 0.0f64;
    for t in &mesh.triangles {
        let p = t.map(|i| mesh.positions[i as usize].as_dvec3());
        let face = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
        for &i in t {
            let n = normals[i as usize].as_dvec3().normalize();
            spread = spread.max(n.dot(face).abs().min(1.0).acos());
        }
    }
    spread
}

/// A bound tabulated over the viewing cosine.
struct Table {
    nodes: Vec<(f64, f64)>,
}

const NODES: usize = 64;

impl Table {
    fn new(lo: f64, f: impl Fn(f64) -> f64) -> Self {
        let nodes = (0..NODES)
            .map(|k| {
                let mu = lo + (1.0 - lo) * k as f64 / (NODES - 1) as f64;
                (mu, f(mu))
            })
            .collect();
        Self { nodes }
    }

    /// Smallest value over the angles [θ(hi), θ(lo)] widened by `widen` radians.
    fn min_over(&self, mu_lo: f64, mu_hi: f64, widen: f64) -> f64 {
        let lo = (mu_lo.clamp(-1.0, 1.0).acos() + widen)
            .min(std::f64::consts::FRAC_PI_2)
            .cos();
        let hi = (mu_hi.clamp(-1.0, 1.0).acos() - widen).max(0.0).cos();
        let first = self.nodes.iter().rposition(|n| n.0 <= lo).unwrap_or(0);
        let last = self
            .nodes
            .iter()
            .position(|n| n.0 >= hi)
            .unwrap_or(self.nodes.len() - 1);
        self.nodes[first..=last]
            .iter()
            .map(|n| n.1)
            .fold(f64::INFINITY, f64::min)
    }
}

/// The albedo bound of `material` as a function of the viewing cosine (≥ 0.15).
fn table(material: &Material, spread: f64) -> Table {
    let horizon = spread.sin();
    let alpha = f64::from(material.roughness * material.roughness);
    let base = f64::from(material.base_color.min_element());
    let ior = f64::from(material.ior);
    match material.kind {
        MaterialKind::Conductor => {
            Table::new(0.15, |mu| reference::conductor(base, alpha, horizon, mu).0)
        }
        MaterialKind::Dielectric => {
            // Inside, light reaching the far side at cosine ν leaves with T(ν) of its energy.
            let out = Table::new(0.0, |nu| {
                reference::dielectric_parts(ior, alpha, horizon, -nu.max(1e-3), &|_| 1.0).1
            });
            let leaves = |nu: f64| base * out.min_over(nu, nu, 2.0 * spread);
            Table::new(0.15, |mu| {
                let (r, t, _) = reference::dielectric_parts(ior, alpha, horizon, mu, &leaves);
                r + base * t
            })
        }
        MaterialKind::MetalRough => Table::new(0.15, |mu| {
            reference::metal_rough(
                base,
                f64::from(material.metallic),
                f64::from(material.transmission),
                ior,
                alpha.max(2e-3),
                horizon,
                mu,
            )
            .0
        }),
        MaterialKind::Diffuse => Table::new(0.15, |_| base * (1.0 - horizon * horizon)),
    }
}

/// Per-pixel lower bounds (row-major, `None` for unbounded pixels) of a `size` × `size` render
/// of the unit sphere of `material` from `camera_z` on the +z axis looking at the origin with
/// vertical field of view `fov_deg`.
pub fn pixel_bounds(
    material: &Material,
    mesh: &Mesh,
    size: u32,
    camera_z: f64,
    fov_deg: f64,
) -> Vec<Option<f64>> {
    let spread = normal_spread(mesh);
    let table = table(material, spread);
    let tan_half = (fov_deg.to_radians() * 0.5).tan();
    let origin = DVec3::new(0.0, 0.0, camera_z);
    // The cosine between the view and the sphere normal at the hit, or None on a miss.
    let cosine = |sx: f64, sy: f64| -> Option<f64> {
        let d = DVec3::new(sx * tan_half, sy * tan_half, -1.0).normalize();
        let b = origin.dot(d);
        let disc = b * b - (origin.length_squared() - 1.0);
        (disc > 0.0).then(|| {
            let p = origin + d * (-b - disc.sqrt());
            -d.dot(p.normalize())
        })
    };
    let steps = 6;
    (0..size * size)
        .map(|i| {
            let (px, py) = (f64::from(i % size), f64::from(i / size));
            let (mut lo, mut hi) = (1.0f64, -1.0f64);
            for a in 0..=steps {
                for b in 0..=steps {
                    let fx = px + a as f64 / steps as f64;
                    let fy = py + b as f64 / steps as f64;
                    let c = cosine(
                        2.0 * fx / f64::from(size) - 1.0,
                        1.0 - 2.0 * fy / f64::from(size),
                    )?;
                    lo = lo.min(c);
                    hi = hi.max(c);
                }
            }
            // The sphere's centre inside the footprint: the footprint reaches cos θ = 1.
            let centre = f64::from(size) / 2.0;
            if (px..=px + 1.0).contains(&centre) && (py..=py + 1.0).contains(&centre) {
                hi = 1.0;
            }
            (lo >= 0.2).then(|| table.min_over(lo, hi, spread))
        })
        .collect()
}

/// The material's base colour is grey (the bound uses its smallest channel).
pub fn is_grey(material: &Material) -> bool {
    material.base_color == Vec3::splat(material.base_color.x)
}
