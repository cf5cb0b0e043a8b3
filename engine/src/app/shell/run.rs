//! [`ShellRun`]: the shell around a [`Game`], one per run, driven by the window runner or
//! headless ([`super::run_headless`]) with the same calls per frame:
//! `before_frame` (scripted cues, rebinding presses, the pause and editor actions, the
//! transitions and their effects: `ShellHooks::begin_level`, progress saves; settings applied) →
//! `ui` (the current screen in egui) → `after_ui` (the screen's choice carried out; settings
//! applied live and saved) → `Engine::frame` → `after_frame` (play time, checkpoints and the
//! level's end from `Engine::take_progress_events`).
//!
//! Settings apply live: volumes to the audio buses and the whole value to `Engine::settings`
//! (`Engine::set_settings`), bindings to the input map (with the runner's own keys), and
//! through [`ShellRun::wants`] / [`ShellRun::scaling_goal`] the window's capture, fullscreen,
//! vsync and frame limiter and the render thread's workload scaling (target frame rate,
//! resolution scale). While the screen is not Playing the engine is paused
//! (`Engine::set_paused`: no game hooks, no fixed steps; the picture keeps converging).
//! Main thread. Must not: open windows or render (the runner does).

use std::collections::VecDeque;
use std::path::PathBuf;

use super::cues::{Cue, CueAction, EditorCue};
use super::files::{Notice, PlayerFiles};
use super::settings_edit::SettingsEditor;
use super::state::{Screen, ShellEffect, ShellInput, ShellState};
use super::{ending, hud, pause, settings_screen, theme, title};
use crate::app::input::game_actions;
use crate::app::input::{Binding, InputMap, actions};
use crate::app::persist::Settings;
use crate::app::persist::UserDirs;
use crate::app::runner::Engine;
use crate::app::runner::FrameReport;
use crate::app::runner::Game;
use crate::app::runner::{GameSummary, HudInfo, ProgressEvent, ShellInfo};
use crate::commit::ScalingRequest;
use crate::sim::triggers::Outcome;

/// How the shell runs.
#[derive(Debug)]
pub struct ShellConfig {
    /// Where the settings and the progress save live (`UserDirs::from_env`, or
    /// `UserDirs::under` for tests and portable installs).
    pub dirs: UserDirs,
    /// Scripted input, played in order (tests, demos); empty for players.
    pub cues: Vec<Cue>,
}

/// What the window should be like now (the runner makes it so).
#[derive(Clone, Debug, PartialEq)]
pub struct WindowWants {
    /// Capture the mouse for looking around (Playing only).
    pub captured: bool,
    pub fullscreen: bool,
    pub vsync: bool,
    /// Frame limiter rate (the target frame rate setting).
    pub max_fps: Option<f64>,
    /// The player chose Quit.
    pub exit: bool,
}

/// The shell's per-run state.
pub struct ShellRun {
    state: ShellState,
    files: PlayerFiles,
    editor: SettingsEditor,
    info: ShellInfo,
    runner_keys: InputMap,
    /// What the engine has now.
    applied: Option<Settings>,
    cues: VecDeque<Cue>,
    waited: u32,
    pending: Vec<ShellInput>,
    presses: Vec<Binding>,
    exit: bool,
    screenshot: Option<PathBuf>,
    styled: bool,
    dragging: bool,
    hud: HudInfo,
    summary: GameSummary,
    /// The runner draws the editor on the Editor screen (else the placeholder shows).
    editor_drawn: bool,
    /// Editor cues played and not yet taken by the runner.
    editor_cues: Vec<EditorCue>,
    /// What workload scaling settled on (`FrameStats::workload_summary`), from the window.
    workload: Option<String>,
}

impl ShellRun {
    /// After `Game::setup` (which may set the game's actions): loads the player's files (a
    /// corrupt one is replaced by defaults and noticed), applies the settings and pauses the
    /// engine at the title screen. `runner_keys` are the runner's own keys (stats, fullscreen,
    /// vsync), kept next to the game's actions.
    pub fn new(
        config: ShellConfig,
        engine: &mut Engine,
        game: &mut dyn Game,
        runner_keys: InputMap,
    ) -> Self {
        let files = PlayerFiles::load(config.dirs, engine.actions());
        let editor = SettingsEditor::new(files.settings.clone(), engine.actions().clone());
        let mut run = Self {
            state: ShellState::new(),
            files,
            editor,
            info: game
                .shell()
                .map_or_else(ShellInfo::default, |s| s.shell_info()),
            runner_keys,
            applied: None,
            cues: config.cues.into(),
            waited: 0,
            pending: Vec::new(),
            presses: Vec::new(),
            exit: false,
            screenshot: None,
            styled: false,
            dragging: false,
            hud: HudInfo::default(),
            summary: GameSummary::default(),
            editor_drawn: false,
            editor_cues: Vec::new(),
            workload: None,
        };
        run.apply_settings(engine);
        engine.set_paused(true);
        run
    }

