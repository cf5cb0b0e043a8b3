//! Tests of the CPU compose's scales and reuse (`cpu_compose.rs`): non-integer scales, tiny
//! films and windows, bad values, and one [`HostCompose`] reused across size changes, each
//! against a plain per-pixel Catmull-Rom reference tonemapped exactly (`linear_to_srgb8`).

use glam::Vec3;

use super::*;
use crate::render::film::linear_to_srgb8;

/// A film with ramps over [−0.2, 2.2], a repeating pattern (so neighbours differ), a NaN, an
/// infinite and a negative pixel where the film is large enough.
fn film(w: u32, h: u32) -> Film {
    let mut film = Film::new(w, h);
    let n = film.mean.len() as f32;
    for (i, p) in film.mean.iter_mut().enumerate() {
        let t = i as f32 / n;
        *p = Vec3::new(t * 2.4 - 0.2, (1.0 - t) * 1.3, (i % 5) as f32 * 0.2);
    }
    for (k, bad) in [
        Vec3::new(f32::NAN, 0.5, 0.5),
        Vec3::new(f32::INFINITY, -1.0, 0.25),
        Vec3::new(f32::NEG_INFINITY, f32::NAN, 3.0),
    ]
    .into_iter()
    .enumerate()
    {
        let at = (k * 7 + 3) % film.mean.len();
        if film.mean.len() > 8 {
            film.mean[at] = bad;
        }
    }
    film
}

/// The window pixel `(x, y)` of `film` upscaled to `size`, computed on its own: the film
/// pixel centres the shader maps, taps clamped to the film, across then down (the compose's
/// order of sums), tonemapped exactly.
fn reference(film: &Film, size: (u32, u32), x: u32, y: u32, tonemap: &TonemapSettings) -> [u8; 3] {
    let tap = |i: u32, from: u32, to: u32| {
        let f = (i as f32 + 0.5) * (from as f32 / to as f32) - 0.5;
        let base = f.floor();
        let taps = [-1.0, 0.0, 1.0, 2.0].map(|d| (base + d).clamp(0.0, from as f32 - 1.0) as u32);
        (taps, catmull_rom(f - base))
    };
    let (tx, wx) = tap(x, film.width, size.0);
    let (ty, wy) = tap(y, film.height, size.1);
    let texel = |x: u32, y: u32| {
        let c = film.mean[(y * film.width + x) as usize];
        let c = Vec3::from_array(c.to_array().map(|v| if v.is_nan() { 0.0 } else { v }));
        c.clamp(Vec3::splat(-1e30), Vec3::splat(1e30))
    };
    let row = |y: u32| {
        texel(tx[0], y) * wx[0]
            + texel(tx[1], y) * wx[1]
            + texel(tx[2], y) * wx[2]
            + texel(tx[3], y) * wx[3]
    };
    let c = row(ty[0]) * wy[0] + row(ty[1]) * wy[1] + row(ty[2]) * wy[2] + row(ty[3]) * wy[3];
    linear_to_srgb8(c, tonemap)
}

/// Largest difference of any channel between `bytes` (RGBA) and the reference, and whether
/// every alpha is 255.
fn worst(film: &Film, size: (u32, u32), bytes: &[u8], tonemap: &TonemapSettings) -> (u8, bool) {
    assert_eq!(bytes.len(), (size.0 * size.1 * 4) as usize);
    let (mut worst, mut opaque) = (0u8, true);
    for y in 0..size.1 {
        for x in 0..size.0 {
            let i = ((y * size.0 + x) * 4) as usize;
            let want = reference(film, size, x, y, tonemap);
            for k in 0..3 {
                worst = worst.max(bytes[i + k].abs_diff(want[k]));
            }
            opaque &= bytes[i + 3] == 255;
        }
    }
    (worst, opaque)
}

#[test]
fn non_integer_scales_tiny_films_and_bad_values_match_a_per_pixel_reference() {
    let cases = [
        ((321, 180), (1280, 720)),
        ((320, 180), (1280, 720)),
        ((1, 1), (7, 5)),
        ((2, 1), (3, 4)),
        ((33, 17), (1, 1)),
        ((40, 23), (97, 61)),
        ((64, 32), (64, 32)),
        ((97, 61), (40, 23)),
    ];
    let mut kept = HostCompose::default();
    for filmic in [false, true] {
        let tonemap = TonemapSettings {
            exposure_ev: 0.7,
            filmic,
        };
        for (film_size, size) in cases {
            let film = film(film_size.0, film_size.1);
            let fresh = compose_host_film(&film, size, &tonemap, false);
            let (d, opaque) = worst(&film, size, &fresh, &tonemap);
            assert!(
                d <= 1 && opaque,
                "{film_size:?} → {size:?} filmic {filmic}: off by {d}"
            );
            // The same compose reused across every size change gives the same bytes.
            assert_eq!(kept.compose(&film, size, &tonemap, false), &fresh[..]);
        }
    }
}

#[test]
fn a_one_pixel_film_fills_the_window_with_its_colour() {
    let mut one = Film::new(1, 1);
    one.mean[0] = Vec3::new(0.18, 0.5, 2.0);
    let tonemap = TonemapSettings::default();
    let want = linear_to_srgb8(one.mean[0], &tonemap);
    let bgra = compose_host_film(&one, (13, 9), &tonemap, true);
    for px in bgra.chunks_exact(4) {
        for k in 0..3 {
            assert!(px[2 - k].abs_diff(want[k]) <= 1, "{px:?} vs {want:?}");
        }
        assert_eq!(px[3], 255);
    }
    // An empty film, or one whose pixels are missing, is black.
    let mut short = Film::new(4, 4);
    short.mean.truncate(3);
    for empty in [Film::new(0, 0), short] {
        let out = compose_host_film(&empty, (5, 3), &tonemap, false);
        assert!(out.chunks_exact(4).all(|p| p == [0, 0, 0, 255]));
    }
}
