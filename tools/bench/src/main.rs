//! `bench`: the measurements behind `docs/PERFORMANCE.md`, each printed as a Markdown table
//! with the machine it ran on. Speed figures are medians of repeated runs; compare ratios taken
//! in one run, since this VM drifts between runs.
//!
//! * `bench build` — BLAS build time per million triangles, TLAS build time for 10,000 instances.
//! * `bench rays <level> [--asset-root DIR]` — rays per second of the CPU traversal (1 thread and
//!   all threads) and of the GPU traversal (lavapipe without a GPU) for camera, shadow and
//!   diffuse-bounce rays made from the level's camera and lights.
//! * `bench chamber-rays [--chamber N] [--threads T]` — rays per second of the CPU path tracer
//!   on a Reflect chamber's view at its file's camera, as the game renders it, with a film hash
//!   (equal for two builds that trace the same paths).
//! * `bench error` — time for each tracer to reach a fixed relative error against the Cornell
//!   reference, beside Mitsuba 3's time to the same error from its own reference statistics.
//! * `bench chart [--quick] [--scenes …] [--panels …]` — error against time for every
//!   estimator, bounce cap (1–8) and BVH build, on the two reference scenes and two test scenes,
//!   for both tracers: `docs/charts/*.png`, `docs/charts/accuracy.csv` and the generated section
//!   of `docs/ACCURACY.md` (partial runs write under `target/bench-chart/`).
//! * `bench pipeline` — the frame pipeline on the demo level: BVH upkeep per frame against full
//!   rebuilds, commit bytes, the refit/rebuild threshold, ray-query throughput, and the overlap
//!   of game update and render; and upkeep and commit bytes on the wading test level, the water
//!   rippling under the walking explorer (`--only wading`; CSV files beside the tables).
//! * `bench balance [--record]` — Brigade's workload balancers (§4.3, Table 1, Figure 9) and
//!   ours, replayed on recorded per-unit costs of the demo city on simulated tracers
//!   (`tools/bench/data/balance/`, tables in `docs/PERFORMANCE.md`, charts in `docs/charts/`).
//! * `bench ghosting` — error on a fast-moving object and its trail per converging policy
//!   (`ghosting.csv` beside the table; figures in `docs/ACCURACY.md`).
//! * `bench denoise` — the denoiser's time per frame at 320×180 and 1280×720 (CPU, GPU twin)
//!   and its RMSE at 1, 2 and 4 spp with and without, and its bias
//!   (`docs/charts/denoise_rmse.png`, `docs/ACCURACY.md`, `docs/PERFORMANCE.md`).
//! * `bench picture [--quick]` — the error of the picture a Reflect player sees: each chamber's
//!   replay through the game's frame loop at 160×90 and 320×180, denoiser off and on, against
//!   converged renders of the same views, and its frame-to-frame stability
//!   (`docs/charts/picture_error.png`, `docs/ACCURACY.md`).
//! * `bench picture-ruins [--quick]` — the same for It's About Time: each puzzle's replay, frames
//!   with the camera in its render area, the game's settings (render areas on, denoiser on) at
//!   160×90 and 320×180 against converged renders with the full light (`docs/PERFORMANCE.md`).
//! * `bench present [--runs N] [--threads 1,2]` — the CPU compose of the CPU tracer's film
//!   (160×90, 320×180, 480×270) into a 1280×720 window, the F3 overlay drawn on the CPU and the
//!   frame's copy, at 1 and 2 threads, against the code before (`docs/PERFORMANCE.md`).
//! * `bench two-lights` — Brigade's two light samples per hit against single-pick NEE at equal
//!   time, a day and a night view of It's About Time's ruins (`docs/charts/two_lights.png`,
//!   `docs/ACCURACY.md`).

