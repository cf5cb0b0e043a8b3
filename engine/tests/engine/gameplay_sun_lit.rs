//! The `SunLit` condition: a volume's centre sees the sun, by a query ray on the scene the
//! picture is traced from. A wall stands west of a glyph slot; with the sun low in the west the
//! slot is in the wall's shadow, with it low in the east it is lit, and a second slot beside the
//! wall's end is lit both times. The rule follows the sun as the game moves it. And the
//! `SunElevation` condition: a rule that holds after dusk follows a physical sky's turned time,
//! and one over the level's own sun reads its direction's elevation.

use candela::app::{Engine, Step};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;

const LEVEL: &str = r#"Level(
    materials: [(name: "stone", kind: Diffuse)],
    boxes: [(name: "floor", size: (20, 0.2, 20), material: "stone"),
            (name: "wall", size: (0.4, 3, 2), material: "stone"),
            (name: "slot", size: (0.3, 0.3, 0.3), material: "stone")],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "wall", transform: (translation: (-1, 1.5, 0))),
        (model: "slot", name: "shaded", transform: (translation: (0, 0.5, 0)),
         body: Sensor(shape: Box)),
        (model: "slot", name: "open", transform: (translation: (0, 0.5, 4)),
         body: Sensor(shape: Box)),
    ],
    camera: (position: (0, 3, 8), look_at: (0, 0, 0), vertical_fov_deg: 45),
    sun: (direction: (-1, 0.5, 0), irradiance: (3, 3, 3)),
    gameplay: (
        volumes: [(name: "shaded", instance: "shaded"), (name: "open", instance: "open")],
        rules: [
            (name: "shaded_lit", when: SunLit("shaded"), then: []),
            (name: "open_lit", when: SunLit("open"), then: []),
        ],
    ),
)"#;

#[test]
fn a_slot_in_a_walls_shadow_is_lit_only_when_the_sun_comes_round() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_sun_lit_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("slots.ron");
    std::fs::write(&path, LEVEL)?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let mut engine = Engine::new(
        RenderConfig::cpu(16, 8),
        candela::app::Environment::of(&scene.scene),
    )?;
    let _spawned = engine.spawn_level(&scene);
    // Which rules hold after a few frames with the sun towards `direction`.
    let lit_towards = |engine: &mut Engine, direction: [f32; 3]| -> anyhow::Result<Vec<bool>> {
        if let Some(sun) = engine.environment_mut().sun.as_mut() {
            sun.direction = direction;
        }
        for _ in 0..3 {
            engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
            let _ = engine.rendered();
        }
        Ok(["shaded_lit", "open_lit"]
            .iter()
            .map(|name| engine.logic().rule_holds(name))
            .collect())
    };
    let west = lit_towards(&mut engine, [-1.0, 0.5, 0.0])?;
    // The first step ran before the level's first commit, on an empty query scene: the shaded
    // slot must not have counted as lit then (its rule would have risen and fallen).
    let shaded_fired_early = engine.logic().rule_fired("shaded_lit");
    let east = lit_towards(&mut engine, [1.0, 0.5, 0.0])?;
    let west_again = lit_towards(&mut engine, [-1.0, 0.4, 0.0])?;
    let _ = std::fs::remove_dir_all(&dir);
    drop(engine.shutdown());
    assert_eq!(
        west,
        [false, true],
        "sun in the west: the wall shades the slot"
    );
    assert!(
        !shaded_fired_early,
        "the shaded slot was lit before the scene held the wall"
    );
    assert_eq!(east, [true, true], "sun in the east: both slots lit");
    assert_eq!(west_again, [false, true], "the shadow comes back");
    Ok(())
}

/// A physical sky over Teotihuacan on 21 March 2026; rules for the night (the sun 6° or more
/// below the horizon) and for a high sun (at least 30°).
const NIGHT_LEVEL: &str = r#"Level(
    materials: [(name: "stone", kind: Diffuse)],
    boxes: [(name: "floor", size: (20, 0.2, 20), material: "stone")],
    instances: [(model: "floor", transform: (translation: (0, -0.1, 0)))],
    camera: (position: (0, 3, 8), look_at: (0, 0, 0), vertical_fov_deg: 45),
    sky: Physical((time: Some((latitude_deg: 19.69, longitude_deg: -98.84, year: 2026,
        month: 3, day: 21, utc_hours: 18.0)))),
    gameplay: (
        rules: [
            (name: "night", when: SunElevation(at_most: Some(-6)), then: []),
            (name: "high", when: SunElevation(at_least: Some(30)), then: []),
        ],
    ),
)"#;

#[test]
fn sun_elevation_rules_follow_the_turned_time() -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_sun_elev_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("night.ron");
    std::fs::write(&path, NIGHT_LEVEL)?;
    let scene = load_level(&path, &AssetRoot::new(&dir)?)?;
    let _ = std::fs::remove_dir_all(&dir);
    let mut engine = Engine::new(
        RenderConfig::cpu(8, 4),
        candela::app::Environment::of(&scene.scene),
    )?;
    let _spawned = engine.spawn_level(&scene);
    // Local solar time is UTC − 6.59 h here: sets the time, runs two steps, reads the rules
    // and the sun's elevation as the engine has it.
    let at = |engine: &mut Engine, utc: f64| -> anyhow::Result<(bool, bool, f64)> {
        let mut set = Some(utc);
        for _ in 0..2 {
            engine.frame(1.0 / 60.0, &mut |step: &mut Step<'_>| {
                if let Some(hours) = set.take() {
                    step.commands.set_time_of_day(hours);
                }
            })?;
            let _ = engine.rendered();
        }
        let elevation = engine.sky_now().map_or(f64::NAN, |s| s.sun.elevation_deg);
        Ok((
            engine.logic().rule_holds("night"),
            engine.logic().rule_holds("high"),
            elevation,
        ))
    };
    let noon = at(&mut engine, 18.6)?;
    let dusk = at(&mut engine, 0.9)?;
    let night = at(&mut engine, 2.0)?;
    let morning = at(&mut engine, 14.0)?;
    drop(engine.shutdown());
    assert!(noon.2 > 60.0 && !noon.0 && noon.1, "noon: {noon:?}");
    assert!(
        (-6.0..0.0).contains(&dusk.2) && !dusk.0 && !dusk.1,
        "civil dusk is not night yet: {dusk:?}"
    );
    assert!(night.2 < -6.0 && night.0 && !night.1, "night: {night:?}");
    assert!(
        (0.0..30.0).contains(&morning.2) && !morning.0 && !morning.1,
        "morning: {morning:?}"
    );
    Ok(())
}
