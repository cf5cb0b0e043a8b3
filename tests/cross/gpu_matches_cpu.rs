//! The GPU and CPU tracers run the same algorithm with the same RNG over the same flattened
//! scene, so on the same scene and seed their images agree within Monte-Carlo noise, and in
//! fact sample for sample except where f32 rounding differs between the two (a handful of
//! paths then take another branch and diverge).
//!
//! Checks, on the mirror-and-glass reference scene (every material kind of the reference set,
//! textures aside) and on a textured glTF model:
//! * region means (whole image and 4×4 regions, per channel) agree within 4.5 σ + 1e-5 ×
//!   (1 + |mean|), with σ from both renders' batch spreads added in quadrature (treating them
//!   as independent, the conservative choice: shared random numbers make the true difference
//!   smaller); the 1e-5 term is f32 rounding, and is the whole tolerance where σ is 0 (a
//!   region of constant sky or of black: there the tracers must agree to rounding, not be
//!   skipped);
//! * the images are the same paths: the RMS per-pixel difference is below half the RMS per-pixel
//!   noise of one render. If the tracers diverged everywhere (two independent estimates), the RMS
//!   difference would be √2 times that noise.

use candela::assets::{AssetRoot, SceneDesc, load_scene};
use candela_tests::{Which, external, region_stat, render_batches_with, repo};

/// Compares the tracers on `desc`; returns how many region channels had zero variance.
fn compare(label: &str, desc: &SceneDesc, size: u32, spp: u32) -> usize {
    compare_method(label, desc, size, spp, candela::layout::METHOD_DEFAULT)
}

/// [`compare`] with estimator `method` (`layout::METHOD_*` bits).
pub(crate) fn compare_method(
    label: &str,
    desc: &SceneDesc,
    size: u32,
    spp: u32,
    method: u32,
) -> usize {
    compare_at(label, desc, size, spp, method, 1.0)
}

/// [`compare_method`] for a scene whose radiance is of the order of `unit` (the rounding term
/// of each region's tolerance is 10⁻⁵ · (`unit` + |mean|): with `unit` 1 it is loose for a
/// night's values of 10⁻⁷).
fn compare_at(label: &str, desc: &SceneDesc, size: u32, spp: u32, method: u32, unit: f64) -> usize {
    let render = |which| render_batches_with(which, desc, size, size, spp, 4, 5, method);
    let cpu = render(Which::Cpu).expect("cpu render");
    let gpu = render(Which::Gpu).expect("gpu render");
    let (cm, cv) = (cpu.mean(), cpu.variance_of_mean());
    let (gm, gv) = (gpu.mean(), gpu.variance_of_mean());
    let cell = size / 4;
    let mut worst = 0.0f64;
    let mut zero_variance = 0;
    for region in 0..17u32 {
        let keep = |x: u32, y: u32| region == 16 || (x / cell + 4 * (y / cell)) == region;
        let c = region_stat(size, &cm, &cv, keep);
        let g = region_stat(size, &gm, &gv, keep);
        for ch in 0..3 {
            let sigma = (c.std_error[ch].powi(2) + g.std_error[ch].powi(2)).sqrt();
            let difference = (c.mean[ch] - g.mean[ch]).abs();
            let rounding = 1e-5 * (unit + c.mean[ch].abs().max(g.mean[ch].abs()));
            let tolerance = 4.5 * sigma + rounding;
            if sigma > 0.0 {
                worst = worst.max(difference / sigma);
            } else {
                zero_variance += 1;
            }
            assert!(
                difference <= tolerance,
                "{label}: region {region} channel {ch}: cpu {:.6} gpu {:.6}, |Δ| {difference:.3e} > {tolerance:.3e} (σ {sigma:.3e})",
                c.mean[ch],
                g.mean[ch]
            );
        }
    }
    let n = cm.len() as f64;
    let diff2: f64 = cm
        .iter()
        .zip(&gm)
        .map(|(a, b)| (*a - *b).length_squared() as f64)
        .sum::<f64>()
        / n;
    let noise2: f64 = cv.iter().map(|v| v.iter().sum::<f64>()).sum::<f64>() / n;
    let same = cm
        .iter()
        .zip(&gm)
        .filter(|(a, b)| (**a - **b).abs().max_element() <= 1e-4 * (1.0 + a.abs().max_element()))
        .count();
    eprintln!(
        "{label}: worst region |z| {worst:.2} ({zero_variance} zero-variance region channels compared to rounding); RMS difference {:.2e} vs RMS noise {:.2e}; {:.1} % of pixels equal to 1e-4",
        diff2.sqrt(),
        noise2.sqrt(),
        100.0 * same as f64 / n
    );
    assert!(
        diff2 <= 0.25 * noise2,
        "{label}: the tracers do not follow the same paths: RMS difference {:.3e} vs noise {:.3e}",
        diff2.sqrt(),
        noise2.sqrt()
    );
    zero_variance
}

