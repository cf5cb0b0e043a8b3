//! Visible laser beams (`sim::triggers::beam_geometry`) in the engine's frame loop, headless:
//! a laser leaves a crate along +X, a mirror yawed 45° turns it to +Z, a wall stops it. The
//! beam's pieces are placed on the traced path (ends within 1 mm), do not change the path
//! (the same path with the beam on and off), follow the mirror when it turns, enter the light
//! table, and on a CPU render show their emission and light the floor below them more than the
//! render noise can explain.

use std::path::PathBuf;

use crate::common::mean_and_error;
use candela::app::{Engine, SpawnedLevel, Step};
use candela::assets::{AssetRoot, CameraDesc};
use candela::ecs::{GlobalTransform, Transform};
use candela::level::load_level;
use candela::render::cpu::CpuTracer;
use candela::render::{FrameSettings, RenderConfig, Tracer, frame_uniforms};
use candela::sim::triggers::{BeamPool, BeamSegment, LaserPath};
use candela::trace::Ray;
use glam::{Quat, Vec3};

struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The beam of the test level: radiance (1, 0.2, 0.1) × 20, 0.12 m wide (over two pixels of
/// the test render at the camera's distance, so a pixel on its axis sees nothing else).
const BEAM: &str = "Some((color: (1, 0.2, 0.1), strength: 20, radius: 0.06))";
const RADIANCE: Vec3 = Vec3::new(20.0, 4.0, 2.0);

fn level(beam: &str) -> String {
    format!(
        r#"Level(
    materials: [(name: "grey", kind: Diffuse), (name: "mirror", kind: Conductor)],
    boxes: [(name: "floor", size: (12, 0.2, 12), material: "grey"),
            (name: "crate", size: (0.5, 0.5, 0.5), material: "grey"),
            (name: "pane", size: (0.05, 1, 1), material: "mirror"),
            (name: "wall", size: (0.1, 2, 4), material: "grey")],
    camera: (position: (-0.3, 2.2, -3.5), look_at: (-0.3, 0.6, 0), vertical_fov_deg: 50),
    sky: Constant((0.02, 0.02, 0.02)),
    instances: [
        (model: "floor", name: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "crate", name: "emitter", transform: (translation: (-2, 1, 0))),
        (model: "pane", name: "mirror", dynamic: true,
            transform: (translation: (1, 1, 0), rotation_deg: (0, 45, 0))),
        (model: "wall", name: "wall", transform: (translation: (1, 1, 3), rotation_deg: (0, 90, 0))),
    ],
    gameplay: (lasers: [(instance: "emitter", origin: (0.3, 0, 0), direction: (1, 0, 0),
                         beam: {beam})]),
)"#
    )
}

/// The test level with `beam` (a `beam:` value), spawned in an engine (CPU tracer, 16×8).
fn engine(name: &str, beam: &str) -> anyhow::Result<(Engine, SpawnedLevel, CameraDesc, Scratch)> {
    let dir = std::env::temp_dir().join(format!("candela_beams_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let scratch = Scratch(dir.clone());
    let path = dir.join("beams.ron");
    std::fs::write(&path, level(beam))?;
    let level = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&level.scene),
    )?;
    let spawned = engine.spawn_level(&level);
    Ok((engine, spawned, level.scene.camera, scratch))
}

/// `n` frames of 1/60 s (one fixed step each).
fn frames(engine: &mut Engine, n: u32) -> anyhow::Result<()> {
    for _ in 0..n {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let _ = engine.rendered();
    }
    Ok(())
}

fn path(engine: &Engine, emitter: hecs::Entity) -> anyhow::Result<LaserPath> {
    Ok((*engine.world().get::<&LaserPath>(emitter)?).clone())
}

