//! [`ThirdPersonGame`]: a level played in third person — the level's first character
//! (`characters` in the file) driven by a [`ThirdPersonPlayer`] with its follow camera. Each
//! fixed step turns the step's actions into a `PlayerInput` (`player_input.rs`, with the
//! player's settings), steps the player, and sends the event of the usable it used to the
//! level's rules; it keeps the same log as the first-person game ([`Happened`]). The player
//! lifts, carries, puts down and throws light bodies and pushes heavy ones (its hands,
//! `player::Hands`); the prompt says what E does. Games such as
//! It's About Time wrap it and add their own rules; the playground plays any level with a
//! character in it.
//!
//! Main thread, inside the engine's hooks. Must not: read devices (the step's actions come
//! from the devices or from a replay, alike), or know a particular game's rules.

use std::path::{Path, PathBuf};

use super::first_person_game::Happened;
use super::player_input::player_input;
use crate::app::input::ActionSet;
use crate::app::replay::{Recorder, Replay, ReplayError, ReplayTarget, StepInput, level_hash};
use crate::app::runner::{EditHooks, EditTarget, Engine, Environment, SpawnedLevel};
use crate::app::runner::{Game, HudInfo, LevelEntry, LevelEvent, SetupError, ShellHooks};
use crate::app::runner::{ShellInfo, Step};
use crate::level::PlayableLevel;
use crate::player::ThirdPersonPlayer;

/// The prompt while the character carries a body.
pub const CARRY_PROMPT: &str = "E  put down · left mouse  throw";

/// The prompt while a body the character can lift is in front of it.
pub const TAKE_PROMPT: &str = "E  pick up";

/// The game name replays of [`ThirdPersonGame`] carry unless the game sets its own.
pub const THIRD_PERSON_GAME: &str = "candela-third-person";

/// A level played in third person by its first character.
pub struct ThirdPersonGame {
    level_path: PathBuf,
    level: PlayableLevel,
    game_name: String,
    level_id: String,
    actions: ActionSet,
    player: Option<ThirdPersonPlayer>,
    spawned: SpawnedLevel,
    log: Vec<(u64, Happened)>,
    start_input: Option<StepInput>,
    edit: Option<EditTarget>,
}

impl ThirdPersonGame {
    /// A game of an already loaded `level` (`level::load_level`); `level_path` names it in
    /// messages and replays, whose level id is the file's stem until
    /// [`ThirdPersonGame::set_replay_names`] says otherwise.
    pub fn of_level(level_path: &Path, level: PlayableLevel) -> Self {
        let level_id = level_path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        Self {
            level_path: level_path.to_path_buf(),
            level,
            game_name: THIRD_PERSON_GAME.into(),
            level_id,
            actions: ActionSet::standard(),
            player: None,
            spawned: SpawnedLevel::default(),
            log: Vec::new(),
            start_input: None,
            edit: None,
        }
    }

    /// The game name and level id recordings of this game carry.
    pub fn set_replay_names(&mut self, game: &str, level_id: &str) {
        self.game_name = game.into();
        self.level_id = level_id.into();
    }

    /// The actions the game reads (the standard set by default; a game appends its own with
    /// `ActionSet::with`). Set before `setup`; recordings carry them.
    pub fn set_actions(&mut self, actions: ActionSet) {
        self.actions = actions;
    }

    /// The actions the game reads.
    pub fn actions(&self) -> &ActionSet {
        &self.actions
    }

    /// What the editor (F1) edits: `None` gives the shell's placeholder.
    pub fn set_edit_target(&mut self, target: Option<EditTarget>) {
        self.edit = target;
    }

    /// The environment (sun, sky, render settings, camera) of the level, for `Engine::new`.
    pub fn environment(&self) -> Environment {
        Environment::of(&self.level.scene)
    }

    /// The level file.
    pub fn level_path(&self) -> &Path {
        &self.level_path
    }

    /// The level's id in replays.
    pub fn level_id(&self) -> &str {
        &self.level_id
    }

    /// The loaded level.
    pub fn level(&self) -> &PlayableLevel {
        &self.level
    }

    /// The level's instances, once set up.
    pub fn spawned(&self) -> &SpawnedLevel {
        &self.spawned
    }

    /// The player, once set up.
    pub fn player(&self) -> Option<&ThirdPersonPlayer> {
        self.player.as_ref()
    }

    /// The player, once set up, to move or retune it.
    pub fn player_mut(&mut self) -> Option<&mut ThirdPersonPlayer> {
        self.player.as_mut()
    }