/// A diffuse sphere under a constant sky: the corner regions see only the sky and have zero
/// variance (every sample returns the sky), so only the rounding tolerance applies there.
#[test]
fn constant_sky_regions_agree_to_rounding() {
    use candela::assets::{Material, MaterialKind, SkyDesc};
    use candela_tests::{camera, icosphere, single_mesh_model};
    use glam::Vec3;
    let sphere = single_mesh_model(
        icosphere(Vec3::ZERO, 1.0, 3, false),
        Material {
            kind: MaterialKind::Diffuse,
            base_color: Vec3::splat(0.6),
            ..Material::default()
        },
    );
    let mut desc = SceneDesc::single(sphere, camera(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 40.0));
    desc.sky = SkyDesc::Constant([0.7, 0.6, 0.5]);
    let zero_variance = compare("constant sky", &desc, 32, 2);
    assert!(
        zero_variance >= 4 * 3,
        "the four corner regions should have zero variance in every channel ({zero_variance} region channels had)"
    );
}

#[test]
fn mirror_glass_scene_agrees() {
    let scene = "cornell_mirror_glass";
    let level = repo().join(format!("assets/test_scenes/reference/{scene}.ron"));
    let root = AssetRoot::new(external().join("reference").join(scene)).expect("root");
    let desc = load_scene(&level, &root).expect("level");
    let _ = compare(scene, &desc, 64, 8);
}

/// Base-colour, metallic-roughness, normal and emissive textures, the metallic-roughness BSDF,
/// generated tangents, a sun with a finite disc, a gradient sky and a thin-lens camera.
#[test]
fn textured_helmet_in_sunlight_agrees() {
    use candela::assets::{SkyDesc, SunDesc, load_model_file};
    let path = external().join("gltf/DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
    let path = if path.exists() {
        path
    } else {
        external().join("gltf/DamagedHelmet/glTF/DamagedHelmet.gltf")
    };
    let model = load_model_file(&path).expect("DamagedHelmet loads");
    let mut camera = candela_tests::camera(glam::Vec3::new(0.0, 0.3, 3.0), glam::Vec3::ZERO, 40.0);
    camera.aperture_radius = 0.05;
    let mut desc = SceneDesc::single(model, camera);
    desc.sun = Some(SunDesc {
        direction: [0.4, 1.0, 0.6],
        irradiance: [3.0, 2.9, 2.7],
        angular_radius_deg: 2.0,
    });
    desc.sky = SkyDesc::Gradient {
        zenith: [0.2, 0.35, 0.7],
        horizon: [0.7, 0.75, 0.8],
        ground: [0.15, 0.12, 0.1],
    };
    let _ = compare("DamagedHelmet", &desc, 48, 4);
}

/// The light tree (`METHOD_LIGHT_TREE`: sampling, and its PMF for MIS at emitters hit by BSDF
/// rays) on the many-room scene of 4,096 emitters, small.
#[test]
fn light_tree_agrees() {
    use candela::layout::{METHOD_DEFAULT, METHOD_LIGHT_TREE};
    let dir = repo().join("assets/test_scenes/many_lights");
    let root = AssetRoot::new(&dir).expect("root");
    let desc = load_scene(&dir.join("rooms.ron"), &root).expect("level");
    let _ = compare_method(
        "many rooms, light tree",
        &desc,
        32,
        4,
        METHOD_DEFAULT | METHOD_LIGHT_TREE,
    );
}

/// The physical sky (`SkyDesc::Physical`: the sky-view table on binding 16 read by
/// `shaders/shared/sky_view.wgsl`, and its sun disc): a diffuse floor and a sphere in
/// afternoon sun, the camera seeing the floor, the sphere's shadow, the horizon and the sky
/// above it, with the sun's azimuth off the camera's axes so both sides of the table's
/// symmetry plane are read.
#[test]
fn physical_sky_agrees() {
    use candela::assets::{Material, MaterialKind, Mesh, SceneInstance, SkyDesc};
    use candela::sky::{HAZE_TURBIDITY_3, PhysicalSky};
    use candela_tests::{camera, icosphere, single_mesh_model};
    use glam::Vec3;
    let h = 20.0;
    let floor = Mesh {
        name: "floor".into(),
        positions: vec![
            Vec3::new(-h, 0.0, -h),
            Vec3::new(-h, 0.0, h),
            Vec3::new(h, 0.0, h),
            Vec3::new(h, 0.0, -h),
        ],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0, 0],
        ..Default::default()
    };
    let diffuse = |albedo: f32| Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        ..Material::default()
    };
    let mut desc = SceneDesc::single(
        single_mesh_model(floor, diffuse(0.5)),
        camera(Vec3::new(0.0, 1.5, 6.0), Vec3::new(0.0, 1.2, 0.0), 70.0),
    );
    let sphere = single_mesh_model(
        icosphere(Vec3::new(0.0, 1.0, 0.0), 1.0, 3, false),
        diffuse(0.7),
    );
    desc.models.push(sphere);
    desc.instances
        .push(SceneInstance::placed(1, glam::Mat4::IDENTITY));
    desc.sun = None;
    desc.sky = SkyDesc::Physical(PhysicalSky {
        sun_elevation_deg: 35.0,
        sun_azimuth_deg: 230.0,
        time: None,
        haze: HAZE_TURBIDITY_3,
        aerosol: candela::sky::Aerosol::TURBIDITY_3,
        ozone: 1.0,
        ground_albedo: [0.3; 3],
        sun_scale: 1.0,
        night_sky: 1.0,
        clouds: None,
    });
    let _ = compare("physical sky", &desc, 32, 4);
}

