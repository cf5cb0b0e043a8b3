//! [`FirstPersonGame`]: a level played in first person — the game the `playground` tool runs
//! and the platform tests replay. Spawns the level and a [`FirstPersonPlayer`] at the level's
//! camera; each fixed step turns the step's actions into a `PlayerInput` (`player_input.rs`,
//! with the player's settings), steps the player and sends the event of what it used to the
//! level's rules; keeps a log of what happened (events sent, rules fired, the outcome) for
//! tools and tests; in a window, draws a crosshair and the focused usable's prompt. Its HUD's
//! prompt follows the player's state (pick up, or drop while carrying) and says "Too far" for
//! a moment after a use press at something out of reach.
//!
//! Main thread, inside the engine's hooks. Must not: read devices (the step's actions come
//! from the devices or from a replay, alike).

use std::path::{Path, PathBuf};

use super::player_input::player_input;
use crate::app::input::ActionSet;
use crate::app::replay::ReplayError;
use crate::app::replay::StepInput;
use crate::app::replay::level_hash;
use crate::app::replay::{Recorder, Replay, ReplayTarget};
use crate::app::runner::SpawnedLevel;
use crate::app::runner::{EditHooks, EditTarget};
use crate::app::runner::{Engine, Environment};
use crate::app::runner::{Game, LevelEvent, SetupError, Step};
use crate::app::runner::{HudInfo, LevelEntry, ShellHooks, ShellInfo};
use crate::assets::{AssetResult, AssetRoot};
use crate::level::{PlayableLevel, load_level};
use crate::player::{FirstPersonConfig, FirstPersonPlayer, FocusKind};

/// Fixed steps a HUD message such as "Too far" stays up (1.5 s at 60 steps per second).
pub const MESSAGE_STEPS: u64 = 90;

/// The prompt while carrying a body.
pub const CARRY_PROMPT: &str = "E  drop · left mouse  throw";

/// The message after a use press at something out of reach.
pub const TOO_FAR: &str = "Too far";

/// The game name replays of [`FirstPersonGame`] carry.
pub const FIRST_PERSON_GAME: &str = "playground";

/// Something that happened, with the fixed step it happened in (0-based).
#[derive(Clone, Debug, PartialEq)]
pub enum Happened {
    /// The player used a usable: its event, sent to the rules.
    Used(String),
    /// A rule's condition rose (`then` ran) or fell (`otherwise` ran).
    Rule { name: String, rising: bool },
    /// The level was won or lost; the rule's name.
    Ended(String),
}

impl Happened {
    /// What a level event is in the log: a rule rising or falling, the level ending; `None`
    /// for the events the log leaves out (volumes, clips).
    pub fn of_level_event(event: &LevelEvent) -> Option<Self> {
        match event {
            LevelEvent::Rule { name, firing } => Some(Happened::Rule {
                name: name.clone(),
                rising: firing.rising,
            }),
            LevelEvent::Ended(outcome) => Some(Happened::Ended(format!("{outcome:?}"))),
            _ => None,
        }
    }
}

/// A level played in first person.
pub struct FirstPersonGame {
    level_path: PathBuf,
    level: PlayableLevel,
    /// Draw the crosshair and prompt in `Game::ui` (the plain window runner); under the shell
    /// its HUD draws them from `Game::hud` instead.
    own_hud: bool,
    config: FirstPersonConfig,
    player: Option<FirstPersonPlayer>,
    spawned: SpawnedLevel,
    log: Vec<(u64, Happened)>,
    start_input: Option<StepInput>,
    /// What F1's editor edits (a level of one file, when loaded from one).
    edit: Option<EditTarget>,
    /// The last fixed step run, and the last one whose use press was out of reach.
    last_step: u64,
    too_far_at: Option<u64>,
}

impl FirstPersonGame {
    /// Loads `level_path` (paths confined to `root`); the level is spawned by [`Game::setup`].
    pub fn load(level_path: &Path, root: &AssetRoot) -> AssetResult<Self> {
        let mut game = Self::of_level(level_path, load_level(level_path, root)?);
        game.edit = Some(EditTarget::single_file(level_path, root.clone()));
        Ok(game)
    }

