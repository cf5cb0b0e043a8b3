//! The game runner's shell: the screens around a [`crate::app::Game`] — title menu, playing
//! (HUD), pause menu, settings, the editor hook (F1) and the ending — with one consistent look,
//! the player's settings applied live and saved atomically, and progress saved at checkpoints
//! and level ends. The same [`ShellRun`] drives a window ([`crate::app::run_game`], in `app/window/`) or headless
//! ([`run_headless`]).
//!
//! One file per job: `state` (the screens' state machine, pure), `settings_edit` (the settings
//! screen's model, pure), `files` (settings and progress files, notices of corrupt ones),
//! `cues` (scripted input), `run` (the per-frame glue), `theme` (the look), `title`, `hud`,
//! `pause` (with the editor placeholder), `settings_screen`, `ending` (egui screens) and
//! `headless`. The hooks a game offers the shell ([`ShellHooks`], through `Game::shell`) and
//! the data they carry ([`ShellInfo`], [`HudInfo`], [`GameSummary`], …) live in the runner
//! (`app/runner/shell_hooks.rs`: the first-person game, a layer below, implements them) and
//! are re-exported here. Main thread. Must not: render or own the window (the window runner
//! does), or use `app`'s `window` or `harness` (the layers after it).

mod cues;
mod ending;
mod files;
mod headless;
mod hud;
mod pause;
mod run;
mod settings_edit;
mod settings_screen;
mod state;
mod theme;
mod title;

pub use crate::app::runner::{
    GameSummary, HudInfo, LevelEntry, LevelStart, ProgressEvent, ShellHooks, ShellInfo,
};
pub use cues::{Cue, CueAction, EditorCue};
pub use ending::clock_text;
pub use files::{Notice, PlayerFiles};
pub use headless::run_headless;
pub use run::{ShellConfig, ShellRun, WindowWants};
pub use settings_edit::{Conflict, FRAME_RATES, SettingsEditor, action_label, binding_label};
pub use state::{Screen, ShellEffect, ShellInput, ShellState};
pub use theme::style;
pub use title::{continue_label, continue_point};