mod balance;
mod balance_plot;
mod balance_pool;
mod balance_record;
mod bounce_budget;
mod build;
mod chamber_rays;
mod chart;
mod chart_methods;
mod chart_plan;
mod chart_reference;
mod chart_scenes;
mod chart_self_ref;
mod denoise;
mod denoise_frame;
mod denoise_plot;
mod denoise_reference;
mod error;
mod ghosting;
mod instance_merge;
mod machine;
mod memory;
mod memory_plot;
mod picture;
#[cfg(test)]
mod picture_check;
mod picture_metrics;
mod picture_outliers;
mod picture_plot;
mod picture_report;
mod picture_ruins;
#[cfg(test)]
mod picture_ruins_check;
mod picture_ruins_report;
mod picture_ruins_run;
mod picture_ruins_stability;
mod picture_run;
mod picture_skip;
mod picture_stability;
mod picture_tracer;
mod pipeline;
mod pipeline_overlap;
mod pipeline_queries;
mod pipeline_refit;
mod pipeline_wading;
mod plot;
mod present;
mod present_before;
mod present_overlay_before;
mod present_overlay_reference;
mod present_reference;
mod rays;
mod report;
mod report_reading;
mod two_lights;
mod two_lights_plot;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "bench", about = "Candela speed measurements")]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// BLAS per million triangles and TLAS for 300, 2,000 and 10,000 instances.
    Build(build::BuildArgs),
    /// Rays per second per tracer and ray kind on a level.
    Rays(rays::RaysArgs),
    /// Rays per second of the CPU path tracer on a Reflect chamber's view, as the game renders it.
    ChamberRays(chamber_rays::ChamberRaysArgs),
    /// The CPU denoise stage's time per frame on a Reflect chamber's view, as the game runs it.
    DenoiseFrame(denoise_frame::DenoiseFrameArgs),
    /// Traversal of a Reflect chamber's two-level scene against its triangles merged into one
    /// BLAS, on the same rays.
    InstanceMerge(instance_merge::InstanceMergeArgs),
    /// Error and frame time of Reflect's chamber views per bounce cap, against a reference
    /// with more bounces: how many bounces a chamber needs in play.
    BounceBudget(bounce_budget::BounceBudgetArgs),
    /// Time to a fixed error against the Cornell reference, beside Mitsuba's.
    Error(error::ErrorArgs),
    /// Error against time for every estimator, bounce cap and BVH build on the reference and
    /// test scenes: CSV, charts, and the generated section of docs/ACCURACY.md.
    Chart(chart_plan::ChartArgs),
    /// The frame pipeline on the demo level: upkeep, refit threshold, queries, overlap.
    Pipeline(pipeline::PipelineArgs),
    /// Error on a fast-moving object and its trail per converging policy.
    Ghosting(ghosting::GhostingArgs),
    /// The denoiser: time per frame (CPU, GPU twin) and RMSE at 1, 2, 4 spp with and without.
    Denoise(denoise::DenoiseArgs),
    /// The error and stability of the picture a Reflect player sees, against converged renders
    /// of the same views.
    Picture(picture::PictureArgs),
    /// The error of the picture an It's About Time player sees per render area, against
    /// converged renders of the same views (render areas off, the full light).
    PictureRuins(picture_ruins::RuinsPictureArgs),
    /// Scene memory by kind (triangles, BVH, instances, textures, lights) for Reflect and a
    /// 1.4 M-triangle ruin, beside Brigade's 737 MB.
    Memory(memory::MemoryArgs),
    /// Two light samples per hit (Brigade §6.2.3) against single-pick NEE at equal time on
    /// It's About Time's ruins, a day and a night view.
    TwoLights(two_lights::TwoLightsArgs),
    /// The CPU compose and overlay of the CPU tracer's film into a 1280×720 window, before and now.
    Present(present::PresentArgs),
    /// Workload balancing schemes replayed on recorded per-unit costs (Table 1, Figure 9).
    Balance(balance::BalanceArgs),
}

fn main() -> anyhow::Result<()> {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let machine = machine::describe();
    println!("{machine}");
    match Args::parse().command {
        Command::Build(a) => build::run(&a),
        Command::Memory(a) => memory::run(&a),
        Command::Rays(a) => rays::run(&a),
        Command::ChamberRays(a) => chamber_rays::run(&a),
        Command::DenoiseFrame(a) => denoise_frame::run(&a),
        Command::InstanceMerge(a) => instance_merge::run(&a),
        Command::BounceBudget(a) => bounce_budget::run(&a),
        Command::Error(a) => error::run(&a),
        Command::Chart(a) => {
            let plan = a.plan()?;
            let outcome = chart::measure(&a, &plan)?;
            report::write(&plan, &outcome, &machine)?;
            println!(
                "bench chart: {:.1} min; wrote {} and {}",
                outcome.seconds / 60.0,
                plan.out.display(),
                plan.doc.display()
            );
            Ok(())
        }
        Command::Pipeline(a) => pipeline::run(&a),
        Command::Ghosting(a) => ghosting::run(&a),
        Command::Denoise(a) => denoise::run(&a),
        Command::Balance(a) => balance::run(&a),
        Command::TwoLights(a) => two_lights::run(&a),
        Command::Picture(a) => picture::run(&a),
        Command::PictureRuins(a) => picture_ruins::run(&a),
        Command::Present(a) => present::run(&a),
    }
}
