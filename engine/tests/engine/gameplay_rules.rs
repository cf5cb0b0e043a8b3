//! Trigger rules in the engine's frame loop (headless, CPU tracer at 16×8, 1 spp), one case
//! each: a door that needs two plates, a volume that notices only the player (with enter,
//! stay and exit events), and a laser that reaches a receiver over a mirror until a rule turns
//! the mirror matte (the `Material` action on a static instance, seen by the next frame's ray
//! queries).

use std::path::PathBuf;

use candela::app::{Engine, SpawnedLevel, Step};
use candela::assets::AssetRoot;
use candela::audio::Bus;
use candela::ecs::Transform;
use candela::level::load_level;
use candela::render::RenderConfig;
use candela::sim::physics::{CharacterController, CharacterInput, character_bundle};
use candela::sim::triggers::{LaserPath, OccupantKind, Outcome, Phase, VolumeEvent};
use glam::Vec3;

struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const HEAD: &str = r#"
    materials: [(name: "grey", kind: Diffuse), (name: "mirror", kind: Conductor),
                (name: "matte", kind: Diffuse, base_color: (0.2, 0.2, 0.2)),
                (name: "lamp", kind: Diffuse, emission: (5, 5, 5)),
                (name: "glass", kind: Dielectric, ior: 1.5)],
    boxes: [(name: "floor", size: (12, 0.2, 12), material: "grey"),
            (name: "plate", size: (1, 0.04, 1), material: "grey"),
            (name: "crate", size: (0.5, 0.5, 0.5), material: "grey"),
            (name: "pane", size: (0.05, 1, 1), material: "mirror"),
            (name: "lamp", size: (0.5, 0.05, 0.5), material: "lamp"),
            (name: "slab", size: (0.5, 1, 1), material: "glass"),
            (name: "wall", size: (0.1, 2, 4), material: "grey")],
    camera: (position: (0, 3, 8), look_at: (0, 0, 0), vertical_fov_deg: 50),
"#;

const FLOOR: &str =
    r#"(model: "floor", transform: (translation: (0, -0.1, 0)), body: Static(shape: Box))"#;

/// Loads a level made of `HEAD`, the floor, `instances` and `gameplay`, and spawns it in an
/// engine.
fn engine(
    name: &str,
    instances: &str,
    gameplay: &str,
) -> anyhow::Result<(Engine, SpawnedLevel, Scratch)> {
    let dir = std::env::temp_dir().join(format!("candela_rules_{name}_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let scratch = Scratch(dir.clone());
    let path = dir.join(format!("{name}.ron"));
    std::fs::write(
        &path,
        format!("Level({HEAD} instances: [{FLOOR}, {instances}], gameplay: ({gameplay}))"),
    )?;
    let sounds = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets/common/sounds");
    std::fs::create_dir_all(dir.join("sounds"))?;
    for name in ["hum_loop.wav", "music_loop.wav"] {
        std::fs::copy(sounds.join(name), dir.join("sounds").join(name))?;
    }
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let config = RenderConfig::cpu(16, 8);
    let mut engine = Engine::new(config, candela::app::Environment::of(&scene.scene))?;
    let spawned = engine.spawn_level(&scene);
    Ok((engine, spawned, scratch))
}

/// Runs `frames` frames of 1/60 s (one fixed step each), calling `each` after every frame.
fn frames(
    engine: &mut Engine,
    frames: u32,
    mut each: impl FnMut(&mut Engine, u64),
) -> anyhow::Result<()> {
    for _ in 0..frames {
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        let step = engine.logic().steps();
        each(engine, step);
        let _ = engine.rendered();
    }
    Ok(())
}

fn entered(events: &[VolumeEvent], volume: usize) -> bool {
    events
        .iter()
        .any(|e| e.volume == volume && e.phase == Phase::Enter)
}

#[test]
fn door_needs_both_plates() -> anyhow::Result<()> {
    let (mut engine, spawned, _dir) = engine(
        "plates",
        r#"(model: "plate", name: "a", transform: (translation: (-2, 0.02, 0)),
               body: Sensor(shape: Cuboid(half_extents: (0.5, 0.2, 0.5)))),
           (model: "plate", name: "b", transform: (translation: (2, 0.02, 0)),
               body: Sensor(shape: Cuboid(half_extents: (0.5, 0.2, 0.5)))),
           (model: "crate", transform: (translation: (-2, 0.6, 0)), body: Dynamic(shape: Box)),
           (model: "crate", transform: (translation: (2, 3, 0)), body: Dynamic(shape: Box)),
           (model: "crate", name: "door", transform: (translation: (0, 0.25, -3)))"#,
        r#"animations: [(name: "open", tracks: [(target: "door", property: Translation,
                interpolation: Linear, keys: [(time_seconds: 0, value: [0, 0, 0]),
                                              (time_seconds: 0.5, value: [0, 2, 0])])])],
           volumes: [(name: "a", instance: "a"), (name: "b", instance: "b")],
           rules: [(name: "both", when: All([Occupied("a"), Occupied("b")]),
                    then: [Play(clip: "open")])]"#,
    )?;
    let door = spawned.by_name["door"];
    let (mut a_step, mut b_step, mut moved_step) = (None, None, None);
    frames(&mut engine, 120, |engine, step| {
        let log = engine.logic().last_step();
        if entered(&log.volume_events, 0) {
            a_step.get_or_insert(step);
        }
        if entered(&log.volume_events, 1) {
            b_step.get_or_insert(step);
        }
        let y = engine
            .world()
            .get::<&Transform>(door)
            .map(|t| t.translation.y);
        if moved_step.is_none() && y.is_ok_and(|y| y > 0.25) {
            moved_step = Some(step);
        }
    })?;
    let (a, b) = (a_step.expect("plate a"), b_step.expect("plate b"));
    let moved = moved_step.expect("the door never moved");
    println!("plate a at step {a}, plate b at {b}, door moved at {moved}");
    assert!(
        a + 10 < b,
        "the second crate falls from higher: a {a}, b {b}"
    );
    assert_eq!(moved, b + 1, "the door waits for the second plate");
    let y = engine.world().get::<&Transform>(door)?.translation.y;
    assert!((y - 2.25).abs() < 1e-5, "door at {y}");
    drop(engine.shutdown());
    Ok(())
}

