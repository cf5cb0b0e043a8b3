//! Records `assets/test_scenes/platform/first_person.replay`: a scripted bot plays
//! `first_person.ron` through the engine's own frame loop (headless, CPU tracer, one fixed step
//! per frame) by pressing keys and moving the mouse like a player would, and the engine records
//! every step's actions (`StepInput::record`). The bot steers from the player's state after
//! each step, towards simple waypoints: to the glass cube, pick it up (E), carry it over the
//! pressure plate and aim at it, drop it (E: it lands where the crosshair points), walk onto the lift, ride up, walk to the lever and use it (E).
//!
//! Run: `cargo run --release -p candela --example record_platform_replays` (re-record after the
//! level or the player's controller changed; `engine/tests/engine/player_first_person.rs` fails
//! loudly when the committed replay no longer solves the level). Deterministic: the same
//! build records the same file. Units: metres, radians, mouse counts.

use std::path::PathBuf;

use anyhow::{Context, bail};
use candela::app::{
    ActionSet, Engine, FIRST_PERSON_GAME, FirstPersonGame, Game, Happened, KeyCode, Recorder,
    StepInput,
    steer::{self, Steer, yaw_to},
};
use candela::assets::AssetRoot;
use candela::ecs::Transform;
use candela::player::{FirstPersonPlayer, FocusKind};
use candela::render::RenderConfig;
use glam::{Vec2, Vec3, Vec3Swizzles};

/// The plate's centre and the lever's front face (from the level file).
const PLATE: Vec3 = Vec3::new(2.0, 0.02, 1.0);
const LIFT: Vec3 = Vec3::new(0.0, 0.2, -2.0);
const SWITCH: Vec3 = Vec3::new(0.0, 4.6, -7.845);
/// Where the bot stands to use the lever (on the upper floor).
const SWITCH_STAND: Vec2 = Vec2::new(0.0, -6.7);
/// Give up after this many steps (a minute of play).
const MAX_STEPS: u64 = 60 * 60;

fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Phase {
    ToCube,
    Carry,
    Release,
    ToLift,
    Ride,
    ToSwitch,
    Done(u64),
}

/// What the bot does this step: keys held, E pressed, mouse counts.
#[derive(Default)]
struct Act {
    forward: bool,
    use_key: bool,
    mouse: Vec2,
}

/// [`steer::aim`] into an [`Act`].
fn aim(player: &FirstPersonPlayer, yaw: f32, pitch: f32, act: &mut Act) -> (f32, f32) {
    let mut s = Steer::default();
    let errors = steer::aim(player, yaw, pitch, &mut s);
    act.mouse = s.mouse;
    errors
}

/// [`steer::walk_to`] into an [`Act`].
fn walk_to(
    player: &FirstPersonPlayer,
    feet: Vec3,
    target: Vec2,
    pitch: f32,
    within: f32,
    act: &mut Act,
) -> bool {
    let mut s = Steer::default();
    let there = steer::walk_to(player, feet, target, pitch, within, &mut s);
    act.mouse = s.mouse;
    act.forward = s.forward;
    there
}

struct Bot {
    phase: Phase,
    cube: hecs::Entity,
    waited: u32,
}

