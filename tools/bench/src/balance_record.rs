//! `bench balance --record`: per-unit render costs of the demo city under a spinning camera,
//! recorded on the CPU tracer (`candela::render::balance::record_unit_costs`) into the cost
//! files `bench balance` replays.
//!
//! The camera stands at the flythrough's plaza viewpoint and turns about the vertical at a
//! fixed pitch (slightly up), like the paper's spinning camera in the Aztec scene; the slow and the fast
//! camera differ only in degrees per frame. The scene is static (the flythrough's motions are
//! left out: the camera changes what each row costs far more than drones do).
//! Owns: the camera path and the recording loop. Must not: simulate.

use std::path::Path;

use anyhow::Context;
use candela::assets::{AssetRoot, CameraDesc, load_scene};
use candela::render::balance::{CostTrace, record_unit_costs};
use candela::render::{FrameSettings, frame_uniforms};
use candela::scene::RenderScene;

/// One recorded camera.
#[derive(Clone, Copy, Debug)]
pub struct Spin {
    /// File stem and table label ("slow", "fast").
    pub name: &'static str,
    /// Turn per frame, degrees.
    pub deg_per_frame: f32,
}

/// The two cameras of Table 1.
pub const SPINS: [Spin; 2] = [
    Spin {
        name: "slow",
        deg_per_frame: 0.5,
    },
    Spin {
        name: "fast",
        deg_per_frame: 4.0,
    },
];

/// Camera position, world metres (the flythrough's plaza viewpoint at frame 104).
const EYE: [f32; 3] = [68.0, 24.0, 68.0];
/// Pitch above the horizon, degrees (the top rows see sky, as the paper's Figure 10 shows for
/// Aztec: at 12° down the view is all city and the rows differ far less), and the starting
/// heading (towards the city centre).
const PITCH_UP_DEG: f32 = 6.0;
const START_YAW_DEG: f32 = 225.0;
/// Vertical field of view, degrees.
const FOV_DEG: f32 = 50.0;

/// The camera of frame `frame` of `spin`.
pub fn camera_at(spin: Spin, frame: u32) -> CameraDesc {
    let yaw = (START_YAW_DEG + spin.deg_per_frame * frame as f32).to_radians();
    let pitch = PITCH_UP_DEG.to_radians();
    let dir = [
        yaw.cos() * pitch.cos(),
        pitch.sin(),
        yaw.sin() * pitch.cos(),
    ];
    CameraDesc {
        position: EYE,
        look_at: [EYE[0] + dir[0], EYE[1] + dir[1], EYE[2] + dir[2]],
        up: [0.0, 1.0, 0.0],
        vertical_fov_deg: FOV_DEG,
        aperture_radius: 0.0,
        focus_distance: None,
    }
}

/// Records `frames` frames of `spin` at `width × height`, `spp` samples per pixel.
pub fn record(
    repo: &Path,
    spin: Spin,
    frames: u32,
    width: u32,
    height: u32,
    spp: u32,
) -> anyhow::Result<CostTrace> {
    let dir = repo.join("assets/test_scenes/demo");
    let desc = load_scene(&dir.join("demo.ron"), &AssetRoot::new(&dir)?)
        .context("loading the demo level")?;
    let scene = RenderScene::build(&desc);
    let progress = indicatif::ProgressBar::new(frames as u64);
    progress.set_style(
        indicatif::ProgressStyle::with_template(
            "{msg} [{bar:40}] {pos}/{len} frames, {elapsed} (eta {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    progress.set_message(format!("recording the {} camera", spin.name));
    let mut trace = CostTrace {
        width,
        height,
        notes: vec![
            (
                "scene".into(),
                "assets/test_scenes/demo/demo.ron (static)".into(),
            ),
            ("camera".into(), spin.name.into()),
            ("deg_per_frame".into(), spin.deg_per_frame.to_string()),
            ("eye".into(), format!("{EYE:?}")),
            ("pitch_up_deg".into(), PITCH_UP_DEG.to_string()),
            ("fov_deg".into(), FOV_DEG.to_string()),
            ("spp".into(), spp.to_string()),
            (
                "tracer".into(),
                "cpu, one unit per thread, thread CPU time".into(),
            ),
            ("threads".into(), rayon::current_num_threads().to_string()),
        ],
        ..Default::default()
    };
    for frame in 0..frames {
        let mut settings = FrameSettings::new(width, height, spp, frame, &desc.render);
        settings.sample_base = frame * spp;
        let u = frame_uniforms(
            &camera_at(spin, frame),
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            &scene.header(),
        );
        let costs = record_unit_costs(&scene, &u);
        trace
            .unit_seconds
            .push(costs.iter().map(|c| c.seconds).collect());
        trace.unit_rays.push(costs.iter().map(|c| c.rays).collect());
        progress.inc(1);
    }
    progress.finish_and_clear();
    Ok(trace)
}