#[test]
fn player_volume_sees_the_player_only() -> anyhow::Result<()> {
    let (mut engine, _spawned, _dir) = engine(
        "player",
        r#"(model: "plate", name: "zone", transform: (translation: (0, 0.02, 0)),
               body: Sensor(shape: Cuboid(half_extents: (1, 1, 1)))),
           (model: "crate", transform: (translation: (0, 0.6, 0.5)), body: Dynamic(shape: Box)),
           (model: "lamp", transform: (translation: (0, 3, 0)), light_group: 4)"#,
        r#"volumes: [(name: "zone", instance: "zone", detects: [Player])],
           rules: [(name: "lamp", when: Entered("zone"), then: [ToggleLights(4)])]"#,
    )?;
    let player = engine.world_mut().spawn(character_bundle(
        Vec3::new(-3.0, 0.95, 0.0),
        1.8,
        0.3,
        CharacterController::default(),
    )?);
    let mut phases = Vec::new();
    let mut walk = |engine: &mut Engine, direction: Vec3, n: u32| {
        if let Ok(mut input) = engine.world_mut().get::<&mut CharacterInput>(player) {
            input.move_direction = direction;
        }
        frames(engine, n, |engine, _| {
            for e in &engine.logic().last_step().volume_events {
                assert_eq!(
                    e.kind,
                    OccupantKind::Player,
                    "only the player counts: {e:?}"
                );
                assert_eq!(e.occupant, player);
                if phases.last() != Some(&e.phase) {
                    phases.push(e.phase);
                }
            }
        })
    };
    // 2 m/s: 3 s to walk from x = -3 into the zone and stand there, then 3 s out again.
    walk(&mut engine, Vec3::X, 90)?;
    assert!(
        !engine.light_group_on(4),
        "entering toggled the lamp off: {phases:?}"
    );
    walk(&mut engine, Vec3::NEG_Z, 100)?;
    assert_eq!(phases, vec![Phase::Enter, Phase::Stay, Phase::Exit]);
    drop(engine.shutdown());
    Ok(())
}

