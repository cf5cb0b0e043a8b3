//! The stability suite: where path tracers break, on purpose, for both tracers.
//!
//! * **Energy**: a sphere of each material model under a constant white sky never shows more
//!   than the sky (furnace test); lossless models (a perfect mirror of reflectance 1, clear
//!   smooth glass) show exactly the sky. Tolerance: 4.5 standard errors of the image mean (from
//!   independent batches) + 1e-4 relative. Rough models (conductor, glass, metal-rough) must
//!   also keep at least their single-scatter GGX albedo: over the pixels that see the sphere
//!   at cos θ ≥ 0.2, the mean is at least the mean of the per-pixel bounds of
//!   `candela_tests::furnace_bound` (quadrature, not the code under test; for glass, reflection
//!   plus the light refracted in and out again) less the same tolerance, so a black or dimmed
//!   sphere fails.
//! * **NaN and infinity**: 1,000 frames over adversarial geometry — degenerate (zero-area and
//!   collinear) triangles, zero-area emitters, zero and NaN normals, zero-length tangents with a
//!   normal map, roughness 0 and 1e-8 and 1, grazing views — give no NaN or infinite pixel, and
//!   no sample is even dropped for being non-finite (the tracers count those).

use candela::assets::{
    Material, MaterialKind, Mesh, Model, Placement, SceneDesc, SceneInstance, SkyDesc, Texture,
    TextureRef,
};
use candela::render::{FrameSettings, Tracer, frame_uniforms};
use candela::scene::RenderScene;
use candela_tests::{
    Which, camera, furnace_bound, icosphere, open, render_batches, single_mesh_model,
};
use glam::{Mat4, Vec2, Vec3, Vec4};

fn material(kind: MaterialKind, roughness: f32, metallic: f32) -> Material {
    Material {
        kind,
        base_color: Vec3::ONE,
        roughness,
        metallic,
        ior: 1.5,
        ..Material::default()
    }
}

fn furnace(which: Which, name: &str, m: Material, exact: bool) {
    let mesh = smooth(icosphere(Vec3::ZERO, 1.0, 4, false));
    let bounds = (!exact).then(|| {
        assert!(furnace_bound::is_grey(&m));
        furnace_bound::pixel_bounds(&m, &mesh, 24, 2.6, 50.0)
    });
    let sphere = single_mesh_model(mesh, m);
    let mut desc = SceneDesc::single(sphere, camera(Vec3::new(0.0, 0.0, 2.6), Vec3::ZERO, 50.0));
    desc.sky = SkyDesc::Constant([1.0, 1.0, 1.0]);
    desc.render.max_bounces = 64;
    desc.render.roulette_start = 64;
    let b = render_batches(which, &desc, 24, 24, 16, 6, 5).expect("render");
    let stat = b.region(|_, _| true);
    for c in 0..3 {
        let tolerance = 4.5 * stat.std_error[c] + 1e-4;
        assert!(
            stat.mean[c] <= 1.0 + tolerance,
            "{name} ({which:?}) gains energy: channel {c} mean {} ± {}",
            stat.mean[c],
            stat.std_error[c]
        );
        if exact {
            assert!(
                (stat.mean[c] - 1.0).abs() <= tolerance,
                "{name} ({which:?}) is lossless but shows {} ± {}",
                stat.mean[c],
                stat.std_error[c]
            );
        }
    }
    if let Some(bounds) = bounds {
        let inside = |x: u32, y: u32| bounds[(y * 24 + x) as usize].is_some();
        let count = bounds.iter().flatten().count();
        assert!(count >= 100, "{name}: only {count} pixels bounded");
        let bound = bounds.iter().flatten().sum::<f64>() / count as f64;
        let stat = b.region(inside);
        for c in 0..3 {
            let tolerance = 4.5 * stat.std_error[c] + 1e-4;
            assert!(
                stat.mean[c] >= bound - tolerance,
                "{name} ({which:?}) loses energy: channel {c} mean {:.4} ± {:.4} over {count} pixels, below the single-scatter GGX bound {bound:.4}",
                stat.mean[c],
                stat.std_error[c]
            );
        }
        eprintln!(
            "{name} ({which:?}): sphere mean {:.4} ± {:.4}, single-scatter bound {bound:.4}",
            stat.mean[1], stat.std_error[1]
        );
    }
}

