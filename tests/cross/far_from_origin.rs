//! Stability suite, large coordinates: the Cornell box reference scene moved 1e3, 1e4 and 1e5 m
//! from the world origin (instances and camera alike, along a direction with all three axes)
//! renders the same as at the origin, within noise, on both tracers. This holds because the
//! render side works camera-relative (`candela::accel::origin`); the test also shows that it is
//! needed: rendered in world space as it is (origin 0), the box 1e5 m out differs visibly.
//!
//! Comparison: a 4 × 4 grid of regions plus the whole image, per channel, each render split into
//! independent batches (their spread gives each region mean's standard error, see
//! `candela_tests`); the two renders use different seeds, so their difference has standard error
//! √(σ₀² + σ₁²) and |difference| ≤ 4.5 of those is a false alarm about once in 150,000
//! comparisons. The camera itself moves by up to 4 mm when its world position is rounded to f32
//! at 1e5 m (the game's own precision, not the renderer's): at 64 px across a 2 m box that is
//! a twentieth of a pixel, far below the noise of these regions.

use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::scene::RenderScene;
use candela_tests::{Batches, Which, external, repo};
use glam::{Mat4, Vec3};

const SIZE: u32 = 48;
const SPP: u32 = 16;
const BATCHES: u32 = 6;

fn cornell() -> SceneDesc {
    let level = repo().join("assets/test_scenes/reference/cornell_box.ron");
    let root = AssetRoot::new(external().join("reference/cornell_box")).expect("asset root");
    load_scene(&level, &root).expect("level loads")
}

/// `desc` moved by `offset` metres (instances and camera).
fn moved(mut desc: SceneDesc, offset: Vec3) -> SceneDesc {
    for instance in &mut desc.instances {
        instance.world_from_model = Mat4::from_translation(offset) * instance.world_from_model;
    }
    desc.camera.position = (Vec3::from(desc.camera.position) + offset).into();
    desc.camera.look_at = (Vec3::from(desc.camera.look_at) + offset).into();
    desc
}

/// Renders `desc` with render space's origin at `origin` (`None`: the engine's choice).
fn render(which: Which, desc: &SceneDesc, origin: Option<Vec3>, seed: u32) -> Batches {
    let scene = match origin {
        Some(o) => RenderScene::build_with_origin(desc, o),
        None => RenderScene::build(desc),
    };
    candela_tests::render_scene_batches(which, desc, &scene, SIZE, SIZE, SPP, BATCHES, seed)
        .expect("render")
}

/// Region comparisons that fail (|Δ| > 4.5 σ), as messages, and the largest |Δ|/σ.
fn differences(a: &Batches, b: &Batches) -> (Vec<String>, f64) {
    let mut regions: Vec<(String, Box<dyn Fn(u32, u32) -> bool>)> =
        vec![("image".into(), Box::new(|_, _| true))];
    let cell = SIZE / 4;
    for ry in 0..4 {
        for rx in 0..4 {
            regions.push((
                format!("region ({rx},{ry})"),
                Box::new(move |x, y| x / cell == rx && y / cell == ry),
            ));
        }
    }
    let mut fails = Vec::new();
    let mut worst = 0.0f64;
    for (name, keep) in &regions {
        let (sa, sb) = (a.region(keep), b.region(keep));
        for c in 0..3 {
            let sigma = (sa.std_error[c].powi(2) + sb.std_error[c].powi(2)).sqrt();
            let z = (sa.mean[c] - sb.mean[c]).abs() / sigma.max(1e-12);
            // NaN fails (and is kept as the worst): `f64::max` and `>` would both let it pass.
            worst = if worst.is_nan() || z.is_nan() {
                f64::NAN
            } else {
                worst.max(z)
            };
            if !(z <= 4.5) {
                fails.push(format!(
                    "{name} channel {c}: {:.5} vs {:.5} ({z:.1} σ)",
                    sa.mean[c], sb.mean[c]
                ));
            }
        }
    }
    (fails, worst)
}

fn far_renders_match(which: Which, distances: &[f32]) {
    let base = cornell();
    let direction = Vec3::new(1.0, 0.6, -0.8);
    let at_origin = render(which, &base, None, 1);
    for (i, &d) in distances.iter().enumerate() {
        let far = moved(base.clone(), direction * d);
        let scene = RenderScene::build(&far);
        assert!(
            (scene.origin - direction * d)
                .abs()
                .cmple(Vec3::splat(32.0))
                .all(),
            "origin {} not near the camera",
            scene.origin
        );
        let b = render(which, &far, None, 2 + i as u32);
        let (fails, worst) = differences(&at_origin, &b);
        eprintln!("{which:?} {d:e} m: worst |Δ| = {worst:.2} σ");
        assert!(
            fails.is_empty(),
            "{which:?} at {d:e} m:\n{}",
            fails.join("\n")
        );
    }
}

#[test]
fn cpu_cornell_far_from_the_origin_renders_the_same() {
    far_renders_match(Which::Cpu, &[1e3, 1e4, 1e5]);
}

#[test]
fn gpu_cornell_far_from_the_origin_renders_the_same() {
    far_renders_match(Which::Gpu, &[1e5]);
}

/// The comparison has power: without camera-relative rendering the far box is not the same.
#[test]
fn without_camera_relative_rendering_the_far_box_differs() {
    let base = cornell();
    let at_origin = render(Which::Cpu, &base, None, 1);
    let far = moved(base, Vec3::new(1.0, 0.6, -0.8) * 1e5);
    let world_space = render(Which::Cpu, &far, Some(Vec3::ZERO), 2);
    let (fails, worst) = differences(&at_origin, &world_space);
    eprintln!(
        "world space at 1e5 m: worst |Δ| = {worst:.2} σ, {} failing",
        fails.len()
    );
    assert!(
        fails.len() >= 3,
        "rendering 1e5 m out in world space should differ, worst {worst:.2} σ"
    );
}
