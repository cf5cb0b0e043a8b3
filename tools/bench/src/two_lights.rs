//! `bench two-lights`: Brigade's two light samples per hit (§6.2.3: the sun or moon disc every
//! time, and one triangle picked by power: the engine's default) against plain single-pick
//! next-event estimation (`layout::METHOD_SINGLE_PICK`: the disc is one more entry of the one
//! pick), at equal time, on It's About Time's ruins (`assets/its_about_time/ruins.ron`, its
//! physical sky, date and place): a day view of the sun gate court at 15:30 UTC, a night view
//! of the night shrine at 02:00 UTC with torches 11 and 13 lit (the level's date, 21 March
//! 2026, two days after new moon: no moon up), and, at full moon (2 April 2026, 06:00 UTC, the
//! moon high), the shrine again and the court, which no torch near it lights. Light groups off
//! in a view are left out of its scene.
//!
//! For each view the CPU tracer renders a reference of `--reference-spp` samples per pixel (two
//! halves: their relative MSE / 4 is its noise floor), then `--frames` one-sample frames per
//! estimator, interleaved frame by frame so that load on a shared machine falls on both alike.
//! Every image of a view is scaled so that the reference's mean luminance is 0.18 (as auto
//! exposure would) before its relative MSE is taken. Printed per view and estimator: median ms per frame, relative MSE of one frame, that error
//! times the frame time (error at equal time, since an unbiased estimator's MSE falls as 1/N:
//! lower is better), and the relative MSE of the mean of all frames. The chart
//! (`--chart`, default `docs/charts/two_lights.png`) draws the running mean's relative MSE
//! against cumulative wall time, one panel per view.
//!
//! Owns: [`run`]. Main thread (the rayon pool renders). Must not: change the game or the tracer.

use std::path::PathBuf;

use candela::assets::{AssetRoot, CameraDesc, SceneDesc, SkyDesc, load_scene};
use candela::layout::{GpuFrameUniforms, METHOD_SINGLE_PICK};
use candela::render::cpu::CpuTracer;
use candela::render::{FrameSettings, Tracer, frame_uniforms, method_of};
use candela::scene::RenderScene;
use clap::Parser;
use glam::Vec3;

use super::machine::median;
use super::picture_metrics::rel_mse;
use super::two_lights_plot::{Curve, figure};

#[derive(Parser, Debug)]
pub struct TwoLightsArgs {
    /// Traced width in pixels.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// Traced height in pixels.
    #[arg(long, default_value_t = 90)]
    pub height: u32,
    /// One-sample frames per estimator.
    #[arg(long, default_value_t = 64)]
    pub frames: u32,
    /// Samples per pixel of the reference.
    #[arg(long, default_value_t = 512)]
    pub reference_spp: u32,
    /// Where the chart goes.
    #[arg(long, default_value = "docs/charts/two_lights.png")]
    pub chart: PathBuf,
}

/// One view of the ruins.
struct View {
    name: &'static str,
    position: [f32; 3],
    look_at: [f32; 3],
    utc_hours: f64,
    /// (year, month, day) instead of the level's date.
    date: Option<(i32, u32, u32)>,
    /// Light groups switched on (the level's `lights_off` groups not listed stay off).
    groups_on: &'static [u32],
}

const VIEWS: [View; 4] = [
    View {
        name: "day: sun gate court, 15:30 UTC",
        position: [5.0, 2.5, 7.0],
        look_at: [15.0, 1.0, 0.0],
        utc_hours: 15.5,
        date: None,
        groups_on: &[],
    },
    View {
        name: "night: night shrine, 02:00 UTC, torches 11 and 13",
        position: [-24.5, 2.2, -12.0],
        look_at: [-24.5, 1.0, -20.0],
        utc_hours: 2.0,
        date: None,
        groups_on: &[11, 13],
    },
    View {
        name: "full moon: night shrine, 2 April 06:00 UTC, torches 11 and 13",
        position: [-24.5, 2.2, -12.0],
        look_at: [-24.5, 1.0, -20.0],
        utc_hours: 6.0,
        date: Some((2026, 4, 2)),
        groups_on: &[11, 13],
    },
    View {
        name: "full moon: sun gate court, 2 April 06:00 UTC",
        position: [5.0, 2.5, 7.0],
        look_at: [15.0, 1.0, 0.0],
        utc_hours: 6.0,
        date: Some((2026, 4, 2)),
        groups_on: &[],
    },
];

