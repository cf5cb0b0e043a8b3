//! The GPU denoiser (`render/gpu/denoise.rs`, WGSL) and the CPU one (`render/denoise/`, Rust)
//! agree on the same inputs: the Cornell box's CPU-traced frames (1 spp, 64×36, with a few
//! NaN/inf pixels) and guides, over eight frames, so both the spatial (history < 4 frames) and
//! the temporal variance are exercised — with a still camera, with a camera that turns and
//! slides (the per-pixel reprojection, `shaders/denoise_reproject.wgsl` against
//! `denoise::reproject`), and over a wall whose board (another instance) slides while the
//! camera does (the instances' motions).
//!
//! Tolerance, per pixel and channel: |gpu − cpu| ≤ 2·10⁻³·|cpu| + 10⁻⁴·m, m the image's mean
//! radiance. Derivation: both sides evaluate the same formulas in the same order, so they
//! differ only where WGSL's arithmetic may round differently — `exp` (WGSL allows 3 + 2|x| ULP;
//! the weights that matter have |x| ≤ ~20, so ≤ 43 ULP ≈ 3·10⁻⁶ relative), division (2.5 ULP),
//! `sqrt`, and fused multiply-adds the driver may form (1 ULP each). σ_n = 128 is seven exact
//! squarings, not `pow`. A weighted mean Σwᵢxᵢ/Σwᵢ whose weights carry relative errors ≤ δ moves
//! by ≤ 2δ·max|xᵢ − x̄|; the luminance weight also feeds an input error ε back as ε/(σ_l·√Var),
//! ≤ ~1 here. With δ ≈ 10⁻⁵ (three weights and the kernel per tap), neighbourhood ranges up to
//! ~10× the pixel (the lamp's edge) and five passes compounding: 5 · 2 · 10⁻⁵ · 10 = 10⁻³
//! relative, doubled for margin; the absolute term covers black pixels next to bright ones. The
//! temporal history is plain arithmetic: it must agree to 10⁻⁵ relative.
//!
//! The reprojection adds the same kind of arithmetic to the history (a bilinear gather of the
//! previous history, a weighted mean, after the projection's few divisions, each ≤ 2.5 ULP:
//! a tap's weight moves by ~10⁻⁶, the mean by that times the taps' spread), so 10⁻⁵ holds.
//! Its decisions (same instance, normal within 25°, depth within 5 %, the snap to a pixel
//! centre) are thresholds: a quantity within a few ULP of one could decide differently on the
//! two sides and move a pixel's history wholesale. No pixel is exempted: the camera paths are
//! continuous and none of their pixels lands that close to a threshold (if one ever does, the
//! failing pixel is named and the path can move by a hair).

use crate::denoise_common;

use candela::assets::CameraDesc;
use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::{AtrousKernel, Guides, Svgf, SvgfParams, View, world_from_object};
use candela::render::gpu::{GpuContext, GpuDenoiser};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use denoise_common::{Cornell, Noise};
use glam::{Affine3A, Vec3};

const W: u32 = 64;
const H: u32 = 36;

#[test]
fn gpu_and_cpu_denoisers_agree() -> anyhow::Result<()> {
    agree_with(SvgfParams::default())
}

/// The smaller à-trous kernels go through the same per-pass `radius` uniform on the GPU.
#[test]
fn gpu_and_cpu_denoisers_agree_with_the_3x3_kernels() -> anyhow::Result<()> {
    for kernel in [AtrousKernel::Gauss3x3, AtrousKernel::B3ThenGauss3x3] {
        agree_with(SvgfParams {
            kernel,
            ..SvgfParams::default()
        })?;
    }
    Ok(())
}

