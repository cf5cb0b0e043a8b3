//! The window runner's editor hook: turning [`EditMode`] on and off as the shell's Editor
//! screen (F1 under the shell) or, without the shell (`view`), F1 asks. The editor is opened
//! the first time from the game's `EditHooks::edit_target` (`Game::editor`); a game without one gets the shell's placeholder.
//! Turning it on frees the mouse and, without the shell, holds the engine (`set_paused`);
//! whenever the editor spawns the level again the game hears it (`EditHooks::level_respawned`);
//! leaving it plays from the editor camera (`EditMode::play_from_here`, `EditHooks::play_from`).
//!
//! Main thread. Must not: draw (the editor draws in the overlay pass, `app.rs`).

use super::app::WindowApp;
use crate::app::edit::EditMode;
use crate::app::shell::Screen;

impl WindowApp<'_> {
    /// Turns the editor on or off, as asked this frame.
    pub(super) fn follow_edit_mode(&mut self) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let want = match self.shell.as_ref() {
            Some(shell) => shell.screen() == Screen::Editor,
            None => {
                if std::mem::take(&mut self.edit_toggle) {
                    self.editing = !self.editing;
                }
                self.editing
            }
        };
        let active = self.edit.as_ref().is_some_and(EditMode::active);
        if want && !active {
            if self.edit.is_none() && !self.edit_unavailable {
                match self.game.editor().and_then(|hooks| hooks.edit_target()) {
                    Some((target, spawned)) => match EditMode::open(target, spawned) {
                        Ok(edit) => self.edit = Some(edit),
                        Err(e) => {
                            log::error!("editor: {e}");
                            self.edit_unavailable = true;
                        }
                    },
                    None => {
                        log::info!("editor: this game has no level to edit");
                        self.edit_unavailable = true;
                    }
                }
                if let Some(shell) = self.shell.as_mut() {
                    shell.set_editor_drawn(self.edit.is_some());
                }
            }
            match self.edit.as_mut() {
                Some(edit) => {
                    running.set_captured(false);
                    edit.enter_with(&mut running.engine, self.game.editor());
                }
                None => self.editing = false,
            }
        } else if !want
            && active
            && let Some(edit) = self.edit.as_mut()
        {
            edit.play_from_here(&mut running.engine, self.game.editor());
        }
        if let Some(shell) = self.shell.as_mut() {
            let cues = shell.take_editor_cues();
            if let Some(edit) = self.edit.as_mut().filter(|e| e.active()) {
                for mut cue in cues {
                    cue(edit);
                }
            }
        } else {
            let on = self.edit.as_ref().is_some_and(EditMode::active);
            running.engine.set_paused(on);
        }
    }
}
