//! The ending screen: the outcome's headline (or the game's own), the game's summary lines and
//! the play time, and Continue back to the title.
//!
//! Draws with egui, returns the choice. Main thread. Must not: change state itself.

use egui::RichText;

use super::state::ShellInput;
use super::theme;
use crate::app::runner::GameSummary;
use crate::sim::triggers::Outcome;

/// `seconds` as `m:ss` (or `h:mm:ss`).
pub fn clock_text(seconds: f64) -> String {
    let s = seconds.max(0.0).round() as u64;
    let (h, m, s) = (s / 3600, (s / 60) % 60, s % 60);
    if h > 0 {
        format!("{h}:{m:02}:{s:02}")
    } else {
        format!("{m}:{s:02}")
    }
}

/// Draws the ending screen.
pub fn show(
    ctx: &egui::Context,
    outcome: Option<&Outcome>,
    summary: &GameSummary,
    play_seconds: f64,
) -> Option<ShellInput> {
    theme::dim(ctx);
    let headline = if !summary.headline.is_empty() {
        summary.headline.clone()
    } else {
        match outcome {
            Some(Outcome::Lost(_)) => "Level failed".to_string(),
            _ => "Level complete".to_string(),
        }
    };
    let mut choice = None;
    theme::centred(ctx, "shell_ending", |ui| {
        ui.vertical_centered(|ui| {
            ui.label(theme::heading(&headline));
            ui.add_space(6.0);
            for line in &summary.lines {
                ui.label(line.as_str());
            }
            ui.label(
                RichText::new(format!("Time played  {}", clock_text(play_seconds)))
                    .color(theme::MUTED),
            );
            ui.add_space(10.0);
            if theme::menu_button(ui, "Continue") {
                choice = Some(ShellInput::QuitToTitle);
            }
        });
    });
    choice
}
