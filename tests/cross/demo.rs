//! The demo level (`assets/test_scenes/demo/`): the committed file is exactly what
//! `tools/assetgen` makes; the loaded level has what the frame pipeline is measured on
//! (≥ 200k static triangles, ≥ 100 rigid movers, a ≥ 20k-triangle deforming mesh, several light
//! groups with emitters, a sun and a sky); and `capture --script flythrough.ron` runs it to the
//! end on the CPU tracer at a tiny size, writing every screenshot and the per-frame CSV.

use std::collections::HashSet;

use candela::assets::{AssetRoot, Level, SkyDesc, load_scene};
use clap::Parser;

fn demo_dir() -> std::path::PathBuf {
    candela_tests::repo().join("assets/test_scenes/demo")
}

#[test]
fn committed_demo_is_what_assetgen_makes() -> anyhow::Result<()> {
    let committed = Level::read(&demo_dir().join("demo.ron"))?;
    assert!(
        committed == assetgen::demo_level(),
        "assets/test_scenes/demo/demo.ron is stale: run `cargo run -p assetgen -- demo`"
    );
    Ok(())
}

#[test]
fn demo_level_has_what_the_pipeline_is_measured_on() -> anyhow::Result<()> {
    let path = demo_dir().join("demo.ron");
    let desc = load_scene(&path, &AssetRoot::new(demo_dir())?)?;
    let triangles = |model: usize| -> usize {
        desc.models[model]
            .meshes
            .iter()
            .map(|m| m.triangles.len())
            .sum()
    };
    let static_triangles: usize = desc
        .instances
        .iter()
        .filter(|i| !i.dynamic)
        .map(|i| triangles(i.model))
        .sum();
    let rigid_movers: Vec<&str> = desc
        .instances
        .iter()
        .filter(|i| i.dynamic && i.waves.is_none())
        .filter_map(|i| i.name.as_deref())
        .collect();
    let deforming: Vec<usize> = desc
        .instances
        .iter()
        .filter(|i| i.waves.is_some())
        .map(|i| desc.models[i.model].meshes[0].triangles.len())
        .collect();
    let emitting_groups: HashSet<u32> = desc
        .instances
        .iter()
        .filter(|i| {
            desc.models[i.model]
                .materials
                .iter()
                .any(|m| m.emission.max_element() > 0.0)
        })
        .filter_map(|i| i.light_group)
        .collect();
    eprintln!(
        "demo: {static_triangles} static triangles, {} rigid movers, deforming {deforming:?}, \
         light groups {emitting_groups:?}",
        rigid_movers.len()
    );
    assert!(static_triangles >= 200_000, "{static_triangles}");
    assert!(rigid_movers.len() >= 100, "{}", rigid_movers.len());
    let unique: HashSet<&&str> = rigid_movers.iter().collect();
    assert_eq!(unique.len(), rigid_movers.len(), "mover names are unique");
    assert!(deforming.iter().any(|&t| t >= 20_000), "{deforming:?}");
    assert!(emitting_groups.len() >= 3, "{emitting_groups:?}");
    let sun = desc.sun.expect("the demo has a sun");
    assert!(sun.irradiance.iter().all(|c| *c > 0.0));
    assert!(
        matches!(desc.sky, SkyDesc::Gradient { zenith, .. } if zenith.iter().all(|c| *c > 0.0))
    );
    Ok(())
}

#[test]
fn flythrough_runs_headless_on_the_cpu_tracer() -> anyhow::Result<()> {
    let out = std::env::temp_dir().join(format!("candela_demo_{}", std::process::id()));
    let script = demo_dir().join("flythrough.ron");
    let args = capture::CaptureArgs::parse_from([
        "capture",
        "--script",
        &script.display().to_string(),
        "--out-dir",
        &out.display().to_string(),
        "--tracer",
        "cpu",
        "--width",
        "32",
        "--height",
        "18",
        "--spp",
        "1",
        "--quiet",
    ]);
    let summary = capture::run_script_mode(&args)?;
    eprintln!("{summary}");
    let report = &summary.report;
    assert_eq!(report.frames.len(), 240);
    let stems: Vec<&str> = report.screenshots.iter().map(|s| s.stem.as_str()).collect();
    assert_eq!(stems, ["overview", "city", "street", "pool"]);
    for shot in &report.screenshots {
        let png = shot.png.as_ref().expect("png written");
        let img = image::open(png)?.to_rgb8();
        assert_eq!(img.dimensions(), (32, 18), "{}", png.display());
        // A camera inside a building or a NaN shows as a black film.
        let finite = shot.film.mean.iter().all(|p| p.is_finite());
        let mean = shot.film.image_mean();
        assert!(
            finite && mean.iter().all(|m| *m > 0.0),
            "{}: {mean:?}",
            png.display()
        );
    }
    assert!(out.join("pool.exr").is_file());
    let csv = std::fs::read_to_string(out.join("frames.csv"))?;
    assert_eq!(csv.lines().count(), 241, "header and one row per frame");
    // Every frame after the first refits the pool and rebuilds the TLAS (movers move).
    for t in &report.frames[1..] {
        assert_eq!(
            t.upkeep.blas_refits + t.upkeep.blas_rebuilds,
            1,
            "frame {}",
            t.frame
        );
        assert_eq!(t.upkeep.tlas_builds, 1, "frame {}", t.frame);
        assert!(t.upkeep.instances_written >= 120, "frame {}", t.frame);
    }
    let _ = std::fs::remove_dir_all(&out);
    Ok(())
}
