//! Test-only reference: the single-scatter directional albedo of GGX microfacet lobes by
//! deterministic quadrature, written independently of the code under test (its own f64 GGX
//! distribution, height-correlated Smith masking, Schlick and dielectric Fresnel, reflection
//! and refraction; no call into `microfacet.rs` or `bsdf.rs`).
//!
//! Used as a lower bound on the albedo of the path tracer's rough models by
//! `bsdf_tests.rs` (per direction) and by `tests/cross/stability.rs` (the furnace sphere, through
//! `candela_tests::reference_albedo`). Local shading frame, normal +z, isotropic, so an albedo
//! depends only on `cos_o` = cos θ of the viewing direction; α is GGX α (roughness²).
//!
//! `horizon` (≥ 0) is the sine of the largest angle between the shading and the geometric
//! normal of a mesh: scattered directions within that angle of the shading horizon may fall
//! below the geometric surface and be lost, so the bound counts only directions with
//! |cos θi| > `horizon` (0 for a flat surface).
//!
//! Quadrature: over microfacet normals, with cos θm's GGX distribution function as the variable
//! (tan²θm = α² ξ / (1 − ξ), so `D(m) cos θm dω = dξ dφ / 2π`: the nodes follow the lobe at any
//! α) and the midpoint rule in ξ and φ. The result is given at two resolutions; twice their
//! difference is the stated error (the visibility and horizon cut-offs make the rule
//! first-order, so halving the step halves the error). The rule can also miss mass: grazing
//! normals beyond its last node are not sampled, which only lowers a result (a bound stays a
//! bound). `bsdf_tests.rs` checks both on the normalisation of visible normals for α ≥ 0.04
//! and cos θ ≥ 0.15, the range the bounds are used at: never above 1 by more than the
//! estimate (it does lose up to 1.1 % there, which only lowers a bound).
//! Must not: use the engine's scattering code (it is what this checks).

use glam::DVec3;

/// Smith Λ for a direction of cosine `z` (only |z| matters).
fn lambda(z: f64, alpha: f64) -> f64 {
    let z2 = z * z;
    if z2 <= 0.0 {
        return f64::INFINITY;
    }
    0.5 * ((1.0 + alpha * alpha * (1.0 - z2) / z2).sqrt() - 1.0)
}

/// Height-correlated Smith masking-shadowing of a pair of directions (cosines `zo`, `zi`).
fn g2(zo: f64, zi: f64, alpha: f64) -> f64 {
    1.0 / (1.0 + lambda(zo, alpha) + lambda(zi, alpha))
}

/// Schlick's Fresnel for one channel.
pub fn schlick(f0: f64, cos: f64) -> f64 {
    f0 + (1.0 - f0) * (1.0 - cos.clamp(0.0, 1.0)).powi(5)
}