    /// What the editor (F1) edits: `None` gives the shell's placeholder.
    pub fn set_edit_target(&mut self, target: Option<EditTarget>) {
        self.edit = target;
    }

    /// The game was spawned again by the editor: `spawned` replaces the level's handles.
    pub fn set_spawned(&mut self, spawned: SpawnedLevel) {
        self.spawned = spawned;
    }

    /// A game of an already loaded `level` (a composed level, `level::load_composed`);
    /// `level_path` names it in messages and replays.
    pub fn of_level(level_path: &Path, level: PlayableLevel) -> Self {
        Self {
            level_path: level_path.to_path_buf(),
            level,
            own_hud: true,
            config: FirstPersonConfig::default(),
            player: None,
            spawned: SpawnedLevel::default(),
            log: Vec::new(),
            start_input: None,
            edit: None,
            last_step: 0,
            too_far_at: None,
        }
    }

    /// The environment (sun, sky, render settings, camera) of the level, for `Engine::new`.
    pub fn environment(&self) -> Environment {
        Environment::of(&self.level.scene)
    }

    /// The level file.
    pub fn level_path(&self) -> &Path {
        &self.level_path
    }

    /// The level's id in replays: its file name without the extension.
    pub fn level_id(&self) -> String {
        self.level_path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    }

    /// The content hash of the level file now (replays must match it).
    pub fn level_hash(&self) -> Result<u64, ReplayError> {
        level_hash(&self.level_path)
    }

    /// Opens the recording at `path` for this level: the standard actions at 60 steps per
    /// second, and the level file as it is now (a replay of another level or of an older
    /// version of this one is refused, naming `path`).
    pub fn open_replay(&self, path: &Path) -> Result<Replay, ReplayError> {
        let set = ActionSet::standard();
        let id = self.level_id();
        let target = ReplayTarget {
            game: FIRST_PERSON_GAME,
            level_id: &id,
            level_hash: self.level_hash()?,
            step_hz: 60.0,
            actions: &set,
        };
        Replay::open(path, &target)
    }

    /// A recorder of this level's steps (the target [`FirstPersonGame::open_replay`] checks
    /// against): for `--record FILE` in a window, written when the window closes.
    pub fn recorder(&self) -> Result<Recorder, ReplayError> {
        Ok(Recorder::new(
            FIRST_PERSON_GAME,
            &self.level_id(),
            self.level_hash()?,
            60.0,
            &ActionSet::standard(),
        ))
    }

    /// Where the steps' input comes from once set up (a replay in a window; the devices by
    /// default).
    pub fn start_with(&mut self, input: StepInput) {
        self.start_input = Some(input);
    }

    /// Leaves the crosshair and prompt to the shell's HUD (`run_game`).
    pub fn use_shell_hud(&mut self) {
        self.own_hud = false;
    }

    /// The player, once set up.
    pub fn player(&self) -> Option<&FirstPersonPlayer> {
        self.player.as_ref()
    }

    /// The player, once set up, to move it (a checkpoint, a respawn).
    pub fn player_mut(&mut self) -> Option<&mut FirstPersonPlayer> {
        self.player.as_mut()
    }

    /// The loaded level (its scene, bodies and gameplay).
    pub fn level(&self) -> &PlayableLevel {
        &self.level
    }

    /// The level's instances, once set up.
    pub fn spawned(&self) -> &SpawnedLevel {
        &self.spawned
    }

    /// What happened so far, in order, with the step index.
    pub fn log(&self) -> &[(u64, Happened)] {
        &self.log
    }

    /// The last step whose use press was at something out of reach.
    pub fn too_far_at(&self) -> Option<u64> {
        self.too_far_at
    }

