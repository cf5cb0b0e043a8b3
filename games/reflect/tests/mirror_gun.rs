//! The mirror gun in play, driven by the bot's input like a player: a chamber's cap refuses one
//! mirror too many (and the HUD counts them), reverting a mirror frees the cap, and a mirror is
//! a material override of the panel, not new geometry.

use candela::app::edit::EditHooks;
use candela::app::shell::ShellHooks;
use candela::app::{Engine, Game};
use candela::ecs::Renderable;
use candela::render::RenderConfig;
use glam::Vec3;
use reflect::bot::{Bot, Task};
use reflect::game::{ReflectEvent, ReflectGame};
use reflect::mirror_gun::GunShot;
use reflect::world::ReflectWorld;

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

/// Plays `tasks` from chamber `start` for at most `steps` steps; returns the game, the engine
/// and whether every task finished.
fn drive(start: usize, tasks: Vec<Task>, steps: u32) -> (ReflectGame, Engine, bool) {
    let mut game = ReflectGame::new(world(), start);
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 9), game.inner().environment()).expect("engine");
    game.setup(&mut engine).expect("setup");
    let mut bot = Bot::new(tasks);
    for _ in 0..steps {
        if bot.done() {
            break;
        }
        let act = bot.act(&engine, &game);
        act.press(engine.input_mut());
        engine.frame(1.0 / 60.0, &mut game).expect("frame");
        let _ = engine.rendered();
    }
    let done = bot.done();
    (game, engine, done)
}

fn shoot(panel: &str, at: Vec3, mirror: bool) -> Task {
    Task::Shoot {
        at,
        panel: panel.into(),
        mirror,
    }
}

const PANEL: Vec3 = Vec3::new(6.2, 1.0, -29.0);
const DECOY: Vec3 = Vec3::new(-7.9, 3.5, -20.0);

#[test]
fn the_cap_refuses_a_second_mirror_in_the_first_mirror_chamber() {
    let tasks = vec![
        shoot("panel_2", PANEL, true),
        shoot("panel_2_decoy", DECOY, true),
    ];
    let (game, engine, done) = drive(1, tasks, 600);
    assert!(!done, "the second mirror was made past the cap of 1");
    let refused = game
        .log()
        .iter()
        .any(|(_, e)| *e == ReflectEvent::Shot(GunShot::AtCap));
    assert!(refused, "no refusal: {:?}", game.log());
    assert_eq!(game.gun().active_in(1), 1);
    let hud = game.hud();
    assert!(
        hud.counters.contains(&("Mirrors".into(), "1 / 1".into())),
        "{:?}",
        hud.counters
    );
    // The mirror is the panel with the mirror material: same model, an override.
    let panel = game.inner().spawned().by_name["panel_2"];
    let r = engine
        .world()
        .get::<&Renderable>(panel)
        .expect("renderable");
    assert_eq!(r.material_override, Some(game.world().mirror_material));
}

#[test]
fn reverting_a_mirror_frees_the_cap() {
    let tasks = vec![
        shoot("panel_2", PANEL, true),
        shoot("panel_2", PANEL, false),
        shoot("panel_2_decoy", DECOY, true),
    ];
    let (game, engine, done) = drive(1, tasks, 900);
    assert!(done, "stuck: {:?}", game.log());
    let panel = game.inner().spawned().by_name["panel_2"];
    let r = engine
        .world()
        .get::<&Renderable>(panel)
        .expect("renderable");
    assert_eq!(
        r.material_override, None,
        "the reverted panel has its own material back"
    );
    assert_eq!(game.gun().made, 2);
}

/// Regression: the gun found its panels by instance index, so instances inserted by the
/// editor before the panels shifted the gun onto the wrong entities.
#[test]
fn the_gun_knows_the_panels_after_the_editor_inserts_instances() -> anyhow::Result<()> {
    use candela::app::edit::EditMode;
    use candela::editor::Edit;
    let world = world();
    let panels = world.mirrorable.len();
    let models: Vec<String> = world
        .mirrorable
        .iter()
        .map(|&k| world.level.instances[k].model.clone())
        .collect();
    // Chamber 2 (the first mirror) is the one the editor opens.
    let mut game = ReflectGame::new(world.clone(), 1);
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    assert_eq!(game.gun().panel_count(), panels);
    let (target, spawned) = game.edit_target().expect("the editor opens chamber 2");
    // The committed chamber is edited in memory only: no recovery file beside it.
    let mut mode = EditMode::open(target, spawned)?.without_recovery_files();
    assert!(mode.enter(&mut engine).respawned);
    let level = &mode.state.doc.level;
    let panel = level
        .instances
        .iter()
        .position(|i| models.contains(&i.model))
        .expect("chamber 2 has a mirrorable panel");
    // A copy of the chamber's first instance moves every later one a place on; a copy of a
    // panel is one panel more.
    assert!(
        mode.apply(&mut engine, Edit::DuplicateInstance { index: 0 })?
            .respawned
    );
    mode.apply(&mut engine, Edit::DuplicateInstance { index: panel + 1 })?;
    let spawned = mode.world.spawned().clone();
    game.level_respawned(&mut engine, &spawned);
    assert_eq!(game.gun().panel_count(), panels + 1);
    let handles: Vec<_> = world
        .mirrorable_models
        .iter()
        .map(|&k| spawned.models[k])
        .collect();
    let ecs = engine.world();
    let mut found = 0;
    for &e in &spawned.entities {
        let mirrorable = ecs
            .get::<&Renderable>(e)
            .is_ok_and(|r| handles.contains(&r.model));
        assert_eq!(game.gun().is_panel(e), mirrorable, "{e:?}");
        found += usize::from(mirrorable);
    }
    assert_eq!(found, panels + 1);
    Ok(())
}