/// Asserts that the segment entities of `emitter` lie on its path: piece `i` maps the unit
/// beam's axis ends (0,0,0) and (0,0,1) onto the path's points `i`, `i+1` within 1 mm (in
/// its `Transform` and in the `GlobalTransform` the extractor reads), the rest are hidden.
fn assert_beams_on_path(engine: &Engine, emitter: hecs::Entity) -> anyhow::Result<()> {
    let path = path(engine, emitter)?;
    let pool = (*engine.world().get::<&BeamPool>(emitter)?).clone();
    let pieces: Vec<(Vec3, Vec3)> = path.segments().collect();
    assert!(pieces.len() <= pool.segments.len());
    for (i, &segment) in pool.segments.iter().enumerate() {
        let tag = *engine.world().get::<&BeamSegment>(segment)?;
        assert_eq!((tag.laser, tag.index), (emitter, i as u32));
        let local = engine.world().get::<&Transform>(segment)?.matrix();
        let global = engine.world().get::<&GlobalTransform>(segment)?.0;
        for m in [local, global] {
            match pieces.get(i) {
                Some(&(a, b)) => {
                    let (p0, p1) = (m.transform_point3(Vec3::ZERO), m.transform_point3(Vec3::Z));
                    assert!((p0 - a).length() < 1e-3, "piece {i}: starts {p0}, path {a}");
                    assert!((p1 - b).length() < 1e-3, "piece {i}: ends {p1}, path {b}");
                    let width = m.transform_vector3(Vec3::X).length();
                    assert!((width - 2.0 * pool.radius).abs() < 1e-6, "{width}");
                }
                None => assert_eq!(m.transform_vector3(Vec3::ONE), Vec3::ZERO, "piece {i}"),
            }
        }
    }
    Ok(())
}

#[test]
fn beam_pieces_follow_the_path_and_do_not_change_it() -> anyhow::Result<()> {
    let (mut on, spawned, _, _a) = engine("on", BEAM)?;
    let (mut off, spawned_off, _, _b) = engine("off", "None")?;
    frames(&mut on, 3)?;
    frames(&mut off, 3)?;
    let emitter = spawned.by_name["emitter"];
    let traced = path(&on, emitter)?;
    assert_eq!(traced.points.len(), 3, "start, mirror, wall: {traced:?}");
    assert_eq!(traced.stopped_at, Some(spawned.by_name["wall"]));
    assert_beams_on_path(&on, emitter)?;
    // The beam is in the scene the laser's queries read, yet the path is the one traced
    // without it: queries pass through beam pieces.
    let without = path(&off, spawned_off.by_name["emitter"])?;
    assert_eq!(traced.points, without.points);
    assert!(
        off.world()
            .get::<&BeamPool>(spawned_off.by_name["emitter"])
            .is_err()
    );
    // Its pieces are emitters: 8 triangles for each of the two pieces, none without the beam.
    assert_eq!(off.scene().lights.count, 0);
    assert_eq!(on.scene().lights.count, 16);
    drop(on.shutdown());
    drop(off.shutdown());
    Ok(())
}

#[test]
fn turning_the_mirror_moves_the_beam_with_the_path() -> anyhow::Result<()> {
    let (mut engine, spawned, _, _dir) = engine("turn", BEAM)?;
    let (emitter, mirror) = (spawned.by_name["emitter"], spawned.by_name["mirror"]);
    frames(&mut engine, 3)?;
    let before = path(&engine, emitter)?;
    // Yawed 30° instead of 45°, the mirror sends the beam off at 60° from −X, past the wall's end.
    engine.world_mut().get::<&mut Transform>(mirror)?.rotation =
        Quat::from_rotation_y(30f32.to_radians());
    // Lasers read the scene of the last commit: the step of this frame still sees the old
    // mirror, the next one the turned mirror.
    frames(&mut engine, 1)?;
    assert_eq!(path(&engine, emitter)?.points, before.points);
    assert_beams_on_path(&engine, emitter)?;
    frames(&mut engine, 1)?;
    let after = path(&engine, emitter)?;
    assert_ne!(after.points, before.points);
    let out = (after.points[2] - after.points[1]).normalize();
    let expected = Vec3::new(-(60f32.to_radians().cos()), 0.0, 60f32.to_radians().sin());
    assert!((out - expected).length() < 1e-3, "{out} against {expected}");
    assert_beams_on_path(&engine, emitter)?;
    drop(engine.shutdown());
    Ok(())
}