fn agree_with(params: SvgfParams) -> anyhow::Result<()> {
    let cornell = Cornell::load(W, H)?;
    let guides = cornell.guides();
    let context = GpuContext::headless()?;
    let mut gpu = GpuDenoiser::new(context, params)?;
    let mut cpu = Svgf::new(params);
    let (mut worst_ratio, mut worst_abs) = (0.0f32, 0.0f32);
    for k in 0..8u32 {
        let mut frame = cornell.frame(1, 11, k)?;
        frame[100 + k as usize] = Vec3::new(f32::NAN, 0.0, 0.0);
        frame[900] = Vec3::splat(f32::INFINITY);
        let blend = 1.0 / (k + 1) as f32;
        let c = cpu.denoise(&frame, &guides, blend)?;
        gpu.denoise(&frame, &guides, blend)?;
        let g = gpu.read_output()?;
        assert_eq!(g.mean.len(), c.mean.len());
        let (gh, gm) = gpu.read_history()?;
        let h = cpu.history();
        for (i, (a, b)) in h.illumination.iter().zip(&gh).enumerate() {
            let d = (*a - *b).abs().max_element();
            assert!(
                d <= 1e-5 * (1.0 + a.abs().max_element()),
                "frame {k} history {i}: {a} {b}"
            );
        }
        for (i, (a, b)) in h.moments.iter().zip(&gm).enumerate() {
            let d = (*a - *b).abs().max_element();
            assert!(
                d <= 1e-5 * (1.0 + a.abs().max_element()),
                "frame {k} moments {i}: {a} {b}"
            );
        }
        let m = c.mean.iter().map(|p| p.element_sum() / 3.0).sum::<f32>() / c.mean.len() as f32;
        for (i, (a, b)) in c.mean.iter().zip(&g.mean).enumerate() {
            assert!(
                b.is_finite(),
                "frame {k} pixel {i}: GPU output {b} not finite"
            );
            for ch in 0..3 {
                let tolerance = 2e-3 * a[ch].abs() + 1e-4 * m;
                let d = (a[ch] - b[ch]).abs();
                worst_ratio = worst_ratio.max(d / tolerance);
                worst_abs = worst_abs.max(d);
                assert!(
                    d <= tolerance,
                    "{:?} frame {k} pixel {i} channel {ch}: cpu {a} gpu {b}",
                    params.kernel
                );
            }
        }
    }
    eprintln!("worst difference: {worst_abs:e} ({worst_ratio:.4} of the tolerance)");
    Ok(())
}

/// The largest difference over one frame, GPU against CPU, in absolute terms and as a fraction
/// of the tolerance; panics (naming `what`, the frame and the pixel) past the tolerance.
fn compare(
    what: &str,
    k: u32,
    cpu: &Svgf,
    c: &candela::render::film::Film,
    gpu: &GpuDenoiser,
) -> anyhow::Result<(f32, f32)> {
    let g = gpu.read_output()?;
    assert_eq!(g.mean.len(), c.mean.len());
    let (gh, gm) = gpu.read_history()?;
    let h = cpu.history();
    for (rows, cpu_rows, name) in [
        (&gh, &h.illumination, "history"),
        (&gm, &h.moments, "moments"),
    ] {
        for (i, (a, b)) in cpu_rows.iter().zip(rows.iter()).enumerate() {
            let d = (*a - *b).abs().max_element();
            assert!(
                d <= 1e-5 * (1.0 + a.abs().max_element()),
                "{what} frame {k} {name} {i}: cpu {a} gpu {b}"
            );
        }
    }
    let m = c.mean.iter().map(|p| p.element_sum() / 3.0).sum::<f32>() / c.mean.len() as f32;
    let (mut worst_ratio, mut worst_abs) = (0.0f32, 0.0f32);
    for (i, (a, b)) in c.mean.iter().zip(&g.mean).enumerate() {
        assert!(b.is_finite(), "{what} frame {k} pixel {i}: GPU output {b}");
        for ch in 0..3 {
            let tolerance = 2e-3 * a[ch].abs() + 1e-4 * m;
            let d = (a[ch] - b[ch]).abs();
            worst_ratio = worst_ratio.max(d / tolerance);
            worst_abs = worst_abs.max(d);
            assert!(
                d <= tolerance,
                "{what} frame {k} pixel {i} channel {ch}: cpu {a} gpu {b}"
            );
        }
    }
    Ok((worst_abs, worst_ratio))
}

fn cornell_uniforms(c: &Cornell, camera: &CameraDesc, seed: u32) -> GpuFrameUniforms {
    let s = FrameSettings::new(c.width, c.height, 1, seed, &c.desc.render);
    frame_uniforms(
        camera,
        c.desc.sun.as_ref(),
        &c.desc.sky,
        &s,
        &c.scene.header(),
    )
}

/// The Cornell camera turned about the vertical by `deg` degrees and slid `side` metres to
/// its right.
fn moved(camera: &CameraDesc, deg: f32, side: f32) -> CameraDesc {
    let p = Vec3::from(camera.position);
    let d = Vec3::from(camera.look_at) - p;
    let right = d.cross(Vec3::Y).normalize();
    let q = p + right * side;
    let r = glam::Quat::from_rotation_y(deg.to_radians());
    CameraDesc {
        position: q.into(),
        look_at: (q + r * d).into(),
        ..camera.clone()
    }
}

