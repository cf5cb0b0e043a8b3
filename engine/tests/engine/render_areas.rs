//! Render areas (`render_areas` in a level, `assets::level_render_areas`): the light groups a
//! level names per box of world space, and what they do to the light sampling.
//!
//! * The distribution follows the camera: inside an area the light table holds the emitters of
//!   the groups it names (and those in no group), fewer than all; outside every area, all;
//!   inside two overlapping areas, the union; a group switched off stays out either way.
//! * Unbiased: a floor lit by lamp A (group 1, seen from the area) and lamp B (group 2, out of
//!   the area's sight) behind a wall, direct light only, rendered with the camera in the area
//!   (B out of the table) and with no areas; the region means of the two renders agree within
//!   4.5 σ of their noise on the half of the floor B cannot reach (its contribution is zero by
//!   occlusion) and on the half it lights (B is then reached only by BSDF rays, weighted 1: only
//!   the noise grows), for both light pickers (power and tree). With B's hits weighted as if
//!   NEE could pick it (the integrator's `unsampled` test taken out), the lit half came out 43 %
//!   darker with the power picker (0.108 against 0.190, 31.6 σ), and the test failed.
//! * Bad areas are refused naming the level file and the field.

use std::path::{Path, PathBuf};

use crate::common::mean_and_error;
use candela::app::{Engine, Step};
use candela::assets::{AssetError, AssetRoot, CameraDesc, Level, RenderArea, sampled_groups};
use candela::level::load_level;
use candela::render::cpu::CpuTracer;
use candela::render::{FrameSettings, RenderConfig, Tracer, frame_uniforms};
use glam::Vec3;

struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Emissive triangles of one lamp box (12 triangles).
const LAMP_TRIANGLES: u32 = 12;

/// An 8 × 8 m floor split by a 3 m wall along x = 0; lamp A (group 1) at x = −2, lamp B
/// (group 2) at x = +2, both 1 m above the floor; an ungrouped lamp in a corner (x = z = −3.5);
/// a black sky. The camera looks straight down from 9 m (+x to the right of the image). `areas` is the `render_areas` value,
/// `sampling` the light picker.
fn level(areas: &str, sampling: &str) -> String {
    format!(
        r#"Level(
    materials: [(name: "grey", kind: Diffuse, base_color: (0.7, 0.7, 0.7)),
                (name: "lamp", kind: Diffuse, base_color: (0, 0, 0), emission: (20, 20, 20))],
    boxes: [(name: "floor", size: (8, 0.2, 8), material: "grey"),
            (name: "wall", size: (0.2, 3, 8), material: "grey"),
            (name: "lamp", size: (0.3, 0.3, 0.3), material: "lamp")],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "wall", transform: (translation: (0, 1.5, 0))),
        (model: "lamp", name: "a", transform: (translation: (-2, 1, 0)), light_group: 1),
        (model: "lamp", name: "b", transform: (translation: (2, 1, 0)), light_group: 2),
        (model: "lamp", name: "free", transform: (translation: (-3.5, 0.5, -3.5))),
    ],
    camera: (position: (0, 9, 0), look_at: (0, 0, 0), up: (0, 0, -1), vertical_fov_deg: 50),
    sky: Constant((0, 0, 0)),
    render: (max_bounces: 1, light_sampling: {sampling}),
    render_areas: {areas},
)"#
    )
}

/// The area round the camera's start, seeing group 1 only.
const NEAR: &str = r#"[(name: "near", min: (-1, 8, -1), max: (1, 10, 1), light_groups: [1])]"#;

/// `text` written to a scratch folder and loaded into a headless engine (CPU tracer, 16×8).
fn engine(name: &str, text: &str) -> anyhow::Result<(Engine, Scratch)> {
    let dir = std::env::temp_dir().join(format!("candela_areas_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let scratch = Scratch(dir.clone());
    let path = dir.join("areas.ron");
    std::fs::write(&path, text)?;
    let level = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&level.scene),
    )?;
    let _spawned = engine.spawn_level(&level);
    Ok((engine, scratch))
}

/// One frame of 1/60 s: the upkeep reads the camera and rebuilds the light table.
fn frame(engine: &mut Engine) -> anyhow::Result<()> {
    engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = engine.rendered();
    Ok(())
}

