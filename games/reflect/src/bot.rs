//! The scripted player that records Reflect's committed replays: a list of [`Task`]s (walk
//! somewhere, pick up a cube, carry it and drop it, shoot a panel, use a lever, wait for a
//! rule), each turned into the keys and mouse motion a player would give, from the player's
//! state after each step. The engine records the resulting actions (`StepInput::record`), so a
//! replay is exactly what a person pressing those keys would have recorded.
//!
//! Owns: [`Task`], [`Bot`] and [`Act`] (the steering itself is `candela::app::steer`, shared
//! with the platform level's bot). Main thread, between frames. Must not: move anything
//! itself (only input reaches the game). Units: metres, radians, mouse counts.

use candela::app::steer::{Steer, aim as steer_aim, pitch_to, walk_to as steer_walk, yaw_to};
use candela::app::{Engine, InputState, KeyCode, MouseButton};
use candela::ecs::Transform;
use candela::player::{FirstPersonPlayer, FocusKind};
use glam::{Vec2, Vec3, Vec3Swizzles};

use crate::game::{ReflectEvent, ReflectGame};

/// One thing the bot does, in order.
#[derive(Clone, Debug, PartialEq)]
pub enum Task {
    /// Walk to a point (x, z) until within `within` metres.
    Walk { to: Vec2, within: f32 },
    /// Walk up to the named body and pick it up.
    Pick { body: String },
    /// Carry what is held to `over` (a point on the surface it is to rest on), facing `yaw`
    /// (radians) when given, put the crosshair on it and drop it once the drop's preview lies
    /// within `within` metres of it (x, z); then wait for it to settle.
    Carry {
        over: Vec3,
        within: f32,
        yaw: Option<f32>,
    },
    /// From where it stands, aim at `at` and shoot the panel named `panel` (left button to
    /// make a mirror, right to revert) until it is what was asked.
    Shoot {
        at: Vec3,
        panel: String,
        mirror: bool,
    },
    /// Aim at `at` and press E until the player used something.
    Use { at: Vec3 },
    /// Wait until the rule `name` has risen.
    Rule { name: String },
    /// Wait until the player is in chamber `index`.
    Entered { index: usize },
    /// Wait until the ending.
    Ending,
    /// Wait this many steps.
    Wait { steps: u32 },
}

/// How far short of a drop spot the bot stands, metres (horizontally).
const STAND_BACK: f32 = 1.1;

/// What the bot does this step: keys held, buttons pressed, mouse counts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Act {
    pub forward: bool,
    pub use_key: bool,
    pub primary: bool,
    pub secondary: bool,
    pub mouse: Vec2,
}

impl Act {
    /// Holds this step's keys and buttons on `input` and adds the mouse counts, as a player's
    /// devices would (W forward, E use, left and right buttons).
    pub fn press(&self, input: &mut InputState) {
        input.key(KeyCode::KeyW, self.forward);
        input.key(KeyCode::KeyE, self.use_key);
        input.mouse_button(MouseButton::Left, self.primary);
        input.mouse_button(MouseButton::Right, self.secondary);
        input.mouse_motion(self.mouse.x, self.mouse.y);
    }
}

/// The bot: its tasks and where it is in them.
#[derive(Clone, Debug)]
pub struct Bot {
    tasks: Vec<Task>,
    next: usize,
    waited: u32,
    /// Alternates button presses (a press needs a release before it counts again).
    toggle: bool,
    /// The first-person log's length when the task under way began.
    mark: Option<usize>,
}

/// [`steer_aim`] into an [`Act`].
fn aim(player: &FirstPersonPlayer, yaw: f32, pitch: f32, act: &mut Act) -> (f32, f32) {
    let mut steer = Steer::default();
    let errors = steer_aim(player, yaw, pitch, &mut steer);
    act.mouse = steer.mouse;
    errors
}

/// [`steer_walk`] into an [`Act`].
fn walk_to(
    player: &FirstPersonPlayer,
    feet: Vec3,
    target: Vec2,
    pitch: f32,
    within: f32,
    act: &mut Act,
) -> bool {
    let mut steer = Steer::default();
    let there = steer_walk(player, feet, target, pitch, within, &mut steer);
    act.mouse = steer.mouse;
    act.forward = steer.forward;
    there
}

impl Bot {
    pub fn new(tasks: Vec<Task>) -> Self {
        Self {
            tasks,
            next: 0,
            waited: 0,
            toggle: false,
            mark: None,
        }
    }

    /// The task under way (`None`: all done).
    pub fn task(&self) -> Option<&Task> {
        self.tasks.get(self.next)
    }

    /// Whether every task is done.
    pub fn done(&self) -> bool {
        self.next >= self.tasks.len()
    }

