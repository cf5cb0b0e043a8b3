//! Breakable walls (issue 35 item 6): a wall of four pre-fractured pieces, a boulder with CCD
//! rolled at it. Below the wall's impact speed the boulder is stopped and the wall stands; above
//! it the wall breaks before the boulder touches it and the boulder rolls on through (never
//! stalls), at two speeds; a wall that no speed breaks stops even a boulder that moves further
//! than its own size and the wall's thickness in one step (never tunnels). A `Break` action
//! frees the pieces at any time. The validator refuses a piece that is not an instance, a piece
//! without a body, a `Break` of an unknown breakable and a mass that is not positive.

use std::path::Path;

use candela::app::{Engine, Step};
use candela::assets::{AssetRoot, Level};
use candela::level::{ItemRef, load_level, validate_level};
use candela::render::RenderConfig;
use glam::Vec3;

/// Boulder mass, kg, and radius, m. The wall's front face is at x = −0.125.
const BOULDER_KG: f32 = 200.0;
const BOULDER_RADIUS: f32 = 0.25;
const WALL_FRONT_X: f32 = -0.125;

const LEVEL: &str = r#"Level(
    materials: [(name: "stone", kind: Diffuse)],
    boxes: [(name: "floor", size: (40, 0.2, 8), material: "stone"),
            (name: "brick", size: (0.25, 1, 1), material: "stone"),
            (name: "boulder", size: (0.5, 0.5, 0.5), material: "stone")],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0)), body: Static(shape: Box)),
        (model: "brick", name: "w0", transform: (translation: (0, 0.5, -0.5)), body: Static(shape: Box)),
        (model: "brick", name: "w1", transform: (translation: (0, 0.5, 0.5)), body: Static(shape: Box)),
        (model: "brick", name: "w2", transform: (translation: (0, 1.5, -0.5)), body: Static(shape: Box)),
        (model: "brick", name: "w3", transform: (translation: (0, 1.5, 0.5)), body: Static(shape: Box)),
        (model: "boulder", name: "boulder", transform: (translation: (-4, 0.25, 0)),
         body: Dynamic(shape: Sphere(radius: 0.25), mass: 200, ccd: true)),
    ],
    camera: (position: (0, 3, 8), look_at: (0, 0, 0), vertical_fov_deg: 45),
    gameplay: (
        breakables: [(name: "wall", pieces: ["w0", "w1", "w2", "w3"], impact_speed: Some(6.0),
                      piece_mass: 30)],
        events: ["quake"],
        rules: [(name: "quake", when: Event("quake"), then: [Break("wall")])],
    ),
)"#;

/// What a run saw: whether the wall broke, the boulder's furthest x, its x and speed at the end,
/// and the furthest any piece moved from where it stood (m).
#[derive(Debug)]
struct Run {
    broken: bool,
    furthest_x: f32,
    end_x: f32,
    end_speed: f32,
    piece_moved: f32,
}

/// Loads `level`, rolls the boulder towards the wall at `speed` m/s (0: not at all), sends
/// "quake" at step `quake` if given, and runs `seconds`.
fn roll(level: &str, speed: f32, quake: Option<u32>, seconds: f32) -> anyhow::Result<Run> {
    let dir = std::env::temp_dir().join(format!(
        "candela_breakables_{}_{}",
        std::process::id(),
        (speed * 100.0) as u32
    ));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("wall.ron");
    std::fs::write(&path, level)?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&scene.scene),
    )?;
    let spawned = engine.spawn_level(&scene);
    let boulder = spawned.by_name["boulder"];
    let pieces = ["w0", "w1", "w2", "w3"].map(|name| spawned.by_name[name]);
    let mut starts = Vec::new();
    let mut run = Run {
        broken: false,
        furthest_x: f32::MIN,
        end_x: 0.0,
        end_speed: 0.0,
        piece_moved: 0.0,
    };
    let frames = (seconds * 60.0) as u32;
    for frame in 0..frames {
        engine.frame(1.0 / 60.0, &mut |s: &mut Step<'_>| {
            if frame == 1 && speed > 0.0 {
                s.physics
                    .apply_impulse(boulder, Vec3::X * (BOULDER_KG * speed));
            }
            if Some(frame) == quake {
                s.commands.send_event("quake");
            }
        })?;
        let _ = engine.rendered();
        let physics = engine.physics();
        let (at, _) = physics.pose(boulder).expect("the boulder has a body");
        run.furthest_x = run.furthest_x.max(at.x);
        run.end_x = at.x;
        run.end_speed = physics.linear_velocity(boulder).map_or(0.0, |v| v.length());
        for (i, piece) in pieces.iter().enumerate() {
            let (at, _) = physics.pose(*piece).expect("a piece has a body");
            if starts.len() <= i {
                starts.push(at);
            }
            run.piece_moved = run.piece_moved.max(at.distance(starts[i]));
        }
        run.broken = physics.broken(0) == Some(true);
    }
    let _ = std::fs::remove_dir_all(&dir);
    drop(engine.shutdown());
    Ok(run)
}

