//! [`CloudLayer`]: a 2D cloud layer under the physical sky — an optical-depth field τ(x, z) on
//! the plane y = `height_m`, held as a square texture of `texels`² values that repeats every
//! `size_m` metres and is carried by the wind — its checks, its texels ([`CloudLayer::bake`]),
//! where the wind has taken it at a time ([`CloudLayer::offset_m`], [`cloud_seconds`]) and the
//! one transmittance both tracers multiply the sun's (or moon's) disc by, whichever estimator
//! reached it ([`cloud_transmittance`]; WGSL twin `shaders/shared/clouds.wgsl`).
//!
//! Any thread; plain data and pure functions (the same time gives the same bits, so replays
//! repeat). Units: metres, seconds, engine space (right-handed, Y up); τ is dimensionless and
//! grey. At time t the field is read at (x, z) − wind · t. Must not: know levels, scenes or
//! tracers (the render side keeps the texels, `scene::SkyTable`, and fills the uniforms).

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use super::error::SkyError;
use super::physical::SkyTime;

/// The most texels per side of a cloud texture (1024² floats = 4 MiB).
pub const MAX_CLOUD_TEXELS: u32 = 1024;

/// What the optical depth looks like inside one tile.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum CloudShape {
    /// One Gaussian cloud, τ = `optical_depth` · exp(−r² / (2 `radius_m`²)), r the distance
    /// to `centre_m` (x, z metres inside the tile at time 0; the tile repeats, so the nearest
    /// copy counts).
    Gaussian {
        centre_m: [f32; 2],
        radius_m: f32,
        optical_depth: f32,
    },
    /// Fractal value noise (four octaves, `cells` cells across the tile at the coarsest),
    /// kept where it exceeds 1 − `coverage`: τ = `optical_depth` · clamp((n − (1 − coverage))
    /// / coverage, 0, 1), n in 0..1.
    Noise {
        coverage: f32,
        optical_depth: f32,
        #[serde(default = "default_cells")]
        cells: u32,
        #[serde(default)]
        seed: u32,
    },
}

fn default_cells() -> u32 {
    8
}

/// A cloud layer: a level's `clouds: Some((...))` inside `sky: Physical((...))`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CloudLayer {
    /// Height of the cloud plane (y), metres, 0 < h ≤ 100 000.
    pub height_m: f32,
    /// Wind velocity (x, z), metres per second, each within ±1000.
    #[serde(default)]
    pub wind_m_s: [f32; 2],
    /// Texels per side of the optical-depth texture, 1..=[`MAX_CLOUD_TEXELS`].
    pub texels: u32,
    /// Side of the square the texture covers (it repeats beyond), metres, 0 < s ≤ 10⁷.
    pub size_m: f32,
    pub shape: CloudShape,
}

fn check(field: &'static str, value: f64, ok: bool, range: &'static str) -> Result<(), SkyError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(SkyError::Parameter {
            field,
            value,
            range,
        })
    }
}

impl CloudLayer {
    /// Checks every field; the error names it (`clouds.texels`, `clouds.height_m`, …).
    pub fn validate(&self) -> Result<(), SkyError> {
        let h = self.height_m;
        check(
            "clouds.height_m",
            h.into(),
            h > 0.0 && h <= 1e5,
            "0 < h <= 100000",
        )?;
        for w in self.wind_m_s {
            check(
                "clouds.wind_m_s",
                w.into(),
                w.abs() <= 1000.0,
                "-1000..=1000",
            )?;
        }
        check(
            "clouds.texels",
            self.texels.into(),
            (1..=MAX_CLOUD_TEXELS).contains(&self.texels),
            "1..=1024",
        )?;
        let s = self.size_m;
        check(
            "clouds.size_m",
            s.into(),
            s > 0.0 && s <= 1e7,
            "0 < s <= 1e7",
        )?;
        match self.shape {
            CloudShape::Gaussian {
                centre_m,
                radius_m,
                optical_depth,
            } => {
                for c in centre_m {
                    check("clouds.shape.centre_m", c.into(), true, "finite")?;
                }
                check(
                    "clouds.shape.radius_m",
                    radius_m.into(),
                    radius_m > 0.0,
                    "> 0",
                )?;
                check_depth(optical_depth)
            }
            CloudShape::Noise {
                coverage,
                optical_depth,
                cells,
                ..
            } => {
                check(
                    "clouds.shape.coverage",
                    coverage.into(),
                    (0.0..=1.0).contains(&coverage),
                    "0..=1",
                )?;
                check(
                    "clouds.shape.cells",
                    cells.into(),
                    (1..=256).contains(&cells),
                    "1..=256",
                )?;
                check_depth(optical_depth)
            }
        }
    }

