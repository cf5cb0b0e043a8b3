//! Plain single-pick next-event estimation (`layout::METHOD_SINGLE_PICK`: the sun disc is one
//! more entry of the one light pick) against the default two-light estimator (Brigade §6.2.3:
//! every non-delta hit samples the disc and one triangle). Both are unbiased, so on a scene lit
//! by a sun and an emissive panel at once they converge to the same image:
//! * on the CPU, region means (whole image and 4×4 regions, per channel) of the two estimators,
//!   from independent seeds, agree within 4.5 σ (σ from both renders' batch spreads in
//!   quadrature) + 1e-5 × (1 + |mean|) of f32 rounding (all of it where σ is 0: the sky), for
//!   a sun disc, a delta sun, and single pick over the light tree;
//! * the GPU tracer agrees with the CPU one with the bit set (`gpu_matches_cpu::compare_method`:
//!   the same region test plus the same-paths RMS test).

use candela::assets::{Material, MaterialKind, Mesh, SceneDesc, SceneInstance, SkyDesc, SunDesc};
use candela::layout::{METHOD_DEFAULT, METHOD_LIGHT_TREE, METHOD_SINGLE_PICK};
use candela_tests::{
    Which, camera, icosphere, region_stat, render_batches_with, single_mesh_model,
};
use glam::{Mat4, Vec3};

/// A horizontal quad at height `y` (metres) over [x0, x1] × [z0, z1], facing up or down.
fn quad(y: f32, (x0, x1): (f32, f32), (z0, z1): (f32, f32), up: bool) -> Mesh {
    let corners = if up {
        [(x0, z0), (x0, z1), (x1, z1), (x1, z0)]
    } else {
        [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]
    };
    Mesh {
        name: "quad".into(),
        positions: corners.map(|(x, z)| Vec3::new(x, y, z)).to_vec(),
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0, 0],
        ..Default::default()
    }
}

/// A diffuse floor and sphere under a sun (angular radius `sun_radius_deg`, 0: delta) and a
/// downward-facing emissive panel of 0.36 m² beside the sphere; neither light dominates the
/// pick (panel weight 0.36 × 20 = 7.2 against the sun's ~2.9 W/m²).
pub(crate) fn sun_and_panel(sun_radius_deg: f32) -> SceneDesc {
    let diffuse = |albedo: f32| Material {
        kind: MaterialKind::Diffuse,
        base_color: Vec3::splat(albedo),
        ..Material::default()
    };
    let mut desc = SceneDesc::single(
        single_mesh_model(quad(0.0, (-4.0, 4.0), (-4.0, 4.0), true), diffuse(0.5)),
        camera(Vec3::new(0.0, 2.5, 4.5), Vec3::new(0.3, 0.5, 0.0), 55.0),
    );
    desc.models.push(single_mesh_model(
        icosphere(Vec3::new(0.0, 0.7, 0.0), 0.7, 3, false),
        diffuse(0.7),
    ));
    desc.instances
        .push(SceneInstance::placed(1, Mat4::IDENTITY));
    desc.models.push(single_mesh_model(
        quad(1.6, (1.0, 1.6), (-0.3, 0.3), false),
        Material {
            emission: Vec3::new(20.0, 17.0, 12.0),
            ..diffuse(0.0)
        },
    ));
    desc.instances
        .push(SceneInstance::placed(2, Mat4::IDENTITY));
    desc.sun = Some(SunDesc {
        direction: [0.5, 1.0, 0.3],
        irradiance: [3.0, 2.9, 2.7],
        angular_radius_deg: sun_radius_deg,
    });
    desc.sky = SkyDesc::Constant([0.05, 0.06, 0.08]);
    desc
}

/// Asserts that `a` and `b` (same scene, independent seeds) agree in every region and channel
/// within 4.5 σ (+ rounding); returns the worst |difference| / σ.
pub(crate) fn assert_same_mean(
    label: &str,
    size: u32,
    a: &candela_tests::Batches,
    b: &candela_tests::Batches,
) -> f64 {
    let (am, av) = (a.mean(), a.variance_of_mean());
    let (bm, bv) = (b.mean(), b.variance_of_mean());
    let cell = size / 4;
    let mut worst = 0.0f64;
    for region in 0..17u32 {
        let keep = |x: u32, y: u32| region == 16 || (x / cell + 4 * (y / cell)) == region;
        let sa = region_stat(size, &am, &av, keep);
        let sb = region_stat(size, &bm, &bv, keep);
        for c in 0..3 {
            let sigma = (sa.std_error[c].powi(2) + sb.std_error[c].powi(2)).sqrt();
            let difference = (sa.mean[c] - sb.mean[c]).abs();
            // f32 rounding: the whole tolerance where σ is 0 (a region of constant sky).
            let rounding = 1e-5 * (1.0 + sa.mean[c].abs().max(sb.mean[c].abs()));
            if sigma > 0.0 {
                worst = worst.max(difference / sigma);
            }
            assert!(
                difference <= 4.5 * sigma + rounding,
                "{label}: region {region} channel {c}: first {:.5} ± {:.5}, second {:.5} ± {:.5}",
                sa.mean[c],
                sa.std_error[c],
                sb.mean[c],
                sb.std_error[c]
            );
        }
    }
    eprintln!("{label}: worst {worst:.2} σ");
    worst
}

fn cpu_agrees(label: &str, desc: &SceneDesc, base: u32) {
    let size = 32;
    let render = |method, seed| {
        render_batches_with(Which::Cpu, desc, size, size, 16, 8, seed, method).expect("cpu render")
    };
    let two = render(base, 3);
    let one = render(base | METHOD_SINGLE_PICK, 7);
    let _ = assert_same_mean(label, size, &two, &one);
}

#[test]
fn cpu_single_pick_converges_with_a_sun_disc() {
    cpu_agrees("sun disc", &sun_and_panel(2.0), METHOD_DEFAULT);
}

#[test]
fn cpu_single_pick_converges_with_a_delta_sun() {
    cpu_agrees("delta sun", &sun_and_panel(0.0), METHOD_DEFAULT);
}

#[test]
fn cpu_single_pick_converges_over_the_light_tree() {
    cpu_agrees(
        "light tree",
        &sun_and_panel(2.0),
        METHOD_DEFAULT | METHOD_LIGHT_TREE,
    );
}

/// The GPU tracer's single pick (`pick_chances` in `shaders/direct.wgsl`) matches the CPU's.
#[test]
fn gpu_single_pick_matches_cpu() {
    let _ = crate::gpu_matches_cpu::compare_method(
        "sun and panel, single pick",
        &sun_and_panel(2.0),
        32,
        4,
        METHOD_DEFAULT | METHOD_SINGLE_PICK,
    );
}
