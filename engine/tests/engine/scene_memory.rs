//! `RenderScene::memory` (what `bench memory` reports against Brigade's 737 MB): instancing
//! shares a mesh's triangles and BLAS, so placing it ten times adds instance rows and TLAS
//! nodes only; a texture adds its texels at 8 bytes (RGBA f16) each; the kinds add up to the
//! vectors the tracers read.

use std::path::Path;

use candela::assets::{AssetRoot, SceneInstance, Texture, load_scene};
use candela::layout::{GpuInstance, GpuTexture};
use candela::scene::RenderScene;
use glam::{Mat4, Vec3};

#[test]
fn instancing_shares_storage_and_texels_cost_eight_bytes() -> anyhow::Result<()> {
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/test_scenes/script");
    let desc = load_scene(&assets.join("small.ron"), &AssetRoot::new(&assets)?)?;
    let once = RenderScene::build(&desc);
    let m = once.memory();
    assert!(m.triangles > 0 && m.bvh > 0 && m.instances > 0, "{m:?}");
    assert_eq!(m.instances, once.instances.len() * size_of::<GpuInstance>());
    assert_eq!(
        m.total(),
        m.triangles + m.bvh + m.instances + m.textures + m.lights + m.other
    );

    let mut more = desc.clone();
    let first = more.instances[0].clone();
    for k in 1..=9 {
        let mut copy: SceneInstance = first.clone();
        copy.world_from_model =
            Mat4::from_translation(Vec3::new(0.0, 0.0, 40.0 * k as f32)) * first.world_from_model;
        more.instances.push(copy);
    }
    let ten_scene = RenderScene::build(&more);
    let ten = ten_scene.memory();
    assert_eq!(ten.triangles, m.triangles, "copies store no triangles");
    assert_eq!(ten.instances, m.instances + 9 * size_of::<GpuInstance>());
    // Every BLAS lies before the TLAS root: the copies add no BLAS node, only TLAS nodes.
    assert_eq!(
        ten_scene.tlas_root, once.tlas_root,
        "a copy built its own BLAS"
    );
    assert!(ten.bvh > m.bvh, "the TLAS grows with ten instances");

    let mut textured = desc.clone();
    textured.models[0].textures.push(Texture {
        name: "64²".into(),
        width: 64,
        height: 64,
        texels: vec![[half::f16::ONE; 4]; 64 * 64],
        ..Texture::default()
    });
    let t = RenderScene::build(&textured).memory();
    assert_eq!(
        t.textures,
        m.textures + candela::scene::mips::chain_len(64, 64) * 8 + size_of::<GpuTexture>(),
        "a texture stores its whole mip chain: 64² + 32² + … + 1² texels"
    );
    Ok(())
}