    /// The prompt for what is under the crosshair, or for what is carried.
    pub fn prompt(&self) -> Option<String> {
        let player = self.player.as_ref()?;
        if player.carrying() {
            return Some(CARRY_PROMPT.into());
        }
        match &player.focus()?.kind {
            FocusKind::Usable(u) => Some(u.prompt.clone()),
            FocusKind::Body => Some("E  pick up · left mouse  throw".into()),
            FocusKind::Surface => None,
        }
    }

    /// The messages of the last [`MESSAGE_STEPS`] steps ("Too far").
    pub fn messages(&self) -> Vec<String> {
        self.too_far_at
            .filter(|&at| self.last_step.saturating_sub(at) < MESSAGE_STEPS)
            .map(|_| vec![TOO_FAR.to_string()])
            .unwrap_or_default()
    }
}

impl Game for FirstPersonGame {
    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        engine.set_actions(ActionSet::standard());
        // The player's focus and the level's lasers query the scene in steps: the same input
        // must give the same outcome at any frame rate.
        engine.settle_every_step(true);
        self.spawned = engine.spawn_level(&self.level);
        let camera = crate::extract::RenderCamera::from_desc(&self.level.scene.camera);
        let player = FirstPersonPlayer::at_view(engine.world_mut(), &camera, self.config)
            .map_err(|e| format!("{}: the player: {e}", self.level_path.display()))?;
        self.player = Some(player);
        if let Some(input) = self.start_input.take() {
            engine.set_step_input(input);
        }
        Ok(())
    }

    fn fixed_step(&mut self, step: &mut Step<'_>) {
        let Some(player) = self.player.as_mut() else {
            return;
        };
        let input = player_input(
            step.actions,
            step.action_set,
            step.settings,
            step.step_seconds,
        );
        let done = player.step(step.world, step.physics, &step.queries, &input);
        self.last_step = step.index;
        if done.too_far {
            self.too_far_at = Some(step.index);
        }
        if let Some(event) = done.used {
            step.commands.send_event(event.clone());
            self.log.push((step.index, Happened::Used(event)));
        }
    }

    fn level_event(&mut self, step: &mut Step<'_>, event: &LevelEvent) {
        if let Some(happened) = Happened::of_level_event(event) {
            self.log.push((step.index, happened));
        }
    }

    fn has_ui(&self) -> bool {
        self.own_hud
    }

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }

    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        Some(self)
    }

    fn ui(&mut self, ctx: &egui::Context) {
        if !self.own_hud {
            return;
        }
        let prompt = self.prompt();
        let messages = self.messages();
        egui::Area::new(egui::Id::unique("crosshair"))
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                ui.vertical_centered(|ui| {
                    ui.label(egui::RichText::new("+").size(20.0));
                    for line in prompt.iter().chain(&messages) {
                        ui.label(egui::RichText::new(line).size(18.0).strong());
                    }
                });
            });
    }
}

impl EditHooks for FirstPersonGame {
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)> {
        Some((self.edit.clone()?, self.spawned.clone()))
    }

    fn level_respawned(&mut self, _engine: &mut Engine, spawned: &SpawnedLevel) {
        self.spawned = spawned.clone();
    }

    fn play_from(&mut self, engine: &mut Engine, eye: glam::Vec3, forward: glam::Vec3) {
        self.play_from_view(engine, eye, forward);
    }
}

impl ShellHooks for FirstPersonGame {
    fn shell_info(&self) -> ShellInfo {
        let id = self.level_id();
        ShellInfo {
            title: "Candela Playground".into(),
            subtitle: "Walk, carry, ride and use: the game platform's test level".into(),
            levels: vec![LevelEntry {
                name: id.replace('_', " "),
                id,
            }],
            finished_only: false,
        }
    }

    fn hud(&self) -> HudInfo {
        HudInfo {
            crosshair: true,
            objective: Some("Look around: E uses a switch or picks up a cube".into()),
            prompt: self.prompt(),
            counters: Vec::new(),
            outline: self
                .player
                .as_ref()
                .map_or_else(Vec::new, FirstPersonPlayer::drop_outline),
            messages: self.messages(),
            flash: 0.0,
        }
    }
}
