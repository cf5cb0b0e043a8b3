//! Laser beams read as continuous lines at any resolution, and both tracers draw them alike.
//!
//! A beam is a prism a few millimetres wide (`sim::triggers::beam_model`): at game resolutions
//! it covers a fraction of a pixel, so one sample per pixel hit it in some pixels and missed it
//! in their neighbours (a dotted line). Camera rays now see line emitters prefiltered over the
//! pixel (`render/cpu/lines.rs`, `shaders/shared/lines.wgsl`). Checked here on one frame of one
//! sample per pixel, the way a game's first frame after a change sees it:
//! * every image column the beam crosses shows it (directly, and reflected in a mirror floor),
//!   at 64×36, 160×90 and 320×180;
//! * its brightness summed across the line matches radiance × width seen from that distance
//!   (the prefilter keeps the energy, within 10 %);
//! * the GPU tracer (lavapipe here) draws the same picture as the CPU tracer, and the
//!   prefilter's width is the same constant on both sides.

use candela::assets::{Material, MaterialKind, Mesh, Model, SceneDesc, SceneInstance, SkyDesc};
use candela::layout::MATERIAL_FLAG_LINE;
use candela::render::cpu::lines::{LINE_FOOTPRINT_FIXED_OFFSET, LINE_FOOTPRINT_PIXELS};
use candela::scene::RenderScene;
use candela::sim::triggers::{PlannedBeam, beam_model, segment_transform};
use candela_tests::{Which, camera, render_batches, single_mesh_model};
use glam::Vec3;

/// Radiance of the test beam (red, as Reflect's) and its half-width, metres.
const RADIANCE: Vec3 = Vec3::new(40.0, 3.2, 1.6);
const RADIUS: f32 = 0.005;

/// A horizontal quad of half-size `h` at height `y`, facing +y.
fn floor(y: f32, h: f32) -> Mesh {
    Mesh {
        name: "floor".into(),
        positions: vec![
            Vec3::new(-h, y, -h),
            Vec3::new(-h, y, h),
            Vec3::new(h, y, h),
            Vec3::new(h, y, -h),
        ],
        normals: None,
        uvs: None,
        tangents: None,
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        triangle_materials: vec![0, 0],
    }
}

/// A beam from (−1.5, 0, 0) to (1.5, 0, 0) seen from 4 m, over a mirror floor 1 m below,
/// under a dim sky.
pub fn beam_scene() -> SceneDesc {
    let mirror = single_mesh_model(
        floor(-1.0, 6.0),
        Material {
            kind: MaterialKind::Conductor,
            base_color: Vec3::splat(0.9),
            roughness: 0.0,
            ..Material::default()
        },
    );
    let beam: Model = beam_model(&PlannedBeam {
        radiance: RADIANCE,
        radius: RADIUS,
        light_group: None,
    });
    assert!(
        beam.materials[0].line,
        "the beam's material is a line emitter"
    );
    let mut desc = SceneDesc::single(
        mirror,
        camera(Vec3::new(0.0, 0.3, 4.0), Vec3::new(0.0, -0.3, 0.0), 50.0),
    );
    desc.models.push(beam);
    let t = segment_transform(Vec3::new(-1.5, 0.0, 0.0), Vec3::new(1.5, 0.0, 0.0), RADIUS);
    let mut instance = SceneInstance::placed(1, t.matrix());
    instance.dynamic = true;
    desc.instances.push(instance);
    desc.sky = SkyDesc::Constant([0.02, 0.02, 0.02]);
    desc
}

/// One frame of one sample per pixel, CPU tracer.
fn one_frame(desc: &SceneDesc, width: u32, height: u32) -> Vec<Vec3> {
    let b = render_batches(Which::Cpu, desc, width, height, 1, 1, 7).expect("cpu render");
    b.batches[0].clone()
}

#[test]
fn the_scene_has_one_line() {
    let scene = RenderScene::build(&beam_scene());
    let lines = scene.lines();
    assert_eq!(lines.len(), 1);
    assert!((lines[0].radius - RADIUS).abs() < 1e-6);
    assert!(
        scene
            .materials
            .iter()
            .any(|m| m.flags & MATERIAL_FLAG_LINE != 0)
    );
}