impl Bot {
    fn act(&mut self, engine: &Engine, game: &FirstPersonGame, step: u64) -> Act {
        let mut act = Act::default();
        let world = engine.world();
        let Some(player) = game.player() else {
            return act;
        };
        let feet = player.feet(world);
        let eye = player.eye(world);
        let cube = world
            .get::<&Transform>(self.cube)
            .map_or(Vec3::ZERO, |t| t.translation);
        let held = player.held(world);
        if std::env::var_os("BOT_TRACE").is_some() && step.is_multiple_of(30) {
            println!(
                "step {step} {:?}: feet {feet} yaw {:.3} pitch {:.3} cube {cube} held {held:?} focus {:?}",
                self.phase,
                player.yaw,
                player.pitch,
                player.focus().map(|f| (f.entity, f.distance))
            );
            let st = world
                .get::<&candela::sim::physics::CharacterState>(player.body)
                .map(|s| *s);
            let inp = world
                .get::<&candela::sim::physics::CharacterInput>(player.body)
                .map(|s| *s);
            println!("   state {st:?} input {inp:?}");
        }
        match self.phase {
            Phase::ToCube => {
                let flat = (cube - feet).with_y(0.0);
                let stand = cube.xz() - flat.xz().normalize_or_zero() * 1.0;
                let pitch = (cube.y - eye.y).atan2(flat.length());
                if walk_to(player, feet, stand, pitch, 0.05, &mut act) {
                    let (dy, dp) = aim(player, yaw_to(feet, cube), pitch, &mut act);
                    let on_cube = player
                        .focus()
                        .is_some_and(|f| f.entity == self.cube && f.kind == FocusKind::Body);
                    if dy < 0.02 && dp < 0.02 && on_cube {
                        act.use_key = true;
                    }
                }
                if held == Some(self.cube) {
                    self.phase = Phase::Carry;
                }
            }
            Phase::Carry => {
                // Stand 1.1 m short of the plate, put the crosshair on it and drop once the
                // drop's preview lies on it (the drop places the cube where the view points).
                let flat = (PLATE - feet).with_y(0.0);
                let stand = PLATE.xz() - flat.xz().normalize_or_zero() * 1.1;
                let pitch = (PLATE.y - eye.y).atan2(flat.length());
                if walk_to(player, feet, stand, pitch, 0.04, &mut act) {
                    let (dy, dp) = aim(player, yaw_to(feet, PLATE), pitch, &mut act);
                    let camera = player.camera;
                    let over = engine
                        .physics()
                        .placement(engine.world(), camera)
                        .map_or(f32::INFINITY, |p| (p.position - PLATE).xz().length());
                    self.waited += 1;
                    if dy.abs() < 0.01 && dp.abs() < 0.01 && over < 0.12 && self.waited > 30 {
                        act.use_key = true;
                        self.phase = Phase::Release;
                        self.waited = 0;
                    }
                }
            }
            Phase::Release => {
                self.waited += 1;
                if held.is_some() && self.waited == 10 {
                    act.use_key = true;
                }
                if held.is_none() && self.waited > 60 {
                    self.phase = Phase::ToLift;
                }
            }
            Phase::ToLift => {
                if walk_to(player, feet, LIFT.xz(), 0.0, 0.08, &mut act) {
                    aim(player, 0.0, 0.0, &mut act);
                    self.phase = Phase::Ride;
                    self.waited = 0;
                }
            }
            Phase::Ride => {
                aim(player, 0.0, 0.0, &mut act);
                if feet.y > LIFT.y + 2.95 {
                    self.waited += 1;
                }
                if self.waited > 30 {
                    self.phase = Phase::ToSwitch;
                }
            }
            Phase::ToSwitch => {
                let pitch = (SWITCH.y - eye.y).atan2((SWITCH - eye).with_y(0.0).length());
                if walk_to(player, feet, SWITCH_STAND, pitch, 0.05, &mut act) {
                    let (dy, dp) = aim(player, yaw_to(feet, SWITCH), pitch, &mut act);
                    if dy < 0.02 && dp < 0.02 && player.prompt().is_some() {
                        act.use_key = true;
                    }
                }
                if game
                    .log()
                    .iter()
                    .any(|(_, h)| *h == Happened::Used("lever".into()))
                {
                    self.phase = Phase::Done(step);
                }
            }
            Phase::Done(_) => {}
        }
        act
    }
}

fn main() -> anyhow::Result<()> {
    let level = assets().join("test_scenes/platform/first_person.ron");
    let out = assets().join("test_scenes/platform/first_person.replay");
    let root = AssetRoot::new(assets())?;
    let mut game = FirstPersonGame::load(&level, &root)?;
    let mut engine = Engine::new(RenderConfig::cpu(16, 9), game.environment())?;
    game.setup(&mut engine)
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let set = ActionSet::standard();
    let recorder = Recorder::new(
        FIRST_PERSON_GAME,
        &game.level_id(),
        game.level_hash()?,
        60.0,
        &set,
    );
    engine.set_step_input(StepInput::record(recorder, &out));
    let cube = *game
        .spawned()
        .by_name
        .get("glass_cube")
        .context("no glass_cube")?;
    let mut bot = Bot {
        phase: Phase::ToCube,
        cube,
        waited: 0,
    };
    let mut last = bot.phase;
    for step in 0..MAX_STEPS {
        if let Phase::Done(at) = bot.phase
            && step > at + 60
        {
            break;
        }
        let act = bot.act(&engine, &game, step);
        if bot.phase != last {
            println!("step {step}: {:?}", bot.phase);
            last = bot.phase;
        }
        let input = engine.input_mut();
        input.key(KeyCode::KeyW, act.forward);
        input.key(KeyCode::KeyE, act.use_key);
        input.mouse_motion(act.mouse.x, act.mouse.y);
        engine.frame(1.0 / 60.0, &mut game)?;
        let _ = engine.rendered();
    }
    if !matches!(bot.phase, Phase::Done(_)) {
        bail!(
            "the bot got stuck in {:?} (level or controller changed?)",
            bot.phase
        );
    }
    engine.finish_recording()?;
    for (step, h) in game.log() {
        println!("step {step}: {h:?}");
    }
    println!("wrote {}", out.display());
    let _ = engine.shutdown();
    Ok(())
}