/// The icosphere with exact sphere normals (smooth shading).
fn smooth(mut mesh: Mesh) -> Mesh {
    mesh.normals = Some(mesh.positions.iter().map(|p| p.normalize()).collect());
    mesh
}

fn every_material(which: Which) {
    let mut mirror = material(MaterialKind::Conductor, 0.0, 0.0);
    mirror.base_color = Vec3::ONE;
    furnace(which, "perfect mirror", mirror, true);
    furnace(
        which,
        "smooth glass",
        material(MaterialKind::Dielectric, 0.0, 0.0),
        true,
    );
    furnace(
        which,
        "rough conductor",
        material(MaterialKind::Conductor, 0.5, 0.0),
        false,
    );
    furnace(
        which,
        "rough glass",
        material(MaterialKind::Dielectric, 0.4, 0.0),
        false,
    );
    furnace(
        which,
        "diffuse",
        material(MaterialKind::Diffuse, 1.0, 0.0),
        true,
    );
    furnace(
        which,
        "metal-rough plastic",
        material(MaterialKind::MetalRough, 0.3, 0.0),
        false,
    );
    furnace(
        which,
        "metal-rough metal",
        material(MaterialKind::MetalRough, 0.3, 1.0),
        false,
    );
    let mut glassy = material(MaterialKind::MetalRough, 0.2, 0.0);
    glassy.transmission = 0.5;
    furnace(which, "metal-rough transmissive", glassy, false);
}

#[test]
fn cpu_furnace_for_every_material() {
    every_material(Which::Cpu);
}

#[test]
fn gpu_furnace_for_every_material() {
    every_material(Which::Gpu);
}

