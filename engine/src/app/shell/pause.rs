//! The pause menu (Resume, Settings, Quit to title, Quit game) over the dimmed, still
//! converging picture, and the editor hook's placeholder screen (F1: "Editor (coming)").
//!
//! Draws with egui, returns the choice. Main thread. Must not: change state itself.

use egui::RichText;

use super::state::ShellInput;
use super::theme;

/// Draws the pause menu; `level` names the level under way.
pub fn show(ctx: &egui::Context, level: &str) -> Option<ShellInput> {
    theme::dim(ctx);
    let mut choice = None;
    theme::centred(ctx, "shell_pause", |ui| {
        ui.vertical_centered(|ui| {
            ui.label(theme::heading("Paused"));
            if !level.is_empty() {
                ui.label(RichText::new(level).color(theme::MUTED));
            }
            ui.add_space(10.0);
            if theme::menu_button(ui, "Resume") {
                choice = Some(ShellInput::Resume);
            }
            if theme::menu_button(ui, "Settings") {
                choice = Some(ShellInput::OpenSettings);
            }
            if theme::menu_button(ui, "Quit to title") {
                choice = Some(ShellInput::QuitToTitle);
            }
            if theme::menu_button(ui, "Quit game") {
                choice = Some(ShellInput::Quit);
            }
        });
    });
    choice
}

/// The editor hook's screen until the editor exists.
pub fn editor(ctx: &egui::Context) -> Option<ShellInput> {
    theme::dim(ctx);
    let mut choice = None;
    theme::centred(ctx, "shell_editor", |ui| {
        ui.vertical_centered(|ui| {
            ui.label(theme::heading("Editor (coming)"));
            ui.label(RichText::new("The game is held. F1 returns to it.").color(theme::MUTED));
            ui.add_space(8.0);
            if theme::menu_button(ui, "Back to the game") {
                choice = Some(ShellInput::EditorToggle);
            }
        });
    });
    choice
}