    pub fn state(&self) -> &ShellState {
        &self.state
    }

    pub fn screen(&self) -> Screen {
        self.state.screen()
    }

    /// The player's files as loaded and saved so far (notices included).
    pub fn files(&self) -> &PlayerFiles {
        &self.files
    }

    /// The settings screen's model.
    pub fn editor_mut(&mut self) -> &mut SettingsEditor {
        &mut self.editor
    }

    /// Whether the runner draws the level editor on the Editor screen (`app::edit`); if not,
    /// the screen shows the placeholder.
    pub fn set_editor_drawn(&mut self, drawn: bool) {
        self.editor_drawn = drawn;
    }

    /// The editor cues played since the last call, for the runner's editor.
    pub fn take_editor_cues(&mut self) -> Vec<EditorCue> {
        std::mem::take(&mut self.editor_cues)
    }

    /// What workload scaling settled on, shown on the settings screen beside the target frame
    /// rate (the window passes `FrameStats::workload_summary` each frame).
    pub fn set_workload(&mut self, summary: Option<String>) {
        self.workload = summary;
    }

    /// What the settings screen shows workload scaling settled on.
    pub fn workload(&self) -> Option<&str> {
        self.workload.as_deref()
    }

    /// Queues an input (carried out in the next `before_frame` or `after_ui`).
    pub fn push(&mut self, input: ShellInput) {
        self.pending.push(input);
    }

    /// A key or mouse button went down (the window forwards every press, for rebinding).
    pub fn pressed(&mut self, binding: Binding) {
        self.presses.push(binding);
    }

    /// Start of a frame, before the overlay is built: cues, presses, the pause and editor
    /// actions, transitions, settings.
    pub fn before_frame(&mut self, engine: &mut Engine, game: &mut dyn Game) {
        self.play_cues();
        let mut used = false;
        for press in std::mem::take(&mut self.presses) {
            used |= self.editor.offer(press);
        }
        let input = engine.input();
        if !used && input.pressed_this_frame(game_actions::PAUSE) {
            self.pending.push(ShellInput::Pause);
        }
        if input.pressed_this_frame(game_actions::EDITOR_TOGGLE) {
            self.pending.push(ShellInput::EditorToggle);
        }
        if input.pressed_this_frame(actions::TOGGLE_FULLSCREEN) {
            self.editor.draft.fullscreen = !self.editor.draft.fullscreen;
        }
        if input.pressed_this_frame(actions::TOGGLE_VSYNC) {
            self.editor.draft.vsync = !self.editor.draft.vsync;
        }
        self.carry_out(engine, game);
        self.hud = game.shell().map_or_else(HudInfo::default, |s| s.hud());
        self.apply_settings(engine);
    }

    /// Draws the current screen.
    pub fn ui(&mut self, ctx: &egui::Context) {
        theme::apply(ctx, &mut self.styled);
        let choice = match self.state.screen() {
            Screen::Title => {
                theme::dim(ctx);
                title::show(
                    ctx,
                    &self.info,
                    &self.files.progress,
                    &mut self.files.notices,
                )
            }
            Screen::Playing => {
                hud::show(ctx, &self.hud);
                None
            }
            Screen::Paused => pause::show(ctx, &self.level_name()),
            Screen::Settings => {
                settings_screen::show(ctx, &mut self.editor, self.workload.as_deref(), true)
            }
            Screen::Editor if self.editor_drawn => None,
            Screen::Editor => pause::editor(ctx),
            Screen::Ending => ending::show(
                ctx,
                self.state.outcome(),
                &self.summary,
                self.files.progress.play_seconds,
            ),
        };
        self.dragging = ctx.input(|i| i.pointer.any_down());
        self.pending.extend(choice);
    }

    /// After the overlay: the screen's choice, settings applied and saved.
    pub fn after_ui(&mut self, engine: &mut Engine, game: &mut dyn Game) {
        self.carry_out(engine, game);
        self.apply_settings(engine);
        let changed = self.files.settings != self.editor.draft;
        if changed && !self.dragging && self.editor.draft.check(engine.actions()).is_ok() {
            self.files.settings = self.editor.draft.clone();
            self.files.save_settings(engine.actions());
        }
    }

    /// After `Engine::frame`: play time, checkpoints, the level's end.
    pub fn after_frame(&mut self, engine: &mut Engine, report: &FrameReport) {
        self.files
            .progress
            .add_play_time(f64::from(report.steps) * engine.clock().step_seconds);
        let mut reached = false;
        for event in engine.take_progress_events() {
            match event {
                ProgressEvent::Checkpoint(checkpoint) => {
                    if let Some(level) = self.state.level() {
                        let level = level.level.clone();
                        self.files.progress.reach_checkpoint(&level, &checkpoint);
                        reached = true;
                    }
                }
                ProgressEvent::Ended(outcome) => self.pending.push(ShellInput::LevelEnded(outcome)),
                ProgressEvent::Finished(level) => {
                    self.files.progress.finish_level(&level);
                    reached = true;
                }
            }
        }
        if reached {
            self.files.save_progress();
        }
    }