    /// The optical depth at each texel centre, row-major (row = z, column = x; texel (i, j)
    /// centred at ((i + ½), (j + ½)) · size / texels); empty when the layer fails its checks.
    pub fn bake(&self) -> Vec<f32> {
        if self.validate().is_err() {
            return Vec::new();
        }
        let n = self.texels as usize;
        let step = self.size_m / self.texels as f32;
        let mut out = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let p = Vec2::new((i as f32 + 0.5) * step, (j as f32 + 0.5) * step);
                out.push(self.depth_at(p, i as u32, j as u32));
            }
        }
        out
    }

    fn depth_at(&self, p: Vec2, i: u32, j: u32) -> f32 {
        match self.shape {
            CloudShape::Gaussian {
                centre_m,
                radius_m,
                optical_depth,
            } => {
                let s = self.size_m;
                let d = p - Vec2::from(centre_m);
                // The nearest copy of the centre in the repeating tile.
                let d = d - (d / s).round() * s;
                optical_depth * (-d.length_squared() / (2.0 * radius_m * radius_m)).exp()
            }
            CloudShape::Noise {
                coverage,
                optical_depth,
                cells,
                seed,
            } => {
                let n = self.texels as f32;
                let uv = Vec2::new((i as f32 + 0.5) / n, (j as f32 + 0.5) / n);
                let mut value = 0.0;
                let mut weight = 0.5;
                let mut total = 0.0;
                for octave in 0..4u32 {
                    let c = cells << octave;
                    value += weight * value_noise(uv * c as f32, c, seed.wrapping_add(octave));
                    total += weight;
                    weight *= 0.5;
                }
                let n = value / total;
                let keep = ((n - (1.0 - coverage)) / coverage.max(1e-3)).clamp(0.0, 1.0);
                optical_depth * keep
            }
        }
    }

    /// Where the wind has carried the texture's origin after `seconds`: wind · t, wrapped into
    /// the tile (0..size per axis), metres (x, z). Computed in f64 so that large times keep
    /// their precision.
    pub fn offset_m(&self, seconds: f64) -> Vec2 {
        let s = f64::from(self.size_m);
        let wrap = |w: f32| (f64::from(w) * seconds).rem_euclid(s) as f32;
        Vec2::new(wrap(self.wind_m_s[0]), wrap(self.wind_m_s[1]))
    }
}

fn check_depth(tau: f32) -> Result<(), SkyError> {
    check(
        "clouds.shape.optical_depth",
        tau.into(),
        (0.0..=100.0).contains(&tau),
        "0..=100",
    )
}

/// The clock the wind reads: seconds since 1970-01-01 00:00 UTC of the sky's time of day, or
/// 0 when the sky is placed by angles (the clouds then stand still).
pub fn cloud_seconds(time: Option<&SkyTime>) -> f64 {
    time.map_or(0.0, |t| {
        super::day::days_since_1970(t.year, t.month, t.day) as f64 * 86_400.0 + t.utc_hours * 3600.0
    })
}

/// Smooth value noise on a `period`-periodic lattice (PCG-hashed corners, smoothstep blend).
fn value_noise(p: Vec2, period: u32, seed: u32) -> f32 {
    let cell = p.floor();
    let f = p - cell;
    let f = f * f * (Vec2::splat(3.0) - 2.0 * f);
    let corner = |dx: u32, dz: u32| {
        let x = (cell.x as i64 + dx as i64).rem_euclid(period as i64) as u32;
        let z = (cell.y as i64 + dz as i64).rem_euclid(period as i64) as u32;
        let h = hash(x ^ hash(z ^ hash(seed)));
        (h >> 8) as f32 / 16_777_216.0
    };
    let a = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * f.x;
    let b = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * f.x;
    a + (b - a) * f.y
}