#[test]
fn a_beam_is_continuous_at_any_resolution() {
    let desc = beam_scene();
    let cam = Vec3::from(desc.camera.position);
    let look = (Vec3::from(desc.camera.look_at) - cam).normalize();
    let fov = desc.camera.vertical_fov_deg.to_radians();
    for (width, height) in [(64, 36), (160, 90), (320, 180)] {
        let image = one_frame(&desc, width, height);
        // Columns well inside the beam's span on screen (its ends project to about ±0.45 of
        // the half-width: ±1.5 m at 4 m, 50° vertical, 16:9).
        let span = ((0.18 * width as f32) as u32).max(4);
        let (c0, c1) = (width / 2 - span, width / 2 + span);
        // The beam's row: y = 0 seen from the camera; its mirror image: y = −2.
        let row_of = |p: Vec3| {
            let d = (p - cam).normalize();
            let right = look.cross(Vec3::Y).normalize();
            let up = right.cross(look);
            let sy = d.dot(up) / d.dot(look) / (0.5 * fov).tan();
            ((1.0 - sy) * 0.5 * height as f32) as i64
        };
        // The angle between the centre rays of rows y and y + 1 (centre column).
        let right = look.cross(Vec3::Y).normalize();
        let up = right.cross(look);
        let dir = |y: i64| {
            let sy = 1.0 - 2.0 * (y as f32 + 0.5) / height as f32;
            (look + up * sy * (0.5 * fov).tan()).normalize()
        };
        let row_angle = |y: i64| dir(y).dot(dir(y + 1)).clamp(-1.0, 1.0).acos();
        let footprint_angle = LINE_FOOTPRINT_PIXELS * 2.0 * (0.5 * fov).tan() / height as f32;
        for (what, row, distance) in [
            ("direct", row_of(Vec3::ZERO), (Vec3::ZERO - cam).length()),
            (
                "in the mirror",
                row_of(Vec3::new(0.0, -2.0, 0.0)),
                (Vec3::new(0.0, -2.0, 0.0) - cam).length(),
            ),
        ] {
            let mut worst = f32::INFINITY;
            let mut energy = 0.0f32;
            for x in c0..c1 {
                let mut peak = 0.0f32;
                let mut sum = 0.0f32;
                for y in (row - 3).max(0)..(row + 4).min(height as i64) {
                    let r = image[y as usize * width as usize + x as usize].x;
                    peak = peak.max(r);
                    sum += r;
                }
                worst = worst.min(peak);
                energy += sum;
            }
            let energy = energy / (c1 - c0) as f32 * row_angle(row);
            // Radiance × angular width, red channel (the mirror's 0.9 for the reflection).
            let tint = if what == "direct" { 1.0 } else { 0.9 };
            let expected = RADIANCE.x * tint * 2.0 * RADIUS / distance;
            eprintln!(
                "{width}x{height} {what}: rows near {row}, dimmest column peak {worst:.3}, \
                 energy {energy:.5} vs {expected:.5}"
            );
            // Continuous: every column shows the beam far above the dim background (0.02).
            assert!(
                worst
                    > 0.5 * RADIANCE.x * 2.0 * RADIUS
                        / (distance * footprint_angle).max(2.0 * RADIUS),
                "{width}x{height} {what}: a column of the beam is dark (peak {worst})"
            );
            assert!(
                (energy - expected).abs() < 0.1 * expected + 0.02 * 7.0 * row_angle(row),
                "{width}x{height} {what}: beam brightness {energy} vs {expected}"
            );
        }
    }
}

#[test]
fn both_tracers_draw_the_same_beam() {
    let desc = beam_scene();
    let (w, h) = (64, 36);
    let cpu = render_batches(Which::Cpu, &desc, w, h, 2, 2, 3).expect("cpu");
    let gpu = render_batches(Which::Gpu, &desc, w, h, 2, 2, 3).expect("gpu");
    let (cm, gm) = (cpu.mean(), gpu.mean());
    let beam_pixels = cm.iter().filter(|p| p.x > 1.0).count();
    assert!(
        beam_pixels > w as usize,
        "the beam shows ({beam_pixels} bright pixels)"
    );
    let mut worst = 0.0f32;
    for (c, g) in cm.iter().zip(&gm) {
        worst = worst.max((*c - *g).abs().max_element() / (1.0 + c.abs().max_element()));
    }
    // The beam part is deterministic (no random numbers): agreement to rounding there; the
    // dim floor and sky are the same paths with the same random numbers.
    let bright_diff = cm
        .iter()
        .zip(&gm)
        .filter(|(c, _)| c.x > 1.0)
        .map(|(c, g)| (c.x - g.x).abs() / c.x)
        .fold(0.0f32, f32::max);
    eprintln!("worst relative difference {worst:.2e}, on the beam {bright_diff:.2e}");
    assert!(bright_diff < 1e-3, "the beam differs: {bright_diff}");
    assert!(worst < 0.05, "the pictures differ: {worst}");
}

/// The prefilter's widths (two pixels; one with a fixed per-frame offset, temporal upscaling)
/// are the same numbers in both tracers.
#[test]
fn footprint_constant_agrees() {
    let path = candela_tests::repo().join("shaders/shared/lines.wgsl");
    let text = std::fs::read_to_string(&path).expect("lines.wgsl is readable");
    for (name, expected) in [
        ("LINE_FOOTPRINT_PIXELS", LINE_FOOTPRINT_PIXELS),
        ("LINE_FOOTPRINT_FIXED_OFFSET", LINE_FOOTPRINT_FIXED_OFFSET),
    ] {
        let prefix = format!("const {name}: f32 = ");
        let value: f32 = text
            .lines()
            .find_map(|l| l.strip_prefix(prefix.as_str()))
            .and_then(|v| v.trim_end_matches(';').parse().ok())
            .unwrap_or_else(|| panic!("lines.wgsl declares {name}"));
        assert_eq!(value, expected, "{name}");
    }
}