    /// What the window should be like.
    pub fn wants(&self) -> WindowWants {
        let s = self.applied.as_ref().unwrap_or(&self.editor.draft);
        WindowWants {
            captured: self.state.wants_mouse(),
            fullscreen: s.fullscreen,
            vsync: s.vsync,
            max_fps: s.target_fps.map(f64::from),
            exit: self.exit,
        }
    }

    /// The render thread's workload goal from the settings (target frame rate, resolution).
    pub fn scaling_goal(&self) -> ScalingRequest {
        let s = self.applied.as_ref().unwrap_or(&self.editor.draft);
        ScalingRequest {
            frame_seconds: s.target_fps.map(|fps| 1.0 / fps),
            max_resolution: s.resolution_scale,
        }
    }

    /// A screenshot a cue asked for this frame, once.
    pub fn take_screenshot(&mut self) -> Option<PathBuf> {
        self.screenshot.take()
    }

    /// Saves progress, and settings changed since the last save (the run is ending).
    pub fn finish(&mut self) {
        let set = self.editor.actions().clone();
        if self.files.settings != self.editor.draft && self.editor.draft.check(&set).is_ok() {
            self.files.settings = self.editor.draft.clone();
            self.files.save_settings(&set);
        }
        self.files.save_progress();
    }

    fn level_name(&self) -> String {
        let Some(start) = self.state.level() else {
            return String::new();
        };
        self.info
            .levels
            .iter()
            .find(|l| l.id == start.level)
            .map_or_else(|| start.level.clone(), |l| l.name.clone())
    }

    fn play_cues(&mut self) {
        while let Some(cue) = self.cues.front() {
            if self.waited < cue.wait_frames {
                self.waited += 1;
                return;
            }
            self.waited = 0;
            let Some(cue) = self.cues.pop_front() else {
                return;
            };
            match cue.action {
                CueAction::Input(input) => self.pending.push(input),
                CueAction::Edit(mut edit) => edit(&mut self.editor),
                CueAction::Screenshot(path) => self.screenshot = Some(path),
                CueAction::Editor(cue) => self.editor_cues.push(cue),
                CueAction::Call(mut step) => step(),
            }
        }
    }

    /// Carries out the queued inputs and their effects; pauses the engine off Playing.
    fn carry_out(&mut self, engine: &mut Engine, game: &mut dyn Game) {
        for input in std::mem::take(&mut self.pending) {
            for effect in self.state.handle(input) {
                self.effect(effect, engine, game);
            }
        }
        if self.state.screen() != Screen::Settings && self.editor.capturing().is_some() {
            self.editor
                .offer(Binding::Key(crate::app::input::KeyCode::Escape));
        }
        engine.set_paused(!self.state.simulating());
    }

    fn effect(&mut self, effect: ShellEffect, engine: &mut Engine, game: &mut dyn Game) {
        match effect {
            ShellEffect::BeginLevel(start) => {
                let begun = match game.shell() {
                    Some(hooks) => hooks.begin_level(engine, &start),
                    None => Ok(()),
                };
                if let Err(e) = begun {
                    log::error!("level {:?} cannot start: {e}", start.level);
                    self.files.notices.push(Notice {
                        title: format!("Level {} cannot start", start.level),
                        detail: e.to_string(),
                    });
                    self.state = ShellState::new();
                }
                // Progress reported before the level began is not the new level's.
                engine.take_progress_events();
                engine.cut();
            }
            ShellEffect::RecordEnd(outcome) => {
                if let (Outcome::Won(_), Some(start)) = (&outcome, self.state.level()) {
                    let level = start.level.clone();
                    self.files.progress.finish_level(&level);
                }
                self.summary = game
                    .shell()
                    .map_or_else(GameSummary::default, |s| s.summary());
                self.files.save_progress();
            }
            ShellEffect::SaveProgress => {
                self.files.save_progress();
            }
            ShellEffect::Exit => {
                self.exit = true;
                self.files.save_progress();
            }
        }
    }

    /// Gives the engine the draft when it changed (and is valid).
    fn apply_settings(&mut self, engine: &mut Engine) {
        if self.applied.as_ref() == Some(&self.editor.draft) {
            return;
        }
        if let Err(problem) = self.editor.draft.check(engine.actions()) {
            log::warn!("settings not applied: {problem}");
            return;
        }
        let settings = self.editor.draft.clone();
        if self.applied.as_ref().map(|a| &a.bindings) != Some(&settings.bindings) {
            let map = self
                .runner_keys
                .clone()
                .merged(settings.input_map(engine.actions()));
            engine.set_input_map(&map);
        }
        engine.set_settings(settings.clone());
        self.applied = Some(settings);
    }
}
