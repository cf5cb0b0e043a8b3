//! Tests of temporal upscaling (`upscale`) on synthetic frames: a flat wall seen by a still
//! camera, and an object moving over it. The traced samples are made from a known
//! high-resolution picture at the frame's jitter, so the expected history is known exactly.

use glam::{Affine3A, Vec3};

use super::*;
use crate::render::denoise::{NO_INSTANCE, SvgfParams};
use crate::render::jitter::frame_jitter;

/// A camera at the origin looking down −z, `width × height` pixels.
fn view(width: u32, height: u32) -> View {
    View {
        position: Vec3::ZERO,
        forward: Vec3::NEG_Z,
        right: Vec3::X,
        up: Vec3::Y * (height as f32 / width as f32),
        width,
        height,
        jitter: (0.5, 0.5),
    }
}

/// A wall (instance 0) at 10 m facing the camera, albedo 1, everywhere.
fn wall(width: u32, height: u32) -> Guides {
    let n = (width * height) as usize;
    Guides {
        width,
        height,
        normal: vec![Vec3::Z; n],
        depth: vec![10.0; n],
        albedo: vec![Vec3::ONE; n],
        instance: vec![0; n],
        emissive: vec![false; n],
        specular: vec![false; n],
    }
}

/// The traced frame of the high-resolution picture `truth(X, Y)` at frame `k`'s jitter: each
/// traced pixel's one sample is the value of the high-resolution pixel its offset falls in,
/// plus `noise(x, y)`.
fn trace(
    (tw, th): (u32, u32),
    f: u32,
    k: u64,
    truth: impl Fn(u32, u32) -> f32,
    mut noise: impl FnMut() -> f32,
) -> (Vec<Vec3>, (f32, f32)) {
    let j = frame_jitter(k);
    let (dx, dy) = ((j.0 * f as f32) as u32, (j.1 * f as f32) as u32);
    let mut mean = Vec::new();
    for y in 0..th {
        for x in 0..tw {
            mean.push(Vec3::splat(truth(x * f + dx, y * f + dy) + noise()));
        }
    }
    (mean, j)
}

/// A small deterministic generator, uniform in [−½, ½).
fn uniform(state: &mut u64) -> f32 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    ((*state >> 40) as f32 / (1u64 << 24) as f32) - 0.5
}

#[test]
fn still_camera_converges_to_the_high_resolution_picture() {
    let (tw, th, f) = (8u32, 6u32, 2u32);
    let (w, h) = (tw * f, th * f);
    // A one-pixel checkerboard at the high resolution: traced at 8×6 it averages to 1.25.
    let truth = |x: u32, y: u32| 1.0 + 0.5 * ((x + y) % 2) as f32;
    let guides = wall(w, h);
    let mut svgf = Svgf::new(SvgfParams::default());
    let mut state = 7u64;
    let frames = 64u64;
    let mut film = None;
    for k in 0..frames {
        let (mean, jitter) = trace((tw, th), f, k, truth, || uniform(&mut state));
        let traced = Traced {
            mean: &mean,
            width: tw,
            height: th,
            jitter,
        };
        let blend = 1.0 / (k + 1) as f32; // `Converge` for a still camera
        let (out, _) = svgf
            .denoise_upscaled(traced, &guides, blend, view(w, h), vec![Affine3A::IDENTITY])
            .expect("sizes fit");
        film = Some(out);
    }
    // Each high-resolution pixel got the samples of the frames whose jitter fell in it (12 to
    // 20 of 64), each with noise uniform in ±½ (σ ≈ 0.289): its mean's σ is at most 0.083,
    // the mean absolute error about 0.06 (a traced-size picture would be off by 0.25
    // everywhere).
    let history = svgf.history();
    let mut sum = 0.0;
    for y in 0..h {
        for x in 0..w {
            let p = history.illumination[(y * w + x) as usize];
            let landed = (0..frames)
                .filter(|&k| {
                    let j = frame_jitter(k);
                    (j.0 * 2.0) as u32 == x % 2 && (j.1 * 2.0) as u32 == y % 2
                })
                .count();
            // The length is capped at 1 / (blend · f²) = frames / 4 (`splat`'s floor): every
            // sample that landed, up to that cap, less a sample or two lost to earlier caps.
            let n = landed as f32;
            let low = n.min((frames / 4) as f32) - 2.0;
            assert!(
                p.w <= n && p.w >= low,
                "samples at ({x}, {y}): {} of {n}",
                p.w
            );
            let e = (p.x - truth(x, y)).abs();
            assert!(e < 0.4, "({x}, {y}): {} against {}", p.x, truth(x, y));
            sum += e;
        }
    }
    let mae = sum / (w * h) as f32;
    assert!(mae < 0.12, "mean absolute error of the history {mae}");
    let film = film.expect("frames ran");
    assert_eq!((film.width, film.height), (w, h));
    let film_mean = film.mean.iter().map(|c| c.x).sum::<f32>() / (w * h) as f32;
    assert!((film_mean - 1.25).abs() < 0.05, "film mean {film_mean}");
}

