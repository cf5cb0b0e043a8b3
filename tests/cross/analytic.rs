//! Scenes with closed-form answers, rendered by both tracers: the sun (delta and disc), the
//! sky, a textured emitter, light through an absorbing glass slab (Fresnel, refraction,
//! Beer–Lambert, radiance scaling, internal reflections), and an emitter under open water
//! (absorption tracked along the path inside the medium, at two depths and two colours).
//!
//! Tolerances: 4.5 standard errors of the image mean (estimated from independent batches, see
//! `candela_tests`) plus 1e-4 relative for f32 rounding where the answer has no noise at all.

use candela::assets::{
    Material, MaterialKind, Mesh, Model, Placement, SceneDesc, SceneInstance, SkyDesc, SunDesc,
    Texture, TextureRef, Wrap,
};
use candela_tests::{Which, camera, render_batches};
use glam::{Mat4, Vec2, Vec3};

/// A quad with corners `a, b, c, d` (counter-clockwise seen from the front), UVs (0,1) (1,1)
/// (1,0) (0,0) at those corners (glTF convention: v down the image).
fn quad(a: Vec3, b: Vec3, c: Vec3, d: Vec3, material: u32) -> Mesh {
    Mesh {
        name: "quad".into(),
        positions: vec![a, b, c, d],
        normals: None,
        uvs: Some(vec![
            Vec2::new(0.0, 1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(0.0, 0.0),
        ]),
        tangents: None,
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![material; 2],
    }
}

/// An axis-aligned box from `lo` to `hi`, faces wound outwards.
fn cuboid(lo: Vec3, hi: Vec3, material: u32) -> Mesh {
    let c =
        |x: usize, y: usize, z: usize| Vec3::new([lo.x, hi.x][x], [lo.y, hi.y][y], [lo.z, hi.z][z]);
    let faces = [
        [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)], // +z
        [c(1, 0, 0), c(0, 0, 0), c(0, 1, 0), c(1, 1, 0)], // -z
        [c(1, 0, 1), c(1, 0, 0), c(1, 1, 0), c(1, 1, 1)], // +x
        [c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)], // -x
        [c(0, 1, 1), c(1, 1, 1), c(1, 1, 0), c(0, 1, 0)], // +y
        [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)], // -y
    ];
    let mut mesh = Mesh {
        name: "box".into(),
        ..Default::default()
    };
    for f in faces {
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(f);
        mesh.triangles
            .extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
    }
    mesh.triangle_materials = vec![material; mesh.triangles.len()];
    mesh
}

fn model(meshes: Vec<Mesh>, materials: Vec<Material>, textures: Vec<Texture>) -> Model {
    Model {
        name: "analytic".into(),
        placements: (0..meshes.len())
            .map(|mesh| Placement {
                mesh,
                model_from_mesh: Mat4::IDENTITY,
            })
            .collect(),
        meshes,
        materials,
        textures,
        notes: Vec::new(),
    }
}

fn scene(model: Model, eye: Vec3, target: Vec3, fov: f32) -> SceneDesc {
    let mut d = SceneDesc::single(model, camera(eye, target, fov));
    d.instances = vec![SceneInstance::placed(0, Mat4::IDENTITY)];
    d
}

fn check(which: Which, label: &str, desc: &SceneDesc, size: u32, spp: u32, expected: [f64; 3]) {
    let b = render_batches(which, desc, size, size, spp, 6, 3).expect("render");
    let stat = b.region(|_, _| true);
    for c in 0..3 {
        let tolerance = 4.5 * stat.std_error[c] + 1e-4 * expected[c].abs();
        let error = (stat.mean[c] - expected[c]).abs();
        assert!(
            error <= tolerance,
            "{label} ({which:?}): channel {c}: {} vs expected {} (|error| {error:.3e} > {tolerance:.3e})",
            stat.mean[c],
            expected[c]
        );
    }
}

