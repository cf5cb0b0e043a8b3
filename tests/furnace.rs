//! Furnace tests: scenes whose exact answer is known, rendered by both tracers.
//!
//! * A closed diffuse sphere of albedo 1 inside a closed emitter of uniform radiance Le (the
//!   emitter is black, so light bounces off the inner sphere once and is absorbed): every pixel,
//!   on the sphere or not, must be Le. Exercises emissive-triangle NEE (1,280 lights), BSDF
//!   sampling and their MIS weights.
//! * The inside of a closed sphere of albedo a = 0.5 emitting Le: the radiance field is uniform,
//!   L = Le (1 − a^(B+1)) / (1 − a) with B scattering events. Exercises roulette and long paths.
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

fn check(which: Which, desc: &SceneDesc, expected: f64, spp: u32, batches: u32) {
    let b = render_batches(which, desc, 32, 32, spp, batches, 7).expect("render");
    let stat = b.region(|_, _| true);
    for c in 0..3 {
        let tolerance = 4.5 * stat.std_error[c] + 1e-5 * expected;
        let error = (stat.mean[c] - expected).abs();
        assert!(
            error <= tolerance,
            "{which:?}: channel {c}: mean {} vs expected {expected} (|error| {error:.3e} > {tolerance:.3e}, σ {:.3e})",
            stat.mean[c],
            stat.std_error[c]
        );
    }
}

fn albedo_one_sphere_in_uniform_light(which: Which) {
    let emitter = single_mesh_model(icosphere(Vec3::ZERO, 10.0, 3, true), diffuse(0.0, 1.5));
    let sphere = single_mesh_model(icosphere(Vec3::ZERO, 1.0, 3, false), diffuse(1.0, 0.0));
    check(which, &scene(vec![emitter, sphere]), 1.5, 4, 8);
}

fn inside_emitting_sphere(which: Which) {
    let room = single_mesh_model(icosphere(Vec3::ZERO, 10.0, 2, true), diffuse(0.5, 1.0));
    let mut desc = scene(vec![room]);
    desc.render.max_bounces = 12;
    let expected = (1.0 - 0.5f64.powi(13)) / 0.5;
    check(which, &desc, expected, 4, 8);
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