/// The moonlit night's scene (below), its sky at `night_sky`.
fn moonlit_scene(night_sky: f32) -> SceneDesc {
    use candela::assets::{Material, MaterialKind, Mesh, SceneInstance, SkyDesc};
    use candela::sky::{PhysicalSky, SkyTime};
    use candela_tests::{camera, icosphere, single_mesh_model};
    use glam::Vec3;
    let h = 20.0;
    let floor = Mesh {
        name: "floor".into(),
        positions: vec![
            Vec3::new(-h, 0.0, -h),
            Vec3::new(-h, 0.0, h),
            Vec3::new(h, 0.0, h),
            Vec3::new(h, 0.0, -h),
        ],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0, 0],
        ..Default::default()
    };
    let diffuse = |albedo: f32| Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        ..Material::default()
    };
    let mut desc = SceneDesc::single(
        single_mesh_model(floor, diffuse(0.5)),
        camera(Vec3::new(-6.0, 1.5, 0.0), Vec3::new(4.0, 3.0, 0.0), 70.0),
    );
    desc.models.push(single_mesh_model(
        icosphere(Vec3::new(0.0, 1.0, 0.0), 1.0, 3, false),
        diffuse(0.7),
    ));
    desc.instances
        .push(SceneInstance::placed(1, glam::Mat4::IDENTITY));
    desc.sun = None;
    let sky = PhysicalSky {
        time: Some(SkyTime {
            latitude_deg: 48.1,
            longitude_deg: 11.6,
            year: 2026,
            month: 12,
            day: 23,
            utc_hours: 19.0,
            time_rate: 0.0,
        }),
        night_sky,
        ..PhysicalSky::default()
    };
    // The moonlit sky (the moon's sky-view table after the sun's) is part of what is compared.
    assert!(
        sky.moon_sky().is_ok_and(|m| m.is_some()),
        "the night has no moonlit sky"
    );
    desc.sky = SkyDesc::Physical(sky);
    desc
}

/// A moonlit night (`scene/discs.rs`: the moon is the primary disc, with its phase; stars,
/// airglow and the moonlit sky, `shaders/shared/night.wgsl`, `sky_view.wgsl`): a diffuse floor
/// and a sphere under the moon, the camera looking east and up so the sky with its stars fills
/// the top of the image. The values are ~10⁻⁷ (the rounding term is then loose) and the stars'
/// variance dwarfs the rest; the RMS check, which does not depend on scale, is what holds the
/// tracers to the same paths.
#[test]
fn moonlit_night_agrees() {
    let _ = compare("moonlit night", &moonlit_scene(1.0), 32, 4);
}

/// The same night without stars and airglow, compared at its own scale (rounding 10⁻⁵ of
/// 10⁻⁷): the moonlit sky, the moon's disc and the floor it lights must agree region by region.
#[test]
fn moonlit_sky_agrees() {
    let desc = moonlit_scene(0.0);
    let _ = compare_at(
        "moonlit sky",
        &desc,
        32,
        4,
        candela::layout::METHOD_DEFAULT,
        1e-7,
    );
}