fn diffuse(albedo: f32) -> Material {
    Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        ..Material::default()
    }
}

/// A large diffuse floor (albedo 0.5) seen from above, lit by the sun at 30° elevation: every
/// pixel shows L = ρ E sin(30°) / π. The disc sun (radius 1°) gives the same: a uniform cap fully
/// above the horizon delivers E cos θ exactly.
fn sun_on_a_floor(which: Which, radius_deg: f32) {
    let floor = quad(
        Vec3::new(-100.0, 0.0, -100.0),
        Vec3::new(-100.0, 0.0, 100.0),
        Vec3::new(100.0, 0.0, 100.0),
        Vec3::new(100.0, 0.0, -100.0),
        0,
    );
    let mut desc = scene(
        model(vec![floor], vec![diffuse(0.5)], vec![]),
        Vec3::new(0.0, 5.0, 0.1),
        Vec3::ZERO,
        20.0,
    );
    let elevation = 30f32.to_radians();
    desc.sun = Some(SunDesc {
        direction: [elevation.cos(), elevation.sin(), 0.0],
        irradiance: [2.0, 3.0, 4.0],
        angular_radius_deg: radius_deg,
    });
    let expected = [2.0, 3.0, 4.0].map(|e: f64| 0.5 * e * 0.5 / std::f64::consts::PI);
    check(
        which,
        &format!("sun radius {radius_deg}°"),
        &desc,
        16,
        4,
        expected,
    );
}

/// The same floor under a constant sky of radiance S and no sun: L = ρ S.
fn sky_on_a_floor(which: Which) {
    // 200 m across: the camera sees a 0.7 m patch and every bounce leaves upwards, so only the
    // plane matters. (A 20 km quad made 0.2 % of bounce rays hit their own triangle: the
    // distance of a hit carries rounding of the vertices' 1e4 m magnitude, far more than the
    // origin offset at the hit; see docs/ACCURACY.md, "Known limits".)
    let floor = quad(
        Vec3::new(-100.0, 0.0, -100.0),
        Vec3::new(-100.0, 0.0, 100.0),
        Vec3::new(100.0, 0.0, 100.0),
        Vec3::new(100.0, 0.0, -100.0),
        0,
    );
    let mut desc = scene(
        model(vec![floor], vec![diffuse(0.8)], vec![]),
        Vec3::new(0.0, 2.0, 0.1),
        Vec3::ZERO,
        20.0,
    );
    desc.sky = SkyDesc::Constant([0.5, 1.0, 1.5]);
    check(which, "constant sky", &desc, 16, 8, [0.4, 0.8, 1.2]);
}

/// A 4×4-texel emissive texture (nearest filtering) on a quad that exactly fills a 4×4-pixel
/// image: every pixel shows its texel's linear value (sRGB decoded by the loader; here the
/// texels are given linear). Checked per pixel, so a flipped or shifted UV fails.
fn texture_on_screen(which: Which) {
    let texels: Vec<[half::f16; 4]> = (0..16)
        .map(|i| [i as f32 / 16.0, 1.0 - i as f32 / 16.0, 0.25, 1.0].map(half::f16::from_f32))
        .collect();
    let texture = Texture {
        name: "ramp".into(),
        width: 4,
        height: 4,
        texels: texels.clone(),
        wrap_u: Wrap::Clamp,
        wrap_v: Wrap::Clamp,
        nearest: true,
    };
    let emitter = Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::ZERO,
        emission: Vec3::ONE,
        emission_texture: Some(TextureRef(0)),
        ..Material::default()
    };
    // Camera at z = 1 looking down -z with a 90° FOV sees [-1, 1]² on the plane z = 0.
    let q = quad(
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(-1.0, 1.0, 0.0),
        0,
    );
    let desc = scene(
        model(vec![q], vec![emitter], vec![texture]),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::ZERO,
        90.0,
    );
    let b = render_batches(which, &desc, 4, 4, 4, 2, 1).expect("render");
    for (pixel, value) in b.mean().iter().enumerate() {
        let texel = texels[pixel].map(|h| h.to_f32());
        for c in 0..3 {
            assert!(
                (value[c] - texel[c]).abs() <= 1e-5,
                "textured emitter ({which:?}): pixel {pixel} channel {c}: {} vs texel {}",
                value[c],
                texel[c]
            );
        }
    }
}

