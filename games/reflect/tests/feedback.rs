//! What the player is told, driven headless by the bot's input like a player: the prompt
//! follows what is carried (drop, not pick up), E at a cube out of reach says "Too far", a
//! laser that sends the player back says so with a flash, a plate and the door it opens say
//! what they did (and the chamber counts as solved, then complete once the player goes on),
//! and lifting the cube off the plate says the plate is released and the door closes.

use candela::app::shell::ShellHooks;
use candela::app::steer::{Steer, aim, pitch_to, yaw_to};
use candela::app::{CARRY_PROMPT, Engine, Game, TOO_FAR};
use candela::ecs::Transform;
use candela::render::RenderConfig;
use glam::{Vec2, Vec3};
use reflect::bot::{Act, Bot, Task};
use reflect::game::ReflectGame;
use reflect::game::feedback::{
    DOOR_CLOSED_BEHIND, DOOR_CLOSES, DOOR_OPENS, PLATE_PRESSED, PLATE_RELEASED, SENT_BACK,
    chamber_complete,
};
use reflect::world::ReflectWorld;

fn world() -> ReflectWorld {
    let (path, root) = reflect::cli::locate(None).expect("the game file");
    ReflectWorld::load(&path, &root).expect("the world loads")
}

/// A game started in chamber `start` on a tiny CPU-traced frame.
fn start(start: usize) -> (ReflectGame, Engine) {
    let mut game = ReflectGame::new(world(), start);
    let mut engine =
        Engine::new(RenderConfig::cpu(16, 9), game.inner().environment()).expect("engine");
    game.setup(&mut engine).expect("setup");
    (game, engine)
}

/// One frame (one fixed step) with `act`'s keys and mouse.
fn frame(game: &mut ReflectGame, engine: &mut Engine, act: Act) {
    act.press(engine.input_mut());
    engine.frame(1.0 / 60.0, game).expect("frame");
    let _ = engine.rendered();
}

/// Plays `bot` until `until` holds after a frame (true) or `steps` frames ran (false).
fn play(
    game: &mut ReflectGame,
    engine: &mut Engine,
    bot: &mut Bot,
    steps: u32,
    mut until: impl FnMut(&ReflectGame, &Engine) -> bool,
) -> bool {
    for _ in 0..steps {
        let act = bot.act(engine, game);
        frame(game, engine, act);
        if until(game, engine) {
            return true;
        }
    }
    false
}

fn rose(game: &ReflectGame, rule: &str) -> bool {
    game.log().iter().any(|(_, e)| {
        matches!(e, reflect::game::ReflectEvent::Rule { name, rising: true } if name == rule)
    })
}

fn counter(game: &ReflectGame) -> String {
    let hud = game.hud();
    hud.counters
        .iter()
        .find(|(label, _)| label == "Chamber")
        .map(|(_, v)| v.clone())
        .unwrap_or_default()
}

#[test]
fn carrying_a_cube_the_prompt_offers_drop_not_pick_up() {
    let (mut game, mut engine) = start(0);
    let mut bot = Bot::new(vec![Task::Pick {
        body: "cube_1".into(),
    }]);
    let mut offered_pick_up = false;
    let picked = play(&mut game, &mut engine, &mut bot, 900, |game, engine| {
        let prompt = game.hud().prompt.unwrap_or_default();
        offered_pick_up |= prompt.contains("pick up");
        game.inner()
            .player()
            .is_some_and(|p| p.held(engine.world()).is_some())
    });
    assert!(picked, "the bot never picked up the cube");
    assert!(offered_pick_up, "the cube in reach never offered E pick up");
    // The player sees what it holds at its next step.
    frame(&mut game, &mut engine, Act::default());
    let prompt = game.hud().prompt;
    assert_eq!(prompt.as_deref(), Some(CARRY_PROMPT), "while carrying");
    assert!(!CARRY_PROMPT.contains("pick up"));
}

#[test]
fn pressing_e_at_a_cube_out_of_reach_says_too_far() {
    let (mut game, mut engine) = start(0);
    frame(&mut game, &mut engine, Act::default());
    let cube = game.inner().spawned().by_name["cube_1"];
    let at = engine
        .world()
        .get::<&Transform>(cube)
        .map(|t| t.translation)
        .expect("the cube");
    let mut aimed = false;
    for _ in 0..240 {
        let player = game.inner().player().expect("the player");
        let eye = player.eye(engine.world());
        let mut steer = Steer::default();
        let (dy, dp) = aim(player, yaw_to(eye, at), pitch_to(eye, at), &mut steer);
        let act = Act {
            mouse: steer.mouse,
            ..Act::default()
        };
        frame(&mut game, &mut engine, act);
        if dy.abs() < 0.01 && dp.abs() < 0.01 {
            aimed = true;
            break;
        }
    }
    assert!(aimed, "never aimed at the cube");
    let player = game.inner().player().expect("the player");
    let far = (player.eye(engine.world()) - at).length();
    assert!(far > player.config.reach, "the cube is in reach ({far} m)");
    assert!(
        !game.hud().messages.iter().any(|m| m == TOO_FAR),
        "too far before E"
    );
    let press = Act {
        use_key: true,
        ..Act::default()
    };
    frame(&mut game, &mut engine, press);
    let hud = game.hud();
    assert!(
        hud.messages.iter().any(|m| m == TOO_FAR),
        "E at a cube {far} m away: {:?}",
        hud.messages
    );
    let held = game.inner().player().and_then(|p| p.held(engine.world()));
    assert_eq!(held, None, "picked up from {far} m");
}

