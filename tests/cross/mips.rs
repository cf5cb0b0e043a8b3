//! Texture mip levels chosen by ray cones, in both tracers (`render/cpu/cone.rs`,
//! `render/cpu/texture.rs`, twin `shaders/shared/texture.wgsl`): a checker minified far below
//! one texel per pixel converges to its mean grey with far less per-frame variance than the
//! same checker read on level 0, and the two tracers pick the same levels.

use candela::assets::{
    Material, MaterialKind, Mesh, Model, Placement, SceneDesc, SceneInstance, SkyDesc, Texture,
    TextureRef, Wrap,
};
use candela_tests::{Which, camera, render_batches};
use glam::{Mat4, Vec2, Vec3};

/// A `size²` checker of 0.2 and 0.8 (linear) in cells of `cell` texels: mean 0.5.
fn checker(size: u32, cell: u32, nearest: bool) -> Texture {
    let texels = (0..size * size)
        .map(|i| {
            let (x, y) = (i % size / cell, i / size / cell);
            let v = if (x + y) % 2 == 0 { 0.2 } else { 0.8 };
            [v, v, v, 1.0].map(half::f16::from_f32)
        })
        .collect();
    Texture {
        name: "checker".into(),
        width: size,
        height: size,
        texels,
        wrap_u: Wrap::Repeat,
        wrap_v: Wrap::Repeat,
        nearest,
    }
}

/// The 2 m square at z = 0 textured by `texture` (diffuse, albedo = texture), under a constant
/// white sky, seen from z = 1 with a 90° field of view: it fills the picture and every pixel
/// shows L = albedo (every bounce leaves into the sky).
fn textured_square(texture: Texture) -> SceneDesc {
    let mesh = Mesh {
        name: "square".into(),
        positions: vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ],
        normals: None,
        uvs: Some(vec![
            Vec2::new(0.0, 1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(0.0, 0.0),
        ]),
        tangents: None,
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0; 2],
    };
    let material = Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::ONE,
        base_color_texture: Some(TextureRef(0)),
        ..Material::default()
    };
    let model = Model {
        name: "mips".into(),
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        meshes: vec![mesh],
        materials: vec![material],
        textures: vec![texture],
        notes: Vec::new(),
    };
    let mut desc = SceneDesc::single(model, camera(Vec3::Z, Vec3::ZERO, 90.0));
    desc.instances = vec![SceneInstance::placed(0, Mat4::IDENTITY)];
    desc.sky = SkyDesc::Constant([1.0, 1.0, 1.0]);
    desc
}

/// Overall mean (red) and the mean over pixels of the variance between 1-spp frames.
fn mean_and_frame_variance(which: Which, desc: &SceneDesc) -> (f64, f64) {
    let b = render_batches(which, desc, 16, 16, 1, 8, 7).expect("render");
    let mean = b.mean();
    let k = b.batches.len() as f64;
    let overall = mean.iter().map(|m| m.x as f64).sum::<f64>() / mean.len() as f64;
    let variance = (0..mean.len())
        .map(|p| {
            b.batches
                .iter()
                .map(|f| (f[p].x as f64 - mean[p].x as f64).powi(2))
                .sum::<f64>()
                / (k - 1.0)
        })
        .sum::<f64>()
        / mean.len() as f64;
    (overall, variance)
}

/// 512² one-texel checker over 16×16 pixels: 32 texels per pixel (λ ≈ 5 at the centre). With
/// mips every level read is the grey mean; on level 0 (nearest) each sample is 0.2 or 0.8.
fn minified_checker_is_grey(which: Which) {
    let (mipped, mipped_var) =
        mean_and_frame_variance(which, &textured_square(checker(512, 1, false)));
    let (level0, level0_var) =
        mean_and_frame_variance(which, &textured_square(checker(512, 1, true)));
    eprintln!(
        "minified checker ({which:?}): mips mean {mipped:.5} frame variance {mipped_var:.3e}; level 0 mean {level0:.5} frame variance {level0_var:.3e}"
    );
    // f16 rounding of 0.2 and 0.8 and of the levels' means: within 1e-3 of 0.5.
    assert!(
        (mipped - 0.5).abs() < 1e-3,
        "{which:?}: mipped mean {mipped}"
    );
    assert!(
        mipped_var * 100.0 < level0_var,
        "{which:?}: frame variance with mips {mipped_var:.3e} is not far below level 0's {level0_var:.3e}"
    );
}

#[test]
fn cpu_minified_checker_is_grey_and_steady() {
    minified_checker_is_grey(Which::Cpu);
}

#[test]
fn gpu_minified_checker_is_grey_and_steady() {
    minified_checker_is_grey(Which::Gpu);
}

/// 256² checker of 8-texel cells over 32×32 pixels: λ from 3 at the centre up towards the
/// corners, where level 3 still shows the checker and level 4 is grey, so the stochastic pick
/// between levels shows in the picture; the two tracers must agree path for path.
#[test]
fn gpu_picks_the_same_levels_as_cpu() {
    let desc = textured_square(checker(256, 8, false));
    crate::gpu_matches_cpu::compare_method(
        "mip levels",
        &desc,
        32,
        4,
        candela::layout::METHOD_DEFAULT,
    );
}
