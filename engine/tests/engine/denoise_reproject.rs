//! The denoiser's per-pixel reprojection (`render::denoise::reproject`, issue 13 part 2):
//! projection round trips, a still camera reprojects onto itself exactly (so it converges as
//! before), a moving object carries its history and what it uncovers or covers restarts, and
//! a turning camera over the Cornell box keeps most pixels' history and ends closer to the
//! converged image than restarting on every motion (what the denoiser did before).

use candela::assets::CameraDesc;
use candela::layout::GpuFrameUniforms;
use candela::render::cpu::CpuTracer;
use candela::render::cpu::guides::trace_guides;
use candela::render::denoise::{
    Guides, History, PrevFrame, Svgf, SvgfParams, View, reproject, world_from_object,
};
use candela::render::film::{Converge, ConvergePolicy};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use glam::{Affine3A, Vec3, Vec4};

use super::denoise_common::{Cornell, away_from_lamps, rmse_where};

fn uniforms(c: &Cornell, camera: &CameraDesc, spp: u32, seed: u32) -> GpuFrameUniforms {
    let s = FrameSettings::new(c.width, c.height, spp, seed, &c.desc.render);
    frame_uniforms(
        camera,
        c.desc.sun.as_ref(),
        &c.desc.sky,
        &s,
        &c.scene.header(),
    )
}

fn transforms(c: &Cornell) -> Vec<Affine3A> {
    c.scene.instances.iter().map(world_from_object).collect()
}

/// The Cornell camera turned about the vertical through its position by `deg` degrees.
fn turned(camera: &CameraDesc, deg: f32) -> CameraDesc {
    let p = Vec3::from(camera.position);
    let d = Vec3::from(camera.look_at) - p;
    let r = glam::Quat::from_rotation_y(deg.to_radians());
    CameraDesc {
        look_at: (p + r * d).into(),
        ..camera.clone()
    }
}

#[test]
fn pixel_centres_project_back_onto_themselves() -> anyhow::Result<()> {
    let c = Cornell::load(40, 30)?;
    let view = View::of(&uniforms(&c, &turned(&c.desc.camera, 7.0), 1, 0));
    for (x, y) in [(0, 0), (39, 29), (20, 15), (3, 27), (38, 1)] {
        let (px, py) = view
            .project_direction(view.centre_direction(x, y) * 3.7)
            .expect("in front of the camera");
        assert!(
            (px - (x as f32 + 0.5)).abs() < 1e-3 && (py - (y as f32 + 0.5)).abs() < 1e-3,
            "pixel ({x}, {y}) projected to ({px}, {py})"
        );
    }
    assert_eq!(
        view.project_direction(-view.forward),
        None,
        "behind the camera"
    );
    Ok(())
}

#[test]
fn a_still_camera_reprojects_every_pixel_onto_itself_exactly() -> anyhow::Result<()> {
    let c = Cornell::load(32, 32)?;
    let u = uniforms(&c, &c.desc.camera, 1, 0);
    let guides = trace_guides(&c.scene, &u);
    let (mut plain, mut moving) = (
        Svgf::new(SvgfParams::default()),
        Svgf::new(SvgfParams::default()),
    );
    for k in 0..5u32 {
        let frame = c.frame(1, k, k)?;
        let blend = 1.0 / (k + 1) as f32;
        let a = plain.denoise(&frame, &guides, blend)?;
        let (b, stats) =
            moving.denoise_moving(&frame, &guides, blend, View::of(&u), transforms(&c))?;
        assert_eq!(
            a.mean, b.mean,
            "frame {k}: reprojection changed a still image"
        );
        if k > 0 {
            let stats = stats.expect("a previous frame was reprojected");
            let specular = guides.specular.iter().filter(|s| **s).count();
            assert_eq!(
                stats.reset, specular,
                "frame {k}: only specular pixels restart"
            );
        }
    }
    assert_eq!(plain.history(), moving.history());
    Ok(())
}

/// A flat wall at z = −5 seen by a camera at the origin looking down −Z; instance 0 is a board
/// on it covering world x in `[x0, x1)`, instance 1 the wall around it.
fn wall_guides(view: &View, x0: f32, x1: f32) -> (Guides, Vec<f32>) {
    let mut g = Guides::sky(view.width, view.height);
    let mut world_x = vec![0.0; g.len()];
    for y in 0..view.height {
        for x in 0..view.width {
            let i = (y * view.width + x) as usize;
            let d = view.centre_direction(x, y);
            let t = 5.0 / -d.z;
            let wx = d.x * t;
            g.normal[i] = Vec3::Z;
            g.depth[i] = t;
            g.albedo[i] = Vec3::ONE;
            g.instance[i] = if (x0..x1).contains(&wx) { 0 } else { 1 };
            world_x[i] = wx;
        }
    }
    (g, world_x)
}

