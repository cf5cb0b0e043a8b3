//! The ruins' render areas (`render_areas` in `assets/its_about_time/ruins.ron`, written by
//! `games/its_about_time/layout/`): with the camera at the centre of each area, the light table
//! holds fewer emitters than with the camera on the plaza (outside every area), and exactly as
//! many as with the camera on the plaza and every group the area does not name switched off
//! (the light-switching mechanism, counted independently of the areas). With
//! `Upkeep::sample_from` made a no-op the temple holds all 3,476 and the test fails.

use candela::app::{Engine, Environment, Step};
use candela::assets::CameraDesc;
use candela::render::RenderConfig;
use its_about_time::world::RuinsWorld;

/// The engine's camera moved to `position` (metres, looking north), then one frame; the
/// emitters the light table holds.
fn sampled_at(engine: &mut Engine, position: [f32; 3]) -> anyhow::Result<u32> {
    let camera = CameraDesc {
        position,
        look_at: [position[0], position[1], position[2] - 1.0],
        ..engine.environment().default_camera
    };
    engine.set_default_camera(camera);
    engine.frame(1.0 / 60.0, &mut |_: &mut Step<'_>| {})?;
    let _ = engine.rendered();
    Ok(engine.scene().lights.count)
}

#[test]
fn each_area_samples_only_the_emitters_of_the_groups_it_names() -> anyhow::Result<()> {
    let world = RuinsWorld::open(None)?;
    let level = &world.level;
    anyhow::ensure!(level.render_areas.len() == 6, "{:?}", level.render_areas);
    let mut engine = Engine::new(RenderConfig::cpu(16, 8), Environment::of(&level.scene))?;
    let _spawned = engine.spawn_level(level);
    let mut groups: Vec<u32> = (level.scene.instances.iter())
        .filter_map(|i| i.light_group)
        .collect();
    groups.sort_unstable();
    groups.dedup();
    // The night shrine's torches start off: every group on, so every area has its emitters.
    for &g in &groups {
        engine.set_light_group(g, true);
    }
    let plaza = [0.0, 3.0, 17.0];
    assert!(level.render_areas.iter().all(|a| !a.contains(plaza)));
    let all = sampled_at(&mut engine, plaza)?;
    for area in &level.render_areas {
        let centre: [f32; 3] = std::array::from_fn(|k| 0.5 * (area.min[k] + area.max[k]));
        let masked = sampled_at(&mut engine, centre)?;
        let hidden: Vec<u32> = (groups.iter().copied())
            .filter(|g| !area.light_groups.contains(g))
            .collect();
        for &g in &hidden {
            engine.set_light_group(g, false);
        }
        let switched = sampled_at(&mut engine, plaza)?;
        for &g in &hidden {
            engine.set_light_group(g, true);
        }
        eprintln!("{}: {masked} of {all} emitters sampled", area.name);
        assert!(
            masked > 0 && masked < all,
            "{}: {masked} of {all}",
            area.name
        );
        assert_eq!(masked, switched, "{}", area.name);
    }
    drop(engine.shutdown());
    Ok(())
}