/// Looking through a 1 m thick glass slab (IOR 1.5, absorption leaving 50 % per metre in red,
/// 80 % in green, none in blue) at an emitter of radiance 1, at near-normal incidence (1° FOV):
/// L = (1 − R)² T / (1 − R² T²), R = ((n − 1)/(n + 1))² = 0.04, T = per-channel transmittance
/// over the 1 m path (the sum over all internal reflections; the 1/η² scaling in and η² out
/// cancel). Everything else is black.
fn absorbing_slab(which: Which) {
    let glass = Material {
        kind: MaterialKind::Dielectric,
        base_color: Vec3::ONE,
        roughness: 0.0,
        ior: 1.5,
        attenuation_color: Vec3::new(0.5, 0.8, 1.0),
        attenuation_distance: 1.0,
        ..Material::default()
    };
    let light = Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::ZERO,
        emission: Vec3::ONE,
        ..Material::default()
    };
    let slab = cuboid(Vec3::new(-50.0, -50.0, -1.0), Vec3::new(50.0, 50.0, 0.0), 0);
    let emitter = quad(
        Vec3::new(-500.0, -500.0, -3.0),
        Vec3::new(500.0, -500.0, -3.0),
        Vec3::new(500.0, 500.0, -3.0),
        Vec3::new(-500.0, 500.0, -3.0),
        1,
    );
    let mut desc = scene(
        model(vec![slab, emitter], vec![glass, light], vec![]),
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::ZERO,
        1.0,
    );
    desc.render.max_bounces = 40;
    desc.render.roulette_start = 40;
    let r = 0.04f64;
    let expected = [0.5f64, 0.8, 1.0].map(|t| (1.0 - r).powi(2) * t / (1.0 - r * r * t * t));
    check(which, "absorbing glass slab", &desc, 16, 32, expected);
}

/// Looking down through open water (one surface, IOR 1.33, no walls or bottom face) at an
/// emitter of radiance 1 lying `depth` metres under it, near-normal incidence (1° FOV): the path
/// is transmitted into the water and reaches the emitter inside it, so the segment is absorbed
/// although it never meets the water's back face. L = (1 − R) e^(−σ d) / η², R = ((η − 1)/(η +
/// 1))², σ = −ln(colour) per metre (the colour left after 1 m); reflections see a black sky.
fn open_water(which: Which, depth: f32, colour: Vec3) {
    let water = Material {
        kind: MaterialKind::Dielectric,
        base_color: Vec3::ONE,
        roughness: 0.0,
        ior: 1.33,
        attenuation_color: colour,
        attenuation_distance: 1.0,
        ..Material::default()
    };
    let light = Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::ZERO,
        emission: Vec3::ONE,
        ..Material::default()
    };
    let corners = |z: f32| {
        [
            Vec3::new(-500.0, -500.0, z),
            Vec3::new(500.0, -500.0, z),
            Vec3::new(500.0, 500.0, z),
            Vec3::new(-500.0, 500.0, z),
        ]
    };
    let [a, b, c, d] = corners(0.0);
    let surface = quad(a, b, c, d, 0);
    let [a, b, c, d] = corners(-depth);
    let emitter = quad(a, b, c, d, 1);
    let desc = scene(
        model(vec![surface, emitter], vec![water, light], vec![]),
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::ZERO,
        1.0,
    );
    let eta = 1.33f64;
    let r = ((eta - 1.0) / (eta + 1.0)).powi(2);
    let expected = colour
        .to_array()
        .map(|c| (1.0 - r) * f64::from(c).powf(f64::from(depth)) / (eta * eta));
    check(
        which,
        &format!("open water {depth} m deep"),
        &desc,
        16,
        32,
        expected,
    );
}

