//! `bench chart`: error against time for the engine's estimators, bounce caps and BVH builds,
//! on the reference scenes and the repo's test scenes, for both tracers; CSV, PNG charts and
//! the generated part of `docs/ACCURACY.md`.
//!
//! For each scene × tracer × curve (`chart_methods.rs`), one render accumulates at doubling
//! sample counts (1, 2, 4, … spp, an exact running mean), and after each stage records the wall
//! time so far (the curves of a scene and tracer advance together, stage by stage), the rays
//! traced, and the error against the scene's reference
//! (`chart_reference.rs`: relative MSE, RMSE, mean bias). References: Mitsuba 3 for the two
//! external scenes, the engine's own converged CPU image for the test scenes
//! (`chart_self_ref.rs`). Curves with equal effective settings are measured once.
//!
//! Owns: the measuring loop with its progress bar (the command line and the plan it implies
//! are in `chart_plan.rs`).
//! Must not: write files other than the self-reference cache (`report.rs` does).

use std::path::PathBuf;
use std::time::Instant;

use candela::assets::SceneDesc;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;

use super::chart_methods::{Config, Layout, METHODS, Method};
use super::chart_plan::{ChartArgs, Plan};
use super::chart_reference::{Reference, errors};
use super::chart_scenes::{RefKind, SceneSpec, build_layouts};
use super::chart_self_ref::{RefSettings, ensure};

/// Seed of every curve's renders (self-references use another, see `chart_self_ref.rs`).
const CURVE_SEED: u32 = 7;

/// One measured point.
#[derive(Clone, Debug)]
pub struct Point {
    pub scene: &'static str,
    pub reference: RefKind,
    pub tracer: &'static str,
    pub method: &'static str,
    /// The curve this one's numbers were measured as, when its settings are the same.
    pub same_as: Option<&'static str>,
    pub spp: u32,
    pub seconds: f64,
    pub rays: u64,
    pub rel_mse: f64,
    pub rmse: f64,
    pub bias: [f64; 3],
    /// Standard error of the reference's image mean per channel (the bias floor we can see).
    pub bias_floor: [f64; 3],
    /// The reference's image mean per channel (for relative bias).
    pub ref_mean: [f64; 3],
}

/// What a run produced besides its points: how each self-reference was made.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    pub points: Vec<Point>,
    /// (scene, folder, rendered in this run) per self-reference.
    pub self_refs: Vec<(&'static str, PathBuf, bool)>,
    /// Wall time of the whole measurement, seconds.
    pub seconds: f64,
}

/// One curve under measurement: its own tracer (hence its own film) and running totals.
struct Curve<'a> {
    method: &'static Method,
    config: Config,
    tracer: Box<dyn Tracer>,
    scene: &'a RenderScene,
    done: u32,
    seconds: f64,
    rays: u64,
    points: Vec<Point>,
}

/// What every curve of one scene × tracer shares.
struct Setting<'a> {
    spec: &'static SceneSpec,
    tracer: &'static str,
    desc: &'a SceneDesc,
    size: u32,
    reference: &'a Reference,
}