    fn advance(&mut self) {
        self.next += 1;
        self.waited = 0;
        self.mark = None;
    }

    /// A press every other step (pressing needs a release in between).
    fn pulse(&mut self) -> bool {
        self.toggle = !self.toggle;
        self.toggle
    }

    /// What to do this step.
    pub fn act(&mut self, engine: &Engine, game: &ReflectGame) -> Act {
        let mut act = Act::default();
        let world = engine.world();
        let Some(player) = game.inner().player() else {
            return act;
        };
        let Some(task) = self.tasks.get(self.next).cloned() else {
            return act;
        };
        let feet = player.feet(world);
        let eye = player.eye(world);
        let held = player.held(world);
        let named = |name: &str| game.inner().spawned().by_name.get(name).copied();
        let position = |e: hecs::Entity| {
            world
                .get::<&Transform>(e)
                .map_or(Vec3::ZERO, |t| t.translation)
        };
        match task {
            Task::Walk { to, within } => {
                if walk_to(player, feet, to, 0.0, within, &mut act) {
                    self.advance();
                }
            }
            Task::Pick { body } => {
                let Some(e) = named(&body) else {
                    return act;
                };
                let at = position(e);
                let flat = (at - feet).with_y(0.0);
                let stand = at.xz() - flat.xz().normalize_or_zero() * 1.0;
                let pitch = pitch_to(eye, at);
                if walk_to(player, feet, stand, pitch, 0.06, &mut act) {
                    let (dy, dp) = aim(player, yaw_to(feet, at), pitch, &mut act);
                    let on = player
                        .focus()
                        .is_some_and(|f| f.entity == e && f.kind == FocusKind::Body);
                    if dy < 0.03 && dp < 0.03 && on && self.pulse() {
                        act.use_key = true;
                    }
                }
                if held == Some(e) {
                    self.advance();
                }
            }
            Task::Carry { over, within, yaw } => {
                if held.is_none() {
                    // Dropped: let it settle.
                    self.waited += 1;
                    if self.waited > 60 {
                        self.advance();
                    }
                    return act;
                }
                // Stand 1.1 m short of the spot, facing it (or `yaw`), put the crosshair on
                // it and drop once the drop's preview lies on it, as a player would.
                let facing = yaw.unwrap_or_else(|| yaw_to(feet, over));
                let back = Vec2::new(-facing.sin(), -facing.cos()) * STAND_BACK;
                let stand = over.xz() - back;
                let pitch = pitch_to(eye, over);
                if walk_to(player, feet, stand, pitch, 0.04, &mut act) {
                    let (dy, dp) = aim(player, facing, pitch, &mut act);
                    let spot = engine.physics().placement(world, player.camera);
                    let off = spot.map_or(f32::INFINITY, |p| (p.position - over).xz().length());
                    self.waited += 1;
                    if dy.abs() < 0.01 && dp.abs() < 0.01 && off < within && self.waited > 20 {
                        act.use_key = true;
                        self.waited = 0;
                    }
                }
            }
            Task::Shoot { at, panel, mirror } => {
                let Some(e) = named(&panel) else {
                    return act;
                };
                let (dy, dp) = aim(player, yaw_to(eye, at), pitch_to(eye, at), &mut act);
                if dy < 0.01 && dp < 0.01 && self.pulse() {
                    if mirror {
                        act.primary = true;
                    } else {
                        act.secondary = true;
                    }
                }
                if game.gun().is_mirror(e) == mirror {
                    self.advance();
                }
            }
            Task::Use { at } => {
                let (dy, dp) = aim(player, yaw_to(eye, at), pitch_to(eye, at), &mut act);
                if dy < 0.02 && dp < 0.02 && player.prompt().is_some() && self.pulse() {
                    act.use_key = true;
                }
                let log = game.inner().log();
                let mark = *self.mark.get_or_insert(log.len());
                if log[mark.min(log.len())..]
                    .iter()
                    .any(|(_, h)| matches!(h, candela::app::Happened::Used(_)))
                {
                    self.advance();
                }
            }
            Task::Rule { name } => {
                let risen = game.log().iter().any(|(_, e)| {
                    matches!(e, ReflectEvent::Rule { name: n, rising: true } if *n == name)
                });
                if risen {
                    self.advance();
                }
            }
            Task::Entered { index } => {
                if game.current() == Some(index) {
                    self.advance();
                }
            }
            Task::Ending => {
                if game.ended() {
                    self.advance();
                }
            }
            Task::Wait { steps } => {
                self.waited += 1;
                if self.waited >= steps {
                    self.advance();
                }
            }
        }
        act
    }
}