#[test]
fn a_moving_object_leaves_no_trail() {
    let (tw, th, f) = (16u32, 4u32, 2u32);
    let (w, h) = (tw * f, th * f);
    let object = 20.0;
    // The object covers 4 high-resolution columns from `left(k)`, moving 2 columns a frame.
    let left = |k: u64| 2 + 2 * k as u32;
    let mut svgf = Svgf::new(SvgfParams::default());
    for k in 0..10u64 {
        let on = |x: u32| (left(k)..left(k) + 4).contains(&x);
        let mut guides = wall(w, h);
        for y in 0..h {
            for x in (0..w).filter(|&x| on(x)) {
                let i = (y * w + x) as usize;
                guides.instance[i] = 1;
                guides.depth[i] = 5.0;
                guides.normal[i] = Vec3::new(0.6, 0.0, 0.8);
            }
        }
        let truth = |x: u32, _y: u32| if on(x) { object } else { 1.0 };
        let (mean, jitter) = trace((tw, th), f, k, truth, || 0.0);
        let traced = Traced {
            mean: &mean,
            width: tw,
            height: th,
            jitter,
        };
        // Moving objects: `Converge` floors the blend (an exact mean up to 5 samples).
        let blend = if k == 0 { 1.0 } else { 0.2 };
        // The object's instance carries its motion (two columns a frame, about 0.625 m at its
        // 5 m), as every moving instance does: the reprojection's edge rule tells its old
        // points from a still edge by it (`reproject_edge`).
        let transforms = vec![
            Affine3A::IDENTITY,
            Affine3A::from_translation(Vec3::X * 0.625 * k as f32),
        ];
        let (film, _) = svgf
            .denoise_upscaled(traced, &guides, blend, view(w, h), transforms)
            .expect("sizes fit");
        if k < 3 {
            continue;
        }
        // The wall is exactly 1 wherever it shows: in the history, once sampled, and on film.
        for (i, &id) in guides.instance.iter().enumerate() {
            let kept = svgf.history().illumination[i];
            if id == 0 && kept.w > 0.0 {
                assert!(
                    (kept.x - 1.0).abs() < 1e-3,
                    "frame {k}, pixel {i}: history {kept}"
                );
            }
            let shown = film.mean[i].x;
            if id == 0 {
                assert!(
                    shown < 1.1,
                    "frame {k}, pixel {i}: trail {shown} on the wall"
                );
            } else {
                assert!(shown > 0.5 * object, "frame {k}, pixel {i}: object {shown}");
            }
        }
        assert!(guides.instance.iter().all(|&id| id != NO_INSTANCE));
    }
}

#[test]
fn sizes_that_are_no_multiple_are_refused() {
    let mean = vec![Vec3::ONE; 6];
    let traced = Traced {
        mean: &mean,
        width: 3,
        height: 2,
        jitter: (0.5, 0.5),
    };
    let mut svgf = Svgf::default();
    let e = svgf
        .denoise_upscaled(traced, &wall(7, 4), 1.0, view(7, 4), vec![])
        .expect_err("7 is no multiple of 3");
    assert!(e.to_string().contains("3×2"), "{e}");
}

/// A surface that keeps no history (a specular first hit: glass, a mirror) is filled from this
/// frame's samples. One sample's outlier (glass whose one path saw a light strip) must not be
/// copied at full strength into the displayed pixels around it: in Reflect's chamber 1 it was,
/// into three to eight of them, most of TAAU's relative MSE. Fails with the nearest sample.
#[test]
fn one_outlying_sample_is_not_copied_into_its_neighbours() {
    let (tw, th, f) = (6u32, 4u32, 2u32);
    let (w, h) = (tw * f, th * f);
    let mut guides = wall(w, h);
    guides.specular = vec![true; (w * h) as usize];
    let mut mean = vec![Vec3::splat(0.05); (tw * th) as usize];
    mean[(2 * tw + 3) as usize] = Vec3::splat(8.0);
    let traced = Traced {
        mean: &mean,
        width: tw,
        height: th,
        jitter: frame_jitter(0),
    };
    let mut history = History::new(w, h);
    splat(&mut history, &traced, f, &guides.albedo, 1.0);
    let shown = filled(&history, &traced, f, &guides);
    let bright: Vec<usize> = (0..(w * h) as usize)
        .filter(|&i| shown.illumination[i].x > 4.0)
        .collect();
    assert_eq!(bright.len(), 1, "pixels above half the outlier: {bright:?}");
    // Every pixel has a value; the outlier's neighbours hold a share of it.
    assert!(
        shown
            .illumination
            .iter()
            .all(|p| p.w > 0.0 && p.x >= 0.05 - 1e-6)
    );
}