/// A scene built to break things.
fn adversarial() -> SceneDesc {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    let mut triangle_materials = Vec::new();
    let mut normals = Vec::new();
    let mut tangents = Vec::new();
    let mut uvs = Vec::new();
    let mut add = |p: [Vec3; 3], n: [Vec3; 3], t: Vec4, m: u32| {
        let base = positions.len() as u32;
        positions.extend(p);
        normals.extend(n);
        tangents.extend([t; 3]);
        uvs.extend([Vec2::ZERO, Vec2::X, Vec2::Y]);
        triangles.push([base, base + 1, base + 2]);
        triangle_materials.push(m);
    };
    let up = [Vec3::Y; 3];
    // A floor split in two triangles, both with zero normals (flat fallback) and zero tangents.
    for (a, b, c) in [
        (
            Vec3::new(-5.0, 0.0, -5.0),
            Vec3::new(-5.0, 0.0, 5.0),
            Vec3::new(5.0, 0.0, 5.0),
        ),
        (
            Vec3::new(-5.0, 0.0, -5.0),
            Vec3::new(5.0, 0.0, 5.0),
            Vec3::new(5.0, 0.0, -5.0),
        ),
    ] {
        add([a, b, c], [Vec3::ZERO; 3], Vec4::ZERO, 0);
    }
    // Degenerate triangles: zero area, collinear, duplicate points; one of them emissive.
    add([Vec3::ONE; 3], up, Vec4::ZERO, 1);
    add([Vec3::ZERO, Vec3::X, Vec3::X * 2.0], up, Vec4::ZERO, 1);
    add(
        [Vec3::Y, Vec3::Y, Vec3::new(1.0, 1.0, 0.0)],
        up,
        Vec4::ZERO,
        2,
    );
    // Slabs of every rough extreme, tilted, with NaN and opposite-facing normals.
    let nan = Vec3::splat(f32::NAN);
    for (i, m) in [2u32, 3, 4, 5, 6, 7].iter().enumerate() {
        let x = i as f32 * 1.4 - 3.5;
        let a = Vec3::new(x, 0.2, -1.0);
        let b = Vec3::new(x + 1.0, 1.5, -1.2);
        let c = Vec3::new(x + 0.2, 1.6, 0.8);
        add(
            [a, b, c],
            [nan, -Vec3::Y, Vec3::Y],
            Vec4::new(1.0, 0.0, 0.0, -1.0),
            *m,
        );
        add([a, c, b], [Vec3::ZERO, Vec3::X, Vec3::Y], Vec4::ZERO, *m);
    }
    // A proper little emitter so that light sampling has something to do.
    add(
        [
            Vec3::new(-0.5, 3.0, -0.5),
            Vec3::new(0.5, 3.0, -0.5),
            Vec3::new(0.0, 3.0, 0.5),
        ],
        [-Vec3::Y; 3],
        Vec4::ZERO,
        1,
    );
    let count = triangles.len();
    assert_eq!(triangle_materials.len(), count);
    let flat = Texture {
        name: "normal map".into(),
        width: 1,
        height: 1,
        texels: vec![[0.5, 0.5, 1.0, 1.0].map(half::f16::from_f32)],
        ..Default::default()
    };
    let emitter = Material {
        base_color: Vec3::ZERO,
        emission: Vec3::splat(50.0),
        two_sided_emission: true,
        ..Material::default()
    };
    let mut mirror = material(MaterialKind::Conductor, 0.0, 0.0);
    mirror.normal_texture = Some(TextureRef(0));
    let model = Model {
        name: "adversarial".into(),
        meshes: vec![Mesh {
            name: "adversarial".into(),
            positions,
            normals: Some(normals),
            uvs: Some(uvs),
            tangents: Some(tangents),
            triangles,
            triangle_materials,
        }],
        materials: vec![
            Material {
                normal_texture: Some(TextureRef(0)),
                ..material(MaterialKind::Diffuse, 1.0, 0.0)
            },
            emitter,
            mirror,
            material(MaterialKind::Conductor, 1e-8, 0.0),
            material(MaterialKind::Dielectric, 1e-8, 0.0),
            material(MaterialKind::Dielectric, 1.0, 0.0),
            material(MaterialKind::MetalRough, 0.0, 0.5),
            material(MaterialKind::MetalRough, 1.0, 1.0),
        ],
        textures: vec![flat],
        placements: vec![Placement {
            mesh: 0,
            model_from_mesh: Mat4::IDENTITY,
        }],
        notes: Vec::new(),
    };
    let mut desc = SceneDesc::single(
        model,
        camera(Vec3::new(0.3, 0.05, 6.0), Vec3::new(0.0, 0.8, 0.0), 70.0),
    );
    desc.instances.push(SceneInstance::placed(
        0,
        Mat4::from_scale(Vec3::new(1.0, 1.0, 1e-7)),
    ));
    desc.sky = SkyDesc::Gradient {
        zenith: [0.3, 0.4, 0.8],
        horizon: [1.0, 1.0, 1.0],
        ground: [0.1, 0.1, 0.1],
    };
    desc.sun = Some(candela::assets::SunDesc {
        direction: [0.3, 0.1, 0.2],
        irradiance: [5.0; 3],
        angular_radius_deg: 0.0,
    });
    desc
}

fn no_nan(which: Which) {
    let desc = adversarial();
    let scene = RenderScene::build(&desc);
    let mut tracer: Box<dyn Tracer> = open(which, &scene).expect("tracer");
    let mut dropped = 0;
    for frame in 0..1000u32 {
        let s = FrameSettings::new(8, 8, 1, 3, &desc.render).continuing(frame);
        let u = frame_uniforms(
            &desc.camera,
            desc.sun.as_ref(),
            &desc.sky,
            &s,
            &scene.header(),
        );
        dropped += tracer.render(&scene, &u).expect("render").counts.dropped;
        if frame % 100 == 99 {
            let film = tracer.film().expect("film");
            assert!(
                film.mean.iter().all(|p| p.is_finite()),
                "{which:?}: non-finite pixel by frame {frame}"
            );
        }
    }
    let film = tracer.film().expect("film");
    assert!(film.mean.iter().all(|p| p.is_finite()));
    assert!(
        film.mean.iter().any(|p| p.max_element() > 0.0),
        "the scene is lit"
    );
    assert_eq!(
        dropped, 0,
        "{which:?}: {dropped} samples were non-finite and dropped"
    );
}

#[test]
fn cpu_no_nan_over_adversarial_geometry() {
    no_nan(Which::Cpu);
}

#[test]
fn gpu_no_nan_over_adversarial_geometry() {
    no_nan(Which::Gpu);
}