/// Issue 32 item 3.10: the two denoisers agree frame by frame while the camera turns and
/// slides over the Cornell box (real traced frames and guides, a few non-finite pixels), and
/// the reprojection both keeps and drops history on the way.
#[test]
fn gpu_and_cpu_denoisers_agree_while_the_camera_moves() -> anyhow::Result<()> {
    let cornell = Cornell::load(W, H)?;
    let context = GpuContext::headless()?;
    let params = SvgfParams::default();
    let mut gpu = GpuDenoiser::new(context, params)?;
    let mut cpu = Svgf::new(params);
    let transforms: Vec<Affine3A> = cornell
        .scene
        .instances
        .iter()
        .map(world_from_object)
        .collect();
    let (mut worst_ratio, mut worst_abs, mut kept, mut reset) = (0.0f32, 0.0f32, 0, 0);
    for k in 0..8u32 {
        let camera = moved(&cornell.desc.camera, 0.7 * k as f32, 0.013 * k as f32);
        let u = cornell_uniforms(&cornell, &camera, 40 + k);
        let mut tracer = CpuTracer::new();
        tracer.render(&cornell.scene, &u)?;
        let mut frame = tracer.film()?.mean;
        frame[100 + k as usize] = Vec3::new(f32::NAN, 0.0, 0.0);
        frame[900] = Vec3::splat(f32::INFINITY);
        let guides = trace_guides(&cornell.scene, &u);
        let blend = (1.0 / (k + 1) as f32).max(0.2);
        let view = View::of(&u);
        let (c, stats) = cpu.denoise_moving(&frame, &guides, blend, view, transforms.clone())?;
        gpu.denoise_moving(&frame, &guides, blend, view, transforms.clone())?;
        if let Some(s) = stats {
            kept += s.kept;
            reset += s.reset;
        }
        let (a, r) = compare("moving camera", k, &cpu, &c, &gpu)?;
        worst_abs = worst_abs.max(a);
        worst_ratio = worst_ratio.max(r);
    }
    eprintln!(
        "moving camera: {kept} pixels kept their history, {reset} restarted; worst difference \
         {worst_abs:e} ({worst_ratio:.4} of the tolerance)"
    );
    assert!(
        kept > 4 * reset && reset > 0,
        "{kept} kept, {reset} reset: the path must exercise both"
    );
    Ok(())
}

/// A wall at z = −5 seen from `view` (looking down −Z): instance 0 a board covering world x in
/// `[x0, x1)`, instance 1 the wall around it; albedo 0.8 on the board, 0.5 on the wall.
fn wall(view: &View, x0: f32, x1: f32) -> Guides {
    let mut g = Guides::sky(view.width, view.height);
    for y in 0..view.height {
        for x in 0..view.width {
            let i = (y * view.width + x) as usize;
            let d = view.centre_direction(x, y);
            let t = (5.0 + view.position.z) / -d.z;
            let wx = view.position.x + d.x * t;
            let board = (x0..x1).contains(&wx);
            g.normal[i] = Vec3::Z;
            g.depth[i] = t;
            g.albedo[i] = Vec3::splat(if board { 0.8 } else { 0.5 });
            g.instance[i] = if board { 0 } else { 1 };
        }
    }
    g
}

/// The instances' motions: a board slides 0.23 m a frame to the right while the camera slides
/// 0.05 m to the left, over noisy synthetic radiance; the two denoisers agree every frame.
#[test]
fn gpu_and_cpu_denoisers_agree_while_an_object_moves() -> anyhow::Result<()> {
    let context = GpuContext::headless()?;
    let params = SvgfParams::default();
    let mut gpu = GpuDenoiser::new(context, params)?;
    let mut cpu = Svgf::new(params);
    let mut noise = Noise(0x1234_5678);
    let (mut worst_ratio, mut worst_abs, mut kept, mut reset) = (0.0f32, 0.0f32, 0, 0);
    for k in 0..8u32 {
        let view = View {
            position: Vec3::new(-0.05 * k as f32, 0.0, 0.0),
            forward: Vec3::NEG_Z,
            right: Vec3::X,
            up: Vec3::Y * (H as f32 / W as f32),
            width: W,
            height: H,
            jitter: (0.5, 0.5),
        };
        let shift = 0.23 * k as f32;
        let guides = wall(&view, -1.0 + shift, 1.0 + shift);
        let frame: Vec<Vec3> = guides
            .albedo
            .iter()
            .map(|a| *a * (2.0 * noise.next()))
            .collect();
        let board = Affine3A::from_translation(Vec3::new(shift, 0.0, 0.0));
        let transforms = vec![board, Affine3A::IDENTITY];
        let blend = (1.0 / (k + 1) as f32).max(0.2);
        let (c, stats) = cpu.denoise_moving(&frame, &guides, blend, view, transforms.clone())?;
        gpu.denoise_moving(&frame, &guides, blend, view, transforms)?;
        if let Some(s) = stats {
            kept += s.kept;
            reset += s.reset;
        }
        let (a, r) = compare("moving board", k, &cpu, &c, &gpu)?;
        worst_abs = worst_abs.max(a);
        worst_ratio = worst_ratio.max(r);
    }
    eprintln!(
        "moving board: {kept} pixels kept their history, {reset} restarted; worst difference \
         {worst_abs:e} ({worst_ratio:.4} of the tolerance)"
    );
    assert!(
        kept > 4 * reset && reset > 0,
        "{kept} kept, {reset} reset: the path must exercise both"
    );
    Ok(())
}
