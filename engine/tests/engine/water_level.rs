//! Simulated water in a level (issue 35 item 1): a 96 × 96 grid water (18,432 triangles) with
//! `waves.simulate`, a kinematic wader walked through it by the game and a ball dropped into
//! it, run twice through the engine's frame loop, gives identical heights and state hashes at
//! every frame, and the ripples reach the rendered scene; bad `simulate` fields are refused
//! naming the level file, the instance and the field.

use std::path::{Path, PathBuf};

use candela::app::{Engine, Environment, Phase, Step};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::physics::CharacterInput;
use candela::sim::water::WaterSim;
use glam::Vec3;

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Self {
        let path =
            std::env::temp_dir().join(format!("candela_water_{name}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(&path).expect("temp dir");
        Dir(path)
    }
    fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.0.join(name);
        std::fs::write(&p, text).expect("write");
        p
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A pool level: `divisions` per axis on a 12 m grid, the water's `waves`, a floor 0.6 m
/// under the surface, a wader capsule and a ball.
fn level(divisions: &str, waves: &str) -> String {
    format!(
        r#"Level(
    materials: [(name: "water", kind: Dielectric), (name: "grey", kind: Diffuse)],
    grids: [(name: "pool", size: (12, 12), divisions: {divisions}, material: "water"),
            (name: "floor", size: (12, 12), divisions: (1, 1), material: "grey")],
    boxes: [(name: "ball", size: (0.5, 0.5, 0.5), material: "grey")],
    instances: [
        (model: "pool", name: "pool", waves: Some({waves})),
        (model: "floor", transform: (translation: (0, -0.6, 0)), body: Static(shape: Trimesh)),
        (model: "ball", name: "wader", transform: (translation: (-4, 0.3, 0)),
         body: Kinematic(shape: Capsule(half_height: 0.6, radius: 0.3))),
        (model: "ball", name: "ball", transform: (translation: (2, 1.5, 1)),
         body: Dynamic(shape: Sphere(radius: 0.25), mass: 5)),
    ],
    camera: (position: (0, 6, 9), look_at: (0, 0, 0), vertical_fov_deg: 45),
)"#
    )
}

const WAVES: &str = "(amplitude: 0.02, wavelength: 3, speed: 0.6, \
                     simulate: Some((wave_speed: 1.5, damping: 0.4, push: 0.5)))";

/// What one run saw per frame: the state hash, the water's heights, the commit's bytes.
struct Run {
    hashes: Vec<u64>,
    heights: Vec<Vec<f32>>,
    bytes: Vec<usize>,
    /// Seconds per frame in the pose and upkeep phases (printed, never asserted).
    pose: Vec<f64>,
    upkeep: Vec<f64>,
    scene_heights: Vec<f32>,
    hash_sees_water: bool,
}

fn run(frames: usize) -> anyhow::Result<Run> {
    let dir = Dir::new("run");
    let path = dir.write("pool.ron", &level("(96, 96)", WAVES));
    let level = load_level(&path, &AssetRoot::new(&dir.0)?)?;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let (pool, wader) = (spawned.by_name["pool"], spawned.by_name["wader"]);
    let mut out = Run {
        hashes: Vec::new(),
        heights: Vec::new(),
        bytes: Vec::new(),
        pose: Vec::new(),
        upkeep: Vec::new(),
        scene_heights: Vec::new(),
        hash_sees_water: false,
    };
    for _ in 0..frames {
        // The game walks the wader along x at 1.2 m/s, knee deep.
        let mut walk = |step: &mut Step<'_>| {
            let t = (step.index + 1) as f32 * step.step_seconds as f32;
            if let Ok(mut transform) = step.world.get::<&mut Transform>(wader) {
                transform.translation = Vec3::new(-4.0 + 1.2 * t, 0.3, 0.0);
            }
        };
        let report = engine.frame(1.0 / 60.0, &mut walk)?;
        let _ = engine.rendered();
        out.bytes.push(report.commit_bytes);
        out.pose.push(report.phases.get(Phase::Pose));
        out.upkeep.push(report.phases.get(Phase::Upkeep));
        out.hashes.push(engine.state_hash());
        let sim = engine.world().get::<&WaterSim>(pool)?;
        out.heights.push(sim.field.heights().to_vec());
    }
    out.scene_heights = engine
        .scene()
        .vertices
        .iter()
        .map(|v| v.position[1])
        .collect();
    // The hash sees the water itself: a millimetre more at one vertex changes it.
    let before = engine.state_hash();
    engine
        .world_mut()
        .get::<&mut WaterSim>(pool)?
        .field
        .raise(48, 48, 1e-3);
    out.hash_sees_water = engine.state_hash() != before;
    drop(engine.shutdown());
    Ok(out)
}

