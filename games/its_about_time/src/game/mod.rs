//! [`TimeGame`]: It's About Time's rules over the engine's third-person game — artifacts
//! taken, the sun altar that turns time while Q or R is held, the HUD (artifacts, the time of
//! day, the prompt, messages) and the ending.
//!
//! The level carries the puzzles themselves (rules: the sun gate opens while `SunLit` holds on
//! its glyph; taking an artifact counts it; standing at the temple altar with every artifact
//! wins). The game adds what rules cannot: turning time (`Commands::advance_time`) and the
//! HUD. The day clock's arithmetic is in `day.rs`, the HUD in `hud.rs`, the time-of-day dial in
//! `dial.rs`, the footsteps and sound loops in `soundscape.rs`.
//!
//! Main thread, inside the engine's hooks (`candela::app::Game`). Must not: read devices (the
//! step's actions come from the devices or a replay alike) or reach into the renderer.

use candela::app::edit::{EditHooks, EditTarget};
use candela::app::shell::ShellHooks;
use candela::app::{Engine, Game, Happened, LevelEvent, SetupError, SpawnedLevel, Step};
use candela::app::{Replay, StepInput, ThirdPersonGame};
use candela::sim::animation::ActionKind;
use candela::sky::SkyNow;

use crate::world::{LEVEL_ID, RuinsWorld, TIME_BACK, TIME_FORWARD, actions};

pub mod day;
mod dial;
mod hud;
pub mod soundscape;

use soundscape::Soundscape;

/// The game name the recordings carry.
pub const GAME_NAME: &str = "its_about_time";

/// The event a sun altar's usable sends (`gameplay.usables` in the level): the game turns
/// time while the explorer stands at it and holds Q or R.
pub const ALTAR_EVENT: &str = "sun_altar";

/// Events of artifacts start with this (`artifact_sun` …).
pub const ARTIFACT_PREFIX: &str = "artifact_";

/// Seconds of day an altar turns per second held (three quarters of an hour a second).
pub const ALTAR_RATE: f64 = 2700.0;

/// The most exposure, stops, the window's sky meter may set: about what the ground a few
/// metres from a lit torch needs (a flame of 0.1 m² at radiance 2 gives 0.02 W·m⁻² at 3 m;
/// 0.5 / π of that × 2⁶ is mid grey), so after sunset the ruins read by torchlight instead of
/// being exposed for the starlight the meter sees.
pub const NIGHT_MAX_EV: f32 = 6.0;

/// Fixed steps a HUD message stays up (3 s at 60 steps per second).
const MESSAGE_STEPS: u64 = 180;

/// Something that happened, for tools, tests and the bot.
#[derive(Clone, Debug, PartialEq)]
pub enum TimeEvent {
    /// An artifact was taken: its event name.
    Artifact(String),
    /// Time was turned at an altar by this many seconds of day in one step.
    Turned(f64),
    /// A rule's condition rose or fell, at this local solar time (hours; `None` when the sky
    /// has no time).
    Rule {
        name: String,
        rising: bool,
        hours: Option<f64>,
    },
    /// The explorer began (true) or stopped (false) leaning into a block with its push pose.
    Push(bool),
    /// The ending was reached.
    Ending,
}

/// It's About Time.
pub struct TimeGame {
    inner: ThirdPersonGame,
    /// Fixed steps played, and the one the ending came in.
    steps: u64,
    step_seconds: f64,
    ended_at: Option<u64>,
    artifacts: Vec<String>,
    log: Vec<(u64, TimeEvent)>,
    /// The sky at the start of the last step (the HUD's dial).
    sky: Option<SkyNow>,
    /// Messages and the step each came in.
    messages: Vec<(u64, String)>,
    /// Whether the explorer stands at a sun altar (its prompt is up).
    at_altar: bool,
    /// Whether the level's `sun_gate` rule holds (the gate is open).
    gate_open: bool,
    /// The artifacts the level holds, in level order.
    in_level: Vec<String>,
    /// The explorer leaned into a block in the last step.
    pushing: bool,
    /// Footsteps and sound loops.
    sounds: Soundscape,
}

