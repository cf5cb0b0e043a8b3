//! `bench balance --pool`: the schemes driving a real pool of CPU tracers
//! (`candela::render::balance::CpuPool`, each tracer its own thread pool) on the demo city
//! under the slow camera of the recording, every frame rendered and timed for real.
//!
//! On this 2-core VM the tracers share the cores with each other and with whatever else runs,
//! so this shows that the scheme code runs a real pool and roughly how it fares, not figures to
//! set beside the simulated ones. Owns: the live run and its table. Must not: simulate.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Context;
use candela::assets::{AssetRoot, load_scene};
use candela::render::balance::{
    CpuPool, PoolSpec, PoolTracer, SchemeKind, idle_share, unit_count,
};
use candela::render::film::Film;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;

use super::balance_record::{SPINS, camera_at};

/// Renders `frames` frames per scheme on a pool of `threads` tracers; returns a Markdown table.
pub fn run(
    repo: &Path,
    frames: u32,
    (width, height, spp): (u32, u32, u32),
    threads: &[usize],
) -> anyhow::Result<String> {
    let dir = repo.join("assets/test_scenes/demo");
    let desc = load_scene(&dir.join("demo.ron"), &AssetRoot::new(&dir)?)
        .context("loading the demo level")?;
    let scene = RenderScene::build(&desc);
    let pool = CpuPool::new(threads)?;
    let units = unit_count(height);
    let mut out = format!(
        "### A real pool: {} CPU tracers of {threads:?} threads, slow camera, {frames} frames, \
         {width}×{height} px, {spp} spp\n\n| scheme | mean idle % | worst frame after the first, % | \
         mean frame, ms |\n|---|---:|---:|---:|\n",
        threads.len()
    );
    for kind in SchemeKind::ALL {
        let mut scheme = kind.build(units, threads.len());
        let mut last = None;
        let mut film = Film::new(width, height);
        let (mut idle, mut frame_ms) = (Vec::new(), Vec::new());
        for frame in 0..frames {
            let mut settings = FrameSettings::new(width, height, spp, frame, &desc.render);
            settings.sample_base = frame * spp;
            let u = frame_uniforms(
                &camera_at(SPINS[0], frame),
                desc.sun.as_ref(),
                &desc.sky,
                &settings,
                &scene.header(),
            );
            let split = scheme.next(last.as_ref());
            let times = pool.render(&scene, &u, &split, &mut film)?;
            idle.push(idle_share(&times.tracer_seconds));
            frame_ms.push(times.frame_seconds() * 1e3);
            last = Some(times);
        }
        let mean = idle.iter().sum::<f64>() / idle.len().max(1) as f64;
        let worst = idle.iter().skip(1).copied().fold(0.0, f64::max);
        let ms = frame_ms.iter().sum::<f64>() / frame_ms.len().max(1) as f64;
        let _ = writeln!(
            out,
            "| {} | {:.1} | {:.1} | {ms:.0} |",
            scheme.name(),
            mean * 100.0,
            worst * 100.0
        );
    }
    Ok(out)
}

/// Renders `frames` frames per scheme on a [`PoolTracer`] of the GPU tracer (tracer 0) and
/// `cpu_tracers` one-thread CPU tracers, as the render thread would run it; returns a Markdown
/// table with each tracer's share of the units.
pub fn run_gpu(
    repo: &Path,
    frames: u32,
    (width, height, spp): (u32, u32, u32),
    cpu_tracers: u8,
) -> anyhow::Result<String> {
    let dir = repo.join("assets/test_scenes/demo");
    let desc = load_scene(&dir.join("demo.ron"), &AssetRoot::new(&dir)?)
        .context("loading the demo level")?;
    let scene = RenderScene::build(&desc);
    let mut out = format!(
        "### A real GPU + CPU pool: the GPU tracer and {cpu_tracers} one-thread CPU tracers, \
         slow camera, {frames} frames, {width}×{height} px, {spp} spp\n\n| scheme | mean idle % | \
         worst frame after the first, % | mean frame, ms | GPU's share of the units, last frame |\n\
         |---|---:|---:|---:|---:|\n"
    );
    let mut device = String::new();
    for kind in SchemeKind::ALL {
        let spec = PoolSpec {
            gpu: true,
            cpu_tracers,
            cpu_threads: 1,
            scheme: kind,
        };
        let mut pool = PoolTracer::new(spec, None, &scene)?;
        device = pool.device();
        let (mut idle, mut frame_ms, mut share) = (Vec::new(), Vec::new(), 0.0);
        for frame in 0..frames {
            let mut settings = FrameSettings::new(width, height, spp, frame, &desc.render);
            settings.sample_base = frame * spp;
            let u = frame_uniforms(
                &camera_at(SPINS[0], frame),
                desc.sun.as_ref(),
                &desc.sky,
                &settings,
                &scene.header(),
            );
            pool.render(&scene, &u)?;
            let times = pool.last_times().context("the pool measured its frame")?;
            idle.push(idle_share(&times.tracer_seconds));
            frame_ms.push(times.frame_seconds() * 1e3);
            share = times.split.counts()[0] as f64 / times.split.units() as f64;
        }
        let mean = idle.iter().sum::<f64>() / idle.len().max(1) as f64;
        let worst = idle.iter().skip(1).copied().fold(0.0, f64::max);
        let ms = frame_ms.iter().sum::<f64>() / frame_ms.len().max(1) as f64;
        let _ = writeln!(
            out,
            "| {kind:?} | {:.1} | {:.1} | {ms:.0} | {:.1} % |",
            mean * 100.0,
            worst * 100.0,
            share * 100.0
        );
    }
    let _ = writeln!(out, "\n({device})");
    Ok(out)
}
