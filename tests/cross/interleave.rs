//! Interleaved indirect light (`layout::METHOD_INDIRECT_HALF` / `METHOD_INDIRECT_QUARTER`,
//! `render/cpu/interleave.rs`): one pixel in two or four traces a path's first diffuse or
//! glossy bounce per sample, weighted ×2 or ×4. Checked:
//! * it is unbiased: on a scene lit by a sun and an emissive panel (every surface diffuse, so
//!   every path's first bounce is interleaved), region means of the full and the interleaved
//!   estimators, from independent seeds, agree within 4.5 σ on the CPU;
//! * it does what it is for: the bounce rays fall to about a quarter (a half) of the full
//!   estimator's, camera rays stay the same, and the direct light's shadow rays at the first
//!   hit stay;
//! * the GPU tracer agrees with the CPU one with the bit set (same paths, same weights).

use candela::layout::{METHOD_DEFAULT, METHOD_INDIRECT_HALF, METHOD_INDIRECT_QUARTER};
use candela::scene::RenderScene;
use candela_tests::{Which, open, render_batches_with, uniforms_with};

use crate::single_pick::{assert_same_mean, sun_and_panel};

const SIZE: u32 = 32;

#[test]
fn cpu_interleaved_indirect_converges_to_the_full_estimate() {
    let desc = sun_and_panel(2.0);
    // 16 samples per batch: a multiple of 4, so each batch holds every pixel's turns.
    let render = |method, seed| {
        render_batches_with(Which::Cpu, &desc, SIZE, SIZE, 16, 8, seed, method).expect("cpu render")
    };
    let full = render(METHOD_DEFAULT, 3);
    for (label, bit) in [
        ("one in two", METHOD_INDIRECT_HALF),
        ("one in four", METHOD_INDIRECT_QUARTER),
    ] {
        let interleaved = render(METHOD_DEFAULT | bit, 11);
        let _ = assert_same_mean(label, SIZE, &full, &interleaved);
    }
}

/// Camera, shadow and bounce rays of 8 samples per pixel of the scene with `method`.
fn ray_counts(method: u32) -> [u64; 3] {
    let desc = sun_and_panel(2.0);
    let scene = RenderScene::build(&desc);
    let mut tracer = open(Which::Cpu, &scene).expect("cpu tracer");
    let uniforms = uniforms_with(&desc, &scene, (SIZE, SIZE), 8, 5, method, 0);
    let stats = tracer.render(&scene, &uniforms).expect("cpu render");
    [
        stats.counts.camera,
        stats.counts.shadow,
        stats.counts.bounce,
    ]
}

#[test]
fn interleaving_traces_a_share_of_the_bounce_rays_and_keeps_the_rest() {
    let [camera, shadow, bounce] = ray_counts(METHOD_DEFAULT);
    assert!(
        bounce > camera / 2,
        "the scene must bounce: {bounce} of {camera}"
    );
    for (bit, share) in [(METHOD_INDIRECT_HALF, 0.5), (METHOD_INDIRECT_QUARTER, 0.25)] {
        let [c, s, b] = ray_counts(METHOD_DEFAULT | bit);
        assert_eq!(c, camera, "camera rays");
        let ratio = b as f64 / bounce as f64;
        assert!(
            (ratio - share).abs() < 0.1,
            "bounce rays {b} of {bounce} ({ratio:.3}), expected about {share}"
        );
        // Every first hit still samples its lights: at least that share of the shadow rays
        // (the first hit's) stays, and the rest follows the bounces.
        let kept = s as f64 / shadow as f64;
        assert!(
            kept > share && kept < 1.0,
            "shadow rays {s} of {shadow} ({kept:.3})"
        );
    }
}

/// The GPU tracer's interleaving (`shaders/shared/interleave.wgsl`) matches the CPU's.
#[test]
fn gpu_interleaved_indirect_matches_cpu() {
    let _ = crate::gpu_matches_cpu::compare_method(
        "sun and panel, one in four",
        &sun_and_panel(2.0),
        32,
        4,
        METHOD_DEFAULT | METHOD_INDIRECT_QUARTER,
    );
}
