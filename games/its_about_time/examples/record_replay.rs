//! Records It's About Time's committed replays (`assets/its_about_time/replays/*.replay`): the
//! scripted explorer (`its_about_time::bot`) follows a way of `its_about_time::routes` — the
//! whole game (`full_game`: the sun gate, the rolling stone, the court of weights, the night
//! shrine, then the temple altar) or one puzzle from the start — through the engine's own
//! frame loop (headless, CPU tracer, one fixed step per frame), the engine recording every
//! step's actions. Fails when the bot gets stuck (the level changed: fix its way).
//!
//! Run: `cargo run --release -p its_about_time --example record_replay [NAME ...]` (no name:
//! all of them). Re-record after the level or the explorer's controller changed:
//! `games/its_about_time/tests/replays.rs` fails loudly when a committed replay no longer
//! solves its puzzle. When a way fails, the example prints what happened and where the moving
//! pieces lie; `IAT_TRACE=<instance>` prints that instance's position every 20 steps.

use anyhow::{Context, bail};
use candela::app::{Engine, Game, StepInput};
use candela::render::RenderConfig;
use its_about_time::bot::Bot;
use its_about_time::game::TimeGame;
use its_about_time::replays::{named, recorder};
use its_about_time::routes::{NAMES, route};
use its_about_time::world::RuinsWorld;

/// Give up after this many steps (six minutes of play).
const MAX_STEPS: u64 = 360 * 60;

fn record(world: &RuinsWorld, name: &str) -> anyhow::Result<()> {
    let tasks = route(name).with_context(|| format!("no way named {name:?}: {NAMES:?}"))?;
    let out = named(world.root.path(), name);
    let mut game = TimeGame::new(world.clone());
    // As the harness replays it: the sky's table follows the turned sun on a worker thread.
    let render = RenderConfig {
        sky_rebuild: candela::scene::SkyRebuild::Background,
        ..RenderConfig::cpu(16, 9)
    };
    let mut engine = Engine::new(render, game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    engine.set_step_input(StepInput::record(recorder(world)?, &out));
    let mut bot = Bot::new(tasks);
    let mut last = None;
    let mut after = 0;
    for step in 0..MAX_STEPS {
        if bot.done() {
            after += 1;
            if after > 30 {
                break;
            }
        }
        let act = bot.act(&engine, &game);
        if bot.task() != last.as_ref() {
            let at = game
                .inner()
                .player()
                .map(|p| p.centre(engine.world(), None));
            println!("{name} step {step}: {:?} (explorer at {at:?})", bot.task());
            last = bot.task().cloned();
        }
        if let Ok(name) = std::env::var("IAT_TRACE")
            && step % 20 == 0
            && let Some(&entity) = game.inner().spawned().by_name.get(&name)
            && let Ok(t) = engine.world().get::<&candela::ecs::Transform>(entity)
        {
            println!("  trace {step}: {name} at {:?}", t.translation);
        }
        act.press(engine.input_mut());
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    if !bot.done() {
        for (step, e) in game.log() {
            if !matches!(e, its_about_time::game::TimeEvent::Turned(_)) {
                println!("  step {step}: {e:?}");
            }
        }
        // Where the moving pieces ended, to see what blocked the way.
        let mut moving: Vec<_> = game.inner().spawned().by_name.iter().collect();
        moving.sort_by_key(|(name, _)| name.as_str());
        for (name, &entity) in moving {
            if let Ok(t) = engine.world().get::<&candela::ecs::Transform>(entity)
                && (name.starts_with("stone_wall")
                    || name.starts_with("boulder")
                    || name.starts_with("weight"))
            {
                println!("  {name} at {:?}", t.translation);
            }
        }
        println!("  breakables broken: {:?}", engine.physics().broken(0));
        bail!("{name}: the bot got stuck at {:?}", bot.task());
    }
    engine.finish_recording()?;
    println!(
        "{name}: artifacts {:?}, ending {}, wrote {}",
        game.artifacts(),
        game.ended(),
        out.display()
    );
    let _ = engine.shutdown();
    Ok(())
}

fn main() -> anyhow::Result<()> {
    let world = RuinsWorld::open(None)?;
    let asked: Vec<String> = std::env::args().skip(1).collect();
    let names: Vec<&str> = if asked.is_empty() {
        NAMES.to_vec()
    } else {
        asked.iter().map(String::as_str).collect()
    };
    for name in names {
        record(&world, name)?;
    }
    Ok(())
}