#[test]
fn a_laser_that_sends_the_player_back_says_so_with_a_flash() {
    let (mut game, mut engine) = start(1);
    // Started in chamber 2, the door behind never opened: nothing closed behind the player.
    frame(&mut game, &mut engine, Act::default());
    assert_eq!(game.hud().messages, Vec::<String>::new());
    // Straight through the laser fence in front of chamber 2's exit.
    let mut bot = Bot::new(vec![Task::Walk {
        to: Vec2::new(0.0, -31.0),
        within: 0.15,
    }]);
    let hit = play(&mut game, &mut engine, &mut bot, 900, |game, _| {
        game.sent_back() > 0
    });
    assert!(hit, "the fence never sent the player back");
    let hud = game.hud();
    assert!(
        hud.messages.iter().any(|m| m == SENT_BACK),
        "{:?}",
        hud.messages
    );
    assert!(hud.flash > 0.5, "flash {}", hud.flash);
}

/// The bot's tasks that put chamber 1's cube on its plate.
fn cube_on_plate() -> Vec<Task> {
    vec![
        Task::Pick {
            body: "cube_1".into(),
        },
        Task::Carry {
            over: Vec3::new(3.0, 0.08, -11.0),
            within: 0.15,
            yaw: None,
        },
    ]
}

#[test]
fn the_plate_and_the_door_it_opens_say_so_and_the_chamber_counts_as_done() {
    let (mut game, mut engine) = start(0);
    assert_eq!(counter(&game), "");
    let mut tasks = cube_on_plate();
    tasks.extend([
        Task::Rule {
            name: "door_1".into(),
        },
        Task::Walk {
            to: Vec2::new(0.0, -14.5),
            within: 0.15,
        },
        Task::Walk {
            to: Vec2::new(0.0, -19.0),
            within: 0.15,
        },
    ]);
    let mut bot = Bot::new(tasks);
    let opened = play(&mut game, &mut engine, &mut bot, 1800, |game, _| {
        rose(game, "door_1")
    });
    assert!(opened, "the door never opened: {:?}", game.log());
    let messages = game.hud().messages;
    let pressed = messages.iter().position(|m| m == PLATE_PRESSED);
    let opens = messages.iter().position(|m| m == DOOR_OPENS);
    assert!(
        pressed.is_some() && opens.is_some() && pressed < opens,
        "{messages:?}"
    );
    assert_eq!(counter(&game), "1 / 5 solved");
    let objective = game.hud().objective.unwrap_or_default();
    assert!(objective.contains("door is open"), "{objective}");

    let entered = play(&mut game, &mut engine, &mut bot, 1800, |game, _| {
        game.current() == Some(1)
    });
    assert!(entered, "never walked into chamber 2");
    let messages = game.hud().messages;
    assert!(messages.contains(&chamber_complete(0)), "{messages:?}");
    assert_eq!(counter(&game), "2 / 5");
    // Inside the next room, the door that opened closes behind the player.
    let closed = play(&mut game, &mut engine, &mut bot, 600, |game, _| {
        rose(game, "close_behind_2")
    });
    assert!(closed, "the door behind never closed: {:?}", game.log());
    let messages = game.hud().messages;
    assert!(
        messages.iter().any(|m| m == DOOR_CLOSED_BEHIND),
        "{messages:?}"
    );
}

#[test]
fn lifting_the_cube_off_the_plate_releases_it_and_closes_the_door() {
    let (mut game, mut engine) = start(0);
    let mut tasks = cube_on_plate();
    // Lift it off again and carry it away from the plate.
    tasks.extend([
        Task::Pick {
            body: "cube_1".into(),
        },
        Task::Carry {
            over: Vec3::new(0.0, 0.08, -6.0),
            within: 0.3,
            yaw: None,
        },
    ]);
    let mut bot = Bot::new(tasks);
    let opened = play(&mut game, &mut engine, &mut bot, 1800, |game, _| {
        rose(game, "door_1")
    });
    assert!(opened, "the door never opened: {:?}", game.log());
    let closed = play(&mut game, &mut engine, &mut bot, 1800, |game, _| {
        game.log().iter().any(|(_, e)| {
            matches!(e, reflect::game::ReflectEvent::Rule { name, rising: false } if name == "door_1")
        })
    });
    assert!(
        closed,
        "the door never closed (bot at {:?}): {:?}",
        bot.task(),
        game.log()
    );
    let messages = game.hud().messages;
    assert!(messages.iter().any(|m| m == PLATE_RELEASED), "{messages:?}");
    assert!(messages.iter().any(|m| m == DOOR_CLOSES), "{messages:?}");
    assert_eq!(counter(&game), "1 / 5");
}
