//! Records Reflect's committed replays (`assets/reflect/replays/`): the scripted bot
//! (`reflect::bot`, tasks in `reflect::bot_tasks`) plays each chamber from its start, then the
//! whole game from the first chamber to the ending, through the engine's own frame loop
//! (headless, CPU tracer, one fixed step per frame), and the engine records every step's
//! actions. Fails when the bot gets stuck (a chamber changed: fix its tasks).
//!
//! Run: `cargo run --release -p reflect --example record_replays [-- chamber_2 ...]` (no
//! arguments: every chamber and the full game). Re-record after a chamber or the player's
//! controller changed: the tests in `games/reflect/tests/` fail loudly when a committed
//! replay no longer solves its chamber.

use std::path::{Path, PathBuf};

use anyhow::bail;
use candela::app::{Engine, Game, StepInput};
use candela::render::RenderConfig;
use reflect::bot::Bot;
use reflect::bot_tasks::chamber_tasks;
use reflect::game::ReflectGame;
use reflect::replays::{FULL_GAME, recorder};
use reflect::world::ReflectWorld;

/// Give up after this many steps per chamber (two minutes of play).
const MAX_STEPS: u64 = 120 * 60;

fn record(
    world: &ReflectWorld,
    id: &str,
    start: usize,
    chambers: &[usize],
    out: &Path,
) -> anyhow::Result<()> {
    let mut game = ReflectGame::new(world.clone(), start);
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    engine.set_step_input(StepInput::record(recorder(world, id)?, out));
    let tasks = chambers.iter().flat_map(|&c| chamber_tasks(c)).collect();
    let mut bot = Bot::new(tasks);
    let mut last = None;
    let limit = MAX_STEPS * chambers.len() as u64;
    let mut after = 0;
    for step in 0..limit {
        if bot.done() {
            after += 1;
            if after > 30 {
                break;
            }
        }
        let act = bot.act(&engine, &game);
        if bot.task() != last.as_ref() {
            println!("{id} step {step}: {:?}", bot.task());
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
        bail!("{id}: the bot got stuck at {:?}", bot.task());
    }
    engine.finish_recording()?;
    if std::env::var_os("BOT_LOG").is_some() {
        for (step, e) in game.log() {
            println!("  step {step}: {e:?}");
        }
    }
    println!(
        "{id}: finished {:?}, ending {}, wrote {}",
        game.finished(),
        game.ended(),
        out.display()
    );
    let _ = engine.shutdown();
    Ok(())
}

fn main() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/reflect/replays");
    std::fs::create_dir_all(&dir)?;
    let wanted: Vec<String> = std::env::args().skip(1).collect();
    let all: Vec<usize> = (0..world.chambers.len()).collect();
    for (i, chamber) in world.chambers.iter().enumerate() {
        if wanted.is_empty() || wanted.contains(&chamber.id) {
            record(
                &world,
                &chamber.id,
                i,
                &[i],
                &dir.join(format!("{}.replay", chamber.id)),
            )?;
        }
    }
    if wanted.is_empty() || wanted.iter().any(|w| w == FULL_GAME) {
        record(
            &world,
            FULL_GAME,
            0,
            &all,
            &dir.join(format!("{FULL_GAME}.replay")),
        )?;
    }
    Ok(())
}
