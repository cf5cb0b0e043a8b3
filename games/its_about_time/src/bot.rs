//! The scripted explorer that records the committed replays: a list of [`Task`]s (walk to a
//! point, use what it stands at, hold R or Q at the altar until a rule rises, wait for a rule
//! or the ending), each turned into the keys and mouse motion a player would give, from the
//! explorer's state after each step. The engine records the resulting actions
//! (`StepInput::record`), so a replay is what a person pressing those keys would have made.
//!
//! In third person the keys move the explorer relative to the camera: the bot turns the
//! follow camera with the mouse towards where it walks (at most [`MAX_COUNTS`] counts a step)
//! and holds W once the camera faces within 0.3 rad of it.
//!
//! Owns: [`Task`], [`Bot`], [`Act`]. Main thread, between frames. Must not: move anything
//! itself (only input reaches the game). Units: metres, radians, mouse counts.

use candela::app::{Engine, InputState, KeyCode, MOUSE_RADIANS_PER_COUNT};
use glam::{Vec2, Vec3};

use crate::game::TimeGame;

/// Most mouse counts per step.
pub const MAX_COUNTS: f32 = 40.0;

/// One thing the bot does, in order.
#[derive(Clone, Debug, PartialEq)]
pub enum Task {
    /// Walk to a point (x, z) until within `within` metres.
    Walk { to: Vec2, within: f32 },
    /// Press E (every other step) until the usable sending `event` was used once more than
    /// when the task began (a torch lit a second time).
    Use { event: String },
    /// At an altar: hold R (`forward`) or Q until the level's rule `rule` holds, then one more
    /// second of steps with nothing held.
    TurnUntil { rule: String, forward: bool },
    /// Wait until the level's rule `name` holds.
    Rule { name: String },
    /// Wait until the ending.
    Ending,
    /// Wait this many steps.
    Wait { steps: u32 },
}

/// What the bot does this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Act {
    pub forward: bool,
    pub use_key: bool,
    pub time_back: bool,
    pub time_forward: bool,
    pub mouse: Vec2,
}

impl Act {
    /// Holds this step's keys on `input` and adds the mouse counts, as a player's devices
    /// would (W forward, E use, Q and R time).
    pub fn press(&self, input: &mut InputState) {
        input.key(KeyCode::KeyW, self.forward);
        input.key(KeyCode::KeyE, self.use_key);
        input.key(KeyCode::KeyQ, self.time_back);
        input.key(KeyCode::KeyR, self.time_forward);
        input.mouse_motion(self.mouse.x, self.mouse.y);
    }
}

/// Wraps an angle to (−π, π].
fn wrap(a: f32) -> f32 {
    (a + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI
}

/// The bot: its tasks and where it is in them.
#[derive(Clone, Debug)]
pub struct Bot {
    tasks: Vec<Task>,
    next: usize,
    waited: u32,
    toggle: bool,
    /// How often the event of the `Use` under way had been used when it began.
    uses_before: Option<usize>,
}

impl Bot {
    pub fn new(tasks: Vec<Task>) -> Self {
        Self {
            tasks,
            next: 0,
            waited: 0,
            toggle: false,
            uses_before: None,
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
        self.uses_before = None;
    }

    /// What to do this step.
    pub fn act(&mut self, engine: &Engine, game: &TimeGame) -> Act {
        let mut act = Act::default();
        let Some(player) = game.inner().player() else {
            return act;
        };
        let Some(task) = self.tasks.get(self.next).cloned() else {
            return act;
        };
        let centre = player.centre(engine.world(), None);
        match task {
            Task::Walk { to, within } => {
                let d = Vec3::new(to.x - centre.x, 0.0, to.y - centre.z);
                if d.length() <= within {
                    self.advance();
                    return act;
                }
                // Follow-camera yaw that looks along d (0 along −Z, positive towards +X).
                let want = d.x.atan2(-d.z);
                let error = wrap(want - player.follow.yaw_rad);
                // Mouse right (+x) turns the camera right (its yaw grows).
                act.mouse.x = (error / MOUSE_RADIANS_PER_COUNT).clamp(-MAX_COUNTS, MAX_COUNTS);
                act.forward = error.abs() < 0.3;
            }
            Task::Use { event } => {
                let uses = (game.inner().log().iter())
                    .filter(|(_, h)| *h == candela::app::Happened::Used(event.clone()))
                    .count();
                let before = *self.uses_before.get_or_insert(uses);
                if uses > before {
                    self.advance();
                } else {
                    self.toggle = !self.toggle;
                    act.use_key = self.toggle;
                }
            }
            Task::TurnUntil { rule, forward } => {
                if engine.logic().rule_holds(&rule) {
                    self.waited += 1;
                    if self.waited > 60 {
                        self.advance();
                    }
                } else {
                    act.time_forward = forward;
                    act.time_back = !forward;
                }
            }
            Task::Rule { name } => {
                if engine.logic().rule_holds(&name) {
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
