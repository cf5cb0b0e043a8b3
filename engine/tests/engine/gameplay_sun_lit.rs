//! The `SunLit` condition: a volume's centre sees the sun, by a query ray on the scene the
//! picture is traced from. A wall stands west of a glyph slot; with the sun low in the west the
//! slot is in the wall's shadow, with it low in the east it is lit, and a second slot beside the
//! wall's end is lit both times. The rule follows the sun as the game moves it.

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