impl TimeGame {
    /// A new game over the loaded `world`.
    pub fn new(world: RuinsWorld) -> Self {
        let mut inner = ThirdPersonGame::of_level(&world.path, world.level.clone());
        inner.set_replay_names(GAME_NAME, LEVEL_ID);
        inner.set_actions(actions());
        inner.set_edit_target(Some(EditTarget::single_file(
            &world.path,
            world.root.clone(),
        )));
        let in_level = world
            .level
            .gameplay
            .usables
            .iter()
            .map(|u| u.usable.event.clone())
            .filter(|e| e.starts_with(ARTIFACT_PREFIX))
            .collect();
        Self {
            inner,
            steps: 0,
            step_seconds: 1.0 / 60.0,
            ended_at: None,
            artifacts: Vec::new(),
            log: Vec::new(),
            sky: None,
            messages: Vec::new(),
            at_altar: false,
            gate_open: false,
            in_level,
            pushing: false,
            sounds: Soundscape::default(),
        }
    }

    /// Footsteps and the sound loops' mix.
    pub fn soundscape(&self) -> &Soundscape {
        &self.sounds
    }

    /// The engine's third-person game underneath.
    pub fn inner(&self) -> &ThirdPersonGame {
        &self.inner
    }

    /// The engine's third-person game underneath, to start a replay or a recording on it.
    pub fn inner_mut(&mut self) -> &mut ThirdPersonGame {
        &mut self.inner
    }

    /// Opens a recording of this game (refused, naming the file, when it does not fit).
    pub fn open_replay(&self, path: &std::path::Path) -> anyhow::Result<Replay> {
        Ok(self.inner.open_replay(path)?)
    }

    /// Plays `input` from the first step on.
    pub fn start_with(&mut self, input: StepInput) {
        self.inner.start_with(input);
    }

    /// The artifacts the level holds (usables whose event starts with `artifact_`), in level
    /// order.
    pub fn artifacts_in_level(&self) -> &[String] {
        &self.in_level
    }

    /// The artifacts taken so far, in order.
    pub fn artifacts(&self) -> &[String] {
        &self.artifacts
    }

    /// Whether the ending was reached.
    pub fn ended(&self) -> bool {
        self.ended_at.is_some()
    }

    /// Seconds of play until the ending (or until now).
    pub fn play_seconds(&self) -> f64 {
        self.ended_at.unwrap_or(self.steps) as f64 * self.step_seconds
    }

    /// What happened, with the step.
    pub fn log(&self) -> &[(u64, TimeEvent)] {
        &self.log
    }

    /// The sky as the last step saw it.
    pub fn sky(&self) -> Option<&SkyNow> {
        self.sky.as_ref()
    }

    /// The explorer plays its model's clip `clip` once (it reaches down for an artifact, it
    /// cheers at the ending), then walks on. An explorer model without the clip just walks on.
    fn act(&self, step: &mut Step<'_>, clip: &str) {
        if let Some(player) = self.inner.player() {
            let _ = player.request_action(step.world, clip, ActionKind::Once);
        }
    }

    /// Logs when the explorer begins and stops leaning into a block (the engine's third-person
    /// player plays its `push` clip meanwhile).
    fn push_pose(&mut self, step: &mut Step<'_>) {
        let Some(player) = self.inner.player() else {
            return;
        };
        let pushing = player.pushing();
        if pushing != self.pushing {
            self.pushing = pushing;
            self.log.push((step.index, TimeEvent::Push(pushing)));
        }
    }

    fn say(&mut self, line: impl Into<String>) {
        let now = self.steps;
        self.messages
            .retain(|(at, _)| now.saturating_sub(*at) < MESSAGE_STEPS);
        self.messages.push((now, line.into()));
    }
}