impl Curve<'_> {
    /// Renders up to `chunk` more samples towards `stage` into the curve's film (timed);
    /// returns whether the curve reached `stage`.
    fn render_chunk(&mut self, stage: u32, chunk: u32, at: &Setting<'_>) -> anyhow::Result<bool> {
        let desc = at.desc;
        let spp = chunk.min(stage - self.done);
        let mut s = FrameSettings::new(at.size, at.size, spp, CURVE_SEED, &desc.render)
            .continuing(self.done);
        s.max_bounces = self.config.max_bounces;
        s.roulette_start = self.config.roulette_start;
        s.method = self.method.method;
        s.roulette_scale = self.method.roulette_scale;
        let sun = desc.sun.as_ref();
        let u = frame_uniforms(&desc.camera, sun, &desc.sky, &s, &self.scene.header());
        let started = Instant::now();
        let stats = self.tracer.render(self.scene, &u)?;
        self.seconds += started.elapsed().as_secs_f64();
        self.rays += stats.rays();
        self.done += spp;
        Ok(self.done == stage)
    }

    /// Records a point at the samples rendered so far (not timed: reads the film back).
    fn record(&mut self, at: &Setting<'_>) -> anyhow::Result<()> {
        let e = errors(&self.tracer.film()?.mean, at.reference);
        self.points.push(Point {
            scene: at.spec.name,
            reference: at.spec.reference,
            tracer: at.tracer,
            method: self.method.name,
            same_as: None,
            spp: self.done,
            seconds: self.seconds,
            rays: self.rays,
            rel_mse: e.rel_mse,
            rmse: e.rmse,
            bias: e.bias,
            bias_floor: e.bias_floor,
            ref_mean: at.reference.image_mean,
        });
        Ok(())
    }
}

/// Most samples per pixel one render call of a curve traces: a sixteenth of its last stage's
/// total, so that its time is spread over the run in short pieces between the other curves'.
pub fn chunk_spp(max_spp: u32) -> u32 {
    (max_spp / 16).max(1)
}

/// The sample counts of a curve: 1, 2, 4, … up to `max_spp`.
pub fn stages(max_spp: u32) -> Vec<u32> {
    std::iter::successors(Some(1u32), |s| s.checked_mul(2))
        .take_while(|&s| s <= max_spp)
        .collect()
}

/// The curves of `plan` on a level with `desc`'s settings, and the first curve of each
/// distinct configuration (the ones to render).
fn curves(plan: &Plan, desc: &SceneDesc) -> (Vec<&'static Method>, Vec<&'static Method>) {
    let methods: Vec<&Method> = METHODS.iter().filter(|m| m.in_any(&plan.panels)).collect();
    let mut distinct: Vec<&Method> = Vec::new();
    for m in &methods {
        if !distinct
            .iter()
            .any(|d| d.config(&desc.render) == m.config(&desc.render))
        {
            distinct.push(m);
        }
    }
    (methods, distinct)
}

