//! Records It's About Time's committed replay (`assets/its_about_time/replays/full_game.replay`):
//! the scripted explorer (`its_about_time::bot`) walks to the sun altar, turns time forward until
//! sunlight falls through the shrine's slot onto its glyph and the sun gate opens, walks through
//! the gate, takes the Sun Disc, and brings it back to the temple altar — through the engine's
//! own frame loop (headless, CPU tracer, one fixed step per frame), the engine recording every
//! step's actions. Fails when the bot gets stuck (the level changed: fix its tasks).
//!
//! Run: `cargo run --release -p its_about_time --example record_replay`. Re-record after the
//! level or the explorer's controller changed: `games/its_about_time/tests/replays.rs` fails
//! loudly when the committed replay no longer reaches the ending.

use anyhow::bail;
use candela::app::{Engine, Game, StepInput};
use candela::render::RenderConfig;
use glam::Vec2;
use its_about_time::bot::{Bot, Task};
use its_about_time::game::TimeGame;
use its_about_time::replays::{full_game, recorder};
use its_about_time::world::RuinsWorld;

/// Give up after this many steps (three minutes of play).
const MAX_STEPS: u64 = 180 * 60;

/// The way through the ruins, start to ending.
pub fn tasks() -> Vec<Task> {
    let walk = |x: f32, z: f32, within: f32| Task::Walk {
        to: Vec2::new(x, z),
        within,
    };
    vec![
        Task::Wait { steps: 20 },
        walk(5.0, 6.6, 0.25),
        Task::TurnUntil {
            rule: "sun_gate".into(),
            forward: true,
        },
        walk(14.5, 4.0, 0.4),
        walk(14.5, 0.0, 0.3),
        Task::Rule {
            name: "sun_gate".into(),
        },
        Task::Wait { steps: 150 },
        walk(20.6, 0.0, 0.15),
        Task::Use {
            event: "artifact_sun".into(),
        },
        walk(14.5, 0.0, 0.4),
        walk(14.5, 4.0, 0.4),
        walk(7.0, 4.0, 0.4),
        walk(0.0, 0.0, 0.4),
        walk(0.0, -12.3, 0.3),
        Task::Ending,
    ]
}

fn main() -> anyhow::Result<()> {
    let world = RuinsWorld::open(None)?;
    let out = full_game(world.root.path());
    let mut game = TimeGame::new(world.clone());
    // As the harness replays it: the sky's table follows the turned sun on a worker thread.
    let render = RenderConfig {
        sky_rebuild: candela::scene::SkyRebuild::Background,
        ..RenderConfig::cpu(16, 9)
    };
    let mut engine = Engine::new(render, game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    engine.set_step_input(StepInput::record(recorder(&world)?, &out));
    let mut bot = Bot::new(tasks());
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
            println!("step {step}: {:?} (explorer at {at:?})", bot.task());
            last = bot.task().cloned();
        }
        act.press(engine.input_mut());
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    if !bot.done() {
        for (step, e) in game.log() {
            println!("  step {step}: {e:?}");
        }
        bail!("the bot got stuck at {:?}", bot.task());
    }
    engine.finish_recording()?;
    println!(
        "artifacts {:?}, ending {}, wrote {}",
        game.artifacts(),
        game.ended(),
        out.display()
    );
    let _ = engine.shutdown();
    Ok(())
}