#[test]
fn two_runs_of_a_wading_level_agree_at_every_frame() -> anyhow::Result<()> {
    let (a, b) = (run(240)?, run(240)?);
    for (i, (x, y)) in a.hashes.iter().zip(&b.hashes).enumerate() {
        assert_eq!(x, y, "frame {i}: state hashes differ");
        assert_eq!(a.heights[i], b.heights[i], "frame {i}: heights differ");
    }
    let last = &a.heights[a.heights.len() - 1];
    let worst = last.iter().fold(0.0f32, |m, h| m.max(h.abs()));
    assert!(worst > 1e-3, "the wader made no ripples ({worst} m)");
    assert!(last.iter().all(|h| h.is_finite()));
    assert!(a.hash_sees_water, "the state hash does not cover the water");
    // The rendered scene carries swell + ripples (the water is the first mesh's vertices).
    assert!(a.scene_heights.iter().all(|h| h.is_finite()));
    let bytes = &a.bytes[60..];
    let mean = bytes.iter().sum::<usize>() / bytes.len();
    let max = bytes.iter().max().copied().unwrap_or(0);
    println!(
        "96x96 simulated water, a wader and a ball: commit bytes per frame mean {mean}, max {max}"
    );
    let ms = |v: &[f64]| v[60..].iter().sum::<f64>() * 1e3 / (v.len() - 60) as f64;
    println!(
        "per frame: pose {:.3} ms (swell + ripples + normals), upkeep {:.3} ms (refit)",
        ms(&a.pose),
        ms(&a.upkeep)
    );
    Ok(())
}

fn refused(name: &str, divisions: &str, waves: &str, expect: &[&str]) {
    let dir = Dir::new(name);
    let path: &Path = &dir.write(&format!("{name}.ron"), &level(divisions, waves));
    let root = AssetRoot::new(&dir.0).expect("root");
    let text = match load_level(path, &root) {
        Ok(_) => panic!("{name}: should be refused"),
        Err(e) => e.to_string(),
    };
    assert!(
        text.contains(&format!("{name}.ron")),
        "no level file: {text}"
    );
    for part in expect {
        assert!(text.contains(part), "{name}: {part:?} missing from: {text}");
    }
}

fn simulate(fields: &str) -> String {
    format!("(amplitude: 0.02, wavelength: 3, speed: 0.6, simulate: Some(({fields})))")
}

#[test]
fn a_water_grid_of_zero_divisions_is_refused() {
    refused("zero", "(0, 96)", WAVES, &["grid \"pool\"", "divisions"]);
}

#[test]
fn a_simulated_water_of_one_division_is_refused() {
    refused(
        "one",
        "(1, 96)",
        WAVES,
        &["instance 0", "waves.simulate", "2 divisions"],
    );
}

#[test]
fn a_nan_or_negative_wave_speed_is_refused() {
    let nan = simulate("wave_speed: NaN, damping: 0.4");
    refused(
        "nan",
        "(96, 96)",
        &nan,
        &["instance 0", "waves.simulate.wave_speed", "NaN"],
    );
    let negative = simulate("wave_speed: -1, damping: 0.4");
    refused(
        "negative",
        "(96, 96)",
        &negative,
        &["waves.simulate.wave_speed", "-1"],
    );
}

#[test]
fn negative_damping_or_push_and_zero_substeps_are_refused() {
    let damping = simulate("wave_speed: 1, damping: -0.1");
    refused(
        "damping",
        "(96, 96)",
        &damping,
        &["waves.simulate.damping", "-0.1"],
    );
    let push = simulate("wave_speed: 1, damping: 0.1, push: inf");
    refused("push", "(96, 96)", &push, &["waves.simulate.push", "inf"]);
    let substeps = simulate("wave_speed: 1, damping: 0.1, substeps: 0");
    refused(
        "substeps",
        "(96, 96)",
        &substeps,
        &["waves.simulate.substeps", "1..=16"],
    );
}