#[test]
fn a_slow_boulder_is_stopped_and_the_wall_stands() -> anyhow::Result<()> {
    let run = roll(LEVEL, 3.0, None, 2.5)?;
    assert!(!run.broken, "{run:?}");
    assert!(
        run.furthest_x <= WALL_FRONT_X - BOULDER_RADIUS + 0.05,
        "the boulder went into the wall: {run:?}"
    );
    assert!(run.piece_moved < 0.01, "the wall moved: {run:?}");
    Ok(())
}

#[test]
fn a_fast_boulder_breaks_the_wall_and_rolls_on_at_two_speeds() -> anyhow::Result<()> {
    for speed in [9.0, 40.0] {
        let run = roll(LEVEL, speed, None, 1.5)?;
        assert!(run.broken, "{speed} m/s: {run:?}");
        // Never stalls: it keeps most of its speed through the pieces (200 kg against 30 kg
        // ones) and ends well past the wall.
        assert!(
            run.end_x > 0.125 + 3.0 && run.end_speed > 0.5 * speed,
            "{speed} m/s: the boulder stalled in the wall: {run:?}"
        );
    }
    Ok(())
}

#[test]
fn a_wall_no_speed_breaks_stops_a_boulder_faster_than_a_step_is_wide() -> anyhow::Result<()> {
    // 90 m/s is 1.5 m per 1/60 s step, more than the boulder's 0.5 m and the wall's 0.25 m.
    assert!(LEVEL.contains("impact_speed: Some(6.0),"));
    let holds = LEVEL.replace("impact_speed: Some(6.0),", "");
    let run = roll(&holds, 90.0, None, 1.0)?;
    assert!(!run.broken, "{run:?}");
    assert!(
        run.furthest_x <= WALL_FRONT_X - BOULDER_RADIUS + 0.05,
        "the boulder tunnelled: {run:?}"
    );
    Ok(())
}

#[test]
fn a_break_action_frees_the_pieces() -> anyhow::Result<()> {
    let standing = roll(LEVEL, 0.0, None, 1.0)?;
    assert!(
        !standing.broken && standing.piece_moved < 0.01,
        "{standing:?}"
    );
    let quake = roll(LEVEL, 0.0, Some(5), 2.0)?;
    assert!(quake.broken, "{quake:?}");
    // The pieces are sent from the wall's centre at 1.5 m/s (the default) and tipped; friction
    // on the floor stops them within a few tenths of a metre.
    assert!(quake.piece_moved > 0.2, "the pieces stayed put: {quake:?}");
    Ok(())
}

#[test]
fn the_validator_names_the_breakable_mistakes() {
    let problem = |from: &str, to: &str| {
        assert!(LEVEL.contains(from), "{from:?}");
        let level = Level::parse(Path::new("wall.ron"), &LEVEL.replace(from, to)).expect("parses");
        let problems = validate_level(&level);
        assert_eq!(problems.len(), 1, "{from:?} → {to:?}: {problems:?}");
        problems[0].clone()
    };
    assert!(
        validate_level(&Level::parse(Path::new("wall.ron"), LEVEL).expect("parses")).is_empty()
    );
    let cases: &[(&str, &str, ItemRef, &str, &str)] = &[
        (
            r#""w3"]"#,
            r#""w9"]"#,
            ItemRef::Breakable(0),
            "pieces",
            "no instance",
        ),
        (
            r#"name: "w3", transform: (translation: (0, 1.5, 0.5)), body: Static(shape: Box)"#,
            r#"name: "w3", transform: (translation: (0, 1.5, 0.5))"#,
            ItemRef::Instance(4),
            "body",
            "no body",
        ),
        (
            r#"Break("wall")"#,
            r#"Break("gate")"#,
            ItemRef::Rule(0),
            "then",
            "does not declare",
        ),
        (
            "piece_mass: 30",
            "piece_mass: 0",
            ItemRef::Breakable(0),
            "piece_mass",
            "kilograms",
        ),
        (
            "impact_speed: Some(6.0)",
            "impact_speed: Some(-1.0)",
            ItemRef::Breakable(0),
            "impact_speed",
            "metres per second",
        ),
    ];
    for (from, to, item, field, says) in cases {
        let p = problem(from, to);
        assert_eq!((p.item, p.field), (*item, *field), "{from:?} → {to:?}: {p}");
        assert!(p.to_string().contains(says), "{p}");
    }
}