#[test]
fn laser_over_a_mirror_reaches_the_receiver_until_the_mirror_goes_matte() -> anyhow::Result<()> {
    // The beam leaves the emitter along +X, the pane (yawed 45°) turns it to +Z, into the
    // receiver's volume. Reaching it wins, and turns the pane matte: the beam then stops at
    // the pane and leaves the receiver.
    let (mut engine, spawned, _dir) = engine(
        "laser",
        r#"(model: "crate", name: "emitter", transform: (translation: (-2, 1, 0))),
           (model: "pane", name: "mirror", transform: (translation: (1, 1, 0), rotation_deg: (0, 45, 0))),
           (model: "crate", name: "receiver", transform: (translation: (1, 1, 2.5)),
               body: Sensor(shape: Cuboid(half_extents: (0.4, 0.4, 0.4))))"#,
        r#"lasers: [(instance: "emitter", origin: (0.3, 0, 0), direction: (1, 0, 0))],
           volumes: [(name: "receiver", instance: "receiver", detects: [Lasers])],
           rules: [(name: "lit", when: Occupied("receiver"),
                    then: [Win, Material(instance: "mirror", material: "matte")])]"#,
    )?;
    let (emitter, receiver) = (spawned.by_name["emitter"], spawned.by_name["receiver"]);
    let mut phases = Vec::new();
    frames(&mut engine, 6, |engine, _| {
        for e in &engine.logic().last_step().volume_events {
            assert_eq!((e.kind, e.occupant), (OccupantKind::Laser, emitter));
            phases.push(e.phase);
        }
    })?;
    assert_eq!(engine.logic().outcome(), Some(&Outcome::Won("lit".into())));
    assert!(phases.contains(&Phase::Enter), "{phases:?}");
    assert_eq!(phases.last(), Some(&Phase::Exit), "{phases:?}");
    let path: LaserPath = (*engine.world().get::<&LaserPath>(emitter)?).clone();
    assert_eq!(path.points.len(), 2, "stops at the matte pane: {path:?}");
    assert!(
        path.stopped_at == Some(spawned.by_name["mirror"]),
        "{path:?}"
    );
    assert!(engine.logic().volumes().occupants(0).next().is_none());
    let _ = receiver;
    drop(engine.shutdown());
    Ok(())
}

#[test]
fn emitters_and_music_start_with_the_level() -> anyhow::Result<()> {
    let (mut engine, _spawned, _dir) = engine(
        "sound",
        r#"(model: "lamp", name: "lamp", transform: (translation: (1, 3, 0)), light_group: 1)"#,
        r#"sounds: [(name: "hum", path: "sounds/hum_loop.wav"),
                    (name: "theme", path: "sounds/music_loop.wav")],
           music: (sound: "theme", volume: 0.5),
           emitters: [(instance: "lamp", sound: "hum", volume: 0.3)]"#,
    )?;
    frames(&mut engine, 3, |_, _| {})?;
    let played = engine.audio().played();
    assert_eq!(played.len(), 2, "{played:?}");
    let music = played.iter().find(|p| p.bus == Bus::Music).expect("music");
    assert!(music.looped && music.position.is_none(), "{music:?}");
    assert_eq!(engine.audio().volume(Bus::Music), 0.5);
    let hum = played.iter().find(|p| p.bus == Bus::Effects).expect("hum");
    assert!(hum.looped, "{hum:?}");
    assert_eq!(hum.position, Some(Vec3::new(1.0, 3.0, 0.0)));
    assert!((hum.volume - 0.3).abs() < 1e-6);
    let peak = engine
        .audio()
        .recorded_samples()
        .expect("silent")
        .iter()
        .flatten()
        .fold(0.0f32, |m, s| m.max(s.abs()));
    assert!(peak > 0.01, "nothing audible: {peak}");
    drop(engine.shutdown());
    Ok(())
}

#[test]
fn laser_through_a_glass_slab_comes_out_parallel_and_shifted() -> anyhow::Result<()> {
    // A 0.5 m slab of glass (n = 1.5) yawed 30°: the beam refracts in, out again parallel to
    // where it came from, shifted sideways by t·sin(θ − θt)/cos θt with sin θt = sin θ / n.
    let (mut engine, spawned, _dir) = engine(
        "glass",
        r#"(model: "crate", name: "emitter", transform: (translation: (-2, 1, 0))),
           (model: "slab", transform: (translation: (0, 1, 0), rotation_deg: (0, 30, 0))),
           (model: "wall", name: "wall", transform: (translation: (3, 1, 0)))"#,
        r#"lasers: [(instance: "emitter", origin: (0.3, 0, 0), direction: (1, 0, 0))]"#,
    )?;
    frames(&mut engine, 3, |_, _| {})?;
    let emitter = spawned.by_name["emitter"];
    let path: LaserPath = (*engine.world().get::<&LaserPath>(emitter)?).clone();
    assert_eq!(
        path.points.len(),
        4,
        "start, into the glass, out of it, the wall: {path:?}"
    );
    assert_eq!(path.stopped_at, Some(spawned.by_name["wall"]));
    let out = (path.points[3] - path.points[2]).normalize();
    assert!((out - Vec3::X).length() < 1e-4, "leaves parallel: {out}");
    let theta = 30f32.to_radians();
    let theta_t = (theta.sin() / 1.5).asin();
    let shift = 0.5 * (theta - theta_t).sin() / theta_t.cos();
    let measured = path.points[3].z.abs();
    // The beam restarts 1e-4·(1 + |p|) ≈ 2e-4 m off each surface it turns at (`laser.rs`), so
    // two turns may move it sideways by up to about 4e-4 m.
    assert!(
        (measured - shift).abs() < 4e-4,
        "shifted {measured} m, expected {shift} m"
    );
    drop(engine.shutdown());
    Ok(())
}