/// Runs every curve of `plan`, with a progress bar over measured points. The curves of one
/// scene and tracer advance together, stage by stage and within a stage in round-robin chunks
/// of [`chunk_spp`] (each curve its own tracer and film), so that a busy spell of this shared
/// machine slows all of them alike instead of one curve: their time ratios are what the
/// charts compare.
pub fn measure(args: &ChartArgs, plan: &Plan) -> anyhow::Result<Outcome> {
    let started = Instant::now();
    let descs: Vec<SceneDesc> = plan
        .scenes
        .iter()
        .map(|s| s.load(&args.external))
        .collect::<anyhow::Result<_>>()?;
    let stages_per_curve: usize = plan
        .tracers
        .iter()
        .map(|&t| {
            stages(if t == "gpu" {
                plan.gpu_spp
            } else {
                plan.cpu_spp
            })
            .len()
        })
        .sum();
    let total: usize = descs
        .iter()
        .map(|d| curves(plan, d).1.len() * stages_per_curve)
        .sum();
    let progress = indicatif::ProgressBar::new(total as u64);
    progress.set_style(
        indicatif::ProgressStyle::with_template(
            "{msg}\n[{bar:40}] {pos}/{len} points, {elapsed} (eta {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let mut outcome = Outcome::default();
    let mut context = None;
    for (spec, desc) in plan.scenes.iter().copied().zip(&descs) {
        let (methods, distinct) = curves(plan, desc);
        let layouts: Vec<Layout> = Layout::ALL
            .into_iter()
            .filter(|l| distinct.iter().any(|m| m.layout == *l))
            .collect();
        let mut built = build_layouts(desc, &layouts);
        built
            .entry(Layout::Default)
            .or_insert_with(|| RenderScene::build(desc));
        let default_scene = &built[&Layout::Default];
        let ref_dir = match spec.mitsuba_dir(&args.external) {
            Some(dir) => dir,
            None => {
                let settings = RefSettings {
                    refs: &args.refs,
                    spp: plan.ref_spp,
                    refresh: args.refresh_refs,
                };
                let (dir, rendered) = ensure(
                    settings,
                    spec.name,
                    desc,
                    default_scene,
                    spec.cpu_size,
                    &progress,
                )?;
                outcome.self_refs.push((spec.name, dir.clone(), rendered));
                dir
            }
        };
        for &tracer_name in &plan.tracers {
            let (size, max_spp) = if tracer_name == "gpu" {
                (spec.gpu_size, plan.gpu_spp)
            } else {
                (spec.cpu_size, plan.cpu_spp)
            };
            let reference = Reference::load(&ref_dir, size)?;
            let at = Setting {
                spec,
                tracer: tracer_name,
                desc,
                size,
                reference: &reference,
            };
            progress.set_message(format!("{} {tracer_name}: setting up", spec.name));
            let mut running = Vec::new();
            for &method in &distinct {
                let scene = built.get(&method.layout).unwrap_or(default_scene);
                let mut tracer: Box<dyn Tracer> = if tracer_name == "gpu" {
                    let context = match &context {
                        Some(c) => std::sync::Arc::clone(c),
                        None => context
                            .insert(candela::render::gpu::GpuContext::headless()?)
                            .clone(),
                    };
                    Box::new(candela::render::gpu::GpuTracer::new(context, scene)?)
                } else {
                    Box::new(candela::render::cpu::CpuTracer::new())
                };
                // Warm-up (the GPU compiles its shader on the first dispatch).
                let warm = FrameSettings::new(size, size, 1, 99, &desc.render);
                let sun = desc.sun.as_ref();
                let u = frame_uniforms(&desc.camera, sun, &desc.sky, &warm, &scene.header());
                tracer.render(scene, &u)?;
                tracer.clear();
                running.push(Curve {
                    method,
                    config: method.config(&desc.render),
                    tracer,
                    scene,
                    done: 0,
                    seconds: 0.0,
                    rays: 0,
                    points: Vec::new(),
                });
            }
            let chunk = chunk_spp(max_spp);
            for stage in stages(max_spp) {
                progress.set_message(format!(
                    "{} {tracer_name}: {} curves at {stage} spp",
                    spec.name,
                    running.len()
                ));
                // Round robin in chunks, so that no curve's time is one long stretch.
                let mut open: Vec<usize> = (0..running.len()).collect();
                while !open.is_empty() {
                    let mut still = Vec::new();
                    for i in open {
                        let curve = &mut running[i];
                        if curve.render_chunk(stage, chunk, &at)? {
                            curve.record(&at)?;
                            progress.inc(1);
                        } else {
                            still.push(i);
                        }
                    }
                    open = still;
                }
            }
            for method in &methods {
                let config = method.config(&desc.render);
                let Some(curve) = running.iter().find(|c| c.config == config) else {
                    continue;
                };
                let same_as = (curve.method.name != method.name).then_some(curve.method.name);
                outcome.points.extend(curve.points.iter().map(|p| Point {
                    method: method.name,
                    same_as,
                    ..p.clone()
                }));
            }
        }
    }
    progress.finish_and_clear();
    outcome.seconds = started.elapsed().as_secs_f64();
    Ok(outcome)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stages_double_up_to_the_limit() {
        assert_eq!(stages(1), [1]);
        assert_eq!(stages(64), [1, 2, 4, 8, 16, 32, 64]);
        assert_eq!(stages(100).last(), Some(&64));
        assert_eq!(stages(u32::MAX).len(), 32);
        assert_eq!((chunk_spp(256), chunk_spp(64), chunk_spp(4)), (16, 4, 1));
    }
}
