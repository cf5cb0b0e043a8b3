//! The `SunLit` trigger and the rendered shadow agree (issue 35 item 7): a flat glyph lies on
//! the floor across the edge of a wall's shadow, half in it and half out, at two hours (the
//! sun a little south of west, then a little north of west, so the edge crosses the glyph's
//! centre). At each hour the rule that the glyph sees the sun holds exactly when the CPU
//! tracer's picture is sunlit at the glyph's centre, and the picture shows the glyph both lit
//! and shaded. The camera looks down at the glyph's centre, so that is the middle pixel.

use candela::app::{Engine, Environment, Step};
use candela::assets::AssetRoot;
use candela::level::load_level;
use candela::render::RenderConfig;
use glam::Vec3;

/// Metres. The wall spans z −1…1 at x −1.05…−0.95, 3 m tall; with the sun `(−1, 0.5, s)`
/// the floor at x = 1 is in its shadow for z ≤ 1 − 1.95·s (s > 0) or z ≤ 1 − 2.05·s (s < 0),
/// so s = ±0.1 puts the edge about 0.2 m to either side of the glyph's centre (z = 1), and
/// the glyph (z 0.5…1.5) is cut by it.
const LEVEL: &str = r#"Level(
    materials: [(name: "stone", kind: Diffuse, base_color: (0.6, 0.6, 0.6))],
    boxes: [(name: "floor", size: (20, 0.2, 20), material: "stone"),
            (name: "wall", size: (0.1, 3, 2), material: "stone"),
            (name: "glyph", size: (0.6, 0.02, 1), material: "stone")],
    instances: [
        (model: "floor", transform: (translation: (0, -0.1, 0))),
        (model: "wall", transform: (translation: (-1, 1.5, 0))),
        (model: "glyph", name: "glyph", transform: (translation: (1, 0.01, 1)),
         body: Sensor(shape: Box)),
    ],
    camera: (position: (1, 6, 1.6), look_at: (1, 0.02, 1), vertical_fov_deg: 20),
    sun: (direction: (-1, 0.5, 0.1), irradiance: (3, 3, 3)),
    sky: Gradient(zenith: (0.2, 0.3, 0.5), horizon: (0.4, 0.4, 0.4), ground: (0.1, 0.1, 0.1)),
    gameplay: (
        volumes: [(name: "glyph", instance: "glyph")],
        rules: [(name: "glyph_lit", when: SunLit("glyph"), then: [])],
    ),
)"#;

const SIZE: u32 = 48;

/// What one hour showed: the rule, and the picture's luminance at the glyph's centre and at
/// two points about a third of the glyph to either side of it along z.
#[derive(Debug)]
struct Hour {
    rule: bool,
    centre: f32,
    quarters: [f32; 2],
}

fn luminance(c: Vec3) -> f32 {
    c.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}

fn at_hour(engine: &mut Engine, sun_z: f32) -> anyhow::Result<Hour> {
    if let Some(sun) = engine.environment_mut().sun.as_mut() {
        sun.direction = [-1.0, 0.5, sun_z];
    }
    let frames = 24;
    let mut film = None;
    for f in 0..frames {
        if f + 1 == frames {
            engine.capture_next();
        }
        engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
        for r in engine.rendered().into_iter().flatten() {
            film = r.film.or(film);
        }
    }
    while film.is_none() {
        match engine.wait_rendered() {
            Some(r) => film = r?.film,
            None => anyhow::bail!("the render thread stopped without a film"),
        }
    }
    let film = film.ok_or_else(|| anyhow::anyhow!("no film"))?;
    // A 3 × 3 mean round pixel (x, y), luminance.
    let at = |x: u32, y: u32| -> f32 {
        let mut sum = 0.0;
        for dy in 0..3 {
            for dx in 0..3 {
                let i = ((y + dy - 1) * film.width + (x + dx - 1)) as usize;
                sum += film.mean.get(i).copied().map_or(f32::NAN, luminance);
            }
        }
        sum / 9.0
    };
    // The view is 2·6·tan(10°) ≈ 2.1 m tall at the glyph: 8 pixels are ≈ 0.35 m, points at
    // z ≈ 0.65 and 1.35, both on the glyph and 0.15 m or more from either hour's edge.
    let (mid, quarter) = (SIZE / 2, 8);
    Ok(Hour {
        rule: engine.logic().rule_holds("glyph_lit"),
        centre: at(mid, mid),
        quarters: [at(mid, mid - quarter), at(mid, mid + quarter)],
    })
}

#[test]
fn the_sun_lit_rule_agrees_with_the_rendered_shadow_across_a_glyph_at_two_hours()
-> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("candela_sun_shadow_{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("glyph.ron");
    std::fs::write(&path, LEVEL)?;
    let level = load_level(&path, &AssetRoot::new(&dir)?);
    let _ = std::fs::remove_dir_all(&dir);
    let level = level?;
    let mut engine = Engine::new(RenderConfig::cpu(SIZE, SIZE), Environment::of(&level.scene))?;
    let _spawned = engine.spawn_level(&level);
    let south_of_west = at_hour(&mut engine, 0.1)?;
    let north_of_west = at_hour(&mut engine, -0.1)?;
    drop(engine.shutdown());
    for (name, hour) in [
        ("south of west", &south_of_west),
        ("north of west", &north_of_west),
    ] {
        let [a, b] = hour.quarters;
        let (shaded, lit) = (a.min(b), a.max(b));
        assert!(
            lit > 2.0 * shaded && shaded > 0.0,
            "{name}: the glyph is not half in the shadow: {hour:?}"
        );
        let rendered_lit = hour.centre > 0.5 * (lit + shaded);
        assert_eq!(
            hour.rule, rendered_lit,
            "{name}: the rule and the picture disagree at the glyph's centre: {hour:?}"
        );
    }
    assert!(
        south_of_west.rule && !north_of_west.rule,
        "the edge should cross the centre between the hours: {south_of_west:?} {north_of_west:?}"
    );
    Ok(())
}
