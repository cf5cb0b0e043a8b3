//! The render thread's denoiser stage (`render/denoise_stage.rs`) with the GPU tracer hands
//! the tracer's frame, still on the device, to the WGSL denoiser (`gpu::GpuDenoiser`), and its
//! output agrees with the CPU denoiser's on the same frames while the camera moves; with the
//! CPU tracer the stage stays on the CPU denoiser, its output exactly `Svgf`'s.
//!
//! Tolerance: as `denoise_gpu_matches_cpu.rs` (|gpu − cpu| ≤ 2·10⁻³·|cpu| + 10⁻⁴·m, m the
//! image's mean radiance): the same two denoisers on the same inputs; the frame only took a
//! copy on the device instead of an upload.

use candela::assets::CameraDesc;
use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::{Svgf, SvgfParams, View, world_from_object};
use candela::render::gpu::{GpuContext, GpuTracer};
use candela::render::{DenoiseStage, FilmView, FrameSettings, Tracer, frame_uniforms};
use glam::{Affine3A, Vec3};

use super::denoise_common::Cornell;

const W: u32 = 64;
const H: u32 = 36;

/// Frame `k` of a camera that turns and slides, film blend 1 (the stage's tracer renders each
/// frame alone).
fn uniforms(c: &Cornell, k: u32) -> GpuFrameUniforms {
    let camera: &CameraDesc = &c.desc.camera;
    let p = Vec3::from(camera.position);
    let d = Vec3::from(camera.look_at) - p;
    let q = p + d.cross(Vec3::Y).normalize() * (0.011 * k as f32);
    let r = glam::Quat::from_rotation_y((0.6 * k as f32).to_radians());
    let moved = CameraDesc {
        position: q.into(),
        look_at: (q + r * d).into(),
        ..camera.clone()
    };
    let mut s = FrameSettings::new(c.width, c.height, 1, 7, &c.desc.render);
    s.sample_base = k;
    s.film_blend = 1.0;
    frame_uniforms(
        &moved,
        c.desc.sun.as_ref(),
        &c.desc.sky,
        &s,
        &c.scene.header(),
    )
}

/// Runs six frames of `tracer` through a stage and through `Svgf` on the frames read back;
/// returns the worst difference as a fraction of the tolerance and whether every output was
/// on the device.
fn run(c: &Cornell, tracer: &mut dyn Tracer) -> anyhow::Result<(f32, bool)> {
    let params = SvgfParams::default();
    let mut stage = DenoiseStage::new(params);
    let mut cpu = Svgf::new(params);
    let transforms: Vec<Affine3A> = c.scene.instances.iter().map(world_from_object).collect();
    let (mut worst, mut on_device) = (0.0f32, true);
    for k in 0..6u32 {
        let u = uniforms(c, k);
        tracer.render(&c.scene, &u)?;
        let blend = (1.0 / (k + 1) as f32).max(0.2);
        stage.run(&c.scene, &u, tracer, blend, 1)?;
        on_device &= matches!(stage.film_view(), Some(FilmView::Device { .. }));
        let frame = tracer.film()?.mean;
        let guides = trace_guides(&c.scene, &u);
        let (want, _) =
            cpu.denoise_moving(&frame, &guides, blend, View::of(&u), transforms.clone())?;
        let got = stage.capture()?;
        assert_eq!(
            (got.width, got.height),
            (W, H),
            "frame {k}: the film's size"
        );
        let m =
            want.mean.iter().map(|p| p.element_sum() / 3.0).sum::<f32>() / want.mean.len() as f32;
        for (i, (a, b)) in want.mean.iter().zip(&got.mean).enumerate() {
            for ch in 0..3 {
                let tolerance = 2e-3 * a[ch].abs() + 1e-4 * m;
                let d = (a[ch] - b[ch]).abs();
                worst = worst.max(d / tolerance);
                assert!(
                    d <= tolerance,
                    "frame {k} pixel {i} channel {ch}: CPU denoiser {a}, stage {b}"
                );
            }
        }
    }
    Ok((worst, on_device))
}

#[test]
fn with_the_gpu_tracer_the_stage_denoises_on_the_device_as_the_cpu_denoiser_does()
-> anyhow::Result<()> {
    let c = Cornell::load(W, H)?;
    let mut tracer = GpuTracer::new(GpuContext::headless()?, &c.scene)?;
    let (worst, on_device) = run(&c, &mut tracer)?;
    eprintln!("GPU tracer through the stage: worst difference {worst:.4} of the tolerance");
    assert!(
        on_device,
        "the stage read the GPU tracer's frame back to the CPU denoiser"
    );
    Ok(())
}

#[test]
fn with_the_cpu_tracer_the_stage_stays_on_the_cpu_denoiser() -> anyhow::Result<()> {
    let c = Cornell::load(W, H)?;
    let (worst, on_device) = run(&c, &mut CpuTracer::new())?;
    assert!(
        !on_device,
        "the CPU tracer's frame went to the GPU denoiser"
    );
    assert_eq!(worst, 0.0, "the CPU path changed");
    Ok(())
}