/// The engine's camera moved to `position` (looking down), then one frame; the emitters the
/// light table holds.
fn sampled_at(engine: &mut Engine, position: [f32; 3]) -> anyhow::Result<u32> {
    let camera = CameraDesc {
        position,
        look_at: [position[0], 0.0, position[2]],
        ..engine.environment().default_camera
    };
    engine.set_default_camera(camera);
    frame(engine)?;
    Ok(engine.scene().lights.count)
}

#[test]
fn the_light_table_holds_the_groups_seen_from_the_cameras_area() -> anyhow::Result<()> {
    let areas = r#"[(name: "near", min: (-1, 8, -1), max: (1, 10, 1), light_groups: [1]),
        (name: "east", min: (0.5, 8, -1), max: (4, 10, 1), light_groups: [2])]"#;
    let (mut engine, _dir) = engine("table", &level(areas, "Power"))?;
    let all = 3 * LAMP_TRIANGLES;
    // In "near": group 1 and the ungrouped lamp.
    assert_eq!(
        sampled_at(&mut engine, [0.0, 9.0, 0.0])?,
        2 * LAMP_TRIANGLES
    );
    // Outside every area: all three lamps.
    assert_eq!(sampled_at(&mut engine, [-3.0, 9.0, 0.0])?, all);
    // In "east" alone: group 2 and the ungrouped lamp.
    assert_eq!(
        sampled_at(&mut engine, [3.0, 9.0, 0.0])?,
        2 * LAMP_TRIANGLES
    );
    // In both: the union.
    assert_eq!(sampled_at(&mut engine, [0.75, 9.0, 0.0])?, all);
    // Group 1 switched off stays out of the table outside the areas too.
    engine.set_light_group(1, false);
    assert_eq!(
        sampled_at(&mut engine, [-3.0, 9.0, 0.0])?,
        2 * LAMP_TRIANGLES
    );
    assert_eq!(sampled_at(&mut engine, [0.0, 9.0, 0.0])?, LAMP_TRIANGLES);
    drop(engine.shutdown());
    Ok(())
}

#[test]
fn sampled_groups_are_the_union_of_the_areas_containing_the_point() {
    let area = |name: &str, min: [f32; 3], max: [f32; 3], light_groups: Vec<u32>| RenderArea {
        name: name.into(),
        min,
        max,
        light_groups,
    };
    let areas = [
        area("a", [0.0; 3], [2.0; 3], vec![3, 1]),
        area("b", [1.0; 3], [3.0; 3], vec![1, 2]),
    ];
    assert_eq!(sampled_groups(&areas, [0.5; 3]), Some(vec![1, 3]));
    assert_eq!(sampled_groups(&areas, [1.5; 3]), Some(vec![1, 2, 3]));
    // Faces belong to the box.
    assert_eq!(sampled_groups(&areas, [3.0; 3]), Some(vec![1, 2]));
    assert_eq!(sampled_groups(&areas, [-0.1, 1.0, 1.0]), None);
    assert_eq!(sampled_groups(&[], [0.0; 3]), None);
}

/// Per render (`seeds` of them, `w × h` at `spp`), the mean radiance (luminance-free: RGB
/// mean) over pixel columns `columns` of the image.
fn region_means(
    engine: &Engine,
    (w, h, spp, seeds): (u32, u32, u32, u32),
    regions: &[std::ops::Range<u32>],
) -> anyhow::Result<Vec<Vec<f64>>> {
    let scene = engine.scene();
    let env = engine.environment();
    let mut out = vec![Vec::new(); regions.len()];
    for seed in 0..seeds {
        let settings = FrameSettings::new(w, h, spp, 7000 + seed, &env.render);
        let u = frame_uniforms(
            &env.default_camera,
            None,
            &env.sky,
            &settings,
            &scene.header(),
        );
        let mut tracer = CpuTracer::new();
        tracer.render(scene, &u)?;
        let film = tracer.film()?.mean;
        for (r, columns) in regions.iter().enumerate() {
            let mut sum = 0.0f64;
            for py in 0..h {
                for px in columns.clone() {
                    let v: Vec3 = film[(py * w + px) as usize];
                    sum += f64::from(v.x + v.y + v.z) / 3.0;
                }
            }
            out[r].push(sum / f64::from(h * columns.len() as u32));
        }
    }
    Ok(out)
}

