//! Development aid: times GPU pipeline creation and dispatches on a level.
//! `cargo run --release -p candela --example gpu_timing -- <level.ron> [asset-root] [size] [spp]`
use std::time::Instant;

use candela::assets::{AssetRoot, load_scene};
use candela::render::*;
use candela::scene::RenderScene;

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let level = std::path::PathBuf::from(
        args.get(1)
            .map(String::as_str)
            .unwrap_or("assets/test_scenes/cornell_box.ron"),
    );
    let root = match args.get(2) {
        Some(r) if r != "-" => AssetRoot::new(r)?,
        _ => AssetRoot::new(level.parent().unwrap_or(std::path::Path::new(".")))?,
    };
    let size: u32 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(128);
    let spp: u32 = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(4);
    let desc = load_scene(&level, &root)?;
    let scene = RenderScene::build(&desc);
    let t = Instant::now();
    let ctx = gpu::GpuContext::headless()?;
    let mut tracer = gpu::GpuTracer::new(ctx, &scene)?;
    println!("context + pipeline {:?}", t.elapsed());
    let rounds: u32 = args.get(5).and_then(|s| s.parse().ok()).unwrap_or(3);
    let loop_start = Instant::now();
    for round in 0..rounds {
        let mut settings = FrameSettings::new(
            size,
            size,
            if round == 0 { 1 } else { spp },
            0,
            &desc.render,
        );
        settings.sample_base = round * 100;
        let u = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &settings,
            &scene.header(),
        );
        let s = tracer.render(&scene, &u)?;
        println!(
            "{} spp: {:.3} s, {:.3} M rays/s ({} rays)",
            settings.spp,
            s.seconds,
            s.rays() as f64 / s.seconds / 1e6,
            s.rays()
        );
    }
    println!("{rounds} rounds in {:?}", loop_start.elapsed());
    Ok(())
}