/// Unpolarised dielectric Fresnel; `eta` = η transmitted / η incident. (F, cos θt).
fn fresnel(cos_i: f64, eta: f64) -> (f64, f64) {
    let sin2_t = (1.0 - cos_i * cos_i).max(0.0) / (eta * eta);
    if sin2_t >= 1.0 {
        return (1.0, 0.0);
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    (0.5 * (rs * rs + rp * rp), cos_t)
}

/// ∫ f(m) (wo·m) / wo.z D(m) dωm over visible normals (wo·m > 0), computed as
/// ∫ f(m) (wo·m) / (wo.z m.z) · D(m) cos θm dωm: for `f` = Fresnel × G2 of the scattered
/// direction, the single-scatter albedo (`dωi = 4 (wo·m) dωm` for reflection, the BSDF's
/// `D G2 / (4 wo.z)` per unit `dωi`). `f` gets the normal.
fn visible_normals(alpha: f64, wo: DVec3, steps: usize, f: &dyn Fn(DVec3) -> f64) -> f64 {
    let (n_xi, n_phi) = (steps, steps / 2);
    let mut sum = 0.0;
    for i in 0..n_xi {
        let xi = (i as f64 + 0.5) / n_xi as f64;
        let tan2 = alpha * alpha * xi / (1.0 - xi);
        let cos_m = 1.0 / (1.0 + tan2).sqrt();
        let sin_m = (1.0 - cos_m * cos_m).max(0.0).sqrt();
        for j in 0..n_phi {
            let phi = std::f64::consts::TAU * (j as f64 + 0.5) / n_phi as f64;
            let m = DVec3::new(sin_m * phi.cos(), sin_m * phi.sin(), cos_m);
            let wo_m = wo.dot(m);
            if wo_m > 0.0 {
                sum += f(m) * wo_m / (wo.z * cos_m);
            }
        }
    }
    sum / (n_xi * n_phi) as f64
}

/// The quadrature at two resolutions: (fine value, 2 × |fine − coarse| as its error).
fn refined(alpha: f64, wo: DVec3, f: &dyn Fn(DVec3) -> f64) -> (f64, f64) {
    let coarse = visible_normals(alpha, wo, 384, f);
    let fine = visible_normals(alpha, wo, 768, f);
    (fine, 2.0 * (fine - coarse).abs())
}

fn direction(cos_o: f64) -> DVec3 {
    DVec3::new((1.0 - cos_o * cos_o).max(0.0).sqrt(), 0.0, cos_o)
}

fn reflect(w: DVec3, m: DVec3) -> DVec3 {
    2.0 * w.dot(m) * m - w
}

/// ∫ G1(wo) (wo·m) D(m) / wo.z dωm over visible normals: 1 for an exact quadrature (the
/// distribution of visible normals is normalised). (value, error).
pub fn visible_normal_total(alpha: f64, cos_o: f64) -> (f64, f64) {
    let wo = direction(cos_o);
    let g1 = 1.0 / (1.0 + lambda(cos_o, alpha));
    refined(alpha, wo, &|_| g1)
}

/// Single-scatter albedo of a GGX conductor with Schlick Fresnel of reflectance `f0` at
/// normal incidence, for `cos_o > 0`. (albedo, quadrature error).
pub fn conductor(f0: f64, alpha: f64, horizon: f64, cos_o: f64) -> (f64, f64) {
    let wo = direction(cos_o);
    refined(alpha, wo, &|m| {
        let wi = reflect(wo, m);
        if wi.z <= horizon {
            return 0.0;
        }
        schlick(f0, wo.dot(m)) * g2(wo.z, wi.z, alpha)
    })
}

/// The two single-scatter parts of a GGX dielectric of relative index `ior` (inside over
/// outside), seen from outside (`cos_o > 0`) or inside (`cos_o < 0`), in energy (no η²
/// factors): (reflected, refracted × `weight`(|cos θt|), quadrature error). `weight` lets a
/// caller follow the refracted light (1 for the plain refracted share).
pub fn dielectric_parts(
    ior: f64,
    alpha: f64,
    horizon: f64,
    cos_o: f64,
    weight: &dyn Fn(f64) -> f64,
) -> (f64, f64, f64) {
    let eta = if cos_o > 0.0 { ior } else { 1.0 / ior };
    // The viewing side as +z.
    let wo = direction(cos_o.abs());
    let reflected = |m: DVec3| {
        let (f, _) = fresnel(wo.dot(m), eta);
        let r = reflect(wo, m);
        if r.z > horizon {
            f * g2(wo.z, r.z, alpha)
        } else {
            0.0
        }
    };
    let refracted = |m: DVec3| {
        let cos_i = wo.dot(m);
        let (f, cos_t) = fresnel(cos_i, eta);
        if f >= 1.0 {
            return 0.0;
        }
        let t = (-wo / eta + m * (cos_i / eta - cos_t)).normalize();
        if t.z < -horizon {
            (1.0 - f) * g2(wo.z, t.z, alpha) * weight(-t.z)
        } else {
            0.0
        }
    };
    let (r, r_error) = refined(alpha, wo, &reflected);
    let (t, t_error) = refined(alpha, wo, &refracted);
    (r, t, r_error + t_error)
}

/// Single-scatter albedo of a GGX dielectric as a path's throughput carries it: reflection
/// plus refraction × `tint`, where radiance crossing into the denser side is scaled by 1/η²
/// and, crossing out of it, the η² gain is taken out (energy). (albedo, quadrature error).
pub fn dielectric(ior: f64, alpha: f64, tint: f64, cos_o: f64) -> (f64, f64) {
    let crossing = if cos_o > 0.0 { 1.0 / (ior * ior) } else { 1.0 };
    let (r, t, error) = dielectric_parts(ior, alpha, 0.0, cos_o, &|_| 1.0);
    (r + t * tint * crossing, error)
}

/// ∫ (1 − Schlick(f0, μ)) 2μ dμ over [`horizon`, 1]: the cosine-weighted share that passes
/// a Schlick coat, by the midpoint rule with 20,000 nodes (error below 1e-8).
pub fn coat_transmittance(f0: f64, horizon: f64) -> f64 {
    let n = 20_000;
    let width = 1.0 - horizon;
    (0..n)
        .map(|i| {
            let mu = horizon + width * (i as f64 + 0.5) / n as f64;
            (1.0 - schlick(f0, mu)) * 2.0 * mu
        })
        .sum::<f64>()
        * width
        / n as f64
}

/// Single-scatter albedo of the glTF metallic-roughness model for one channel (`cos_o > 0`):
/// the GGX lobe with Schlick Fresnel of `f0` = lerp(((ior − 1)/(ior + 1))², base, metallic),
/// plus Lambert diffuse of `base` × (1 − metallic)(1 − transmission) under the coat on both
/// ways. The transmission lobe is left out (the result is a lower bound for transmissive
/// surfaces). `alpha` is the model's clamped α. (albedo, quadrature error).
pub fn metal_rough(
    base: f64,
    metallic: f64,
    transmission: f64,
    ior: f64,
    alpha: f64,
    horizon: f64,
    cos_o: f64,
) -> (f64, f64) {
    let f0_dielectric = ((ior - 1.0) / (ior + 1.0)).powi(2);
    let f0 = f0_dielectric + (base - f0_dielectric) * metallic;
    let (spec, error) = conductor(f0, alpha, horizon, cos_o);
    let diffuse = base
        * (1.0 - metallic)
        * (1.0 - transmission)
        * (1.0 - schlick(f0, cos_o))
        * coat_transmittance(f0, horizon);
    (spec + diffuse, error)
}