/// Renders the engine's scene (its game-side copy, what the last commit holds) `seeds` times
/// at `w × h`, `spp` samples each; every render's film.
fn renders(
    engine: &Engine,
    camera: &CameraDesc,
    (w, h, spp, seeds): (u32, u32, u32, u32),
) -> anyhow::Result<Vec<Vec<Vec3>>> {
    let scene = engine.scene();
    let env = engine.environment();
    let mut out = Vec::new();
    for seed in 0..seeds {
        let settings = FrameSettings::new(w, h, spp, 1000 + seed, &env.render);
        let u = frame_uniforms(camera, None, &env.sky, &settings, &scene.header());
        let mut tracer = CpuTracer::new();
        tracer.render(scene, &u)?;
        out.push(tracer.film()?.mean);
    }
    Ok(out)
}

/// The camera ray through image point (`x`, `y`) in pixels (world space), as the tracers
/// make it (`render/cpu/integrator.rs`, no lens).
fn camera_ray(camera: &CameraDesc, (w, h): (u32, u32), x: f32, y: f32) -> Ray {
    let position = Vec3::from(camera.position);
    let forward = (Vec3::from(camera.look_at) - position).normalize();
    let right = forward.cross(Vec3::from(camera.up)).normalize();
    let up = right.cross(forward);
    let tan_half = (camera.vertical_fov_deg.to_radians() * 0.5).tan();
    let sx = 2.0 * x / w as f32 - 1.0;
    let sy = 1.0 - 2.0 * y / h as f32;
    let d = forward + right * (tan_half * w as f32 / h as f32 * sx) + up * (tan_half * sy);
    Ray::new(position, d.normalize())
}

