//! Furnace tests: scenes whose exact answer is known, rendered by both tracers.
//!
//! * A closed diffuse sphere of albedo 1 inside a closed emitter of uniform radiance Le (the
//!   emitter is black, so light bounces off the inner sphere once and is absorbed): every pixel,
//!   on the sphere or not, must be Le. Exercises emissive-triangle NEE (1,280 lights), BSDF
//!   sampling and their MIS weights.
//! * The inside of a closed sphere of albedo a emitting Le: the radiance field is uniform,
//!   L = Le (1 − a^(B+1)) / (1 − a) with B scattering events. Checked twice:
//!   - the bounce cap: a = 0.8, B = 4, roulette off (it starts after the cap), so the answer
//!     for B = 4 differs from B = 3 or 5 by ~0.33, far beyond the noise; the test asserts that
//!     its tolerance does tell B from B ± 1 (with a = 0.5 and B = 12 the cap changes L by
//!     2.4e-4, below the roulette noise, so a wrong cap passed);
//!   - long paths with roulette: a = 0.5, B = 12, roulette from the 4th event, which must
//!     leave the mean unbiased.
//! * An albedo-1 sphere under a constant sky: no light sampling; exact, zero-variance answer.
//!
//! Tolerances: 4.5 standard errors of the image mean, the standard error estimated from the
//! spread of independent batches (see `candela_tests`), plus 1e-5 relative for f32 rounding
//! in the zero-variance case. A false failure at 4.5σ has probability ~7e-6 per check.

use candela::assets::{Material, MaterialKind, Model, SceneDesc, SceneInstance, SkyDesc};
use candela_tests::{Which, camera, icosphere, render_batches, single_mesh_model};
use glam::{Mat4, Vec3};

fn diffuse(albedo: f32, emission: f32) -> Material {
    Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        emission: Vec3::splat(emission),
        ..Material::default()
    }
}

fn scene(models: Vec<Model>) -> SceneDesc {
    let mut desc = SceneDesc::single(
        models[0].clone(),
        camera(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, 40.0),
    );
    desc.models = models;
    desc.instances = (0..desc.models.len())
        .map(|model| SceneInstance::placed(model, Mat4::IDENTITY))
        .collect();
    desc
}

/// Checks the image mean against `expected`; returns the largest tolerance used.
fn check(which: Which, desc: &SceneDesc, expected: f64, spp: u32, batches: u32) -> f64 {
    let b = render_batches(which, desc, 32, 32, spp, batches, 7).expect("render");
    let stat = b.region(|_, _| true);
    let mut largest = 0.0f64;
    for c in 0..3 {
        let tolerance = 4.5 * stat.std_error[c] + 1e-5 * expected;
        let error = (stat.mean[c] - expected).abs();
        assert!(
            error <= tolerance,
            "{which:?}: channel {c}: mean {} vs expected {expected} (|error| {error:.3e} > {tolerance:.3e}, σ {:.3e})",
            stat.mean[c],
            stat.std_error[c]
        );
        largest = largest.max(tolerance);
    }
    largest
}

fn albedo_one_sphere_in_uniform_light(which: Which) {
    let emitter = single_mesh_model(icosphere(Vec3::ZERO, 10.0, 3, true), diffuse(0.0, 1.5));
    let sphere = single_mesh_model(icosphere(Vec3::ZERO, 1.0, 3, false), diffuse(1.0, 0.0));
    check(which, &scene(vec![emitter, sphere]), 1.5, 4, 8);
}

/// Uniform radiance inside a closed emitting sphere of albedo `a` with `bounces` scattering
/// events (emission 1).
fn uniform_field(a: f64, bounces: i32) -> f64 {
    (1.0 - a.powi(bounces + 1)) / (1.0 - a)
}

fn inside_emitting_sphere(which: Which) {
    // The bounce cap, without roulette (it would start after the last event).
    let room = single_mesh_model(icosphere(Vec3::ZERO, 10.0, 2, true), diffuse(0.8, 1.0));
    let mut desc = scene(vec![room]);
    desc.render.max_bounces = 4;
    desc.render.roulette_start = 5;
    let expected = uniform_field(0.8, 4);
    let tolerance = check(which, &desc, expected, 4, 8);
    for other in [3, 5] {
        let gap = (uniform_field(0.8, other) - expected).abs();
        assert!(
            gap > 2.0 * tolerance,
            "{which:?}: the check cannot tell {other} bounces from 4 ({gap:.3e} vs tolerance {tolerance:.3e})"
        );
    }
    // Long paths under roulette: unbiased.
    let room = single_mesh_model(icosphere(Vec3::ZERO, 10.0, 2, true), diffuse(0.5, 1.0));
    let mut desc = scene(vec![room]);
    desc.render.max_bounces = 12;
    desc.render.roulette_start = 4;
    check(which, &desc, uniform_field(0.5, 12), 4, 8);
}

fn sphere_under_constant_sky(which: Which) {
    let sphere = single_mesh_model(icosphere(Vec3::ZERO, 1.0, 3, false), diffuse(1.0, 0.0));
    let mut desc = scene(vec![sphere]);
    desc.sky = SkyDesc::Constant([0.7, 0.7, 0.7]);
    check(which, &desc, 0.7, 2, 4);
}

#[test]
fn cpu_albedo_one_sphere_in_uniform_light() {
    albedo_one_sphere_in_uniform_light(Which::Cpu);
}

#[test]
fn gpu_albedo_one_sphere_in_uniform_light() {
    albedo_one_sphere_in_uniform_light(Which::Gpu);
}

#[test]
fn cpu_inside_emitting_sphere() {
    inside_emitting_sphere(Which::Cpu);
}

#[test]
fn gpu_inside_emitting_sphere() {
    inside_emitting_sphere(Which::Gpu);
}

#[test]
fn cpu_sphere_under_constant_sky() {
    sphere_under_constant_sky(Which::Cpu);
}

#[test]
fn gpu_sphere_under_constant_sky() {
    sphere_under_constant_sky(Which::Gpu);
}