/// The estimators compared, in legend order.
const METHODS: [(&str, bool); 2] = [("two lights (default)", false), ("single pick", true)];

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The ruins seen from `view`: its camera, its time, and only the light groups it has on.
fn view_scene(view: &View) -> anyhow::Result<SceneDesc> {
    let root = repo().join("assets");
    let level = root.join("its_about_time/ruins.ron");
    let mut desc = load_scene(&level, &AssetRoot::new(&root)?)?;
    desc.instances
        .retain(|i| i.light_group.is_none_or(|g| view.groups_on.contains(&g)));
    desc.camera = CameraDesc {
        position: view.position,
        look_at: view.look_at,
        ..desc.camera
    };
    let SkyDesc::Physical(sky) = &mut desc.sky else {
        anyhow::bail!("{}: sky: expected a physical sky", level.display());
    };
    let Some(time) = sky.time.as_mut() else {
        anyhow::bail!("{}: sky.time: expected a date and place", level.display());
    };
    time.utc_hours = view.utc_hours;
    if let Some((year, month, day)) = view.date {
        (time.year, time.month, time.day) = (year, month, day);
    }
    Ok(desc)
}

/// Mean radiance of `spp` samples per pixel of `u`, in chunks of 16 from sample base `base`.
fn converged(
    tracer: &mut CpuTracer,
    scene: &RenderScene,
    u: &GpuFrameUniforms,
    spp: u32,
    base: u32,
) -> anyhow::Result<Vec<Vec3>> {
    const CHUNK: u32 = 16;
    let chunks = spp.div_ceil(CHUNK).max(1);
    let mut sum = vec![Vec3::ZERO; (u.width * u.height) as usize];
    for c in 0..chunks {
        let frame = GpuFrameUniforms {
            spp: CHUNK,
            sample_base: base + c * CHUNK,
            film_blend: 1.0,
            ..*u
        };
        tracer.clear();
        tracer.render(scene, &frame)?;
        for (s, p) in sum.iter_mut().zip(&tracer.film()?.mean) {
            *s += *p;
        }
    }
    Ok(sum.into_iter().map(|s| s / chunks as f32).collect())
}

