//! The night sky that escaping rays see, CPU side (twin: `shaders/shared/night.wgsl`): the lit
//! part of a disc (the moon's phase), the second disc (the fainter of sun and moon), the
//! star field, the airglow and the moonlit sky (the moon's sky-view table), all read from the frame uniforms (`scene/discs.rs` fills them).
//!
//! Any thread; pure functions in f32 (the same operations in the same order as the WGSL, so
//! both tracers find the same stars). Directions are unit vectors in engine space; radiance
//! in the sky's linear RGB units. Must not: sample or trace (the integrator does).
//!
//! Stars are hashed on a cube around the celestial sphere (`STAR_CELLS`² cells per face): a
//! cell holds at most one star, placed inside its middle 60 % so its disc
//! (`star_sin_radius`) never crosses the cell's edge, with magnitude m = 6.5 + log10(ξ)/0.48
//! (N(< m) ∝ 10^(0.48 m)), clamped at −1.5. Stars and airglow are dimmed by the air mass
//! X(μ) = 1 / (μ + 0.025 e^(−11 μ)) (Rozenberg 1966) of the zenith transmittance; the airglow
//! brightens towards the horizon as a layer at 90 km (van Rhijn).

use glam::Vec3;

use std::f32::consts::{LOG2_10, LOG10_2};

use crate::layout::{GpuFrameUniforms, STAR_CELLS, STAR_THRESHOLD};
use crate::sky::moon_view_radiance;

/// (Earth radius / (Earth radius + 90 km))², the van Rhijn factor's constant.
const VAN_RHIJN_K: f32 = 0.972_32;

/// Whether direction `d`, already inside the disc of centre `centre` (unit), falls on its lit
/// part: the visible hemisphere's normal there faces `terminator` (zero: always lit).
pub fn disc_lit(d: Vec3, centre: Vec3, sin_radius: f32, terminator: Vec3) -> bool {
    if terminator == Vec3::ZERO || sin_radius <= 0.0 {
        return true;
    }
    let p = (d - centre * d.dot(centre)) / sin_radius;
    let q = p.length_squared().min(1.0);
    let normal = p - centre * (1.0 - q).sqrt();
    normal.dot(terminator) >= 0.0
}

/// Whether unit direction `d` falls inside the disc of unit centre `centre` and sine of
/// radius `sin_radius`: |d × centre| ≤ sin r on the near side. The cross product keeps f32
/// precision for tiny discs, where d · centre near 1 has a few hundred levels across the disc.
pub fn disc_inside(d: Vec3, centre: Vec3, sin_radius: f32) -> bool {
    d.dot(centre) > 0.0 && d.cross(centre).length_squared() <= sin_radius * sin_radius
}

/// Radiance of the second disc towards `d` (zero outside it or on its dark part).
pub fn second_disc(u: &GpuFrameUniforms, d: Vec3) -> Vec3 {
    let centre = Vec3::from(u.second_direction);
    if u.second_sin_radius <= 0.0 || !disc_inside(d, centre, u.second_sin_radius) {
        return Vec3::ZERO;
    }
    if !disc_lit(
        d,
        centre,
        u.second_sin_radius,
        Vec3::from(u.second_terminator),
    ) {
        return Vec3::ZERO;
    }
    Vec3::from(u.second_radiance)
}

/// PCG hash (O'Neill; the `pcg_hash` of Jarzynski & Olano 2020).
pub fn pcg(v: u32) -> u32 {
    let state = v.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

fn unit(h: u32) -> f32 {
    (h >> 8) as f32 / 16_777_216.0
}

/// The star of the cell that celestial direction `c` (unit) falls in: its direction and
/// magnitude, if the cell holds one.
pub fn cell_star(c: Vec3) -> Option<(Vec3, f32)> {
    let a = c.abs();
    let (face, uu, vv, major) = if a.x >= a.y && a.x >= a.z {
        (u32::from(c.x < 0.0), c.y / a.x, c.z / a.x, a.x)
    } else if a.y >= a.z {
        (2 + u32::from(c.y < 0.0), c.x / a.y, c.z / a.y, a.y)
    } else {
        (4 + u32::from(c.z < 0.0), c.x / a.z, c.y / a.z, a.z)
    };
    if major <= 0.0 {
        return None;
    }
    let n = STAR_CELLS as f32;
    let i = (((uu + 1.0) * 0.5 * n) as u32).min(STAR_CELLS - 1);
    let j = (((vv + 1.0) * 0.5 * n) as u32).min(STAR_CELLS - 1);
    let h0 = pcg((face * STAR_CELLS + j) * STAR_CELLS + i);
    if h0 >= STAR_THRESHOLD {
        return None;
    }
    let h1 = pcg(h0);
    let h2 = pcg(h1);
    let h3 = pcg(h2);
    let su = (i as f32 + 0.2 + 0.6 * unit(h1)) / n * 2.0 - 1.0;
    let sv = (j as f32 + 0.2 + 0.6 * unit(h2)) / n * 2.0 - 1.0;
    let sign = if face % 2 == 1 { -1.0 } else { 1.0 };
    let s = match face / 2 {
        0 => Vec3::new(sign, su, sv),
        1 => Vec3::new(su, sign, sv),
        _ => Vec3::new(su, sv, sign),
    };
    let magnitude = (6.5 + unit(h3).max(1e-7).log2() * LOG10_2 / 0.48).max(-1.5);
    Some((s.normalize(), magnitude))
}

/// Direction `d` (engine space) in the celestial frame of the uniforms.
pub fn to_celestial(u: &GpuFrameUniforms, d: Vec3) -> Vec3 {
    Vec3::new(
        d.dot(Vec3::from_slice(&u.celestial_x[..3])),
        d.dot(Vec3::from_slice(&u.celestial_y[..3])),
        d.dot(Vec3::from_slice(&u.celestial_z[..3])),
    )
}

/// The air's transmittance towards `d` (upper hemisphere): the zenith's to the air mass.
fn extinction(u: &GpuFrameUniforms, mu: f32) -> Vec3 {
    let air_mass = 1.0 / (mu + 0.025 * (-11.0 * mu).exp());
    Vec3::from(u.zenith_transmittance).powf(air_mass)
}

/// Stars and airglow towards `d` (zero below the horizon), after the air's extinction.
pub fn star_field(u: &GpuFrameUniforms, d: Vec3) -> Vec3 {
    if d.y <= 0.0 || (u.star_radiance <= 0.0 && u.airglow == [0.0; 3]) {
        return Vec3::ZERO;
    }
    let van_rhijn = 1.0 / (1.0 - VAN_RHIJN_K * (1.0 - d.y * d.y)).sqrt();
    let mut light = Vec3::from(u.airglow) * van_rhijn;
    if u.star_radiance > 0.0 {
        let c = to_celestial(u, d);
        if let Some((s, magnitude)) = cell_star(c)
            && c.dot(s) > 0.0
            && c.cross(s).length_squared() <= u.star_sin_radius * u.star_sin_radius
        {
            light += Vec3::splat(u.star_radiance * (-0.4 * magnitude * LOG2_10).exp2());
        }
    }
    light * extinction(u, d.y)
}

/// Everything of the night an escaping ray adds to the sun's sky table: the second disc, stars,
/// airglow and the moonlit sky (the moon's table in `sky_table`, `sky::moon_view_radiance`;
/// nothing by day).
pub fn night_radiance(u: &GpuFrameUniforms, sky_table: &[[f32; 4]], d: Vec3) -> Vec3 {
    second_disc(u, d) + star_field(u, d) + moon_view_radiance(sky_table, u.moon_sky, d)
}