#[test]
fn the_beam_shows_its_emission_and_lights_the_floor() -> anyhow::Result<()> {
    let (mut on, spawned, camera, _a) = engine("light_on", BEAM)?;
    let (mut off, _, _, _b) = engine("light_off", "None")?;
    frames(&mut on, 3)?;
    frames(&mut off, 3)?;
    let (w, h, spp, seeds) = (192, 144, 4, 6);
    let lit = renders(&on, &camera, (w, h, spp, seeds))?;
    let dark = renders(&off, &camera, (w, h, spp, seeds))?;
    let queries = on.queries();
    let is_beam =
        |e: Option<hecs::Entity>| e.is_some_and(|e| on.world().get::<&BeamSegment>(e).is_ok());
    let floor = spawned.by_name["floor"];
    let (mut beam_pixels, mut floor_pixels) = (Vec::new(), Vec::new());
    for py in 0..h {
        for px in 0..w {
            let at = |dx: f32, dy: f32| {
                queries.closest(&camera_ray(&camera, (w, h), px as f32 + dx, py as f32 + dy))
            };
            // A pixel shows nothing but the beam when the beam covers the camera's view of it
            // prefiltered: every sample in the pixel sees the beam over a strip two pixels
            // wide around it (`render/cpu/lines.rs`), so the beam must cover the pixel and one
            // pixel all round (its centre and the corners of that 3×3 block).
            let corners = [
                (0.5, 0.5),
                (-1.0, -1.0),
                (2.0, -1.0),
                (-1.0, 2.0),
                (2.0, 2.0),
            ];
            if corners
                .iter()
                .all(|&(dx, dy)| is_beam(at(dx, dy).and_then(|h| h.entity)))
            {
                beam_pixels.push((py * w + px) as usize);
            }
            // Floor under the first piece (x from −1.7 to 1, z = 0), within 0.6 m of it.
            let centre = queries.closest_where(
                &camera_ray(&camera, (w, h), px as f32 + 0.5, py as f32 + 0.5),
                |e| !is_beam(e),
            );
            if let Some(hit) = centre
                && hit.entity == Some(floor)
                && hit.position.z.abs() < 0.6
                && (-1.5..0.8).contains(&hit.position.x)
            {
                floor_pixels.push((py * w + px) as usize);
            }
        }
    }
    assert!(beam_pixels.len() >= 10, "{} beam pixels", beam_pixels.len());
    assert!(
        floor_pixels.len() >= 50,
        "{} floor pixels",
        floor_pixels.len()
    );
    // Seen head-on, a fully covered pixel is the beam's radiance: black, emitting, nothing
    // behind it, no noise (f32 sums: 1e-4 relative) where the prefilter's strip lies inside
    // the beam; near the square prism's edges (a cylinder of its half-width is what the
    // prefilter covers) a little less, never more, and the background then shows through
    // (measured: 1,481 of 1,872 pixel renders exact, the dimmest at 0.936 of the beam).
    let mut exact = 0;
    let mut lowest = f32::INFINITY;
    for &p in &beam_pixels {
        for film in &lit {
            let seen = film[p];
            let share = seen / RADIANCE;
            assert!(
                share.max_element() < 1.0 + 1e-4
                    && share.min_element() > 0.9
                    && (share - Vec3::splat(share.x)).abs().max_element() < 0.02,
                "pixel {p}: {seen}, the beam emits {RADIANCE}"
            );
            lowest = lowest.min(share.min_element());
            exact += usize::from((seen - RADIANCE).abs().max_element() < 1e-4 * RADIANCE.x);
        }
        let behind = dark.iter().map(|f| f[p].x).fold(0.0, f32::max);
        assert!(
            behind < 0.1 * RADIANCE.x,
            "without the beam pixel {p} is {behind}"
        );
    }
    eprintln!(
        "{} beam pixel renders: {exact} exact, the dimmest at {lowest:.3} of the beam",
        beam_pixels.len() * lit.len()
    );
    assert!(
        exact * 2 >= beam_pixels.len() * lit.len(),
        "only {exact} of {} beam pixel renders show exactly the beam's radiance",
        beam_pixels.len() * lit.len()
    );
    // The floor below: its mean red over the region, per seed, with the beam and without.
    let region = |films: &[Vec<Vec3>]| -> Vec<f64> {
        films
            .iter()
            .map(|f| {
                floor_pixels.iter().map(|&p| f[p].x as f64).sum::<f64>() / floor_pixels.len() as f64
            })
            .collect()
    };
    let (with, var_with) = mean_and_error(&region(&lit));
    let (without, var_without) = mean_and_error(&region(&dark));
    let sigma = (var_with + var_without).sqrt();
    // Six standard errors: a chance excess of that size has probability below 1e-8.
    assert!(
        with - without > 6.0 * sigma,
        "floor red {with} with the beam, {without} without, σ of the difference {sigma}"
    );
    drop(on.shutdown());
    drop(off.shutdown());
    Ok(())
}

/// Spawning the level again (what the editor's F1 and a restart do: `despawn_level`, then
/// `spawn_level_with` the same models) reuses the laser's beam model: the scene does not grow.
/// Found by the shell soak (`reflect --soak-shell`, `docs/RELIABILITY.md`): every F1 added
/// one beam model per laser.
#[test]
fn spawning_the_level_again_does_not_grow_the_scene() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_beams_again_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let _scratch = Scratch(dir.clone());
    let path = dir.join("beams.ron");
    std::fs::write(&path, level(BEAM))?;
    let level = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&level.scene),
    )?;
    let mut spawned = engine.spawn_level(&level);
    frames(&mut engine, 2)?;
    let sizes = |engine: &Engine| {
        let s = engine.scene();
        (
            s.triangles.len(),
            s.vertices.len(),
            s.materials.len(),
            s.blocks.len(),
        )
    };
    let first = sizes(&engine);
    for again in 1..=4 {
        engine.despawn_level(&spawned, &level);
        spawned = engine.spawn_level_with(&level, Some(spawned.models.clone()));
        frames(&mut engine, 2)?;
        assert_eq!(sizes(&engine), first, "spawned again {again} times");
        let emitter = spawned.by_name["emitter"];
        assert_beams_on_path(&engine, emitter)?;
    }
    Ok(())
}
