//! The denoiser's guides taken from the CPU tracer's own first hits (`render/cpu/guides.rs`,
//! `Tracer::record_guides`) instead of a guide pass of their own. Checked on the Cornell box
//! with a mirror and a glass sphere (the external reference scene):
//! * with every sample's camera ray through its pixel's centre (a fixed `pixel_jitter` of
//!   (½, ½): the guide pass's rays), the recorded guides equal the guide pass's, every field of
//!   every pixel — mirrors followed, glass, the lamp and the sky included;
//! * the denoiser fed by the tracer (`DenoiseStage`) gives the very film it gives with the
//!   guide pass;
//! * a tracer that was not asked records nothing, and a frame with jittered samples records
//!   each sample's own ray (its depths differ from the centre rays' at edges only).

use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela::layout::METHOD_DEFAULT;
use candela::render::Tracer;
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::SvgfParams;
use candela::render::jitter;
use candela::render::{DenoiseStage, RenderError};
use candela::scene::RenderScene;
use candela_tests::{external, repo, uniforms_with};

const SIZE: (u32, u32) = (48, 40);

fn mirror_glass() -> SceneDesc {
    let scene = "cornell_mirror_glass";
    let level = repo().join(format!("assets/test_scenes/reference/{scene}.ron"));
    let root = AssetRoot::new(external().join("reference").join(scene)).expect("root");
    load_scene(&level, &root).expect("level")
}

/// The frame's uniforms; `centred` puts every camera ray through its pixel's centre.
fn uniforms(
    desc: &SceneDesc,
    scene: &RenderScene,
    centred: bool,
) -> candela::layout::GpuFrameUniforms {
    let mut u = uniforms_with(desc, scene, SIZE, 1, 7, METHOD_DEFAULT, 0);
    if centred {
        u.pixel_jitter = jitter::pack((0.5, 0.5));
    }
    u
}

#[test]
fn first_hit_guides_equal_the_guide_pass_on_centre_rays() {
    let desc = mirror_glass();
    let scene = RenderScene::build(&desc);
    let u = uniforms(&desc, &scene, true);
    assert_eq!(
        u.lens_radius, 0.0,
        "a pinhole camera: the guide pass's rays"
    );
    let mut tracer = CpuTracer::new();
    tracer.record_guides(true);
    tracer.render(&scene, &u).expect("render");
    let recorded = tracer.take_guides().expect("the tracer recorded guides");
    let pass = trace_guides(&scene, &u);
    let count = |v: &[bool]| v.iter().filter(|&&b| b).count();
    // The scene exercises every kind of first hit.
    assert!(count(&pass.specular) > 20, "mirror and glass pixels");
    assert!(count(&pass.emissive) > 0, "lamp pixels");
    assert!(
        pass.albedo
            .iter()
            .zip(&pass.specular)
            .any(|(a, &s)| s && *a != glam::Vec3::ONE),
        "a mirror pixel whose albedo was followed to a wall"
    );
    for i in 0..pass.len() {
        assert_eq!(
            (
                recorded.normal[i],
                recorded.depth[i],
                recorded.albedo[i],
                recorded.instance[i],
                recorded.emissive[i],
                recorded.specular[i]
            ),
            (
                pass.normal[i],
                pass.depth[i],
                pass.albedo[i],
                pass.instance[i],
                pass.emissive[i],
                pass.specular[i]
            ),
            "pixel {} ({}, {})",
            i,
            i % SIZE.0 as usize,
            i / SIZE.0 as usize
        );
    }
    assert!(tracer.take_guides().is_none(), "handed over once");
}

/// The denoised film of two frames (the second reprojects the first) with the tracer's guides
/// recorded or traced by the stage's own pass.
fn denoised(desc: &SceneDesc, scene: &RenderScene, record: bool) -> Result<Vec<f32>, RenderError> {
    let mut tracer = CpuTracer::new();
    tracer.record_guides(record);
    let mut stage = DenoiseStage::new(SvgfParams::default());
    let mut u = uniforms(desc, scene, true);
    for (frame, blend) in [(0u32, 1.0f32), (1, 0.5)] {
        u.sample_base = frame;
        tracer.render(scene, &u)?;
        stage.run(scene, &u, &mut tracer, blend, 1)?;
    }
    Ok(stage
        .capture()?
        .mean
        .iter()
        .flat_map(|v| v.to_array())
        .collect())
}

#[test]
fn the_denoiser_fed_by_the_tracer_gives_the_guide_pass_film() {
    let desc = mirror_glass();
    let scene = RenderScene::build(&desc);
    let fed = denoised(&desc, &scene, true).expect("recorded");
    let pass = denoised(&desc, &scene, false).expect("guide pass");
    assert!(fed.iter().any(|&v| v > 0.0), "a lit picture");
    assert_eq!(fed, pass);
}

#[test]
fn guides_are_recorded_only_when_asked_and_follow_the_jittered_sample() {
    let desc = mirror_glass();
    let scene = RenderScene::build(&desc);
    let u = uniforms(&desc, &scene, false);
    let mut tracer = CpuTracer::new();
    tracer.render(&scene, &u).expect("render");
    assert!(tracer.take_guides().is_none(), "not asked");
    tracer.record_guides(true);
    tracer.render(&scene, &u).expect("render");
    let recorded = tracer.take_guides().expect("asked");
    let pass = trace_guides(&scene, &u);
    // Jittered rays hit the same surfaces as the centre rays almost everywhere (same instance),
    // at depths that differ by sub-pixel amounts; not bit for bit.
    let same_instance = (0..pass.len())
        .filter(|&i| recorded.instance[i] == pass.instance[i])
        .count();
    let exact_depth = (0..pass.len())
        .filter(|&i| recorded.depth[i] == pass.depth[i])
        .count();
    let n = pass.len();
    assert!(
        same_instance * 10 > n * 9,
        "{same_instance} of {n} pixels see the same instance"
    );
    assert!(
        exact_depth * 2 < n,
        "{exact_depth} of {n} depths equal the centre rays': the samples were not jittered"
    );
}