fn open_water_cases(which: Which) {
    for depth in [0.5, 2.0] {
        for colour in [Vec3::new(0.5, 0.8, 1.0), Vec3::new(0.9, 0.6, 0.3)] {
            open_water(which, depth, colour);
        }
    }
}

#[test]
fn cpu_delta_sun() {
    sun_on_a_floor(Which::Cpu, 0.0);
}
#[test]
fn gpu_delta_sun() {
    sun_on_a_floor(Which::Gpu, 0.0);
}
#[test]
fn cpu_disc_sun() {
    sun_on_a_floor(Which::Cpu, 1.0);
}
#[test]
fn gpu_disc_sun() {
    sun_on_a_floor(Which::Gpu, 1.0);
}
#[test]
fn cpu_constant_sky() {
    sky_on_a_floor(Which::Cpu);
}
#[test]
fn gpu_constant_sky() {
    sky_on_a_floor(Which::Gpu);
}
#[test]
fn cpu_textured_emitter() {
    texture_on_screen(Which::Cpu);
}
#[test]
fn gpu_textured_emitter() {
    texture_on_screen(Which::Gpu);
}
#[test]
fn cpu_absorbing_slab() {
    absorbing_slab(Which::Cpu);
}
#[test]
fn gpu_absorbing_slab() {
    absorbing_slab(Which::Gpu);
}
#[test]
fn cpu_open_water() {
    open_water_cases(Which::Cpu);
}
#[test]
fn gpu_open_water() {
    open_water_cases(Which::Gpu);
}

/// Thin lens: whatever point of the lens a camera ray starts from, it passes through the point
/// the pinhole ray of the same pixel position reaches on the plane in focus.
#[test]
fn thin_lens_rays_meet_on_the_focal_plane() {
    use candela::render::cpu::integrator::camera_ray;
    use candela::render::cpu::rng::Rng;
    use candela::render::{FrameSettings, frame_uniforms};
    let mut cam = camera(Vec3::new(1.0, 2.0, 5.0), Vec3::new(0.0, 0.5, 0.0), 35.0);
    cam.aperture_radius = 0.2;
    cam.focus_distance = Some(4.0);
    let settings = FrameSettings::new(64, 48, 1, 0, &Default::default());
    let lens = frame_uniforms(
        &cam,
        None,
        &SkyDesc::default(),
        &settings,
        &Default::default(),
    );
    cam.aperture_radius = 0.0;
    let pinhole = frame_uniforms(
        &cam,
        None,
        &SkyDesc::default(),
        &settings,
        &Default::default(),
    );
    let forward = Vec3::from(lens.camera_forward);
    let mut spread = 0.0f32;
    for sample in 0..256 {
        let (px, py) = (sample % 64, (sample * 7) % 48);
        let a = camera_ray(&pinhole, px, py, &mut Rng::new(px, py, sample, 9));
        let b = camera_ray(&lens, px, py, &mut Rng::new(px, py, sample, 9));
        // Where each ray crosses the plane 4 m in front of the camera.
        let at = |r: &candela::trace::Ray| {
            let t = (4.0 - (r.origin - Vec3::from(lens.camera_position)).dot(forward))
                / r.direction.dot(forward);
            r.origin + r.direction * t
        };
        assert!(
            (at(&a) - at(&b)).length() < 1e-4,
            "sample {sample}: {} vs {}",
            at(&a),
            at(&b)
        );
        spread = spread.max((b.origin - a.origin).length());
    }
    assert!(
        spread > 0.1 && spread <= 0.2 + 1e-5,
        "lens samples cover the aperture: {spread}"
    );
}