#[test]
fn a_moving_board_carries_its_history_and_what_it_covers_or_uncovers_restarts() {
    let view = View {
        position: Vec3::ZERO,
        forward: Vec3::NEG_Z,
        right: Vec3::X,
        up: Vec3::Y * 0.75,
        width: 64,
        height: 48,
        jitter: (0.5, 0.5),
    };
    // A pixel is 2·5/64 = 0.156 m wide on the wall; the board moves 0.5 m (3.2 pixels).
    let shift = 0.5;
    let (prev_guides, prev_x) = wall_guides(&view, -1.0, 1.0);
    let (guides, now_x) = wall_guides(&view, -1.0 + shift, 1.0 + shift);
    // The previous history holds each pixel's board-space x (wall: world x), length 4.
    let mut history = History::new(view.width, view.height);
    for (i, h) in history.illumination.iter_mut().enumerate() {
        *h = Vec4::new(prev_x[i] + 10.0, 1.0, 1.0, 4.0);
    }
    let board = |t: f32| Affine3A::from_translation(Vec3::new(t, 0.0, 0.0));
    let prev = PrevFrame {
        view,
        guides: prev_guides,
        world_from_object: vec![board(0.0), Affine3A::IDENTITY],
    };
    let (moved, stats) = reproject(
        &history,
        &prev,
        &guides,
        &view,
        &[board(shift), Affine3A::IDENTITY],
    );
    let margin = 0.2; // more than a pixel on the wall
    let (mut checked_kept, mut checked_reset) = (0, 0);
    for i in 0..guides.len() {
        let h = moved.illumination[i];
        let on_board = guides.instance[i] == 0;
        // Where this point was a frame ago.
        let was = if on_board { now_x[i] - shift } else { now_x[i] };
        let was_on_board = (-1.0..1.0).contains(&was);
        let clear = (was + 1.0).abs() > margin && (was - 1.0).abs() > margin;
        if !clear {
            continue;
        }
        if on_board == was_on_board {
            assert!(h.w == 4.0, "pixel {i}: kept history expected, got {h}");
            assert!(
                (h.x - (was + 10.0)).abs() < 1e-3,
                "pixel {i}: history from x = {was}, got {}",
                h.x - 10.0
            );
            checked_kept += 1;
        } else {
            assert_eq!(h.w, 0.0, "pixel {i}: covered or uncovered, must restart");
            checked_reset += 1;
        }
    }
    assert!(
        checked_kept > 1000 && checked_reset > 60,
        "{checked_kept} kept, {checked_reset} reset checked"
    );
    assert_eq!(stats.kept + stats.reset, guides.len());
}

#[test]
fn a_turning_camera_keeps_its_history_and_ends_closer_to_the_converged_image() -> anyhow::Result<()>
{
    let c = Cornell::load(48, 48)?;
    let frames = 12u32;
    let camera = |k: u32| turned(&c.desc.camera, 0.4 * k as f32);
    let last = camera(frames - 1);
    let reference = {
        let mut t = CpuTracer::new();
        t.render(&c.scene, &uniforms(&c, &last, 1024, 9_999))?;
        t.film()?.mean
    };
    let (mut reprojecting, mut restarting) = (
        Svgf::new(SvgfParams::default()),
        Svgf::new(SvgfParams::default()),
    );
    let mut converge = Converge::new(ConvergePolicy::default());
    let (mut out_a, mut out_b, mut kept) = (Vec::new(), Vec::new(), 0.0);
    let mut guides = Guides::sky(0, 0);
    for k in 0..frames {
        let u = uniforms(&c, &camera(k), 1, k);
        let mut t = CpuTracer::new();
        t.render(&c.scene, &u)?;
        let frame = t.film()?.mean;
        guides = trace_guides(&c.scene, &u);
        let motion = candela::commit::Motion {
            cut: k == 0,
            camera: if k == 0 { 0.0 } else { 0.4f32.to_radians() },
            objects: false,
            lighting: 0.0,
        };
        let blend = converge.blend_reprojected(&motion);
        let (a, stats) =
            reprojecting.denoise_moving(&frame, &guides, blend, View::of(&u), transforms(&c))?;
        if let Some(s) = stats {
            kept = s.kept as f64 / (s.kept + s.reset) as f64;
        }
        out_a = a.mean;
        out_b = restarting.denoise(&frame, &guides, 1.0)?.mean;
    }
    let keep = away_from_lamps(&guides);
    let (ea, eb) = (
        rmse_where(&out_a, &reference, &keep),
        rmse_where(&out_b, &reference, &keep),
    );
    eprintln!(
        "kept {:.1} % of pixels; RMSE reprojecting {ea:.4}, restarting {eb:.4}",
        kept * 100.0
    );
    assert!(kept > 0.85, "only {:.1} % kept their history", kept * 100.0);
    assert!(
        ea < 0.8 * eb,
        "reprojecting {ea} is not clearly below restarting {eb}"
    );
    Ok(())
}
