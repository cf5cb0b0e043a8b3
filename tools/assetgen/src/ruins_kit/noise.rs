//! Deterministic noise for the ruins kit: an integer hash, tiling 2D value noise and fbm (for
//! textures and the sand terrain) and 3D value noise (for chipping stone meshes).
//!
//! Every function is a pure function of its arguments built from integer hashing, `floor`,
//! multiplications and additions (no transcendental functions), so the output is the same on
//! every machine and run. Must not: hold state or depend on any random-number crate.

/// A hash of three integers and a seed to `0..1`.
pub fn hash3(x: i64, y: i64, z: i64, seed: u64) -> f32 {
    let mut h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (z as u64).wrapping_mul(0x1656_67B1_9E37_79F9)
        ^ seed.wrapping_mul(0xD6E8_FEB8_6659_FD93);
    h ^= h >> 31;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 29;
    h = h.wrapping_mul(0x94D0_49BB_1331_11EB);
    h ^= h >> 32;
    (h >> 40) as f32 / (1u64 << 24) as f32
}

fn smooth(t: f32) -> f32 {
    t * t * (3.0 - 2.0 * t)
}

/// Value noise in `0..1` at `(x, y)` (in cells), repeating every `period` cells on both axes
/// (`period` ≥ 1), so an image sampled over exactly `period` cells tiles seamlessly.
pub fn value2(x: f32, y: f32, period: i64, seed: u64) -> f32 {
    value2xy(x, y, period, period, seed)
}

/// [`value2`] repeating every `px` cells along x and `py` cells along y.
pub fn value2xy(x: f32, y: f32, px: i64, py: i64, seed: u64) -> f32 {
    let (fx, fy) = (x.floor(), y.floor());
    let (ix, iy) = (fx as i64, fy as i64);
    let (tx, ty) = (smooth(x - fx), smooth(y - fy));
    let (px, py) = (px.max(1), py.max(1));
    let corner =
        |dx: i64, dy: i64| hash3((ix + dx).rem_euclid(px), (iy + dy).rem_euclid(py), 0, seed);
    let top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * tx;
    let bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * tx;
    top + (bottom - top) * ty
}

/// Fractal sum of `octaves` octaves of [`value2`] in `0..1`: `(u, v)` in tiles (one tile =
/// the repeat), `cells` cells per tile at the first octave, each octave twice as many cells
/// and `gain` times the amplitude. Tiles with period 1 in `u` and `v`.
pub fn fbm2(u: f32, v: f32, cells: i64, octaves: u32, gain: f32, seed: u64) -> f32 {
    let (mut sum, mut amp, mut norm) = (0.0, 1.0, 0.0);
    let mut n = cells;
    for o in 0..octaves {
        sum += amp * value2(u * n as f32, v * n as f32, n, seed + u64::from(o) * 101);
        norm += amp;
        amp *= gain;
        n *= 2;
    }
    sum / norm
}

/// Value noise in `0..1` at `p` (in cells), not tiling: for displacing mesh vertices.
pub fn value3(p: [f32; 3], seed: u64) -> f32 {
    let f = p.map(f32::floor);
    let i = f.map(|c| c as i64);
    let t = [
        smooth(p[0] - f[0]),
        smooth(p[1] - f[1]),
        smooth(p[2] - f[2]),
    ];
    let c = |dx: i64, dy: i64, dz: i64| hash3(i[0] + dx, i[1] + dy, i[2] + dz, seed);
    let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
    let x00 = lerp(c(0, 0, 0), c(1, 0, 0), t[0]);
    let x10 = lerp(c(0, 1, 0), c(1, 1, 0), t[0]);
    let x01 = lerp(c(0, 0, 1), c(1, 0, 1), t[0]);
    let x11 = lerp(c(0, 1, 1), c(1, 1, 1), t[0]);
    lerp(lerp(x00, x10, t[1]), lerp(x01, x11, t[1]), t[2])
}

/// Two octaves of [`value3`] with cells of `cell` metres, in `0..1`.
pub fn fbm3(p: [f32; 3], cell: f32, seed: u64) -> f32 {
    let q = p.map(|c| c / cell);
    let a = value3(q, seed);
    let b = value3(q.map(|c| c * 2.03 + 17.0), seed + 7);
    (a * 0.65 + b * 0.35).clamp(0.0, 1.0)
}

/// `0` below `a`, `1` above `b`, smooth between.
pub fn smoothstep(a: f32, b: f32, x: f32) -> f32 {
    smooth(((x - a) / (b - a)).clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value2_tiles_and_stays_in_range() {
        for k in 0..50 {
            let (x, y) = (k as f32 * 0.37, k as f32 * 0.71);
            let a = value2(x, y, 8, 3);
            assert!((0.0..=1.0).contains(&a));
            assert!((a - value2(x + 8.0, y, 8, 3)).abs() < 1e-5);
            assert!((a - value2(x, y + 8.0, 8, 3)).abs() < 1e-5);
        }
    }
}