fn hash(v: u32) -> u32 {
    let state = v.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

/// The cloud plane as the tracers read it (twin of the uniforms' `cloud_plane`, `cloud_texels`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CloudPlane {
    /// Height of the plane, render-space y, metres.
    pub height: f32,
    /// Where the texture's origin sits now (render-space x, z, metres).
    pub offset: Vec2,
    /// Side of the tile, metres (≤ 0: no clouds).
    pub size: f32,
    /// Texels per side.
    pub texels: u32,
}

/// T_cloud(p, ω) = exp(−τ) at the point where the ray from `p` along unit `w` crosses the
/// plane, going up; 1 for rays that do not cross it (level or downwards, or starting above
/// it), for no clouds, and when `tau` does not hold `texels`² values. τ is read bilinearly
/// between texel centres, repeating. The same arithmetic as `shaders/shared/clouds.wgsl`.
pub fn cloud_transmittance(plane: &CloudPlane, tau: &[f32], p: Vec3, w: Vec3) -> f32 {
    let n = plane.texels as usize;
    if plane.size <= 0.0 || n == 0 || tau.len() != n * n || w.y <= 0.0 || p.y >= plane.height {
        return 1.0;
    }
    let t = (plane.height - p.y) / w.y;
    let x = p.x + w.x * t - plane.offset.x;
    let z = p.z + w.z * t - plane.offset.y;
    let scale = n as f32 / plane.size;
    let fx = x * scale - 0.5;
    let fz = z * scale - 0.5;
    let (cx, cz) = (fx.floor(), fz.floor());
    let (tx, tz) = (fx - cx, fz - cz);
    let wrap = |c: f32| (c as i64).rem_euclid(n as i64) as usize;
    let (x0, z0) = (wrap(cx), wrap(cz));
    let (x1, z1) = ((x0 + 1) % n, (z0 + 1) % n);
    let at = |i: usize, j: usize| tau[j * n + i];
    let row0 = at(x0, z0) + (at(x1, z0) - at(x0, z0)) * tx;
    let row1 = at(x0, z1) + (at(x1, z1) - at(x0, z1)) * tx;
    (-(row0 + (row1 - row0) * tz)).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blob() -> CloudLayer {
        CloudLayer {
            height_m: 1000.0,
            wind_m_s: [5.0, -3.0],
            texels: 64,
            size_m: 6400.0,
            shape: CloudShape::Gaussian {
                centre_m: [3200.0, 3200.0],
                radius_m: 400.0,
                optical_depth: 2.0,
            },
        }
    }

    #[test]
    fn texel_centres_hold_the_shape_and_the_lookup_reads_them() {
        let layer = blob();
        let tau = layer.bake();
        assert_eq!(tau.len(), 64 * 64);
        let plane = CloudPlane {
            height: 1000.0,
            offset: Vec2::ZERO,
            size: 6400.0,
            texels: 64,
        };
        // Straight up under texel (31, 31)'s centre, (3150, 3150): r² = 2 · 50².
        let p = Vec3::new(3150.0, 0.0, 3150.0);
        let expected = (-2.0 * (-(2.0 * 50.0f32 * 50.0) / (2.0 * 400.0 * 400.0)).exp()).exp();
        let t = cloud_transmittance(&plane, &tau, p, Vec3::Y);
        assert!((t - expected).abs() < 1e-5, "{t} vs {expected}");
        assert_eq!(cloud_transmittance(&plane, &tau, p, -Vec3::Y), 1.0);
        assert_eq!(cloud_transmittance(&plane, &tau[1..], p, Vec3::Y), 1.0);
    }

    #[test]
    fn noise_covers_about_its_share() {
        let layer = CloudLayer {
            shape: CloudShape::Noise {
                coverage: 0.5,
                optical_depth: 1.0,
                cells: 8,
                seed: 3,
            },
            ..blob()
        };
        let tau = layer.bake();
        let covered = tau.iter().filter(|&&t| t > 0.0).count() as f32 / tau.len() as f32;
        assert!((0.2..0.8).contains(&covered), "{covered}");
        assert!(tau.iter().all(|t| (0.0..=1.0).contains(t)));
    }
}