    /// What happened so far, in order, with the step index.
    pub fn log(&self) -> &[(u64, Happened)] {
        &self.log
    }

    /// The prompt for what the character faces: the usable's own, else what E does with the
    /// body it carries or could lift.
    pub fn prompt(&self) -> Option<String> {
        let player = self.player.as_ref()?;
        if let Some((_, usable)) = player.focus() {
            Some(usable.prompt.clone())
        } else if player.hands.carrying() {
            Some(CARRY_PROMPT.into())
        } else {
            player.hands.takeable().map(|_| TAKE_PROMPT.into())
        }
    }

    /// Where the steps' input comes from once set up (a replay in a window; the devices by
    /// default).
    pub fn start_with(&mut self, input: StepInput) {
        self.start_input = Some(input);
    }

    fn target(&self) -> Result<ReplayTarget<'_>, ReplayError> {
        Ok(ReplayTarget {
            game: &self.game_name,
            level_id: &self.level_id,
            level_hash: level_hash(&self.level_path)?,
            step_hz: 60.0,
            actions: &self.actions,
        })
    }

    /// Opens the recording at `path` for this level (the game's actions at 60 steps per
    /// second and the level file as it is now; anything else is refused, naming `path`).
    pub fn open_replay(&self, path: &Path) -> Result<Replay, ReplayError> {
        Replay::open(path, &self.target()?)
    }

    /// A recorder of this level's steps (what [`ThirdPersonGame::open_replay`] accepts).
    pub fn recorder(&self) -> Result<Recorder, ReplayError> {
        let t = self.target()?;
        Ok(Recorder::new(
            t.game,
            t.level_id,
            t.level_hash,
            t.step_hz,
            t.actions,
        ))
    }
}

impl Game for ThirdPersonGame {
    fn setup(&mut self, engine: &mut Engine) -> Result<(), SetupError> {
        engine.set_actions(self.actions.clone());
        // The camera's probes query the scene in steps: the same input must give the same
        // outcome at any frame rate.
        engine.settle_every_step(true);
        self.spawned = engine.spawn_level(&self.level);
        let name = self
            .level
            .characters
            .first()
            .map(|c| c.name.clone())
            .ok_or_else(|| {
                format!(
                    "{}: the level has no character to play",
                    self.level_path.display()
                )
            })?;
        let hero = self.spawned.characters.get(&name).copied().ok_or_else(|| {
            format!(
                "{}: character {name:?} was not spawned",
                self.level_path.display()
            )
        })?;
        let view = crate::extract::RenderCamera::from_desc(&self.level.scene.camera);
        self.player = Some(ThirdPersonPlayer::spawn(
            engine.world_mut(),
            hero.body,
            hero.visual,
            &view,
        ));
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
        let done = player.step(
            step.world,
            step.physics,
            &step.queries,
            &input,
            step.step_seconds as f32,
        );
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

    fn shell(&mut self) -> Option<&mut dyn ShellHooks> {
        Some(self)
    }

    fn editor(&mut self) -> Option<&mut dyn EditHooks> {
        Some(self)
    }
}

impl EditHooks for ThirdPersonGame {
    fn edit_target(&self) -> Option<(EditTarget, SpawnedLevel)> {
        Some((self.edit.clone()?, self.spawned.clone()))
    }

    fn level_respawned(&mut self, _engine: &mut Engine, spawned: &SpawnedLevel) {
        self.spawned = spawned.clone();
        // The character is the level's: an edit spawns it again, with new entities.
        let name = self.level.characters.first().map(|c| c.name.as_str());
        if let (Some(player), Some(hero)) = (
            self.player.as_mut(),
            name.and_then(|n| spawned.characters.get(n)),
        ) {
            player.respawned(hero.body, hero.visual);
        }
    }
}

impl ShellHooks for ThirdPersonGame {
    fn shell_info(&self) -> ShellInfo {
        ShellInfo {
            title: "Candela Playground".into(),
            subtitle: "A level played in third person".into(),
            levels: vec![LevelEntry {
                name: self.level_id.replace('_', " "),
                id: self.level_id.clone(),
            }],
            finished_only: false,
        }
    }

    fn hud(&self) -> HudInfo {
        HudInfo {
            crosshair: false,
            objective: Some(
                "Walk with WASD, turn the camera with the mouse; E uses, picks up and puts down"
                    .into(),
            ),
            prompt: self.prompt(),
            ..HudInfo::default()
        }
    }
}
