//! Where a laser sends the player back (`hazard.rs`, issue 32 weak test 7): the bot walks
//! chamber 2's player straight into the laser fence before its exit; in the step the beam
//! crosses the player, the player is put back at chamber 2's start (feet within a few
//! centimetres, the physics step after it settling them), facing the chamber's start yaw, level,
//! and the game counts one send-back and notes it for that chamber. The player had walked
//! metres away from the start before, so the check cannot pass by standing still.

use candela::app::{Engine, Game};
use candela::render::RenderConfig;
use glam::Vec2;
use reflect::bot::{Act, Bot, Task};
use reflect::game::{ReflectEvent, ReflectGame};
use reflect::world::ReflectWorld;

#[test]
fn a_laser_sends_the_player_back_to_the_chambers_start_facing_its_way() -> anyhow::Result<()> {
    let (path, root) = reflect::cli::locate(None)?;
    let world = ReflectWorld::load(&path, &root)?;
    let chamber = world.chambers[1].clone();
    let mut game = ReflectGame::new(world, 1);
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), game.inner().environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut bot = Bot::new(vec![Task::Walk {
        to: Vec2::new(0.0, -31.0),
        within: 0.15,
    }]);
    let mut furthest = 0.0f32;
    let mut at_hit = None;
    for _ in 0..900 {
        let act: Act = bot.act(&engine, &game);
        act.press(engine.input_mut());
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
        let player = game.inner().player().expect("a player");
        // The simulated pose (the ECS transform is interpolated for the picture).
        let (centre, _) = engine
            .physics()
            .pose(player.body)
            .expect("the player's body");
        let feet = centre - (player.position(engine.world()) - player.feet(engine.world()));
        if game.sent_back() > 0 {
            at_hit = Some((feet, player.yaw, player.pitch));
            break;
        }
        furthest = furthest.max(feet.distance(chamber.start));
    }
    let (feet, yaw, pitch) = at_hit.ok_or_else(|| anyhow::anyhow!("the fence never hit"))?;
    assert!(
        furthest > 3.0,
        "the player walked {furthest} m from the start"
    );
    assert_eq!(game.sent_back(), 1);
    assert!(
        feet.distance(chamber.start) < 0.05,
        "sent back to {feet} instead of chamber 2's start {}",
        chamber.start
    );
    assert_eq!((yaw, pitch), (chamber.yaw, 0.0));
    assert!(
        game.log()
            .iter()
            .any(|(_, e)| *e == ReflectEvent::SentBack(1)),
        "{:?}",
        game.log()
    );
    Ok(())
}