pub fn run(args: &TwoLightsArgs) -> anyhow::Result<()> {
    println!(
        "{}×{} traced, {} one-sample frames per estimator, interleaved; reference {} spp (two-light)\n",
        args.width, args.height, args.frames, args.reference_spp
    );
    println!(
        "| view | estimator | disc: luminance × sr | disc pick chance | ms per frame (median) | rel. MSE, 1 frame | rel. MSE × ms | rel. MSE, mean of {} frames | reference noise floor |\n|---|---|---:|---:|---:|---:|---:|---:|---:|",
        args.frames
    );
    let mut tracer = CpuTracer::new();
    let mut panels = Vec::new();
    for view in &VIEWS {
        let desc = view_scene(view)?;
        let scene = RenderScene::build(&desc);
        let settings = FrameSettings::new(args.width, args.height, 1, 7, &desc.render);
        let base = method_of(desc.render.light_sampling);
        let u = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            &scene.header(),
        );
        let u = GpuFrameUniforms { method: base, ..u };
        let half = (args.reference_spp / 2).max(1);
        let a = converged(&mut tracer, &scene, &u, half, 1 << 20)?;
        let b = converged(&mut tracer, &scene, &u, half, 1 << 21)?;
        // Exposure: every image of the view is scaled so the reference's mean luminance is 0.18
        // (as auto exposure would) before the relative MSE, whose ε of 0.01 would otherwise
        // swamp a moonlit view's radiance (~10⁻⁴).
        let reference: Vec<Vec3> = a.iter().zip(&b).map(|(x, y)| (*x + *y) * 0.5).collect();
        let mean_luminance = reference
            .iter()
            .map(|c| f64::from(c.dot(Vec3::new(0.2126, 0.7152, 0.0722))))
            .sum::<f64>()
            / reference.len().max(1) as f64;
        anyhow::ensure!(
            mean_luminance > 0.0,
            "{}: the reference is black",
            view.name
        );
        let exposure = (0.18 / mean_luminance) as f32;
        let exposed =
            |image: &[Vec3]| -> Vec<Vec3> { image.iter().map(|c| *c * exposure).collect() };
        let floor = rel_mse(&exposed(&a), &exposed(&b)) / 4.0;
        let reference = exposed(&reference);
        let mut ms = [Vec::new(), Vec::new()];
        let mut errors = [Vec::new(), Vec::new()];
        let mut sums = [
            vec![Vec3::ZERO; reference.len()],
            vec![Vec3::ZERO; reference.len()],
        ];
        let mut curves: Vec<Curve> = METHODS
            .iter()
            .map(|(name, _)| Curve {
                name,
                points: Vec::new(),
            })
            .collect();
        let mut elapsed = [0.0f64; 2];
        for f in 0..args.frames {
            for (i, &(_, single)) in METHODS.iter().enumerate() {
                let frame = GpuFrameUniforms {
                    sample_base: f,
                    film_blend: 1.0,
                    method: if single {
                        base | METHOD_SINGLE_PICK
                    } else {
                        base
                    },
                    ..u
                };
                tracer.clear();
                let stats = tracer.render(&scene, &frame)?;
                ms[i].push(stats.seconds * 1e3);
                elapsed[i] += stats.seconds;
                let film = tracer.film()?;
                errors[i].push(rel_mse(&exposed(&film.mean), &reference));
                for (s, p) in sums[i].iter_mut().zip(&film.mean) {
                    *s += *p;
                }
                let n = (f + 1) as f32;
                let mean: Vec<Vec3> = sums[i].iter().map(|s| *s * (exposure / n)).collect();
                curves[i]
                    .points
                    .push((elapsed[i], rel_mse(&mean, &reference)));
            }
        }
        for (i, &(name, single)) in METHODS.iter().enumerate() {
            let chance = if single {
                disc_chance(&GpuFrameUniforms {
                    method: base | METHOD_SINGLE_PICK,
                    ..u
                })
            } else {
                1.0
            };
            let disc = disc_weight(&u);
            let frame_ms = median(&ms[i]);
            let error = errors[i].iter().sum::<f64>() / errors[i].len().max(1) as f64;
            let (_, last) = curves[i].points.last().copied().unwrap_or((0.0, 0.0));
            println!(
                "| {} | {name} | {disc:.3e} | {chance:.3} | {frame_ms:.2} | {error:.4} | {:.3} | {last:.5} | {floor:.5} |",
                view.name,
                error * frame_ms,
            );
        }
        panels.push((view.name, curves));
    }
    if let Some(dir) = args.chart.parent() {
        std::fs::create_dir_all(dir)?;
    }
    figure(
        &args.chart,
        "two lights per hit (Brigade §6.2.3) against single-pick NEE, CPU tracer, It's About Time",
        &panels,
    )?;
    println!("\nwrote {}", args.chart.display());
    Ok(())
}

/// The disc's weight in the pick: luminance × solid angle (a delta sun: its irradiance's
/// luminance); 0 without a disc.
fn disc_weight(u: &GpuFrameUniforms) -> f32 {
    let luminance = |c: [f32; 3]| 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    if u.sun_solid_angle < 0.0 {
        0.0
    } else if u.sun_solid_angle == 0.0 {
        luminance(u.sun_radiance)
    } else {
        luminance(u.sun_radiance) * u.sun_solid_angle
    }
}

/// The single pick's chance of the disc for `u` (the same rule as the tracers'
/// `pick_chances`: the disc's luminance × solid angle against the triangles' total weight).
fn disc_chance(u: &GpuFrameUniforms) -> f32 {
    let disc = disc_weight(u);
    let triangles = if u.light_count > 0 {
        u.light_weight_total.max(0.0)
    } else {
        0.0
    };
    if disc + triangles > 0.0 {
        disc / (disc + triangles)
    } else {
        0.0
    }
}
