//! A scene built with other BLAS parameters (`RenderScene::build_with_blas_params`: an obvhs
//! PLOC preset, one block per leaf) has another tree but renders the same image: same rays,
//! same hits, same random numbers. `bench chart` relies on this to compare layouts by time
//! alone.

use std::path::Path;

use candela::accel::{BlasParams, BuildQuality};
use candela::assets::{AssetRoot, load_scene};
use candela::layout::{INVALID, LEAF_BIT, LEAF_COUNT_SHIFT};
use candela::render::cpu::CpuTracer;
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;

#[test]
fn other_blas_params_change_the_tree_not_the_image() -> anyhow::Result<()> {
    // The capture-script level: a 1,152-triangle pool grid, boxes, lamps, sun and sky.
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/script");
    let desc = load_scene(&assets.join("small.ron"), &AssetRoot::new(&assets)?)?;
    let default = RenderScene::build(&desc);
    let params = BlasParams {
        quality: BuildQuality::Fastest,
        max_leaf_blocks: 1,
        ..BlasParams::default()
    };
    let other = RenderScene::build_with_blas_params(&desc, params);
    // Every BLAS leaf of the other build holds one block; the default packs several.
    let blas_nodes = |s: &RenderScene| s.nodes[..s.tlas_root as usize].to_vec();
    let blocks_per_leaf = |s: &RenderScene| -> Vec<u32> {
        blas_nodes(s)
            .iter()
            .flat_map(|n| n.child)
            .filter(|&c| c != INVALID && c & LEAF_BIT != 0)
            .map(|c| ((c & !LEAF_BIT) >> LEAF_COUNT_SHIFT) + 1)
            .collect()
    };
    assert!(blocks_per_leaf(&other).iter().all(|&b| b == 1));
    assert!(blocks_per_leaf(&default).iter().any(|&b| b > 1));

    let render = |scene: &RenderScene| -> anyhow::Result<Vec<glam::Vec3>> {
        let mut tracer = CpuTracer::new();
        let s = FrameSettings::new(32, 32, 4, 3, &desc.render);
        let sun = desc.sun.as_ref();
        let u = frame_uniforms(&desc.camera, sun, &desc.sky, &s, &scene.header());
        tracer.render(scene, &u)?;
        Ok(tracer.film()?.mean)
    };
    let (a, b) = (render(&default)?, render(&other)?);
    assert!(a.iter().filter(|p| p.max_element() > 0.0).count() > a.len() / 2);
    // Identical up to ties between triangles at exactly the same distance (shared edges),
    // which either tree may break differently: allow a handful of pixels.
    let differing = a
        .iter()
        .zip(&b)
        .filter(|(x, y)| (**x - **y).abs().max_element() > 1e-5);
    assert!(differing.count() <= 4, "images differ beyond edge ties");
    Ok(())
}