#[test]
fn a_speed_past_the_cfl_limit_is_refused_and_substeps_let_it_through() {
    // Cells of 0.125 m at 1/60 s: the limit is 0.125·60/√2 = 5.30 m/s per substep.
    let fast = simulate("wave_speed: 6, damping: 0.4");
    refused(
        "cfl",
        "(96, 96)",
        &fast,
        &["waves.simulate.wave_speed", "CFL", "5.30"],
    );
    let dir = Dir::new("cfl_ok");
    let ok = simulate("wave_speed: 6, damping: 0.4, substeps: 2");
    let path = dir.write("cfl_ok.ron", &level("(96, 96)", &ok));
    let root = AssetRoot::new(&dir.0).expect("root");
    assert!(
        load_level(&path, &root).is_ok(),
        "two substeps should allow 6 m/s"
    );
}

#[test]
fn simulating_a_model_that_is_not_a_grid_is_refused() {
    let dir = Dir::new("not_grid");
    let text = level("(96, 96)", WAVES).replace(
        r#"(model: "ball", name: "ball","#,
        &format!(r#"(model: "ball", waves: Some({WAVES}), name: "ball","#),
    );
    let path = dir.write("not_grid.ron", &text);
    let root = AssetRoot::new(&dir.0).expect("root");
    let message = match load_level(&path, &root) {
        Ok(_) => panic!("a box cannot be simulated water"),
        Err(e) => e.to_string(),
    };
    for part in ["not_grid.ron", "instance 3", "grid model", "\"ball\""] {
        assert!(message.contains(part), "{part:?} missing from: {message}");
    }
}

/// The explorer (the skinned hero, `common/hero/hero.glb`) walks 3 s through the pool,
/// thigh deep, then stands: the ripples come from the character's capsule through the physics
/// world, and the commit with the water, the explorer and a falling ball stays within
/// Brigade's 2 MB.
#[test]
fn the_explorer_wading_leaves_ripples_and_the_commit_stays_under_2_mb() -> anyhow::Result<()> {
    let assets = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets");
    let dir = Dir::new("hero");
    let hero = r#"characters: [(name: "hero", model: "common/hero/hero.glb", model_yaw_deg: 180,
        spawn: (-4, -0.6, 0), capsule: (height: 1.8, radius: 0.3),
        controller: (walk_speed: 2, run_speed: 5, jump_speed: 4),
        states: [(name: "idle", clip: "idle", contact: Grounded, max_speed_mps: 0.3),
                 (name: "walk", clip: "walk", contact: Grounded, min_speed_mps: 0.3)])],
)"#;
    let text = level("(96, 96)", WAVES)
        .trim_end()
        .trim_end_matches(')')
        .to_string()
        + hero;
    let path = dir.write("hero.ron", &text);
    let level = load_level(&path, &AssetRoot::new(&assets)?)?;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), Environment::of(&level.scene))?;
    let spawned = engine.spawn_level(&level);
    let (pool, body) = (spawned.by_name["pool"], spawned.characters["hero"].body);
    let worst = |engine: &Engine| -> anyhow::Result<f32> {
        let sim = engine.world().get::<&WaterSim>(pool)?;
        Ok(sim
            .field
            .heights()
            .iter()
            .fold(0.0f32, |m, h| m.max(h.abs())))
    };
    // Ten seconds standing (the entry ring dies down), three walking, twenty standing.
    let mut bytes = Vec::new();
    let mut walked = 0.0f32;
    let mut standing = 0.0f32;
    for frame in 0..1980 {
        let walking = (600..780).contains(&frame);
        let mut steer = |step: &mut Step<'_>| {
            if let Ok(mut input) = step.world.get::<&mut CharacterInput>(body) {
                input.move_direction = if walking { Vec3::X } else { Vec3::ZERO };
            }
        };
        let report = engine.frame(1.0 / 60.0, &mut steer)?;
        let _ = engine.rendered();
        if walking {
            bytes.push(report.commit_bytes);
        }
        if frame == 599 {
            standing = worst(&engine)?;
        }
        if frame == 779 {
            walked = worst(&engine)?;
        }
    }
    let settled = worst(&engine)?;
    let feet = engine.world().get::<&Transform>(body)?.translation;
    let max = bytes.iter().max().copied().unwrap_or(0);
    println!(
        "explorer: ripples {standing} m standing, {walked} m after walking, {settled} m settled; \
         body at {feet}; commit bytes while walking: max {max}"
    );
    assert!(feet.x > -1.0, "the explorer did not walk: {feet}");
    assert!(walked > 1e-3, "no wake: {walked} m");
    assert!(
        walked > 10.0 * standing,
        "standing {standing} m vs walking {walked} m"
    );
    assert!(settled < 0.1 * walked, "still rippling: {settled} m");
    assert!(max > 0 && max < 2_000_000, "commit {max} bytes");
    drop(engine.shutdown());
    Ok(())
}