impl Game for TimeGame {
    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        self.inner.setup(engine)
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        self.steps = step.index + 1;
        self.step_seconds = step.step_seconds;
        self.sky = step.sky;
        let before = self.inner.log().len();
        self.inner.fixed_step(step);
        self.push_pose(step);
        let used: Vec<String> = self.inner.log()[before..]
            .iter()
            .filter_map(|(_, h)| match h {
                Happened::Used(e) => Some(e.clone()),
                _ => None,
            })
            .collect();
        for event in used {
            if event.starts_with(ARTIFACT_PREFIX) && !self.artifacts.contains(&event) {
                self.act(step, "pick_up");
                self.artifacts.push(event.clone());
                let name = day::artifact_name(&event);
                self.say(format!("You take the {name}"));
                self.log.push((step.index, TimeEvent::Artifact(event)));
            }
        }
        self.at_altar = self
            .inner
            .player()
            .and_then(|p| p.focus())
            .is_some_and(|(_, u)| u.event == ALTAR_EVENT);
        let mut turning = false;
        if self.at_altar && self.ended_at.is_none() {
            let held = |name: &str| {
                step.action_set
                    .id(name)
                    .is_some_and(|id| step.actions.held(id))
            };
            let turn = (held(TIME_FORWARD) as i32 - held(TIME_BACK) as i32) as f64;
            if turn != 0.0 {
                let seconds = turn * ALTAR_RATE * step.step_seconds;
                step.commands.advance_time(seconds);
                self.log.push((step.index, TimeEvent::Turned(seconds)));
                turning = true;
            }
        }
        let centre = self
            .inner
            .player()
            .map(|p| p.centre(step.world, Some(step.physics)));
        let level = (self.inner.level(), self.inner.spawned());
        self.sounds.step(step, level, centre, turning);
    }

    fn level_event(&mut self, step: &mut Step<'_>, event: &LevelEvent) {
        self.inner.level_event(step, event);
        match event {
            LevelEvent::Rule { name, firing } => {
                if name == "sun_gate" {
                    self.gate_open = firing.rising;
                }
                if let Some(line) = day::rule_message(name, firing.rising) {
                    self.say(line);
                }
                self.log.push((
                    step.index,
                    TimeEvent::Rule {
                        name: name.clone(),
                        rising: firing.rising,
                        hours: step.sky.as_ref().and_then(day::local_hours),
                    },
                ));
            }
            LevelEvent::Ended(_) if self.ended_at.is_none() => {
                self.act(step, "celebrate");
                self.ended_at = Some(step.index + 1);
                self.log.push((step.index, TimeEvent::Ending));
            }
            _ => {}
        }
    }

    fn has_ui(&self) -> bool {
        true
    }

    fn ui(&mut self, ctx: &egui::Context) {
        if let Some(sky) = &self.sky
            && let Some(hours) = day::local_hours(sky)
        {
            dial::draw(ctx, hours, &day::clock_label(hours));
        }
    }

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }

    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        Some(self)
    }
}

impl EditHooks for TimeGame {
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)> {
        self.inner.edit_target()
    }

    fn level_respawned(&mut self, engine: &mut Engine, spawned: &SpawnedLevel) {
        self.inner.level_respawned(engine, spawned);
        self.sounds.level_changed();
    }

    fn play_from(&mut self, engine: &mut Engine, eye: glam::Vec3, forward: glam::Vec3) {
        self.inner.play_from(engine, eye, forward);
    }
}

/// The messages of the last [`MESSAGE_STEPS`] steps, oldest first.
fn recent(messages: &[(u64, String)], now: u64) -> Vec<String> {
    messages
        .iter()
        .filter(|(at, _)| now.saturating_sub(*at) < MESSAGE_STEPS)
        .map(|(_, m)| m.clone())
        .collect()
}
