//! The runner's screens as a state machine: Title → Playing ⇄ Paused → Ending → Title, the
//! Settings screen reached from Title and Paused (it returns where it came from), and the
//! Editor (F1 from Playing or Paused): it holds the game like Paused while the window runner
//! draws the level editor (`app::edit`), or a placeholder for a game with no level to edit.
//!
//! Pure logic: [`ShellState::handle`] takes a [`ShellInput`] (a menu choice, the pause or editor
//! action, the level's end, focus lost) and returns the [`ShellEffect`]s for the runner to carry
//! out. Only [`Screen::Playing`] runs the game's hooks and fixed steps and captures the mouse.
//! Main thread. Must not: touch the engine, the window or files (the runner does).

use crate::app::runner::LevelStart;
use crate::sim::triggers::Outcome;

/// What the shell shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Screen {
    Title,
    Playing,
    Paused,
    Settings,
    /// The level editor (F1): the game is held while the runner's editor is drawn.
    Editor,
    Ending,
}

/// Something that happened to the shell.
#[derive(Clone, Debug, PartialEq)]
pub enum ShellInput {
    /// The pause action (Escape, Start): pauses, resumes, or goes back one screen.
    Pause,
    /// The editor action (F1).
    EditorToggle,
    /// A title menu choice: play this level.
    Start(LevelStart),
    Resume,
    OpenSettings,
    /// Leave the settings screen (to Title or Paused, wherever it was opened from).
    CloseSettings,
    /// Abandon the level (from Paused) or leave the ending screen.
    QuitToTitle,
    /// Leave the game.
    Quit,
    /// The level ended (its rules or the game said so).
    LevelEnded(Outcome),
    /// The window lost focus (while playing: pause).
    FocusLost,
}

/// What the runner must do after a transition.
#[derive(Clone, Debug, PartialEq)]
pub enum ShellEffect {
    /// Ask the game to set this level up (`ShellHooks::begin_level`).
    BeginLevel(LevelStart),
    /// Record the level's end in the progress save.
    RecordEnd(Outcome),
    /// Save progress now (leaving a level for the title).
    SaveProgress,
    /// Leave the game.
    Exit,
}

/// The shell's state.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellState {
    screen: Screen,
    /// Where Settings and Editor return to.
    back_to: Screen,
    /// The level being played (set by `Start`, kept through pauses and the ending).
    level: Option<LevelStart>,
    /// How the last level ended.
    outcome: Option<Outcome>,
}

impl Default for ShellState {
    fn default() -> Self {
        Self::new()
    }
}

impl ShellState {
    /// At the title screen.
    pub fn new() -> Self {
        Self {
            screen: Screen::Title,
            back_to: Screen::Title,
            level: None,
            outcome: None,
        }
    }

    pub fn screen(&self) -> Screen {
        self.screen
    }

    /// Whether the game runs (its hooks, fixed steps, game time): only while playing.
    pub fn simulating(&self) -> bool {
        self.screen == Screen::Playing
    }

    /// Whether the mouse should be captured for looking around: only while playing.
    pub fn wants_mouse(&self) -> bool {
        self.screen == Screen::Playing
    }

    /// The level under way (or just ended).
    pub fn level(&self) -> Option<&LevelStart> {
        self.level.as_ref()
    }

    /// How the last level ended, on the ending screen.
    pub fn outcome(&self) -> Option<&Outcome> {
        self.outcome.as_ref()
    }

    /// Carries out `input`; inputs that mean nothing on the current screen change nothing.
    pub fn handle(&mut self, input: ShellInput) -> Vec<ShellEffect> {
        use Screen::*;
        use ShellInput as I;
        let mut effects = Vec::new();
        match (self.screen, input) {
            (_, I::Quit) => effects.push(ShellEffect::Exit),
            (Title, I::Start(start)) => {
                self.level = Some(start.clone());
                self.outcome = None;
                self.screen = Playing;
                effects.push(ShellEffect::BeginLevel(start));
            }
            (Title | Paused, I::OpenSettings) => {
                self.back_to = self.screen;
                self.screen = Settings;
            }
            (Settings, I::CloseSettings | I::Pause) => self.screen = self.back_to,
            (Playing, I::Pause | I::FocusLost) => self.screen = Paused,
            (Paused, I::Pause | I::Resume) => self.screen = Playing,
            (Playing | Paused, I::EditorToggle) => {
                self.back_to = self.screen;
                self.screen = Editor;
            }
            (Editor, I::EditorToggle) => self.screen = self.back_to,
            (Editor, I::Pause | I::Resume) => self.screen = Paused,
            (Paused, I::QuitToTitle) => {
                self.screen = Title;
                effects.push(ShellEffect::SaveProgress);
            }
            (Playing | Paused | Editor, I::LevelEnded(outcome)) => {
                self.outcome = Some(outcome.clone());
                self.screen = Ending;
                effects.push(ShellEffect::RecordEnd(outcome));
            }
            (Ending, I::QuitToTitle | I::Resume) => self.screen = Title,
            _ => {}
        }
        effects
    }
}