#[test]
fn a_render_with_a_group_out_of_the_table_converges_to_the_one_with_every_group()
-> anyhow::Result<()> {
    for sampling in ["Power", "Tree"] {
        let (mut masked, _a) = engine(&format!("masked_{sampling}"), &level(NEAR, sampling))?;
        let (mut full, _b) = engine(&format!("full_{sampling}"), &level("[]", sampling))?;
        frame(&mut masked)?;
        frame(&mut full)?;
        assert_eq!(masked.scene().lights.count, 2 * LAMP_TRIANGLES);
        assert_eq!(full.scene().lights.count, 3 * LAMP_TRIANGLES);
        // 96 × 72 top-down view, +x to the right, 0.117 m a pixel at the floor (50° over 72
        // rows from 9 m): columns 16..44 are x = −3.7..−0.5, west of the wall (lamp B
        // occluded), 52..80 are x = 0.5..3.7, east of it (lit by B).
        let (w, h, spp, seeds) = (96, 72, 4, 16);
        let regions = [16..44, 52..80];
        let a = region_means(&masked, (w, h, spp, seeds), &regions)?;
        let b = region_means(&full, (w, h, spp, seeds), &regions)?;
        for (r, name) in ["west (B occluded)", "east (B lights it)"]
            .iter()
            .enumerate()
        {
            let (ma, va) = mean_and_error(&a[r]);
            let (mb, vb) = mean_and_error(&b[r]);
            let sigma = (va + vb).sqrt();
            let z = (ma - mb).abs() / sigma;
            eprintln!(
                "{sampling} {name}: masked {ma:.5} ± {:.5}, every group {mb:.5} ± {:.5}, z = {z:.2}",
                va.sqrt(),
                vb.sqrt()
            );
            assert!(
                mb > 0.0 && z < 4.5,
                "{sampling} {name}: masked {ma} against {mb}: {z:.2} σ apart (σ = {sigma})"
            );
        }
        drop(masked.shutdown());
        drop(full.shutdown());
    }
    Ok(())
}

/// The error parsing `areas` in an otherwise good level, checking it names the file.
fn refusal(areas: &str) -> String {
    let path = Path::new("levels/areas.ron");
    match Level::parse(path, &level(areas, "Power")) {
        Err(AssetError::Level { path: p, message }) => {
            assert_eq!(p, path);
            message
        }
        other => panic!("{areas}: expected a level error, got {other:?}"),
    }
}

#[test]
fn bad_areas_are_refused_naming_the_file_and_the_field() -> anyhow::Result<()> {
    for (areas, expected) in [
        (
            r#"[(name: "up", min: (0, 2, 0), max: (1, 1, 1), light_groups: [1])]"#,
            r#"render_areas[0] ("up"): min.y is 2 and max.y is 1"#,
        ),
        (
            r#"[(name: "nan", min: (0, 0, NaN), max: (1, 1, 1), light_groups: [1])]"#,
            "min.z is NaN",
        ),
        (
            r#"[(name: "far", min: (0, 0, 0), max: (1, 1, 1), light_groups: [1, 9])]"#,
            r#"render_areas[0] ("far"): light_groups names group 9, which no instance"#,
        ),
        (
            r#"[(name: " ", min: (0, 0, 0), max: (1, 1, 1), light_groups: [])]"#,
            "render_areas[0] (\" \"): name is empty",
        ),
        (
            r#"[(name: "x", min: (0, 0, 0), max: (1, 1, 1), light_groups: [1]),
                (name: "x", min: (0, 0, 0), max: (2, 2, 2), light_groups: [2])]"#,
            r#"render_areas[1] ("x"): name "x" is used by an earlier area"#,
        ),
    ] {
        let message = refusal(areas);
        assert!(message.contains(expected), "{areas}: {message}");
    }
    // The good level reads back what it declares, and writes it again.
    let good = Level::parse(Path::new("a.ron"), &level(NEAR, "Power"))?;
    assert_eq!(good.render_areas.len(), 1);
    assert_eq!(good.render_areas[0].light_groups, vec![1]);
    let again = Level::parse(Path::new("a.ron"), &ron::to_string(&good)?)?;
    assert_eq!(again.render_areas, good.render_areas);
    Ok(())
}
